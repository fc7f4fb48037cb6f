// A model's surface, vertex stage (docs/design.md#rendering): one source for the page (three.js
// RawShaderMaterial, web/src/deform.ts: `#version 300 es` and the defines come first) and the
// video (eigendance.export.renderer: `#version 330` and the defines come first).
//
// Defines: CPU_PATH — the deformed position is the `displaced` attribute (the page's CPU path,
// the video), else texel `vid` of the positions pass's float target; HARMONICS — the page's
// harmonics explorer (web/src/shaders.ts TEXELS, which declares `vid`, comes before this
// source); MATERIAL — a material's look: UV sets (UV1: a second one) and VERTEX_COLOR.
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
#else
  vec3 p = texelFetch(deformed, ivec2(v % deformedWidth, v / deformedWidth), 0).xyz;
#endif
#ifdef HARMONICS
  vHarmonic = 0.0;
  if (colorHarmonic >= 0) {
    vec4 u = harmonicTexel(v, colorHarmonic / 4);
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
}
