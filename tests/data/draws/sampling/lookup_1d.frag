#version 450 core
// lookup.frag for a 1D texture (sampler1D): one lookup per pixel at dyadic coordinates, s per
// quad from -1.5 to 2.5 (and near 0 and 1), LODs from -2 past the last level.
layout(location = 0) out vec4 result;
uniform sampler1D u_tex;
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
  uint hp = hash(pixel.x * 15731u + pixel.y * 789221u + u_seed * 3u);
  float origin = float(hq & 0x3fffu) / 4096.0 - 1.5;
  // Every fourth quad samples near the texture's edge: s within a few texels of 0 or 1.
  if ((hq2 & 3u) == 0u) origin = float(int(hq2 >> 8) % 64 - 32) / 1024.0 + float((hq2 >> 20) & 1u);
  float step = exp2(-float((hq2 >> 3) % 17u) + 2.0);
  // s changes along x by `step` and along y by a quarter of it: both derivatives count.
  float s = origin + step * (float(pixel.x & 1u) + 0.25 * float(pixel.y & 1u));
  float lod = float(hp % 104u) / 8.0 - 2.0;  // -2 .. 10.875 in eighths: .5 ties included
  float bias = float((hp >> 8) % 64u) / 8.0 - 4.0;
  float dx = float(int(hp % 33u) - 16) * exp2(-float((hp >> 12) % 14u) - 2.0);
  float dy = float(int((hp >> 16) % 33u) - 16) * exp2(-float((hp >> 28) % 14u) - 2.0);
  int pick = int((hq2 >> 24) % 4u);  // per quad: an offset
  switch (u_function) {
    case 0: result = texture(u_tex, s); break;
    case 1: result = texture(u_tex, s, bias); break;
    case 2: result = textureLod(u_tex, s, lod); break;
    case 3: result = textureGrad(u_tex, s, dx, dy); break;
    case 4: result = pick < 2 ? textureOffset(u_tex, s, -8) : textureOffset(u_tex, s, 7); break;
    case 5: result = pick < 2 ? textureLodOffset(u_tex, s, lod, 3) : textureLodOffset(u_tex, s, lod, -5); break;
    case 6: {
      int texel = int(hp % 272u) - 8;
      int level = int((hp >> 16) % 11u) - 1;
      result = pick < 2 ? texelFetch(u_tex, texel, level) : texelFetchOffset(u_tex, texel, level, 2);
      break;
    }
    case 7: result = vec4(textureQueryLod(u_tex, s), 0.0, 0.0); break;
    case 8: result = textureProj(u_tex, vec2(s * step, step)); break;
    case 10: result = textureGradOffset(u_tex, s, dx, dy, -3); break;
    default: result = vec4(float(textureSize(u_tex, u_size_lod)), float(textureQueryLevels(u_tex)), 0.0, 0.0); break;
  }
}
