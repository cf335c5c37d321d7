#version 450 core
// lookup.frag for a rectangle texture (sampler2DRect): the same coordinates scaled to texels, and
// the lookups GLSL has for it (no LOD or bias: one level).
layout(location = 0) out vec4 result;
uniform sampler2DRect u_tex;
uniform int u_function;  // which lookup: see main()
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
  uvec2 quad = pixel >> 1u;
  uint hq = hash(quad.x * 7919u + quad.y * 104729u + u_seed);
  uint hq2 = hash(hq ^ 0x9e3779b9u);
  uint hp = hash(pixel.x * 15731u + pixel.y * 789221u + u_seed * 3u);
  vec2 origin = vec2(float(hq & 0x3fffu), float((hq >> 14) & 0x3fffu)) / 4096.0 - 1.5;
  // Every eighth quad samples near the texture's edge: s or t within a few texels of 0 or 1.
  if ((hq2 & 7u) == 0u) origin.x = float(int(hq2 >> 8) % 64 - 32) / 1024.0 + float((hq2 >> 20) & 1u);
  if ((hq2 & 7u) == 1u) origin.y = float(int(hq2 >> 8) % 64 - 32) / 1024.0 + float((hq2 >> 20) & 1u);
  float step = exp2(-float((hq2 >> 3) % 17u) + 2.0);
  vec2 uv = origin + step * vec2(pixel & 1u);
  float lod = float(hp % 104u) / 8.0 - 2.0;  // -2 .. 10.875 in eighths: .5 ties included
  float bias = float((hp >> 8) % 64u) / 8.0 - 4.0;
  vec2 dx = vec2(float(int(hp % 33u) - 16), float(int((hp >> 6) % 33u) - 16)) * exp2(-float((hp >> 12) % 14u) - 2.0);
  vec2 dy = vec2(float(int((hp >> 16) % 33u) - 16), float(int((hp >> 22) % 33u) - 16)) * exp2(-float((hp >> 28) % 14u) - 2.0);
  int pick = int((hq2 >> 24) % 4u);  // per quad: an offset
  // In texels: the texture's size times lookup.frag's coordinates (exact: dyadic times an integer).
  vec2 size = vec2(textureSize(u_tex));
  vec2 st = uv * size;
  vec2 dxt = dx * size, dyt = dy * size;
  switch (u_function) {
    case 0: result = texture(u_tex, st); break;
    case 1: result = textureProj(u_tex, vec3(st * step, step)); break;
    case 3: result = textureGrad(u_tex, st, dxt, dyt); break;
    case 4:
      if (pick == 0) result = textureOffset(u_tex, st, ivec2(-2, 1));
      else if (pick == 1) result = textureOffset(u_tex, st, ivec2(3, -1));
      else if (pick == 2) result = textureOffset(u_tex, st, ivec2(0, 7));
      else result = textureOffset(u_tex, st, ivec2(-8, -8));
      break;
    case 6: {
      ivec2 texel = ivec2(int(hp % 80u) - 8, int((hp >> 8) % 80u) - 8);
      result = pick < 2 ? texelFetch(u_tex, texel) : texelFetchOffset(u_tex, texel, ivec2(2, -1));
      break;
    }
    case 8: result = textureGradOffset(u_tex, st, dxt, dyt, ivec2(-1, 3)); break;
    case 10:
      if (pick == 0) result = textureGather(u_tex, st);
      else if (pick == 1) result = textureGather(u_tex, st, 1);
      else if (pick == 2) result = textureGather(u_tex, st, 2);
      else result = textureGather(u_tex, st, 3);
      break;
    case 11: result = pick < 2 ? textureGatherOffset(u_tex, st, ivec2(-3, 2), 0) : textureGatherOffset(u_tex, st, ivec2(7, -8), 3); break;
    default: result = vec4(size, 0.0, 0.0); break;
  }
}
