#version 450 core
in vec3 g_coord;
out vec4 color;
void main() { color = vec4(g_coord, 1.0); }
