// The studio backdrop of a view, drawn first over its whole viewport (docs/design.md#rendering).
precision highp float;
in vec3 position;
out vec2 vUv;
void main() {
  vUv = position.xy * 0.5 + 0.5;
  gl_Position = vec4(position.xy, 0.999, 1.0);
}
