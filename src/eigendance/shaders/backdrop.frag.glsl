// A vertical gradient with a soft light pool behind the model (colours linear).
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
