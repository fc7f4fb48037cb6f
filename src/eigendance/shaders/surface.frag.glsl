// A model's surface, fragment stage (docs/design.md#rendering): one source for the page and the
// video (see surface.vert.glsl). The studio: lights fixed to the camera (a sky/ground ambient, a
// wrapped key, a cool fill, a rim), a soft shoulder and gamma 2.2.
//
// Normals as thesis Fig. 6.4(d): the flat normal of the deformed triangle (screen derivatives of
// the view-space position) weighted `deformedNormalWeight` against the rest vertex normal,
// turned to face the camera. Without MATERIAL: the clay (one colour, a broad specular). With
// MATERIAL: glTF metallic-roughness in the same studio (docs/design.md#appearance): base colour
// factor × texture × vertex colour, metallic-roughness, normal (tangent frame from the deformed
// surface's screen derivatives, as three.js without tangents), occlusion and emissive maps,
// alpha MASK / BLEND, UNLIT (KHR_materials_unlit); each map reads its UV set (<MAP>_UV) through
// its KHR_texture_transform matrix.
precision highp float;
precision highp int;
uniform float deformedNormalWeight;
uniform bool wire;
in vec3 vViewPosition;
in vec3 vNormal;
layout(location = 0) out highp vec4 fragColor;

// The studio's lights, in view space (fixed to the camera).
const vec3 KEY_COLOR = vec3(1.0, 0.93, 0.84) * 1.05;
const vec3 FILL_COLOR = vec3(0.55, 0.65, 0.85) * 0.35;
const vec3 GROUND = vec3(0.045, 0.040, 0.038);
const vec3 SKY = vec3(0.16, 0.17, 0.20);

vec3 keyDirection() { return normalize(vec3(-0.5, 0.75, 0.45)); }
vec3 fillDirection() { return normalize(vec3(0.8, 0.05, 0.55)); }

/** Thesis Fig. 6.4(d): the rest vertex normal and the deformed triangle's flat normal mixed. */
vec3 studioNormal() {
  vec3 flatNormal = normalize(cross(dFdx(vViewPosition), dFdy(vViewPosition)));
  vec3 vertexNormal = normalize(vNormal);
  if (dot(vertexNormal, flatNormal) < 0.0) vertexNormal = -vertexNormal;
  return normalize(mix(vertexNormal, flatNormal, deformedNormalWeight));
}

/** The sky/ground ambient seen along n. */
vec3 studioAmbient(vec3 n) { return mix(GROUND, SKY, 0.5 + 0.5 * n.y); }

/** The key (wrapped: soft) and the fill falling on a surface of normal n. */
vec3 studioDirect(vec3 n) {
  float wrapped = max((dot(n, keyDirection()) + 0.3) / 1.3, 0.0);
  return KEY_COLOR * wrapped * wrapped + FILL_COLOR * max(dot(n, fillDirection()), 0.0);
}

/** A cool rim light on the silhouette. */
vec3 studioRim(vec3 n, vec3 view) {
  vec3 back = normalize(vec3(0.3, 0.6, -0.75));
  // pow(x, 4) by multiplication: the same numbers, cheaper on a software GPU.
  float edge = 1.0 - max(dot(n, view), 0.0), edge2 = edge * edge;
  return vec3(0.75, 0.82, 1.0) * (0.35 * max(dot(n, back), 0.0) + 0.25) * edge2 * edge2;
}

/** Linear light → the frame's 8-bit values: a soft shoulder (highlights never clip hard) and
 * gamma 2.2. */
vec3 studioOutput(vec3 color) {
  color = color / (1.0 + 0.25 * color);
  return pow(color * 1.25, vec3(1.0 / 2.2));
}

#ifndef MATERIAL
// --- clay ------------------------------------------------------------------------------------
uniform vec3 baseColor;
#ifdef HARMONICS
uniform int colorHarmonic;
in float vHarmonic;
vec3 diverging(float x) {
  x = clamp(x, -1.0, 1.0);
  vec3 cold = vec3(0.05, 0.12, 0.55), warm = vec3(0.55, 0.02, 0.03), mid = vec3(0.75);
  return x < 0.0 ? mix(mid, cold, -x) : mix(mid, warm, x);
}
#endif

