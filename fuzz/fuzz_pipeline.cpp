// Fuzzes the whole pipeline (render/render.h) on tiny meshes: a few triangles whose positions
// and normals come from the input (on a small grid, or any float bits: NaN, infinities, huge),
// drawn into a small image with random tessellation (on or off, flat or PN, every normal mode,
// spacing and winding, any level bits, adaptive levels), shading, culling and, now and then, the
// built-in programs' GLSL twins on the executor.
//
// The scene goes through parse_scene with --set overrides and the mesh through validate_mesh, as
// `tessref render` does (cli/render_command.cpp). Expected: an image, or InputError for bad input.
// A finding: any other exception, a crash, UB, a hang, or an image whose size or depth values
// break the framebuffer's contract (depth in [0, 1]).
#include <fuzzer/FuzzedDataProvider.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "common/error.h"
#include "common/parallel.h"
#include "render/render.h"
#include "scene/scene_loader.h"

namespace {

using namespace tessref;

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz_pipeline: invariant broken: %s\n", what);
    std::abort();
  }
}

// A coordinate: on a 1/32 grid in [-4, 4) mostly, else any float bits.
float coordinate(FuzzedDataProvider& in) {
  if (in.ConsumeIntegralInRange(0, 7) == 0) return std::bit_cast<float>(in.ConsumeIntegral<std::uint32_t>());
  return float(in.ConsumeIntegralInRange(-128, 127)) / 32.0f;
}

// A tessellation level as --set spells it ("nan", "inf", "1e+38", "7.5").
std::string level(FuzzedDataProvider& in) {
  float f = 0.0f;
  switch (in.ConsumeIntegralInRange(0, 3)) {
    case 0: f = std::bit_cast<float>(in.ConsumeIntegral<std::uint32_t>()); break;
    case 1: f = float(in.ConsumeIntegralInRange(-64, 2048)) / 32.0f; break;
    default: f = float(in.ConsumeIntegralInRange(0, 16)); break;
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", double(f));
  return text;
}

template <std::size_t N>
std::string pick(FuzzedDataProvider& in, const char* const (&names)[N]) {
  return names[in.ConsumeIntegralInRange<std::size_t>(0, N - 1)];
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const Parallel parallel(1);
  FuzzedDataProvider in(data, size);

  Mesh mesh;
  const int vertices = in.ConsumeIntegralInRange(3, 6);
  for (int v = 0; v < vertices; ++v) {
    mesh.positions.push_back({coordinate(in), coordinate(in), coordinate(in)});
    mesh.normals.push_back({coordinate(in), coordinate(in), coordinate(in)});
  }
  const int triangles = in.ConsumeIntegralInRange(1, 4);
  for (int i = 0; i < 3 * triangles; ++i)
    mesh.indices.push_back(in.ConsumeIntegralInRange<std::uint32_t>(0, std::uint32_t(vertices - 1)));

  static const char* const kBool[] = {"false", "true"};
  static const char* const kScheme[] = {"flat", "pn"};
  static const char* const kNormals[] = {"linear", "quadratic", "quadratic_corrected", "analytic"};
  static const char* const kSpacing[] = {"equal", "fractional_odd", "fractional_even"};
  static const char* const kWinding[] = {"ccw", "cw"};
  static const char* const kShading[] = {"phong", "normals"};
  std::vector<std::string> sets = {
      "camera.eye=0,0,6", "camera.target=0,0,0", "camera.fov_y_deg=45", "camera.near=0.5", "camera.far=20",
      "transform.rotate_deg=0,0,0",
      "image.width=" + std::to_string(in.ConsumeIntegralInRange(1, 32)),
      "image.height=" + std::to_string(in.ConsumeIntegralInRange(1, 32)),
      "tessellation.enabled=" + pick(in, kBool),
      "tessellation.scheme=" + pick(in, kScheme),
      "tessellation.normal_mode=" + pick(in, kNormals),
      "tessellation.spacing=" + pick(in, kSpacing),
      "tessellation.winding=" + pick(in, kWinding),
      "tessellation.inner=" + level(in) + "," + level(in),
      "tessellation.outer=" + level(in) + "," + level(in) + "," + level(in) + "," + level(in),
      "tessellation.adaptive.enabled=" + pick(in, kBool),
      "tessellation.adaptive.pixels_per_segment=" + level(in),
      "shading=" + pick(in, kShading),
      "cull_back_faces=" + pick(in, kBool),
  };
  // The GLSL twins cost a compilation per run: one run in 16.
  // Their vertex shader's inputs can be renamed or given by location (digits).
  if (in.ConsumeIntegralInRange(0, 15) == 0) {
    sets.push_back("shaders.program=twins");
    if (in.ConsumeBool())
      sets.push_back("shaders.attributes." + in.ConsumeRandomLengthString(24) + "=" + (in.ConsumeBool() ? "position" : "normal"));
  }
  if (in.ConsumeBool()) sets.push_back("shaders.batch_lanes=" + std::to_string(in.ConsumeIntegralInRange(1, 256)));

  // FUZZ_PIPELINE_VERBOSE=1: print the case (to turn a finding into a test).
  static const bool verbose = std::getenv("FUZZ_PIPELINE_VERBOSE") != nullptr;
  if (verbose) {
    for (const std::string& set : sets) std::fprintf(stderr, "--set %s\n", set.c_str());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
      std::fprintf(stderr, "v %a %a %a  n %a %a %a\n", double(mesh.positions[v].x), double(mesh.positions[v].y),
                   double(mesh.positions[v].z), double(mesh.normals[v].x), double(mesh.normals[v].y),
                   double(mesh.normals[v].z));
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
      std::fprintf(stderr, "f %u %u %u\n", mesh.indices[i], mesh.indices[i + 1], mesh.indices[i + 2]);
  }
  try {
    const Scene scene = parse_scene("{}", "fuzz.json", ".", sets);
    validate_mesh(mesh, "fuzz mesh");
    const RenderResult r = render_scene(scene, mesh, parallel);
    const Framebuffer& fb = r.framebuffer;
    check(fb.width == scene.width && fb.height == scene.height, "image size");
    check(fb.color.size() == std::size_t(fb.width) * fb.height && fb.depth.size() == fb.color.size(), "buffers");
    for (float z : fb.depth) check(z >= 0.0f && z <= 1.0f, "depth in [0, 1]");
    check(r.stats.triangles_in == mesh.triangle_count(), "triangles in");
  } catch (const InputError&) {
  }
  return 0;
}
