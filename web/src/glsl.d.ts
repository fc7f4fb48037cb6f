// The GLSL files the page shares with the video (src/eigendance/shaders), imported as text.
declare module "*.glsl?raw" {
  const source: string;
  export default source;
}
