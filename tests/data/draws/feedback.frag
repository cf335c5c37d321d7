#version 450 core
in vec3 f_coord;
flat in int f_patch;
out vec4 color;
void main() { color = vec4(f_coord, 0.25 * float(f_patch & 3) + 0.25); }