void main() {
  vec3 albedo = baseColor; // linear
#ifdef HARMONICS
  if (colorHarmonic >= 0) albedo = diverging(vHarmonic);
#endif
  if (wire) { fragColor = vec4(pow(albedo, vec3(1.0 / 2.2)), 1.0); return; }
  vec3 n = studioNormal();
  vec3 view = normalize(vViewPosition);
  vec3 light = studioAmbient(n) + studioDirect(n);
  float h = max(dot(n, normalize(keyDirection() + view)), 0.0), h3 = h * h * h, h6 = h3 * h3;
  float h12 = h6 * h6;
  float spec = h12 * h12 * 0.18; // pow(h, 24)
  vec3 color = albedo * light + studioRim(n, view) + vec3(spec);
  fragColor = vec4(studioOutput(color), 1.0);
}

#else
// --- a glTF material ---------------------------------------------------------------------------
uniform vec4 baseColorFactor;
uniform float metallicFactor;
uniform float roughnessFactor;
uniform vec3 emissiveFactor;
uniform float alphaCutoff;
// The studio's light on a material, brighter than on the clay: a surface facing the camera
// shows about its own colour, as in a glTF viewer (the clay's moodier light would darken it).
const float MATERIAL_EXPOSURE = 1.5;
in vec2 vUv0;
#ifdef UV1
in vec2 vUv1;
#endif
#ifdef VERTEX_COLOR
in vec4 vColor;
#endif
#ifdef BASE_MAP
uniform sampler2D baseMap;
uniform mat3 baseMapTransform;
#endif
#ifdef NORMAL_MAP
uniform sampler2D normalMap;
uniform mat3 normalMapTransform;
uniform vec2 normalScale;
#endif
#ifdef METALLIC_ROUGHNESS_MAP
uniform sampler2D metallicRoughnessMap;
uniform mat3 metallicRoughnessMapTransform;
#endif
#ifdef OCCLUSION_MAP
uniform sampler2D occlusionMap;
uniform mat3 occlusionMapTransform;
uniform float occlusionStrength;
#endif
#ifdef EMISSIVE_MAP
uniform sampler2D emissiveMap;
uniform mat3 emissiveMapTransform;
#endif

/** UVs through a KHR_texture_transform matrix (identity without one). */
vec2 mapUv(mat3 transform, vec2 uv) { return (transform * vec3(uv, 1.0)).xy; }

/** Linear → sRGB, exactly (an unlit material shows its colour as authored). */
vec3 srgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

#ifdef NORMAL_MAP
/** Tangent frame from screen derivatives of the deformed surface (three.js getTangentFrame):
 * it turns with the surface as it dances. */
mat3 tangentFrame(vec3 eye, vec3 n, vec2 uv) {
  vec3 q0 = dFdx(eye), q1 = dFdy(eye);
  vec2 st0 = dFdx(uv), st1 = dFdy(uv);
  vec3 q1perp = cross(q1, n), q0perp = cross(n, q0);
  vec3 t = q1perp * st0.x + q0perp * st1.x;
  vec3 b = q1perp * st0.y + q0perp * st1.y;
  float det = max(dot(t, t), dot(b, b));
  float scale = det == 0.0 ? 0.0 : inversesqrt(det);
  return mat3(t * scale, b * scale, n);
}
#endif

/** Split-sum environment BRDF (Karis's analytic fit, as three.js DFGApprox). */
vec2 environmentBrdf(float roughness, float dotNV) {
  vec4 r = roughness * vec4(-1.0, -0.0275, -0.572, 0.022) + vec4(1.0, 0.0425, 1.04, -0.04);
  float a004 = min(r.x * r.x, exp2(-9.28 * dotNV)) * r.x + r.y;
  return vec2(-1.04, 1.04) * a004 + r.zw;
}

