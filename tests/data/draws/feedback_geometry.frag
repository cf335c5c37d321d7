#version 450 core
in vec3 g_coord;
flat in int g_corner;
out vec4 color;
void main() { color = vec4(g_coord, 0.25 * float(g_corner & 3) + 0.25); }
