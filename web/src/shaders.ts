// GLSL of the deformation (docs/design.md#rendering): harmonics packed four per RGBA32F texel, the surface pass
// (GPU positions from a float target, or CPU positions as an attribute) and the batched
// positions pass.

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

/** Surface pass, vertex: the deformed position of vertex `vid` (from the positions pass's float
 * target, or the `displaced` attribute on the CPU path), and the harmonics explorer's value. */
export const SURFACE_VERTEX = /* glsl */ `
uniform int colorHarmonic;
uniform float colorScale;
#ifdef CPU_PATH
in vec3 displaced;
#else
uniform sampler2D deformed;
uniform int deformedWidth;
#endif
out vec3 vViewPosition;
out vec3 vNormal;
out float vHarmonic;
void main() {
  int v = int(vid + 0.5);
#ifdef CPU_PATH
  vec3 p = displaced;
#else
  vec3 p = texelFetch(deformed, ivec2(v % deformedWidth, v / deformedWidth), 0).xyz;
#endif
  vHarmonic = 0.0;
  if (colorHarmonic >= 0) {
    vec4 u = harmonicTexel(v, colorHarmonic / 4);
    int q = colorHarmonic - 4 * (colorHarmonic / 4);
    vHarmonic = (q == 0 ? u.x : q == 1 ? u.y : q == 2 ? u.z : u.w) * colorScale;
  }
  vec4 mv = modelViewMatrix * vec4(p, 1.0);
  vViewPosition = -mv.xyz;
  vNormal = normalize(normalMatrix * normal);
  gl_Position = projectionMatrix * mv;
}
`;

/** Surface pass, fragment: the flat normal of the deformed triangle blended with the original
 * vertex normal (docs/design.md#rendering, thesis Fig. 6.4), key + fill light, rim and specular. */
export const SURFACE_FRAGMENT = /* glsl */ `
precision highp float;
uniform vec3 baseColor;
uniform float normalBlend;
uniform int colorHarmonic;
uniform bool wire;
layout(location = 0) out highp vec4 fragColor;
in vec3 vViewPosition;
in vec3 vNormal;
in float vHarmonic;
vec3 diverging(float x) {
  x = clamp(x, -1.0, 1.0);
  vec3 cold = vec3(0.23, 0.30, 0.75), warm = vec3(0.71, 0.02, 0.15), mid = vec3(0.87);
  return x < 0.0 ? mix(mid, cold, -x) : mix(mid, warm, x);
}
void main() {
  vec3 color = colorHarmonic >= 0 ? diverging(vHarmonic) : baseColor;
  if (wire) { fragColor = vec4(color, 1.0); return; }
  vec3 flatNormal = normalize(cross(dFdx(vViewPosition), dFdy(vViewPosition)));
  vec3 smoothNormal = normalize(vNormal);
  if (dot(smoothNormal, flatNormal) < 0.0) smoothNormal = -smoothNormal;
  // normalBlend = weight of the original vertex normal (0: flat deformed normal).
  vec3 n = normalize(mix(flatNormal, smoothNormal, normalBlend));
  vec3 view = normalize(vViewPosition);
  vec3 key = normalize(vec3(0.5, 0.8, 0.6));
  vec3 fill = normalize(vec3(-0.7, -0.2, 0.4));
  float diffuse = max(dot(n, key), 0.0) * 0.75 + max(dot(n, fill), 0.0) * 0.25;
  float rim = pow(1.0 - max(dot(n, view), 0.0), 3.0) * 0.25;
  float spec = pow(max(dot(n, normalize(key + view)), 0.0), 40.0) * 0.25;
  fragColor = vec4(color * (0.22 + diffuse) + vec3(spec + rim), 1.0);
}
`;

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
