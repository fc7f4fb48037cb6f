// A soft contact shadow: the unit square of the floor plane (x, z in [-1, 1]), placed under the
// model by the model matrix, blended over what is drawn.
precision highp float;
uniform mat4 modelViewMatrix;
uniform mat4 projectionMatrix;
in vec3 position;
out vec2 vPlane;
void main() {
  vPlane = position.xz;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
