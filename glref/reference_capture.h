#pragma once
// `tessref capture`: a scene drawn by the GL driver with its GLSL (SceneRenderer), stored as a
// reference for `tessref verify` (verify/verify_scene.h): color.png, depth.exr, tess.bin (the TES
// outputs by transform feedback, one record per emitted vertex, in the --dump-tess format) and
// manifest.json (the driver's names and tessellation limits, the scene as read, its hash, the
// command line, the date). The four files are written whole or not at all.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "mesh/mesh.h"
#include "scene/scene.h"

namespace tessref::glref {

class GlContext;

struct CaptureSummary {
  std::size_t tess_records = 0;  // emitted vertices captured (0 without tessellation)
  std::size_t tess_records_stored = 0;  // of them, in tess.bin
  std::uint32_t patch_stride = 1;       // tess.bin holds the patches whose id is a multiple of it
  nlohmann::json manifest;
};

// scene_json: the merged scene (scene/scene_loader.h: load_scene_json), stored in the manifest.
// max_tess_records: 0 stores every emitted vertex in tess.bin; otherwise only every k-th patch's,
// k the smallest stride that keeps tess.bin within that many records. tess_patches.bin always
// holds every patch's digest (io/tess_digest.h), so coordinates are compared for all.
CaptureSummary capture_reference(GlContext& context, const Scene& scene, const Mesh& mesh,
                                 const nlohmann::json& scene_json, const std::string& command_line,
                                 const std::filesystem::path& dir, std::size_t max_tess_records = 0);

}  // namespace tessref::glref
