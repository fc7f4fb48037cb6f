// GLSL (docs/design.md#rendering): harmonics packed four per RGBA32F texel and the batched
// positions pass (the page's own), and the GLSL shared with the video's renderer: the surface
// pass (GPU positions from a float target, or CPU positions as an attribute; clay or a glTF
// material), the studio backdrop and contact shadow.

/** Shared by both passes: texel j of vertex v holds harmonics 4j…4j+3 of that vertex. */
export const TEXELS = /* glsl */ `
precision highp float;
precision highp int;
precision highp sampler2D;
uniform sampler2D harmonics;
uniform int texWidth;
in float vid;

vec4 harmonicTexel(int v, int j) {
  int index = v * K4 + j;
  return texelFetch(harmonics, ivec2(index % texWidth, index / texWidth), 0);
}
`;

// The surface, the backdrop and the shadow: one GLSL source with the video's renderer
// (src/eigendance/shaders, docs/design.md#rendering), compiled as three.js RawShaderMaterials
// (three.js puts `#version 300 es` and the defines first). The surface reads the harmonics
// (TEXELS, above) with the define HARMONICS: the harmonics explorer.
export { default as SURFACE_VERTEX } from "../../src/eigendance/shaders/surface.vert.glsl?raw";
export { default as SURFACE_FRAGMENT } from "../../src/eigendance/shaders/surface.frag.glsl?raw";
export { default as BACKDROP_VERTEX } from "../../src/eigendance/shaders/backdrop.vert.glsl?raw";
export { default as BACKDROP_FRAGMENT } from
  "../../src/eigendance/shaders/backdrop.frag.glsl?raw";
export { default as SHADOW_VERTEX } from "../../src/eigendance/shaders/shadow.vert.glsl?raw";
export { default as SHADOW_FRAGMENT } from "../../src/eigendance/shaders/shadow.frag.glsl?raw";

/** Positions pass for `tiles` gallery tiles at once: each harmonic texel is fetched once and
 * used for every tile; tile t's positions go to colour attachment t of a float render target. */
export function positionsShaders(tiles: number): { vertex: string; fragment: string } {
  const range = [...Array(tiles).keys()];
  const vertex = /* glsl */ `
uniform vec4 weights[WEIGHTS];
uniform int targetWidth;
uniform vec2 targetSize;
${range.map((t) => `out vec3 vPosition${t};`).join("\n")}
void main() {
  int v = int(vid + 0.5);
${range.map((t) => `  vec3 d${t} = vec3(0.0);`).join("\n")}
  for (int j = 0; j < K4; j++) {
    vec4 u = harmonicTexel(v, j);
    int b = 3 * j;
${range.map((t) => `    d${t} += vec3(dot(u, weights[b + ${3 * t} * K4]), dot(u, weights[b + ${3 * t} * K4 + 1]), dot(u, weights[b + ${3 * t} * K4 + 2]));`).join("\n")}
  }
${range.map((t) => `  vPosition${t} = position + d${t};`).join("\n")}
  vec2 pixel = vec2(float(v % targetWidth), float(v / targetWidth)) + 0.5;
  gl_Position = vec4(pixel / targetSize * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
}
`;
  const fragment = /* glsl */ `
precision highp float;
${range.map((t) => `in vec3 vPosition${t};\nlayout(location = ${t}) out highp vec4 out${t};`).join("\n")}
void main() {
${range.map((t) => `  out${t} = vec4(vPosition${t}, 1.0);`).join("\n")}
}
`;
  return { vertex, fragment };
}