/** The studio seen in direction r by a surface of this roughness: the ambient, and the key and
 * fill as soft boxes, blurred toward the light falling on a surface facing r as it roughens. */
vec3 studioRadiance(vec3 r, float roughness) {
  float key = smoothstep(0.82, 0.97, dot(r, keyDirection()));
  float fill = smoothstep(0.80, 0.97, dot(r, fillDirection()));
  vec3 sharp = studioAmbient(r) + 2.5 * KEY_COLOR * key + 1.5 * FILL_COLOR * fill;
  return mix(sharp, studioAmbient(r) + studioDirect(r), roughness);
}

/** A metallic-roughness surface lit by the studio: diffuse from the ambient and the lights,
 * specular from the studio's radiance with multiple scattering (three.js
 * computeMultiscattering), both occluded by `ao`. */
vec3 studioSurface(vec3 albedo, float metallic, float roughness, float ao, vec3 n, vec3 view) {
  vec3 diffuseColor = albedo * (1.0 - metallic);
  vec3 specularColor = mix(vec3(0.04), albedo, metallic);
  float dotNV = clamp(dot(n, view), 1e-4, 1.0);
  vec2 fab = environmentBrdf(roughness, dotNV);
  vec3 single = specularColor * fab.x + fab.y;
  float ems = 1.0 - (fab.x + fab.y);
  vec3 average = specularColor + (1.0 - specularColor) * 0.047619;
  vec3 multi = single * average / (1.0 - ems * average) * ems;
  vec3 light = studioAmbient(n) * ao + studioDirect(n);
  vec3 radiance = studioRadiance(reflect(-view, n), roughness);
  return diffuseColor * light + (radiance * single + light * multi) * ao;
}

void main() {
  vec4 base = baseColorFactor;
#ifdef VERTEX_COLOR
  base *= vColor;
#endif
#ifdef BASE_MAP
  base *= texture(baseMap, mapUv(baseMapTransform, BASE_MAP_UV));
#endif
#ifdef ALPHA_MASK
  if (base.a < alphaCutoff) discard;
#endif
#ifdef ALPHA_BLEND
  float alpha = base.a;
#else
  float alpha = 1.0;
#endif
#ifdef UNLIT
  fragColor = vec4(srgb(base.rgb), alpha);
#else
  vec3 n = studioNormal();
  vec3 view = normalize(vViewPosition);
#ifdef NORMAL_MAP
  vec2 uv = mapUv(normalMapTransform, NORMAL_MAP_UV);
  vec3 mapped = texture(normalMap, uv).xyz * 2.0 - 1.0;
  mapped.xy *= normalScale;
  mat3 frame = tangentFrame(-vViewPosition, n, uv);
  float side = gl_FrontFacing ? 1.0 : -1.0;
  frame[0] *= side;
  frame[1] *= side;
  n = normalize(frame * mapped);
#endif
  float metallic = metallicFactor, roughness = roughnessFactor;
#ifdef METALLIC_ROUGHNESS_MAP
  vec4 texel = texture(metallicRoughnessMap, mapUv(metallicRoughnessMapTransform,
                                                   METALLIC_ROUGHNESS_MAP_UV));
  roughness *= texel.g;
  metallic *= texel.b;
#endif
  metallic = clamp(metallic, 0.0, 1.0);
  roughness = clamp(roughness, 0.0525, 1.0);
  float ao = 1.0;
#ifdef OCCLUSION_MAP
  ao += occlusionStrength * (texture(occlusionMap, mapUv(occlusionMapTransform,
                                                         OCCLUSION_MAP_UV)).r - 1.0);
#endif
  vec3 emissive = emissiveFactor;
#ifdef EMISSIVE_MAP
  emissive *= texture(emissiveMap, mapUv(emissiveMapTransform, EMISSIVE_MAP_UV)).rgb;
#endif
  vec3 color = MATERIAL_EXPOSURE * studioSurface(base.rgb, metallic, roughness, ao, n, view)
    + studioRim(n, view) * (1.0 - 0.5 * metallic) + emissive;
  fragColor = vec4(studioOutput(color), alpha);
#endif
}
#endif
