#version 450 core
// lookup_cube.frag with CUBE_ARRAY defined (the scene format has no defines): keep the two alike.
#define CUBE_ARRAY
// lookup.frag for a cube map (samplerCube; with CUBE_ARRAY defined, as in lookup_cube_array.frag,
// a samplerCubeArray): a direction per quad with components in [-2, 2) in steps of 1/256, one in
// eight quads near an edge between two faces, near a corner of three, or exactly on an edge
// (|x| = |y|); between the quad's pixels a step of 2^-1 .. 2^-14 along one axis for x and one for y, so implicit LODs run
// from below 0 to past the last level and a quad can straddle faces.
layout(location = 0) out vec4 result;
#ifdef CUBE_ARRAY
uniform samplerCubeArray u_tex;
#else
uniform samplerCube u_tex;
#endif
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
    case 0u: dir.y = sx * abs(dir.x) + e; break;  // near the edge of an x and a y face
    case 1u: dir.z = sx * abs(dir.y) + e; break;
    case 2u: dir.x = sx * abs(dir.z) + e; break;
    case 3u: dir.y = sx * abs(dir.x) + e; dir.z = sy * abs(dir.x) + e2; break;  // near a corner
    case 4u: dir.y = sx * abs(dir.x); break;  // on the edge: a tie between x and y
  }
  float step = exp2(-float((hq2 >> 3) % 14u) - 1.0);
  uint ax = (hq2 >> 20) % 3u, ay = (hq2 >> 22) % 3u;
  dir[ax] += step * float(pixel.x & 1u);
  dir[ay] += step * float(pixel.y & 1u);
  float lod = float(hp % 72u) / 8.0 - 2.0;  // -2 .. 6.875 in eighths: .5 ties included
  float bias = float((hp >> 8) % 64u) / 8.0 - 4.0;
  vec3 dx = vec3(float(int(hp % 33u) - 16), float(int((hp >> 6) % 33u) - 16), float(int((hq3 >> 16) % 33u) - 16)) *
            exp2(-float((hp >> 12) % 10u) - 2.0);
  vec3 dy = vec3(float(int((hp >> 16) % 33u) - 16), float(int((hp >> 22) % 33u) - 16), float(int((hq3 >> 22) % 33u) - 16)) *
            exp2(-float((hp >> 28) % 10u) - 2.0);
  int pick = int((hq2 >> 24) % 4u);
#ifdef CUBE_ARRAY
  // The cube: -1 .. 2.75 in quarters, no ties at .5 (GL rounds them up, llvmpipe to even).
  float cube = float(hq3 % 4u) - 1.0 + 0.25 * float((hq3 >> 4) & 3u) * float(((hq3 >> 4) & 3u) != 2u);
  vec4 at = vec4(dir, cube);
#else
  vec3 at = dir;
#endif
  switch (u_function) {
    case 0: result = texture(u_tex, at); break;
    case 1: result = texture(u_tex, at, bias); break;
    case 2: result = textureLod(u_tex, at, lod); break;
    case 3: result = textureGrad(u_tex, at, dx, dy); break;
    case 4:  // textureGather's component is a constant expression
      if (pick == 0) result = textureGather(u_tex, at);
      else if (pick == 1) result = textureGather(u_tex, at, 1);
      else if (pick == 2) result = textureGather(u_tex, at, 2);
      else result = textureGather(u_tex, at, 3);
      break;
    case 6: result = vec4(textureQueryLod(u_tex, dir), 0.0, 0.0); break;
    // llvmpipe's LOD query drops a cube map's z (docs/textures.md): with z = 0 the two agree.
    case 7: result = vec4(textureQueryLod(u_tex, vec3(dir.xy, 0.0)), 0.0, 0.0); break;
#ifdef CUBE_ARRAY
    default: result = vec4(vec3(textureSize(u_tex, u_size_lod)), float(textureQueryLevels(u_tex))); break;
#else
    default: result = vec4(vec2(textureSize(u_tex, u_size_lod)), float(textureQueryLevels(u_tex)), 0.0); break;
#endif
  }
}
