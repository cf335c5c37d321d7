#version 450 core
// Pass-through: the patches carry no attributes, only their index.
void main() { gl_Position = vec4(0.0); }
