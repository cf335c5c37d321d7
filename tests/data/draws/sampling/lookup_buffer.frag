#version 450 core
// texelFetch on a buffer texture (samplerBuffer), one per pixel, at indices from -8 to u_count + 7
// (inside and past both ends), written as returned; function 9: textureSize.
layout(location = 0) out vec4 result;
uniform samplerBuffer u_tex;
uniform int u_function;
uniform int u_count;  // the buffer texture's texels
uniform uint u_seed;

uint hash(uint x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

void main() {
  uvec2 pixel = uvec2(gl_FragCoord.xy);
  uint hp = hash(pixel.x * 15731u + pixel.y * 789221u + u_seed * 3u);
  int index = int(hp % uint(u_count + 16)) - 8;
  if (u_function == 9) {
    result = vec4(float(textureSize(u_tex)), 0.0, 0.0, 0.0);
    return;
  }
  vec4 texel = texelFetch(u_tex, index);
  result = texel;
}
