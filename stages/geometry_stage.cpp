#include "stages/geometry_stage.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace tessref {
namespace {

// Primitives per task: enough work to pay for a task, few enough to spread a chunk over threads.
constexpr std::size_t kTaskPrimitives = 256;

const char* primitive_name(int vertices) {
  switch (vertices) {
    case 1: return "points";
    case 2: return "lines";
    case 3: return "triangles";
    case 4: return "lines_adjacency";
    default: return "triangles_adjacency";
  }
}

}  // namespace

void check_geometry_input(const GeometryProgram& gs, int vertices) {
  if (gs.input_vertices() != vertices)
    throw std::invalid_argument(std::string("draw: the geometry shader takes ") + primitive_name(gs.input_vertices()) +
                                "; the draw hands it " + primitive_name(vertices) +
                                " (GL: GL_INVALID_OPERATION at the draw)");
}

void append_strip(int corners, std::uint32_t first, std::uint32_t count, std::vector<std::uint32_t>& indices) {
  if (corners == 1) {
    for (std::uint32_t i = 0; i < count; ++i) indices.push_back(first + i);
  } else if (corners == 2) {
    for (std::uint32_t i = 0; i + 1 < count; ++i) indices.insert(indices.end(), {first + i, first + i + 1});
  } else {
    for (std::uint32_t i = 0; i + 2 < count; ++i) {
      const bool odd = i % 2;
      indices.insert(indices.end(), {first + (odd ? i + 1 : i), first + (odd ? i : i + 1), first + i + 2});
    }
  }
}

template <int Corners>
void run_geometry(const GeometryProgram& gs, const PrimitiveBatch<Corners>& in, std::uint32_t first_id,
                  const Parallel& parallel, GeometryOutput& out) {
  check_geometry_input(gs, Corners);
  const std::size_t primitives = in.primitive_count();
  const std::size_t tasks = (primitives + kTaskPrimitives - 1) / kTaskPrimitives;
  // The output's form: every batch of it, and of each task's part, indexed and with the
  // shader's varyings.
  const auto prepare = [&](GeometryOutput& o) {
    o.triangles.indexed = o.lines.indexed = o.points.indexed = true;
    o.triangles.num_varyings = o.lines.num_varyings = o.points.num_varyings = gs.num_varyings();
    o.triangles.flat_varyings = o.lines.flat_varyings = o.points.flat_varyings = gs.flat_varyings();
    o.keep_streams = out.keep_streams;
    for (PointBatch& s : o.streams) s.indexed = true, s.num_varyings = gs.num_varyings();
  };
  prepare(out);
  // Each task writes its own slot; the slots are joined in order below.
  std::vector<GeometryOutput> parts(tasks);
  parallel.for_each(tasks, [&](std::size_t t) {
    const std::size_t first = t * kTaskPrimitives, n = std::min(kTaskPrimitives, primitives - first);
    std::vector<const float*> corners(n * Corners);
    for (std::size_t p = 0; p < n; ++p)
      for (int k = 0; k < Corners; ++k) corners[p * Corners + std::size_t(k)] = in.vertex_data(in.vertex_index(first + p, k));
    prepare(parts[t]);
    gs.run(corners.data(), in.num_varyings, n, first_id + std::uint32_t(first), parts[t]);
  });
  for (const GeometryOutput& part : parts) {
    append_primitives(out.triangles, part.triangles);
    append_primitives(out.lines, part.lines);
    append_primitives(out.points, part.points);
    for (std::size_t s = 0; s < out.streams.size(); ++s) append_primitives(out.streams[s], part.streams[s]);
  }
}

template void run_geometry<1>(const GeometryProgram&, const PointBatch&, std::uint32_t, const Parallel&, GeometryOutput&);
template void run_geometry<2>(const GeometryProgram&, const LineBatch&, std::uint32_t, const Parallel&, GeometryOutput&);
template void run_geometry<4>(const GeometryProgram&, const PrimitiveBatch<4>&, std::uint32_t, const Parallel&, GeometryOutput&);
template void run_geometry<6>(const GeometryProgram&, const PrimitiveBatch<6>&, std::uint32_t, const Parallel&, GeometryOutput&);
template void run_geometry<3>(const GeometryProgram&, const TriangleBatch&, std::uint32_t, const Parallel&, GeometryOutput&);

}  // namespace tessref
