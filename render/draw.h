#pragma once
// What a draw reports and the options every draw takes (render/draw_call.h runs it), and the
// convenient form: a mesh drawn with the built-in programs.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "common/parallel.h"
#include "mesh/mesh.h"
#include "scene/tessellation_settings.h"
#include "raster/rasterizer.h"
#include "stages/tess_stage.h"
#include "stages/programs/transform.h"

namespace tessref {

class Checker;  // check/check.h

struct DrawStats {
  std::uint64_t vertices_shaded = 0;
  std::uint64_t triangles_in = 0;         // mesh triangles (patches, with tessellation)
  std::uint64_t triangles_generated = 0;  // handed to the rasterizer (after tessellation)
  RasterStats raster;                     // triangles_rasterized, fragments_shaded, ...
  TessStats tess;                         // patches, discarded patches, domain points
  double vertex_seconds = 0.0;            // vertex shader and primitive assembly
  double tessellation_seconds = 0.0;
  double raster_seconds = 0.0;            // rasterization and fragment shading
  std::vector<std::string> warnings;      // what a driver would draw but a user should know
  DrawStats& operator+=(const DrawStats& o) {
    vertices_shaded += o.vertices_shaded;
    triangles_in += o.triangles_in;
    triangles_generated += o.triangles_generated;
    raster += o.raster;
    tess += o.tess;
    vertex_seconds += o.vertex_seconds;
    tessellation_seconds += o.tessellation_seconds;
    raster_seconds += o.raster_seconds;
    warnings.insert(warnings.end(), o.warnings.begin(), o.warnings.end());
    return *this;
  }
};

struct DrawOptions {
  // Untessellated draws: primitives per batch handed to the rasterizer; bounds the memory of one
  // batch (64 bytes per vertex and 16 varyings). The image never depends on it.
  std::size_t batch_triangles = 65536;
  // Called on the calling thread after each batch with the fraction of the input done.
  std::function<void(double)> progress;
  // Tessellation: patches per chunk (each chunk is tessellated, then rasterized, then dropped);
  // 0 sizes chunks to about 128k triangles from the levels. The image never depends on it.
  std::size_t tess_chunk_patches = 0;
  // A mesh scene (not a scene of draws): whether draw buffer 1, the world normals (location 1), is
  // kept. false: the framebuffer has colour and depth only (location 1 is neither cleared nor
  // written, as GL drops outputs without a draw buffer), for a caller that does not read it.
  bool normals = true;
  // Tessellation: receives every TES invocation's record (patch id, gl_TessCoord, position,
  // normal), chunk by chunk in patch order, on the calling thread.
  std::function<void(const std::vector<TessDumpRecord>&)> dump_tess;
  // Tessellation: receives each chunk's triangles with their vertices' records (the batch is
  // indexed; vertex k of the batch is record k), before dump_tess, on the calling thread.
  std::function<void(const std::vector<TessDumpRecord>&, const TriangleBatch&)> tess_surface;
  // A scene of draws: each batch of untessellated triangles (GL_TRIANGLES, strips, fans), with
  // the vertex shader's gl_Position, before it is rasterized, on the calling thread.
  std::function<void(const TriangleBatch&)> untessellated_triangles;
  // A scene of draws: called with each draw's index (into Scene::draws) before it is drawn.
  std::function<void(std::size_t)> begin_draw;
  // A scene of draws: the fragment program each call draws with, before its first primitive
  // (inspect --pixel redraws with it), on the calling thread.
  std::function<void(const FragmentProgram&)> fragment_program;
  // Each call's rasterizer state as drawn: the GL state with where the program's vertices carry
  // gl_ClipDistance and gl_CullDistance (RasterState::distances), on the calling thread.
  std::function<void(const RasterState&)> raster_state;
  // A scene of draws, isolines and point mode: each chunk's records and the vertices its lines
  // or points emit, as indices into them, before dump_tess, on the calling thread.
  std::function<void(const std::vector<TessDumpRecord>&, const std::vector<std::uint32_t>&)> tess_lines_points;
  // A scene of draws: each batch of lines, or of points, before it is rasterized, on the calling
  // thread. Untessellated ones (GL_LINES, strips, loops, GL_POINTS) come with null records;
  // isolines and point mode with the chunk's records and, for vertex k of the batch, its record
  // emitted[k].
  std::function<void(const LineBatch&, const std::vector<TessDumpRecord>*, const std::vector<std::uint32_t>*)> line_batch;
  std::function<void(const PointBatch&, const std::vector<TessDumpRecord>*, const std::vector<std::uint32_t>*)> point_batch;
  // Every primitive as the rasterizer receives it (after the geometry shader, before clipping),
  // in the order GL's transform feedback records primitives, on the calling thread: `count`
  // primitives of `corners` (1, 2 or 3) vertices; vertex(p, k) holds corner k of primitive p
  // (gl_Position, then the last stage's outputs: glsl::GlslProgram::output_floats). `stream`: the
  // geometry shader's vertex stream; only stream 0 is rasterized, streams 1..3 are points.
  std::function<void(int stream, int corners, std::size_t count,
                     const std::function<const float*(std::size_t, int)>& vertex)>
      primitives;
  // `render --check`: every stage's outputs tested for NaN and infinity; the first offence throws
  // CheckOffence. Null: nothing is tested and nothing is added to the draw's work.
  Checker* check = nullptr;

  // Whether the executor must keep every TES invocation's record (dump_tess, tess_surface, check).
  bool wants_tess_records() const {
    return dump_tess || tess_surface || tess_lines_points || line_batch || point_batch || check;
  }
  // Whether it must know which record each isoline and point vertex is.
  bool wants_emitted() const { return tess_lines_points || line_batch || point_batch; }
  // Hands one drawn chunk's records to tess_surface and dump_tess, then empties them for the next.
  void hand_out_tess_chunk(std::vector<TessDumpRecord>& records, const TriangleBatch& batch,
                           std::vector<std::uint32_t>* emitted = nullptr) const {
    if (emitted && !emitted->empty() && tess_lines_points) tess_lines_points(records, *emitted);
    if (emitted) emitted->clear();
    if (tess_surface && batch.triangle_count()) tess_surface(records, batch);
    if (dump_tess) dump_tess(records);
    records.clear();
  }
};

// The mesh as a GL draw: its positions and normals as the attribute arrays at locations 0 and 1,
// glDrawElements(GL_PATCHES with 3 vertices a patch, or GL_TRIANGLES) over its indices, drawn with
// the built-in programs (render/builtin_program.h) through run_draw, the path of every draw. The
// bytes of fb do not depend on parallel.threads().
DrawStats draw_mesh(const Mesh& mesh, const programs::TransformVertexShader& vertex_shader,
                    const TessellationSettings& tessellation, const RasterState& raster_state,
                    const FragmentProgram& fragment_shader, Framebuffer& fb,
                    const Parallel& parallel, const DrawOptions& options = {});

}  // namespace tessref
