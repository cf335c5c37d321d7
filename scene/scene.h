#pragma once
// A scene as read from JSON (scenes/*.json; format in README.md): what to draw and how.
// Scene files take every value they omit from scenes/default.json (scene_loader.h); the
// initializers below only serve code that builds a Scene by hand.
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "draw/vertex_fetch.h"
#include "scene/tessellation_settings.h"
#include "raster/rasterizer.h"
#include "stages/programs/phong.h"
#include "texture/texture.h"

namespace tessref {

// Seed004Torus, RoundedCube, Vase: seed 004's meshes (mesh/reference_meshes.h).
enum class MeshType { Icosphere, Torus, Cube, File, Seed004Torus, RoundedCube, Vase };

struct MeshSettings {
  MeshType type = MeshType::Icosphere;
  std::filesystem::path path;  // type file: resolved against the scene file's folder
  // false: vertices at one position share one normal (the file's normals there averaged), so PN
  // patches meet without cracks; true: each face keeps the normals the file gives it (seed 000,
  // Figure 5: where they differ along an edge, the patches part). Procedural meshes have one.
  bool split_normals = false;
  int icosphere_refinements = 1;
  float icosphere_radius = 1.0f;
  float torus_major_radius = 1.0f;
  float torus_minor_radius = 0.4f;
  int torus_major_segments = 16;
  int torus_minor_segments = 8;
  float cube_size = 1.0f;
  int seed004_torus_grid = 10;                  // j: 2 j^2 triangles
  bool seed004_torus_analytic_normals = false;  // false: face averages (the paper's)
  float rounded_cube_cut = 0.585f;
  float rounded_cube_half_size = 0.68f;
};

// model = translate * rotate_z * rotate_y * rotate_x * scale (rotations in degrees).
struct Transform {
  glm::vec3 translate{0.0f};
  glm::vec3 rotate_deg{0.0f};
  glm::vec3 scale{1.0f};
};

struct Camera {
  glm::vec3 eye{0.0f, 0.0f, 5.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_deg = 45.0f;
  float near = 0.1f;
  float far = 100.0f;
  bool fit = false;  // frame the mesh's bounding sphere (mesh/camera.h: fitted_camera)
};

// A point light; its intensity is used as I_a, I_d and I_s alike.
struct Light {
  glm::vec3 position{0.0f};
  glm::vec3 intensity{1.0f};
};

struct Material {
  float ka = 0.4f, kd = 0.5f, ks = 0.3f;
  float shininess = 150.0f;
  glm::vec3 color{0.988f, 0.0f, 0.427f};
};

enum class Shading { Phong, Normals };

// Which programs draw the scene: the built-in C++ programs (the fast default), their GLSL twins on
// tessref's SPIR-V executor, or the user's GLSL files on the executor.
enum class ShaderProgram { Builtin, Twins, Custom };

// A uniform value given in the scene: its numbers (a matrix column after column, an array element
// after element) or booleans, checked against the GLSL type when the program is built.
struct UniformSetting {
  std::string name;  // "u_color", or "u_lights[2]"
  std::vector<double> values;
  bool boolean = false;
};

// shaders.textures: a texture bound to a sampler uniform, as an application creates it
// (glTexStorage* with its internal format and levels, glTexSubImage* per level from an image file,
// glGenerateMipmap when asked, or glTexBufferRange on one of the scene's buffers) with its sampler
// state (glTexParameter). Read by scene/texture_schema.h.
struct TextureSetting {
  std::string sampler;  // the uniform's name
  texture::Target target = texture::Target::k2D;
  // level k's image file, from level 0 (raw: every layer; a 1D array's image: its rows are the layers)
  std::vector<std::filesystem::path> levels;
  std::vector<std::filesystem::path> layers;  // a 2D array's level 0 as one image file per layer
  // GL_TEXTURE_BUFFER: glTexBufferRange(GL_TEXTURE_BUFFER, format, buffers.NAME, offset, size);
  // no size: the rest of the buffer (glTexBuffer when the offset is 0 too).
  std::string buffer;
  std::size_t buffer_offset = 0;
  std::optional<std::size_t> buffer_size;
  // GL_RGBA32F from any image when absent (the image's gray expanded to RGB); else the file's
  // channels must be the format's.
  std::optional<texture::TexelFormat> format;
  // raw_size: the files are the format's bytes as glTexSubImage* takes them (GL_UNPACK_ALIGNMENT
  // 1, the bottom row first, layer after layer), level 0 this many texels wide and high (1 for 1D
  // targets) and this many layers (1 unless an array); else image files.
  std::optional<std::array<int, 3>> raw_size;
  bool generate_mipmaps = false;  // glGenerateMipmap after level 0 is given
  // The file's levels are all the texture has unless generate_mipmaps: its storage then has
  // every level down to 1 x 1.
  texture::SamplerState sampler_state{texture::Filter::Linear, texture::Filter::Linear};
  // A sampler object bound to the unit (glBindSampler): its state replaces sampler_state.
  std::optional<texture::SamplerState> sampler_object;
  int base_level = 0, max_level = 1000;
  std::array<texture::Swizzle, 4> swizzle{texture::Swizzle::Red, texture::Swizzle::Green, texture::Swizzle::Blue,
                                          texture::Swizzle::Alpha};
};

struct ShaderSettings {
  std::string key = "shaders";  // where the scene gives them ("draws.1.shaders"), for messages
  ShaderProgram program = ShaderProgram::Builtin;
  // Custom: GLSL files, resolved against the scene file's folder (tess_control may be empty).
  std::filesystem::path vertex, tess_control, tess_evaluation, geometry, fragment;
  std::vector<UniformSetting> uniforms;
  // Vertex shader input (a name, or a location as digits) -> the mesh attribute that feeds it:
  // "position" or "normal".
  std::vector<std::pair<std::string, std::string>> attributes;
  std::vector<TextureSetting> textures;
  int patch_vertices = 3;  // GL_PATCH_VERTICES: the mesh's index list taken this many at a time
  // The camera, lights, material and tessellation settings set the program's uniforms of the
  // twins' names (u_model, u_view_proj, u_color, ...); an imported draw turns that off, since a
  // uniform its application never set reads 0 on the driver.
  bool scene_uniforms = true;
  int batch_lanes = 256;                        // shader::ExecLimits::batch_lanes
  std::uint64_t max_instructions = 50'000'000;  // shader::ExecLimits::max_instructions
};

// buffers.NAME: a buffer object's bytes, from a file (read when drawn) or written inline.
struct BufferSetting {
  std::string name;
  std::filesystem::path file;  // resolved against the scene file's folder; empty: `data`
  std::vector<std::byte> data;
};

// draws[].mode: the primitive type of glDraw*(mode, ...).
enum class DrawMode { Patches, Triangles, TriangleStrip, TriangleFan, Lines, LineStrip, LineLoop, Points,
                      // Only for a geometry shader, which receives the adjacent vertices too.
                      LinesAdjacency, LineStripAdjacency, TrianglesAdjacency, TriangleStripAdjacency };

// draws[].vertex_arrays.INPUT: a vertex shader input (its name, or a location as digits) and the
// array that feeds it; the location is resolved against the program when drawn.
struct VertexArraySetting {
  std::string input;
  draw::VertexArray array;  // array.buffer: an index into Scene::buffers
};

// draws[].uniform_buffers[]: glBindBufferRange(GL_UNIFORM_BUFFER, binding, buffer, offset, size).
// A glBindBufferRange of GL_UNIFORM_BUFFER or GL_SHADER_STORAGE_BUFFER.
struct UniformBufferSetting {
  std::string key;  // "draws.0.uniform_buffers.1", for messages
  std::uint32_t binding = 0;
  std::size_t buffer = 0;  // into Scene::buffers
  std::size_t offset = 0;
  std::optional<std::size_t> size;  // none: to the end of the buffer
};

// draws[].transform_feedback: glTransformFeedbackVaryings(program, varyings, buffer_mode) and a
// transform feedback active over the draw (render --transform-feedback writes what it records).
struct TransformFeedbackSetting {
  std::string key;  // "draws.0.transform_feedback", for messages
  std::vector<std::string> varyings;  // output names, gl_NextBuffer, gl_SkipComponents1..4
  bool separate = false;              // GL_SEPARATE_ATTRIBS (default GL_INTERLEAVED_ATTRIBS)
  // The buffers it writes: one per varying when separate, else one more per gl_NextBuffer.
  std::size_t buffers() const;
};

// draws[]: one glDraw* call, or a list of them (calls: the multi-draw and indirect forms), with
// the vertex array object, the program and the state it is drawn with.
struct DrawSetting {
  std::string key;  // "draws.0", for messages
  DrawMode mode = DrawMode::Patches;
  int patch_vertices = 3;                    // GL_PATCH_VERTICES
  glm::vec4 default_outer{1.0f};             // GL_PATCH_DEFAULT_OUTER_LEVEL
  glm::vec2 default_inner{1.0f};             // GL_PATCH_DEFAULT_INNER_LEVEL
  std::vector<VertexArraySetting> vertex_arrays;
  std::optional<draw::ElementArray> elements;  // glDrawElements* when set (element.buffer: into buffers)
  draw::PrimitiveRestart restart;
  draw::FetchRules rules;
  // draws[].shaders: this draw's own program (a custom one); none: the scene's `shaders`.
  std::optional<ShaderSettings> shaders;
  std::vector<draw::DrawCall> calls;
  // The fixed-function state it is drawn with (enable, depth_func, cull_face, blend, ...; GL's
  // defaults: depth test, culling, scissor and blending off).
  RasterState raster = gl_initial_state();
  std::vector<UniformBufferSetting> uniform_buffers;
  std::vector<UniformBufferSetting> storage_buffers;  // glBindBufferRange(GL_SHADER_STORAGE_BUFFER, ...)
  // draws[].clear: glClear before the draw, within its scissor box and write masks.
  std::optional<glm::vec4> clear_color;
  std::optional<double> clear_depth;
  std::optional<TransformFeedbackSetting> transform_feedback;
};

// framebuffer: the attachments a scene of draws draws into (draw buffer k takes fragment output
// location k) and the images they hold before the first draw (none: every colour attachment holds
// the background, depth holds 1).
struct ColorAttachmentSetting {
  ColorFormat format = ColorFormat::kRgba32F;
  std::filesystem::path file;
};
struct FramebufferSetting {
  std::vector<ColorAttachmentSetting> color = {ColorAttachmentSetting{}};  // 1 to 8
  DepthFormat depth_format = DepthFormat::k32F;
  std::filesystem::path depth_file;
  bool has_images() const {
    for (const ColorAttachmentSetting& c : color)
      if (!c.file.empty()) return true;
    return !depth_file.empty();
  }
};

struct Scene {
  std::string source;  // the scene file, or "<default scene>": prefixes error messages
  MeshSettings mesh;
  Transform transform;
  Camera camera;
  std::vector<Light> lights;
  Material material;
  int width = 1024, height = 1024;
  glm::vec4 background{0.0f, 0.0f, 0.0f, 1.0f};
  Shading shading = Shading::Phong;
  bool cull_back_faces = true;
  PolygonMode polygon_mode = PolygonMode::kFill;  // the mesh's draw: glPolygonMode
  TessellationSettings tessellation;
  ShaderSettings shaders;
  // A scene with draws describes GL draws (README, "Draws"): they replace the mesh and the
  // built-in programs, and the `shaders` program draws them in order into one framebuffer.
  std::vector<BufferSetting> buffers;
  std::vector<DrawSetting> draws;
  FramebufferSetting framebuffer;
};

inline constexpr int kMaxLights = programs::kMaxLights;  // phong.frag's arrays
inline constexpr int kMaxImageSide = 16384;  // fixed::kMaxViewportPixels
inline constexpr long long kMaxImagePixels = 1ll << 26;  // 8192 x 8192: about 2.4 GB of buffers

}  // namespace tessref
