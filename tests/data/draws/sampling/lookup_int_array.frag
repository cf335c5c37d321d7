#version 450 core
// lookup_array.frag for the signed integer formats (isampler2DArray): the same lookups, each
// result's integers written as their bits (intBitsToFloat), as lookup_int.frag writes them.
layout(location = 0) out vec4 result;
uniform isampler2DArray u_tex;
uniform int u_layer_ties;
uniform int u_function;  // which lookup: see main()
uniform uint u_seed;
uniform int u_size_lod;  // textureSize's LOD (uniform: llvmpipe reads one lane's, see the test)

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
  float r = float(int((hp >> 4) % 56u) - 16) / 8.0;
  if (u_layer_ties == 0 && fract(r) == 0.5) r += 0.125;
  vec3 uvr = vec3(uv, r);
  ivec4 r4;
  switch (u_function) {
    case 0: r4 = texture(u_tex, uvr); break;
    case 1: r4 = texture(u_tex, uvr, bias); break;
    case 2: r4 = textureLod(u_tex, uvr, lod); break;
    case 3: r4 = textureGrad(u_tex, uvr, dx, dy); break;
    case 4:
      if (pick == 0) r4 = textureOffset(u_tex, uvr, ivec2(-2, 1));
      else if (pick == 1) r4 = textureOffset(u_tex, uvr, ivec2(3, -1));
      else if (pick == 2) r4 = textureOffset(u_tex, uvr, ivec2(0, 7));
      else r4 = textureOffset(u_tex, uvr, ivec2(-8, -8));
      break;
    case 5:
      if (pick < 2) r4 = textureLodOffset(u_tex, uvr, lod, ivec2(1, -2));
      else r4 = textureLodOffset(u_tex, uvr, lod, ivec2(-3, 5));
      break;
    case 6: {
      ivec3 texel = ivec3(int(hp % 80u) - 8, int((hp >> 8) % 80u) - 8, int((hp >> 24) % 6u) - 1);
      int level = int((hp >> 16) % 10u) - 1;
      r4 = pick < 2 ? texelFetch(u_tex, texel, level) : texelFetchOffset(u_tex, texel, level, ivec2(2, -1));
      break;
    }
    case 7: r4 = floatBitsToInt(vec4(textureQueryLod(u_tex, uv), 0.0, 0.0)); break;
    case 8: r4 = textureGradOffset(u_tex, uvr, dx, dy, ivec2(-1, 3)); break;
    case 10:  // textureGather's component is a constant expression
      if (pick == 0) r4 = textureGather(u_tex, uvr);
      else if (pick == 1) r4 = textureGather(u_tex, uvr, 1);
      else if (pick == 2) r4 = textureGather(u_tex, uvr, 2);
      else r4 = textureGather(u_tex, uvr, 3);
      break;
    case 11:
      if (pick < 2) r4 = textureGatherOffset(u_tex, uvr, ivec2(-3, 2), 0);
      else r4 = textureGatherOffset(u_tex, uvr, ivec2(7, -8), 3);
      break;
    case 12: r4 = textureGatherOffsets(u_tex, uvr, ivec2[4](ivec2(0, 0), ivec2(-2, 1), ivec2(5, -3), ivec2(-8, 7)), 1); break;
    default: r4 = ivec4(textureSize(u_tex, u_size_lod), textureQueryLevels(u_tex)); break;
  }
  result = intBitsToFloat(r4);
}
