// An elliptic dark pool, transparent at its edge.
precision highp float;
uniform float strength;
in vec2 vPlane;
layout(location = 0) out highp vec4 fragColor;
void main() {
  float r = dot(vPlane, vPlane);
  fragColor = vec4(0.0, 0.0, 0.0, strength * exp(-3.0 * r) * (1.0 - smoothstep(0.7, 1.0, r)));
}
