#pragma once
// Procedural meshes with welded positions and exact smooth normals, counter-clockwise outside.
#include "mesh/mesh.h"

namespace tessref {

// Icosahedron refined n times (each triangle split in four, new points pushed onto the sphere):
// 10 * 4^n + 2 vertices, 20 * 4^n triangles. Normals are the unit radial directions.
Mesh make_icosphere(int refinements, float radius = 1.0f);

// Torus around the y axis: major_segments around the axis, minor_segments around the tube;
// major_segments * minor_segments vertices, twice as many triangles. Normals are analytic.
Mesh make_torus(float major_radius, float minor_radius, int major_segments, int minor_segments);

// Axis-aligned cube centred at the origin with edge length `size`: 8 welded corners,
// 12 triangles, each corner's normal the average of its three faces' normals.
Mesh make_cube(float size = 1.0f);

}  // namespace tessref
