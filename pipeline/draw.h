#pragma once
// The draw call: vertex shader -> [tessellation stages] -> primitive assembly -> rasterizer + FS.
#include <cstddef>
#include <cstdint>
#include <functional>

#include "common/parallel.h"
#include "pipeline/mesh.h"
#include "pipeline/tessellation_settings.h"
#include "raster/rasterizer.h"
#include "stages/programs/transform.h"

namespace tessref {

struct DrawStats {
  std::uint64_t vertices_shaded = 0;
  std::uint64_t triangles_in = 0;         // mesh triangles (patches, with tessellation)
  std::uint64_t triangles_generated = 0;  // handed to the rasterizer (after tessellation)
  RasterStats raster;                     // triangles_rasterized, fragments_shaded, ...
  double vertex_seconds = 0.0;            // vertex shader and primitive assembly
  double tessellation_seconds = 0.0;
  double raster_seconds = 0.0;            // rasterization and fragment shading
};

struct DrawOptions {
  // Triangles per TriangleBatch: bounds the memory of one batch (64 bytes per vertex).
  std::size_t batch_triangles = 65536;
  // Called on the calling thread after each batch with the fraction of the input done.
  std::function<void(double)> progress;
};

// Draws the mesh's triangles, in mesh order, into fb. The bytes of fb do not depend on
// parallel.threads(). Throws InputError for tessellation until the tessellation stages land.
DrawStats draw_mesh(const Mesh& mesh, const programs::TransformVertexShader& vertex_shader,
                    const TessellationSettings& tessellation, const RasterState& raster_state,
                    const FragmentProgram& fragment_shader, Framebuffer& fb,
                    const Parallel& parallel, const DrawOptions& options = {});

}  // namespace tessref
