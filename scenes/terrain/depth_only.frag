#version 450 core
// The shadow map's pass writes depth alone.
void main() {}
