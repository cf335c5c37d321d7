#version 450 core
// lookup_1d.frag's lookups on a 1D depth texture through a sampler1DShadow: the reference depth
// per pixel from -0.125 to 1.125 in 64ths (depth texels are k / 64: ties included).
layout(location = 0) out vec4 result;
uniform sampler1DShadow u_tex;
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
  float ref = float(int((hp >> 5) % 81u) - 8) / 64.0;
  vec3 p = vec3(s, 0.0, ref);
  switch (u_function) {
    case 0: result = vec4(texture(u_tex, p)); break;
    case 1: result = vec4(texture(u_tex, p, bias)); break;
    case 2: result = vec4(textureLod(u_tex, p, lod)); break;
    case 3: result = vec4(textureGrad(u_tex, p, dx, dy)); break;
    case 4: result = vec4(pick < 2 ? textureOffset(u_tex, p, -8) : textureOffset(u_tex, p, 7)); break;
    case 5: result = vec4(textureLodOffset(u_tex, p, lod, 3)); break;
    case 6: result = vec4(textureProj(u_tex, vec4(s * step, 0.0, ref * step, step))); break;
    default: result = vec4(float(textureSize(u_tex, u_size_lod)), float(textureQueryLevels(u_tex)), 0.0, 0.0); break;
  }
}
