#version 450 core
// The sampling sweep's full-screen pass: four corners in clip space, drawn as a strip.
layout(location = 0) in vec2 in_corner;

void main() {
  gl_Position = vec4(in_corner, 0.0, 1.0);
}
