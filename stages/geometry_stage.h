#pragma once
// The geometry stage (GL 4.5, section 11.3): after the vertex or tessellation stages, one shader
// invocation per input primitive (per instance of an instanced geometry shader) emits vertices into
// strips, which are cut into the point, line or triangle lists the rasterizer draws.
#include <array>
#include <cstddef>
#include <cstdint>

#include "common/parallel.h"
#include "raster/vertex.h"

namespace tessref {

// What a geometry shader emitted for a range of primitives: strips already cut into lists, in
// input-primitive order, then gl_InvocationID order, then emission order. Only the batch of the
// shader's output primitive is used.
struct GeometryOutput {
  TriangleBatch triangles;
  LineBatch lines;
  PointBatch points;
  // With keep_streams: the points emitted on vertex streams 1..3 (GL allows streams past 0 with
  // points output only), which transform feedback records and the rasterizer never sees.
  bool keep_streams = false;
  std::array<PointBatch, 3> streams;
};

class GeometryProgram {
 public:
  virtual ~GeometryProgram() = default;
  // The input primitive's vertices (1 points, 2 lines, 3 triangles; 4 and 6: with adjacency).
  virtual int input_vertices() const = 0;
  virtual int num_varyings() const = 0;  // of the output vertices
  virtual VaryingMask flat_varyings() const { return {}; }
  // Runs the shader for `count` primitives: primitive p's vertex k is the vertex data (gl_Position,
  // then in_varyings varyings, PrimitiveBatch::vertex_data) at corners[p * input_vertices() + k],
  // its gl_PrimitiveIDIn first_id + p. Appends to out (whose batches carry num_varyings()). Must be
  // const and thread-safe.
  virtual void run(const float* const* corners, int in_varyings, std::size_t count, std::uint32_t first_id,
                   GeometryOutput& out) const = 0;
};

// Runs gs over every primitive of `in`, in tasks on `parallel`, their outputs appended to out in
// primitive order (the bytes do not depend on the thread count). gl_PrimitiveIDIn counts from
// first_id. Throws std::invalid_argument when the batch's primitive is not the shader's input.
template <int Corners>
void run_geometry(const GeometryProgram& gs, const PrimitiveBatch<Corners>& in, std::uint32_t first_id,
                  const Parallel& parallel, GeometryOutput& out);

// Throws std::invalid_argument, as GL refuses the draw, when the draw's primitives (of `vertices`
// vertices) are not the shader's input primitive.
void check_geometry_input(const GeometryProgram& gs, int vertices);

// Cuts a strip of `count` vertices starting at vertex `first` into a list, as GL 4.5 section 10.1
// assembles strips: triangle i is (i, i+1, i+2) with i and i+1 swapped for odd i (the winding
// kept, the last vertex provoking); line i is (i, i+1). corners 1: the points themselves.
void append_strip(int corners, std::uint32_t first, std::uint32_t count, std::vector<std::uint32_t>& indices);

}  // namespace tessref
