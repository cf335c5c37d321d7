#version 450 core
// lookup_shadow.frag for a 2D array (sampler2DArrayShadow): its coordinates and reference
// depths, with lookup_array.frag's layer coordinate (no ties), through the lookups GLSL has for
// array shadow samplers.
layout(location = 0) out vec4 result;
uniform sampler2DArrayShadow u_tex;
uniform int u_function;  // which lookup: see main()
uniform uint u_seed;
uniform int u_size_lod;

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
  uvec2 quad = pixel >> 1u;
  uint hq = hash(quad.x * 7919u + quad.y * 104729u + u_seed);
  uint hq2 = hash(hq ^ 0x9e3779b9u);
  uint hp = hash(pixel.x * 15731u + pixel.y * 789221u + u_seed * 3u);
  vec2 origin = vec2(float(hq & 0x3fffu), float((hq >> 14) & 0x3fffu)) / 4096.0 - 1.5;
  if ((hq2 & 7u) == 0u) origin.x = float(int(hq2 >> 8) % 64 - 32) / 1024.0 + float((hq2 >> 20) & 1u);
  if ((hq2 & 7u) == 1u) origin.y = float(int(hq2 >> 8) % 64 - 32) / 1024.0 + float((hq2 >> 20) & 1u);
  float step = exp2(-float((hq2 >> 3) % 17u) + 2.0);
  vec2 uv = origin + step * vec2(pixel & 1u);
  float ref = float(hash(hp) % 97u) / 64.0 - 0.25;
  float lod = float(hp % 104u) / 8.0 - 2.0;
  float bias = float((hp >> 8) % 64u) / 8.0 - 4.0;
  vec2 dx = vec2(float(int(hp % 33u) - 16), float(int((hp >> 6) % 33u) - 16)) * exp2(-float((hp >> 12) % 14u) - 2.0);
  vec2 dy = vec2(float(int((hp >> 16) % 33u) - 16), float(int((hp >> 22) % 33u) - 16)) * exp2(-float((hp >> 28) % 14u) - 2.0);
  int pick = int((hq2 >> 24) % 4u);
  float r = float(int((hp >> 4) % 56u) - 16) / 8.0;
  if (fract(r) == 0.5) r += 0.125;
  vec4 p = vec4(uv, r, ref);
  switch (u_function) {
    case 0: result = vec4(texture(u_tex, p)); break;
    case 3: result = vec4(textureGrad(u_tex, p, dx, dy)); break;
    case 4: result = vec4(pick < 2 ? textureOffset(u_tex, p, ivec2(-2, 1)) : textureOffset(u_tex, p, ivec2(3, -1))); break;
    case 5: result = vec4(textureGradOffset(u_tex, p, dx, dy, ivec2(1, -2))); break;
    case 6: result = textureGather(u_tex, p.xyz, ref); break;
    case 7: result = textureGatherOffset(u_tex, p.xyz, ref, ivec2(-3, 2)); break;
    case 8: result = textureGatherOffsets(u_tex, p.xyz, ref, ivec2[4](ivec2(0, 0), ivec2(-2, 1), ivec2(5, -3), ivec2(-8, 7))); break;
    default: result = vec4(vec3(textureSize(u_tex, u_size_lod)), 0.0); break;
  }
}
