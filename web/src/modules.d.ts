// Vite's `?worker&url` imports (the AudioWorklet's module URL, live-input.ts).
declare module "*?worker&url" {
  const url: string;
  export default url;
}
