#version 450 core
// lookup.frag for a 3D texture (sampler3D): the same coordinates for s and t, r per quad from
// -1.5 to 2.5 (and near 0 and 1), stepping along x, y or both, LODs from -2 past the last level.
layout(location = 0) out vec4 result;
uniform sampler3D u_tex;
uniform int u_function;  // which lookup: see main()
uniform uint u_seed;
uniform int u_size_lod;  // textureSize's LOD (uniform: llvmpipe reads one lane's)

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
  vec3 origin = vec3(float(hq & 0x3fffu), float((hq >> 14) & 0x3fffu), float(hq3 & 0x3fffu)) / 4096.0 - 1.5;
  // Every eighth quad samples near an edge: s, t or r within a few texels of 0 or 1.
  if ((hq2 & 7u) == 0u) origin.x = float(int(hq2 >> 8) % 64 - 32) / 1024.0 + float((hq2 >> 20) & 1u);
  if ((hq2 & 7u) == 1u) origin.y = float(int(hq2 >> 8) % 64 - 32) / 1024.0 + float((hq2 >> 20) & 1u);
  if ((hq2 & 7u) == 2u) origin.z = float(int(hq2 >> 8) % 16 - 8) / 64.0 + float((hq2 >> 20) & 1u);
  float step = exp2(-float((hq2 >> 3) % 17u) + 2.0);
  // r steps along x, along y, or neither, by quad.
  uint rstep = (hq3 >> 14) % 3u;
  vec3 uvw = origin + step * vec3(vec2(pixel & 1u), rstep == 0u ? float(pixel.x & 1u) : rstep == 1u ? float(pixel.y & 1u) : 0.0);
  float lod = float(hp % 104u) / 8.0 - 2.0;  // -2 .. 10.875 in eighths: .5 ties included
  float bias = float((hp >> 8) % 64u) / 8.0 - 4.0;
  vec3 dx = vec3(float(int(hp % 33u) - 16), float(int((hp >> 6) % 33u) - 16), float(int((hq3 >> 16) % 33u) - 16)) *
            exp2(-float((hp >> 12) % 14u) - 2.0);
  vec3 dy = vec3(float(int((hp >> 16) % 33u) - 16), float(int((hp >> 22) % 33u) - 16), float(int((hq3 >> 22) % 33u) - 16)) *
            exp2(-float((hp >> 28) % 14u) - 2.0);
  int pick = int((hq2 >> 24) % 4u);  // per quad: an offset
  switch (u_function) {
    case 0: result = texture(u_tex, uvw); break;
    case 1: result = texture(u_tex, uvw, bias); break;
    case 2: result = textureLod(u_tex, uvw, lod); break;
    case 3: result = textureGrad(u_tex, uvw, dx, dy); break;
    case 4:
      if (pick == 0) result = textureOffset(u_tex, uvw, ivec3(-2, 1, 1));
      else if (pick == 1) result = textureOffset(u_tex, uvw, ivec3(3, -1, -2));
      else if (pick == 2) result = textureOffset(u_tex, uvw, ivec3(0, 7, 0));
      else result = textureOffset(u_tex, uvw, ivec3(-8, -8, 7));
      break;
    case 5: result = pick < 2 ? textureLodOffset(u_tex, uvw, lod, ivec3(1, -2, 3)) : textureLodOffset(u_tex, uvw, lod, ivec3(-3, 5, -1)); break;
    case 6: {
      ivec3 texel = ivec3(int(hp % 80u) - 8, int((hp >> 8) % 80u) - 8, int((hp >> 24) % 8u) - 2);
      int level = int((hp >> 16) % 9u) - 1;
      result = pick < 2 ? texelFetch(u_tex, texel, level) : texelFetchOffset(u_tex, texel, level, ivec3(2, -1, 1));
      break;
    }
    case 7: result = vec4(textureQueryLod(u_tex, uvw), 0.0, 0.0); break;
    case 8: result = textureProj(u_tex, vec4(uvw * step, step)); break;
    case 10: result = textureGradOffset(u_tex, uvw, dx, dy, ivec3(-1, 3, 2)); break;
    default: result = vec4(vec3(textureSize(u_tex, u_size_lod)), float(textureQueryLevels(u_tex))); break;
  }
}
