#version 450 core
// The patch corners as they are.
in vec2 in_position;
out vec2 v_position;
void main() { v_position = in_position; }
