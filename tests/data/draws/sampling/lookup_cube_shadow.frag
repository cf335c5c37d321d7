#version 450 core
// lookup_cube.frag's directions for a samplerCubeShadow: a reference depth per pixel from
// -1/32 to 1 + 1/32 in 64ths.
layout(location = 0) out vec4 result;
uniform samplerCubeShadow u_tex;
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
  uint hq3 = hash(hq2 ^ 0x85ebca6bu);
  uint hp = hash(pixel.x * 15731u + pixel.y * 789221u + u_seed * 3u);
  vec3 dir = vec3(float(hq & 0x3ffu), float((hq >> 10) & 0x3ffu), float((hq >> 20) & 0x3ffu)) / 256.0 - 2.0;
  float e = float(int((hq2 >> 8) % 33u) - 16) / 512.0, e2 = float(int((hq3 >> 8) % 33u) - 16) / 512.0;
  float sx = ((hq2 >> 14) & 1u) != 0u ? -1.0 : 1.0, sy = ((hq2 >> 15) & 1u) != 0u ? -1.0 : 1.0;
  switch (hq2 & 7u) {
    case 0u: dir.y = sx * abs(dir.x) + e; break;
    case 1u: dir.z = sx * abs(dir.y) + e; break;
    case 2u: dir.x = sx * abs(dir.z) + e; break;
    case 3u: dir.y = sx * abs(dir.x) + e; dir.z = sy * abs(dir.x) + e2; break;
    case 4u: dir.y = sx * abs(dir.x); break;
  }
  float step = exp2(-float((hq2 >> 3) % 14u) - 1.0);
  uint ax = (hq2 >> 20) % 3u, ay = (hq2 >> 22) % 3u;
  dir[ax] += step * float(pixel.x & 1u);
  dir[ay] += step * float(pixel.y & 1u);
  float ref = float(hp % 68u) / 64.0 - 0.03125;
  float bias = float((hp >> 8) % 64u) / 8.0 - 4.0;
  vec3 dx = vec3(float(int(hp % 33u) - 16), float(int((hp >> 6) % 33u) - 16), float(int((hq3 >> 16) % 33u) - 16)) *
            exp2(-float((hp >> 12) % 10u) - 2.0);
  vec3 dy = vec3(float(int((hp >> 16) % 33u) - 16), float(int((hp >> 22) % 33u) - 16), float(int((hq3 >> 22) % 33u) - 16)) *
            exp2(-float((hp >> 28) % 10u) - 2.0);
  switch (u_function) {
    case 0: result = vec4(texture(u_tex, vec4(dir, ref))); break;
    case 1: result = vec4(texture(u_tex, vec4(dir, ref), bias)); break;
    case 3: result = vec4(textureGrad(u_tex, vec4(dir, ref), dx, dy)); break;
    case 4: result = textureGather(u_tex, dir, ref); break;
    default: result = vec4(vec2(textureSize(u_tex, u_size_lod)), 0.0, 0.0); break;
  }
}
