// A model's surface, vertex stage (docs/design.md#rendering): one source for the page (three.js
// RawShaderMaterial, web/src/deform.ts: `#version 300 es` and the defines come first) and the
// video (eigendance.export.renderer: `#version 330` and the defines come first).
//
// Defines: CPU_PATH — the deformed position is the `displaced` attribute (the page's CPU path,
// the video), else texel `vid` of the positions pass's float target; HARMONICS — the page's
// harmonics explorer (web/src/shaders.ts TEXELS, which declares `vid`, comes before this
// source); MATERIAL — a material's look: UV sets (UV1: a second one) and VERTEX_COLOR;
// REDUCED — a reduced basis (docs/design.md#reduced-basis, the page only): `deformed` holds the
// displacements D_j of the m samples, one per texel, and the vertex gathers its ≤ 8 as linear
// blend skinning with translation-only joints, x = rest + Σ_j w_j D_j, from two vec4 attributes
// of sample indices and two of weights (the integers w·2048, exact: web/src/reduced.ts
// WEIGHT_UNITS); READ_BACK (with REDUCED) — drawn as points, vertex v writes its position to
// pixel v of a float target (web/src/reduced.ts GatherPass).
// A drawn vertex's `vid` is its welded vertex (docs/design.md#appearance): it reads that
// vertex's deformed position.
precision highp float;
precision highp int;
uniform mat4 modelViewMatrix;
uniform mat4 projectionMatrix;
uniform mat3 normalMatrix;
in vec3 normal;
#ifndef HARMONICS
in float vid;
#endif
#ifdef CPU_PATH
in vec3 displaced;
#else
uniform highp sampler2D deformed;
uniform int deformedWidth;
#endif
out vec3 vViewPosition;
out vec3 vNormal;
#ifdef HARMONICS
uniform int colorHarmonic;
uniform float colorScale;
out float vHarmonic;
#endif
#ifdef REDUCED
in vec4 sampleIndices0;
in vec4 sampleIndices1;
in vec4 sampleWeights0;
in vec4 sampleWeights1;
const float WEIGHT_UNIT = 1.0 / 2048.0;
#ifndef CPU_PATH
in vec3 position;
vec3 sampleDisplacement(float j) {
  int i = int(j + 0.5);
  return texelFetch(deformed, ivec2(i % deformedWidth, i / deformedWidth), 0).xyz;
}
vec3 gatherDisplacement() {
  vec3 d = sampleWeights0.x * sampleDisplacement(sampleIndices0.x)
    + sampleWeights0.y * sampleDisplacement(sampleIndices0.y)
    + sampleWeights0.z * sampleDisplacement(sampleIndices0.z)
    + sampleWeights0.w * sampleDisplacement(sampleIndices0.w)
    + sampleWeights1.x * sampleDisplacement(sampleIndices1.x)
    + sampleWeights1.y * sampleDisplacement(sampleIndices1.y)
    + sampleWeights1.z * sampleDisplacement(sampleIndices1.z)
    + sampleWeights1.w * sampleDisplacement(sampleIndices1.w);
  return d * WEIGHT_UNIT;
}
#endif
#ifdef HARMONICS
// The harmonics explorer's value of U = P U_r: the vertex's samples' texels, weighed.
vec4 gatherHarmonicTexel(int j) {
  vec4 u = vec4(0.0);
  for (int s = 0; s < 4; s++) {
    u += sampleWeights0[s] * harmonicTexel(int(sampleIndices0[s] + 0.5), j);
    u += sampleWeights1[s] * harmonicTexel(int(sampleIndices1[s] + 0.5), j);
  }
  return u * WEIGHT_UNIT;
}
#endif
#endif
#ifdef READ_BACK
uniform int targetWidth;
uniform vec2 targetSize;
#endif
#ifdef MATERIAL
in vec2 texcoord0;
out vec2 vUv0;
#ifdef UV1
in vec2 texcoord1;
out vec2 vUv1;
#endif
#ifdef VERTEX_COLOR
in vec4 vertexColor;
out vec4 vColor;
#endif
#endif

void main() {
  int v = int(vid + 0.5);
#ifdef CPU_PATH
  vec3 p = displaced;
#elif defined(REDUCED)
  vec3 p = position + gatherDisplacement();
#else
  vec3 p = texelFetch(deformed, ivec2(v % deformedWidth, v / deformedWidth), 0).xyz;
#endif
#ifdef HARMONICS
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
#endif
#ifdef MATERIAL
  vUv0 = texcoord0;
#ifdef UV1
  vUv1 = texcoord1;
#endif
#ifdef VERTEX_COLOR
  vColor = vertexColor;
#endif
#endif
  vec4 mv = modelViewMatrix * vec4(p, 1.0);
  vViewPosition = -mv.xyz;
  vNormal = normalize(normalMatrix * normal);
  gl_Position = projectionMatrix * mv;
#ifdef READ_BACK
  vViewPosition = p;
  vec2 pixel = vec2(float(v % targetWidth), float(v / targetWidth)) + 0.5;
  gl_Position = vec4(pixel / targetSize * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
#endif
}
