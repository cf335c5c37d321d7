// Fuzzes GLSL through glslang and SPIRV-Tools (shader/glsl_compile.h) into the SPIR-V reader and
// the executor (shader/spirv_module.h, shader/executor.h): mutated programs from a seed corpus of
// valid vertex, tessellation and fragment shaders, each stage run on random inputs and uniforms.
//
// Input: GLSL text up to the first NUL byte, cut into stages by lines "--vert", "--tesc", "--tese"
// and "--frag" (text before the first such line is a vertex shader; tessellation stages need one
// to link), then the value bytes: lane counts, then words that fill every variable (inputs,
// uniforms, built-ins, shared patch data) and two small bound textures, cycled as needed. The
// instruction budget is small, so infinite loops end as runtime errors.
// Expected: a run, or CompileError (InputError), SpirvError (a construct the executor refuses) or
// ShaderRuntimeError (the budget). A finding: any other exception, a crash, UB or a hang.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "shader/executor.h"
#include "shader/glsl_compile.h"
#include "shader/spirv_module.h"
#include "texture/mipmap.h"

namespace {

using namespace tessref::shader;
namespace texture = tessref::texture;

// The value bytes as 32-bit words, cycled (zeros when there are none).
class Words {
 public:
  Words(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint32_t next() {
    std::uint32_t w = 0;
    for (int b = 0; b < 4 && size_ > 0; ++b) w |= std::uint32_t(data_[pos_++ % size_]) << (8 * b);
    return w;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_, pos_ = 0;
};

// The stages of the text, cut at the marker lines.
std::vector<ShaderSource> split_stages(const std::string& text) {
  static const std::pair<const char*, Stage> kMarkers[] = {
      {"--vert", Stage::Vertex}, {"--tesc", Stage::TessControl}, {"--tese", Stage::TessEval}, {"--frag", Stage::Fragment}};
  std::vector<ShaderSource> sources = {{Stage::Vertex, "fuzz.glsl", 1, ""}};
  int line_number = 1;
  for (std::size_t pos = 0; pos < text.size(); ++line_number) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(pos, end - pos);
    pos = end + 1;
    bool marker = false;
    for (const auto& [name, stage] : kMarkers)
      if (line == name) {
        sources.push_back({stage, "fuzz.glsl", line_number + 1, ""});
        marker = true;
      }
    if (!marker) sources.back().text += line + "\n";
  }
  if (sources.size() > 1 && sources.front().text.find_first_not_of(" \t\n") == std::string::npos)
    sources.erase(sources.begin());
  return sources;
}

void run(const std::vector<std::uint32_t>& spirv, Stage stage, Words& words) {
  ExecLimits limits;
  limits.max_instructions = 1 << 14;
  const Executable exe(read_module(spirv), limits);
  Invocations inv(exe);
  // A TCS runs whole patches: groups of output_vertices lanes; a fragment shader whole quads.
  const int n = std::clamp(exe.module().modes.output_vertices, 1, kMaxLanes);
  int lanes = 1 + int(words.next() % 64), groups = 1;
  if (stage == Stage::TessControl) {
    groups = std::max(1, std::min(1 + int(words.next() % 4), kMaxLanes / n));
    lanes = groups * n;
  } else if (stage == Stage::Fragment) {
    lanes = (lanes + 3) / 4 * 4;
  }
  inv.zero_shared(groups);
  inv.begin(lanes, groups);
  for (int l = 0; l < lanes; ++l) inv.set_group(l, l / n % groups);
  for (const Variable& v : exe.module().variables) {
    const VariableSlot* s = exe.slot(v.id);
    if (!s) continue;
    if (s->per_lane) {
      for (std::uint32_t w = 0; w < s->words; ++w)
        for (int l = 0; l < lanes; ++l) inv.row(*s, w)[l] = words.next();
    } else {
      for (int g = 0; g < (s->per_group ? groups : 1); ++g)
        for (std::uint32_t w = 0; w < s->words; ++w) inv.shared(*s, g)[w] = words.next();
    }
  }
  texture::Texture textures[2];
  for (texture::Texture& t : textures) {
    const std::uint32_t target = words.next();
    t.target = static_cast<texture::Target>(target % 9);
    // 1D targets and buffer textures are one row; arrays have 1 to 3 layers, 3D textures slices;
    // cube maps square faces, six per cube.
    const bool cube = texture::is_cube(t.target);
    const int width = 1 + int(words.next() % 3), rows = 1 + int(words.next() % 3);
    const int height = texture::dimensions(t.target) == 1 ? 1 : cube ? width : rows;
    const int layers = cube ? 6 * (t.target == texture::Target::kCubeArray ? 1 + int(target / 9 % 2) : 1)
                       : texture::is_array(t.target) || t.target == texture::Target::k3D ? 1 + int(target / 9 % 3)
                                                                                          : 1;
    std::vector<float> rgba;
    for (int i = 0; i < 4 * width * height * layers; ++i) rgba.push_back(float(words.next() % 256) / 255.0f);
    const std::uint32_t mode = words.next();
    t.format = static_cast<texture::TexelFormat>((mode >> 5) % 30);
    t.levels.push_back(texture::make_level(t.format, width, height, rgba.data(), layers));
    t.sampler.min_filter = static_cast<texture::Filter>((mode >> 9) % 6);
    t.sampler.mag_filter = static_cast<texture::Filter>(mode & 1);
    t.sampler.wrap_s = static_cast<texture::Wrap>((mode >> 1) % 5);
    t.sampler.wrap_t = static_cast<texture::Wrap>((mode >> 12) % 5);
    t.sampler.lod_bias = float(std::int32_t(words.next())) / 65536.0f;
    t.sampler.compare = (mode & 0x10000) != 0;
    t.sampler.compare_func = static_cast<texture::CompareFunc>((mode >> 17) % 8);
    if ((mode & 0x8000) && t.target != texture::Target::kBuffer) texture::generate_mipmaps(t);
    else t.finalize();
  }
  inv.bind_texture(0, &textures[0]);
  inv.bind_texture(1, &textures[1]);
  inv.set_cube_map_seamless((words.next() & 1) != 0);
  inv.run();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // FUZZ_GLSL_VERBOSE=1: say why an input ended early (to check that seeds compile and run).
  static const bool verbose = std::getenv("FUZZ_GLSL_VERBOSE") != nullptr;
  const std::uint8_t* nul = static_cast<const std::uint8_t*>(std::memchr(data, 0, size));
  const std::size_t text_size = nul ? std::size_t(nul - data) : size;
  const std::string text(reinterpret_cast<const char*>(data), text_size);
  Words words(data + std::min(size, text_size + 1), size - std::min(size, text_size + 1));
  try {
    const CompiledProgram program = compile_program(split_stages(text));
    for (const CompiledStage& s : program.stages) run(s.spirv, s.stage, words);
  } catch (const CompileError& e) {
    if (verbose) std::fprintf(stderr, "fuzz_glsl: compile error: %s\n", e.what());
  } catch (const SpirvError& e) {
    if (verbose) std::fprintf(stderr, "fuzz_glsl: refused: %s\n", e.what());
  } catch (const ShaderRuntimeError& e) {
    if (verbose) std::fprintf(stderr, "fuzz_glsl: runtime error: %s\n", e.what());
  }
  return 0;
}
