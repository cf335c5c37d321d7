#include "render/draw_scene.h"

#include <algorithm>
#include <map>
#include <optional>
#include <span>

#include "common/error.h"
#include "raster/clear.h"
#include "render/glsl_scene.h"
#include "render/transform_feedback.h"

namespace tessref {

int primitive_corners(DrawMode mode) {
  switch (mode) {
    case DrawMode::Lines:
    case DrawMode::LineStrip:
    case DrawMode::LineLoop: return 2;
    case DrawMode::Points: return 1;
    case DrawMode::LinesAdjacency:
    case DrawMode::LineStripAdjacency: return 4;
    case DrawMode::TrianglesAdjacency:
    case DrawMode::TriangleStripAdjacency: return 6;
    default: return 3;
  }
}

namespace {

// GL 4.5, 10.1.14, table 10.1: triangle i of a strip with adjacency, as the geometry shader
// receives it (vertex 1, adjacent across 1-2, vertex 2, adjacent across 2-3, vertex 3, adjacent
// across 3-1). Counted from 1 as the table counts: odd triangles swap their first two vertices
// (the strip's winding kept); the first and last take their outer neighbours from the strip's ends.
void append_triangle_strip_adjacency(const std::vector<std::uint32_t>& r, std::vector<std::uint32_t>& out) {
  if (r.size() < 6) return;
  const std::size_t triangles = (r.size() - 4) / 2;
  for (std::size_t i = 0; i < triangles; ++i) {
    const bool first = i == 0, last = i + 1 == triangles, odd = i % 2;
    std::size_t v1 = 2 * i + 1, v2 = 2 * i + 3, v3 = 2 * i + 5;
    std::size_t adj12 = first ? 2 : 2 * i - 1;
    std::size_t adj23 = last ? 2 * i + 6 : 2 * i + 7;  // across the edge the next triangle shares
    std::size_t adj31 = 2 * i + 4;
    if (odd) {
      std::swap(v1, v2);
      std::swap(adj23, adj31);
    }
    for (const std::size_t k : {v1, adj12, v2, adj23, v3, adj31}) out.push_back(r[k - 1]);
  }
}

}  // namespace

std::vector<std::uint32_t> assemble(DrawMode mode, int patch_vertices,
                                    const std::vector<std::vector<std::uint32_t>>& runs) {
  std::vector<std::uint32_t> out;
  for (const std::vector<std::uint32_t>& r : runs) {
    switch (mode) {
      case DrawMode::Patches:
      case DrawMode::Triangles: {
        const std::size_t n = mode == DrawMode::Patches ? std::size_t(patch_vertices) : 3;
        out.insert(out.end(), r.begin(), r.begin() + std::ptrdiff_t(r.size() / n * n));
        break;
      }
      case DrawMode::TriangleStrip:
        // GL 4.5, 10.1.8: triangle i is (i, i+1, i+2), with i and i+1 swapped for odd i so that
        // every triangle keeps the strip's winding.
        for (std::size_t i = 0; i + 2 < r.size(); ++i) {
          const bool odd = i % 2;
          out.insert(out.end(), {r[odd ? i + 1 : i], r[odd ? i : i + 1], r[i + 2]});
        }
        break;
      case DrawMode::TriangleFan:
        for (std::size_t i = 0; i + 2 < r.size(); ++i) out.insert(out.end(), {r[0], r[i + 1], r[i + 2]});
        break;
      case DrawMode::Lines: out.insert(out.end(), r.begin(), r.begin() + std::ptrdiff_t(r.size() / 2 * 2)); break;
      case DrawMode::LineStrip:
      case DrawMode::LineLoop:
        // GL 4.5, 10.1.3 and 10.1.4: segment i joins vertices i and i+1; a loop adds the last to the first.
        for (std::size_t i = 0; i + 1 < r.size(); ++i) out.insert(out.end(), {r[i], r[i + 1]});
        if (mode == DrawMode::LineLoop && r.size() >= 2) out.insert(out.end(), {r.back(), r[0]});
        break;
      case DrawMode::Points: out.insert(out.end(), r.begin(), r.end()); break;
      case DrawMode::LinesAdjacency: out.insert(out.end(), r.begin(), r.begin() + std::ptrdiff_t(r.size() / 4 * 4)); break;
      case DrawMode::TrianglesAdjacency: out.insert(out.end(), r.begin(), r.begin() + std::ptrdiff_t(r.size() / 6 * 6)); break;
      case DrawMode::LineStripAdjacency:
        // GL 4.5, 10.1.12: segment i joins i+1 and i+2, with i and i+3 adjacent.
        for (std::size_t i = 0; i + 3 < r.size(); ++i) out.insert(out.end(), {r[i], r[i + 1], r[i + 2], r[i + 3]});
        break;
      case DrawMode::TriangleStripAdjacency: append_triangle_strip_adjacency(r, out); break;
    }
  }
  return out;
}

namespace {

// The draw's arrays with their inputs resolved to the program's locations.
std::vector<draw::VertexArray> resolve_arrays(const Scene& scene, const DrawSetting& d, const glsl::GlslProgram& program) {
  std::vector<draw::VertexArray> arrays;
  for (const VertexArraySetting& s : d.vertex_arrays) {
    draw::VertexArray a = s.array;
    const bool by_location = s.input.find_first_not_of("0123456789") == std::string::npos;
    if (by_location) {
      a.location = std::uint32_t(std::stoul(s.input));
    } else {
      const auto location = program.attribute_location(s.input);
      if (!location)
        throw InputError(scene.source + ": " + a.key + ": the vertex shader has no active input named \"" +
                         s.input + "\" (glGetAttribLocation would return -1; name an input or give a location)");
      a.location = *location;
    }
    arrays.push_back(std::move(a));
  }
  return arrays;
}

// glBindBufferRange state of one indexed target: binding -> the range bound there. GL keeps it
// from draw to draw, and so does a scene.
// Storage blocks write back into the range (GlslProgram::write_back_storage).
using BufferBindings = std::map<std::uint32_t, std::pair<const UniformBufferSetting*, std::span<std::byte>>>;

// Adds d's ranges of one target (its uniform_buffers or storage_buffers) to the bindings the
// earlier draws left. InputError for a range past its buffer.
void add_bindings(const Scene& scene, const std::vector<UniformBufferSetting>& settings,
                  std::vector<draw::Buffer>& buffers, BufferBindings& bindings) {
  for (const UniformBufferSetting& u : settings) {
    draw::Buffer& b = buffers[u.buffer];
    const std::size_t size = u.size.value_or(b.bytes.size() > u.offset ? b.bytes.size() - u.offset : 0);
    if (u.offset + size > b.bytes.size() || size == 0)
      throw InputError(scene.source + ": " + u.key + ": bytes [" + std::to_string(u.offset) + ", " +
                       std::to_string(u.offset + size) + ") of buffer '" + b.name + "', which holds " +
                       std::to_string(b.bytes.size()) + " bytes");
    bindings[u.binding] = {&u, std::span<std::byte>(b.bytes).subspan(u.offset, size)};
  }
}

// Binds the program's blocks of one target to the ranges bound; a range d binds where the program
// has no block is refused (a scene's binding that reads nothing is a mistake worth naming).
void bind_blocks(const Scene& scene, const DrawSetting& d, const BufferBindings& bindings, bool storage,
                 glsl::GlslProgram& program) {
  const std::vector<glsl::GlslProgram::UniformBlock> blocks = storage ? program.storage_blocks() : program.uniform_blocks();
  for (const UniformBufferSetting& u : storage ? d.storage_buffers : d.uniform_buffers) {
    if (std::any_of(blocks.begin(), blocks.end(), [&](const glsl::GlslProgram::UniformBlock& k) { return k.binding == u.binding; }))
      continue;
    std::string names;
    for (const auto& k : blocks) names += (names.empty() ? "" : ", ") + k.name + " at " + std::to_string(k.binding);
    throw InputError(scene.source + ": " + u.key + ".binding: the program has no " +
                     (storage ? "shader storage" : "uniform") + " block at binding " + std::to_string(u.binding) +
                     " (its blocks: " + (names.empty() ? "none" : names) + "; a block is placed with layout(binding = N))");
  }
  for (const auto& [binding, bound] : bindings) {
    try {
      if (storage) program.bind_storage_buffer(binding, bound.second);
      else program.bind_uniform_buffer(binding, bound.second);
    } catch (const std::invalid_argument& e) {
      throw InputError(scene.source + ": " + bound.first->key + ": " + e.what());
    }
  }
}

// The primitives of one call: its vertices fetched and assembled (InputError naming the scene).
std::vector<std::uint32_t> call_primitives(const Scene& scene, const DrawSetting& d, const std::vector<draw::Buffer>& buffers,
                                           const std::vector<draw::VertexArray>& arrays, const draw::DrawCall& c,
                                           draw::VertexInput& input) {
  try {
    input = draw::fetch_vertices(buffers, arrays, d.elements, d.restart, c, d.rules);
  } catch (const InputError& e) {
    throw InputError(scene.source + ": " + e.what());
  }
  return assemble(d.mode, d.patch_vertices, input.runs);
}

std::uint32_t patches_per_instance(const DrawSetting& d, const std::vector<std::uint32_t>& primitives) {
  return d.mode == DrawMode::Patches ? std::uint32_t(primitives.size() / std::size_t(d.patch_vertices)) : 0;
}

}  // namespace

std::vector<std::vector<CallPatches>> patch_numbering(const Scene& scene, const std::vector<draw::Buffer>& buffers) {
  std::vector<std::vector<CallPatches>> out(scene.draws.size());
  std::uint32_t next = 0;
  for (std::size_t i = 0; i < scene.draws.size(); ++i) {
    const DrawSetting& d = scene.draws[i];
    for (const draw::DrawCall& c : d.calls) {
      draw::VertexInput input;
      // Locations do not change which vertices are fetched: the arrays as the scene gives them.
      std::vector<draw::VertexArray> arrays;
      for (const VertexArraySetting& s : d.vertex_arrays) arrays.push_back(s.array);
      const CallPatches p{next, patches_per_instance(d, call_primitives(scene, d, buffers, arrays, c, input)),
                          c.instance_count};
      out[i].push_back(p);
      next += p.per_instance * p.instances;
    }
  }
  return out;
}

SceneDraws::SceneDraws(const Scene& scene) : scene_(scene), buffers_(load_buffers(scene)), own_(scene.draws.size()) {
  // The scene's program is built once, and only if a draw has no shaders of its own (the scene
  // format then requires it to be custom), unless storage ranges are bound: their sizes are part
  // of the program (runtime arrays), so such a draw gets its own. All are compiled before the
  // first draw, so that a broken one draws nothing.
  BufferBindings storage;
  for (std::size_t i = 0; i < scene.draws.size(); ++i) {
    const DrawSetting& d = scene.draws[i];
    add_bindings(scene, d.storage_buffers, buffers_, storage);
    shader::StorageBufferSizes sizes;
    for (const auto& [binding, bound] : storage) sizes[binding] = bound.second.size();
    const std::string at = sizes.empty() ? "" : " (" + d.key + ": with the shader storage ranges bound then)";
    try {
      if (d.shaders) own_[i] = build_scene_program(scene, *d.shaders, sizes);
      else if (!sizes.empty()) own_[i] = build_scene_program(scene, scene.shaders, sizes);
      else if (!shared_.program) shared_ = build_scene_program(scene);
    } catch (const InputError& e) {
      if (at.empty()) throw;
      throw InputError(e.what() + at);
    }
  }
}

SceneDraws::~SceneDraws() = default;

std::vector<std::pair<std::string, std::vector<std::uint8_t>>> SceneDraws::images() const {
  std::vector<std::pair<std::string, std::vector<std::uint8_t>>> out;
  const auto add = [&](const SceneProgram& p, const std::string& prefix) {
    for (const auto& [name, tex] : p.images) out.emplace_back(prefix + name, tex->levels.at(0).stored);
  };
  add(shared_, "");
  for (std::size_t i = 0; i < own_.size(); ++i) add(own_[i], "draw" + std::to_string(i) + ".");
  return out;
}

std::vector<std::string> SceneDraws::warnings() const {
  std::vector<std::string> out = shared_.warnings;
  for (const SceneProgram& p : own_) out.insert(out.end(), p.warnings.begin(), p.warnings.end());
  return out;
}

std::vector<shader::ShaderSource> SceneDraws::sources(std::size_t draw) const {
  const DrawSetting& d = scene_.draws.at(draw);
  return d.shaders ? scene_sources(scene_, *d.shaders) : scene_sources(scene_);
}

void SceneDraws::for_each_call(std::size_t end, const std::function<void(const PreparedCall&)>& fn) {
  BufferBindings uniform_bindings, storage_bindings;
  std::uint32_t next_patch = 0;
  for (std::size_t i = 0; i < std::min(end, scene_.draws.size()); ++i) {
    const DrawSetting& d = scene_.draws[i];
    glsl::GlslProgram& program = own_[i].program ? *own_[i].program : *shared_.program;
    add_bindings(scene_, d.uniform_buffers, buffers_, uniform_bindings);
    add_bindings(scene_, d.storage_buffers, buffers_, storage_bindings);
    bind_blocks(scene_, d, uniform_bindings, false, program);
    bind_blocks(scene_, d, storage_bindings, true, program);
    program.set_cube_map_seamless(d.raster.cube_map_seamless);
    const std::vector<draw::VertexArray> arrays = resolve_arrays(scene_, d, program);
    for (std::size_t k = 0; k < d.calls.size(); ++k) {
      const draw::DrawCall& c = d.calls[k];
      draw::VertexInput input;
      const std::vector<std::uint32_t> indices = call_primitives(scene_, d, buffers_, arrays, c, input);
      DrawCall call;
      call.indices = indices;
      call.vertex_ids = input.vertex_ids;
      call.vertex_count = input.vertex_ids.size();
      call.instances = int(c.instance_count);
      call.patches = d.mode == DrawMode::Patches;
      call.corners = primitive_corners(d.mode);
      call.patch_vertices = d.patch_vertices;
      call.default_outer = d.default_outer;
      call.default_inner = d.default_inner;
      call.first_patch_id = next_patch;
      next_patch += patches_per_instance(d, indices) * c.instance_count;
      if (!input.instanced.empty())
        call.instance_attributes = [&](int instance, std::vector<glsl::VertexAttribute>& out) {
          draw::fetch_instanced(buffers_, arrays, input, c, std::uint32_t(instance), d.rules, out);
        };
      try {
        fn(PreparedCall{i, k, d, program, input.per_vertex, call});
        program.write_back_storage();  // what the call wrote, for the next draws and the output
      } catch (const InputError& e) {  // an instanced array's fetch
        throw InputError(scene_.source + ": " + e.what());
      } catch (const glsl::StageError& e) {
        throw InputError(scene_.source + ": " + d.key + ": " + e.what());
      } catch (const std::invalid_argument& e) {
        throw InputError(scene_.source + ": " + d.key + ": " + e.what());
      }
    }
  }
}

DrawStats draw_scene_draws(const Scene& scene, Framebuffer& fb, const Parallel& parallel, const DrawOptions& options,
                           std::vector<FeedbackBuffers>* feedback, DrawnMemory* memory) {
  SceneDraws draws(scene);
  // Transform feedback: a recorder for each draw that has it, made at its first call (the
  // program's outputs resolve the names), handed out when the next draw begins.
  std::optional<FeedbackRecorder> recorder;
  DrawOptions recording = options;
  const auto hand_out = [&] {
    if (recorder) feedback->push_back(recorder->buffers());
    recorder.reset();
  };
  DrawStats stats;
  std::size_t next = 0;  // the first draw not begun
  // Draws [next, end) begin: each one's glClear, then the caller hears of it.
  const auto begin_until = [&](std::size_t end) {
    for (; next < end; ++next) {
      const DrawSetting& d = scene.draws[next];
      if (d.clear_color || d.clear_depth)
        clear_buffers(fb, d.raster, d.clear_color,
                      d.clear_depth ? std::optional<float>(float(*d.clear_depth)) : std::nullopt);
      if (options.begin_draw) options.begin_draw(next);
    }
  };
  draws.for_each_call(scene.draws.size(), [&](const PreparedCall& p) {
    begin_until(p.draw + 1);
    const bool records = feedback && p.setting.transform_feedback;
    if (records && (!recorder || recorder->buffers().draw != p.draw)) {
      hand_out();
      recorder.emplace(scene, p.draw, p.program);
      recording.primitives = [&](int stream, int corners, std::size_t count,
                                 const std::function<const float*(std::size_t, int)>& v) {
        recorder->record(stream, corners, count, v);
        if (options.primitives) options.primitives(stream, corners, count, v);
      };
    }
    if (p.call.indices.empty() || p.call.instances == 0) return;
    stats += run_draw(p.program, p.attributes, p.call, p.setting.raster, fb, parallel, records ? recording : options);
  });
  hand_out();
  begin_until(scene.draws.size());  // draws without calls still clear
  stats.warnings = draws.warnings();
  if (memory) {
    memory->buffers = draws.buffers();
    memory->images = draws.images();
  }
  return stats;
}

}  // namespace tessref
