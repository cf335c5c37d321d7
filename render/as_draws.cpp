#include "render/as_draws.h"

#include <cstring>
#include <fstream>

#include "common/error.h"
#include "mesh/camera.h"
#include "render/glsl_scene.h"
#include "stages/tpg.h"

namespace tessref {
namespace {

void write_bytes(const std::filesystem::path& path, const void* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary);
  if (!out || !out.write(static_cast<const char*>(data), std::streamsize(size)) || !out.flush())
    throw InputError("--as-draws: cannot write '" + path.string() + "'");
}

const char* stage_key(shader::Stage s) {
  switch (s) {
    case shader::Stage::Vertex: return "vertex";
    case shader::Stage::TessControl: return "tess_control";
    case shader::Stage::TessEval: return "tess_evaluation";
    case shader::Stage::Geometry: return "geometry";
    default: return "fragment";
  }
}

// The twin evaluation shader's layout line names one spacing and winding; the mesh path draws the
// twins with the scene's instead (the draw form has no such override, as GL has none).
void check_layout_line(const Scene& scene, const std::string& source) {
  const std::size_t at = source.find("layout(triangles");
  const std::string line = at == std::string::npos ? "" : source.substr(at, source.find('\n', at) - at);
  const std::string spacing = glsl_name(scene.tessellation.spacing), winding = glsl_name(scene.tessellation.winding);
  if (line.find(spacing) == std::string::npos || line.find(", " + winding) == std::string::npos)
    throw InputError(scene.source + ": tessellation.spacing, tessellation.winding: the twin evaluation shader's layout is '" +
                     line + "'; a draw takes its shader's own layout, so --as-draws needs " + spacing + " and " + winding +
                     " there (edit the written shader, or set the scene's spacing and winding to the twin's)");
}

}  // namespace

nlohmann::json write_scene_as_draws(const nlohmann::json& scene_json, const Scene& scene, const Mesh& mesh,
                                    const std::filesystem::path& dir) {
  using nlohmann::json;
  if (!scene.draws.empty()) throw InputError(scene.source + ": draws: the scene already describes its draws");
  if (scene.tessellation.enabled && scene.tessellation.scheme == SurfaceScheme::ScalarTaggedPN)
    throw InputError(scene.source + ": tessellation.scheme: scalar_tagged_pn reads per-vertex tags that --as-draws does not write yet");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError("--as-draws: cannot create '" + dir.string() + "': " + ec.message());

  json out = scene_json;
  out.erase("mesh");
  out["description"] = "The mesh scene " + scene.source + " as the GL draw tessref makes of it (tessref scene --as-draws).";
  const Camera camera = fitted_camera(scene, mesh);  // the frame render would draw
  out["camera"] = {{"eye", {camera.eye.x, camera.eye.y, camera.eye.z}},
                   {"target", {camera.target.x, camera.target.y, camera.target.z}},
                   {"up", {camera.up.x, camera.up.y, camera.up.z}},
                   {"fov_y_deg", camera.fov_y_deg}, {"near", camera.near}, {"far", camera.far}, {"fit", false}};

  write_bytes(dir / "positions.bin", mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
  write_bytes(dir / "normals.bin", mesh.normals.data(), mesh.normals.size() * sizeof(glm::vec3));
  write_bytes(dir / "indices.bin", mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
  out["buffers"] = {{"positions", {{"file", "positions.bin"}}},
                    {"normals", {{"file", "normals.bin"}}},
                    {"indices", {{"file", "indices.bin"}}}};

  // The program: the built-in ones as their twins; a user's own as its files.
  Scene twins = scene;
  if (scene.shaders.program == ShaderProgram::Builtin) twins.shaders.program = ShaderProgram::Twins;
  json shaders = json::object();
  for (const shader::ShaderSource& s : scene_sources(twins)) {
    if (twins.shaders.program == ShaderProgram::Twins) {
      if (s.stage == shader::Stage::TessEval) check_layout_line(scene, s.text);
      const std::string name = std::filesystem::path(s.file).filename().string();
      write_bytes(dir / name, s.text.data(), s.text.size());
      shaders[stage_key(s.stage)] = name;
    } else {
      shaders[stage_key(s.stage)] = std::filesystem::absolute(s.file).string();
    }
  }
  if (scene_json.contains("shaders") && scene_json["shaders"].contains("uniforms"))
    shaders["uniforms"] = scene_json["shaders"]["uniforms"];
  out["shaders"] = {{"program", "builtin"}};  // the draw names its own program

  json arrays = json::object();
  for (const auto& [input, source] : scene.shaders.attributes)
    arrays[input] = {{"buffer", source == "position" ? "positions" : "normals"}, {"size", 3}, {"type", "GL_FLOAT"}};
  json enable = json::array({"GL_DEPTH_TEST"});
  if (scene.cull_back_faces) enable.push_back("GL_CULL_FACE");
  json draw{{"shaders", shaders},
            {"mode", scene.tessellation.enabled ? "GL_PATCHES" : "GL_TRIANGLES"},
            {"vertex_arrays", arrays},
            {"elements", {{"buffer", "indices"}, {"type", "GL_UNSIGNED_INT"}}},
            {"count", mesh.indices.size()},
            {"enable", enable},
            {"polygon_mode", out.value("polygon_mode", json("GL_FILL"))}};
  if (scene.tessellation.enabled) draw["patch_vertices"] = twins.shaders.program == ShaderProgram::Twins ? 3 : scene.shaders.patch_vertices;
  out["draws"] = json::array({draw});
  const std::string text = out.dump(2) + "\n";
  write_bytes(dir / "scene.json", text.data(), text.size());
  return out;
}

}  // namespace tessref
