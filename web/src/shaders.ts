// GLSL (docs/design.md#rendering): harmonics packed four per RGBA32F texel, the surface pass
// (GPU positions from a float target, or CPU positions as an attribute), the studio backdrop and
// contact shadow, and the batched positions pass.

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
 * target, or the `displaced` attribute on the CPU path; a reduced basis (REDUCED, after
 * reduced.ts GATHER) gathers its samples' displacements), and the harmonics explorer's value. */
export const SURFACE_VERTEX = /* glsl */ `
uniform int colorHarmonic;
uniform float colorScale;
#ifdef CPU_PATH
in vec3 displaced;
#elif !defined(REDUCED)
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
#elif defined(REDUCED)
  vec3 p = position + gatherDisplacement();
#else
  vec3 p = texelFetch(deformed, ivec2(v % deformedWidth, v / deformedWidth), 0).xyz;
#endif
  vHarmonic = 0.0;
  if (colorHarmonic >= 0) {
#ifdef REDUCED
    vec4 u = gatherHarmonicTexel(colorHarmonic / 4);
#else
    vec4 u = harmonicTexel(v, colorHarmonic / 4);
#endif
    int q = colorHarmonic - 4 * (colorHarmonic / 4);
    vHarmonic = (q == 0 ? u.x : q == 1 ? u.y : q == 2 ? u.z : u.w) * colorScale;
  }
  vec4 mv = modelViewMatrix * vec4(p, 1.0);
  vViewPosition = -mv.xyz;
  vNormal = normalize(normalMatrix * normal);
  gl_Position = projectionMatrix * mv;
}
`;

/** Surface pass, fragment: normals as thesis Fig. 6.4(d) — the flat normal of the deformed
 * triangle weighted `deformedNormalWeight` (0.4) against the original vertex normal
 * (docs/design.md#rendering) — under a studio light rig fixed to the camera: a sky/ground
 * ambient, a soft (wrapped) key light, a cool fill, a rim and a broad specular; then a gentle
 * tone curve and gamma. */
export const SURFACE_FRAGMENT = /* glsl */ `
precision highp float;
uniform vec3 baseColor;
uniform float deformedNormalWeight;
uniform int colorHarmonic;
uniform bool wire;
layout(location = 0) out highp vec4 fragColor;
in vec3 vViewPosition;
in vec3 vNormal;
in float vHarmonic;
vec3 diverging(float x) {
  x = clamp(x, -1.0, 1.0);
  vec3 cold = vec3(0.05, 0.12, 0.55), warm = vec3(0.55, 0.02, 0.03), mid = vec3(0.75);
  return x < 0.0 ? mix(mid, cold, -x) : mix(mid, warm, x);
}
void main() {
  vec3 albedo = colorHarmonic >= 0 ? diverging(vHarmonic) : baseColor; // linear
  if (wire) { fragColor = vec4(pow(albedo, vec3(1.0 / 2.2)), 1.0); return; }
  vec3 flatNormal = normalize(cross(dFdx(vViewPosition), dFdy(vViewPosition)));
  vec3 vertexNormal = normalize(vNormal);
  if (dot(vertexNormal, flatNormal) < 0.0) vertexNormal = -vertexNormal;
  vec3 n = normalize(mix(vertexNormal, flatNormal, deformedNormalWeight));
  vec3 view = normalize(vViewPosition);
  vec3 key = normalize(vec3(-0.5, 0.75, 0.45));
  vec3 fill = normalize(vec3(0.8, 0.05, 0.55));
  vec3 back = normalize(vec3(0.3, 0.6, -0.75));
  vec3 ambient = mix(vec3(0.045, 0.040, 0.038), vec3(0.16, 0.17, 0.20), 0.5 + 0.5 * n.y);
  float wrapped = max((dot(n, key) + 0.3) / 1.3, 0.0);
  vec3 light = ambient + vec3(1.0, 0.93, 0.84) * 1.05 * wrapped * wrapped
    + vec3(0.55, 0.65, 0.85) * 0.35 * max(dot(n, fill), 0.0);
  float fresnel = pow(1.0 - max(dot(n, view), 0.0), 4.0);
  vec3 rim = vec3(0.75, 0.82, 1.0) * (0.35 * max(dot(n, back), 0.0) + 0.25) * fresnel;
  float spec = pow(max(dot(n, normalize(key + view)), 0.0), 24.0) * 0.18;
  vec3 color = albedo * light + rim + vec3(spec);
  color = color / (1.0 + 0.25 * color); // soft shoulder: highlights never clip hard
  fragColor = vec4(pow(color * 1.25, vec3(1.0 / 2.2)), 1.0);
}
`;

/** The studio backdrop of a view, drawn first over its whole viewport: a vertical gradient
 * with a soft light pool behind the model. */
export const BACKDROP_VERTEX = /* glsl */ `
out vec2 vUv;
void main() {
  vUv = position.xy * 0.5 + 0.5;
  gl_Position = vec4(position.xy, 0.999, 1.0);
}
`;

export const BACKDROP_FRAGMENT = /* glsl */ `
precision highp float;
uniform vec3 top;
uniform vec3 bottom;
uniform float aspect;
in vec2 vUv;
layout(location = 0) out highp vec4 fragColor;
void main() {
  vec3 color = mix(bottom, top, smoothstep(0.0, 1.0, vUv.y));
  vec2 p = (vUv - vec2(0.5, 0.58)) * vec2(aspect, 1.0);
  color += vec3(0.012, 0.011, 0.010) * exp(-3.5 * dot(p, p)); // linear, like top and bottom
  fragColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
`;

/** A soft contact shadow: an elliptic dark pool on the floor plane under the model. */
export const SHADOW_VERTEX = /* glsl */ `
out vec2 vPlane;
void main() {
  vPlane = position.xz;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
`;

export const SHADOW_FRAGMENT = /* glsl */ `
precision highp float;
uniform float strength;
in vec2 vPlane;
layout(location = 0) out highp vec4 fragColor;
void main() {
  float r = dot(vPlane, vPlane);
  fragColor = vec4(0.0, 0.0, 0.0, strength * exp(-3.0 * r) * (1.0 - smoothstep(0.7, 1.0, r)));
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
