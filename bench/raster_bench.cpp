// The rasterizer alone: one fixed, seeded soup of clip-space triangles drawn into a 1024x1024
// RGBA32F color + 32-bit depth target (depth test LESS, no culling, a constant-color fragment
// shader), tessref's draw_triangles against Mesa llvmpipe, in the same process.
//
// The soup: 1,000,000 small triangles (edges 0.3 to 6 pixels, log-uniform: the sizes a tessellated
// mesh hands the rasterizer) with 200 large ones (edges 32 to 256 pixels, some crossing the
// viewport sides, so clipped) spread among them; random positions, depths and w (0.5 to 2, so the
// perspective divide matters). About 3.3 M fragments pass the depth test.
//   tessref:  Framebuffer::clear, then draw_triangles on consecutive batches of 65,536 triangles
//             (as the pipeline batches them; "several calls behave as one draw"), all threads.
//   llvmpipe: glClear, one glDrawArrays(GL_TRIANGLES) of a static VBO of the same vec4 positions
//             through a pass-through vertex shader, and a GL_SAMPLES_PASSED query that waits for
//             the draw; the count is checked against tessref's fragments (same coverage rules).
// The closing table gives Mtriangles/s of both and the ratio tessref / llvmpipe.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "bench_common.h"
#include "common/parallel.h"
#include "raster/framebuffer.h"
#include "raster/rasterizer.h"
#include "raster/vertex.h"
#ifdef TESSREF_HAVE_GLREF
#include <epoxy/gl.h>

#include "glref/gl_context.h"
#include "glref/gl_error.h"
#include "glref/gl_program.h"
#include "glref/render_target.h"
#endif

namespace {

using namespace tessref;

constexpr int kSide = 1024;
constexpr std::size_t kSmall = 1000000;
constexpr std::size_t kLargeEvery = 5000;  // one large triangle after every 5,000 small ones
constexpr std::size_t kBatchTriangles = 65536;
const glm::vec4 kBackground(0.1f, 0.1f, 0.1f, 1.0f);
const glm::vec4 kColor(1.0f, 0.5f, 0.25f, 1.0f);

// splitmix64: the soup is the same on every machine and library (no <random> distributions).
struct Rng {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  float uniform() { return float(next() >> 40) * (1.0f / 16777216.0f); }  // [0, 1)
  float in(float lo, float hi) { return lo + (hi - lo) * uniform(); }
};

// Three clip-space vertices of a roughly equilateral triangle with edges near `edge_px` pixels,
// counter-clockwise, at a random place, depth and w.
void add_triangle(Rng& rng, float edge_px, std::vector<glm::vec4>& out) {
  const float px = 2.0f / kSide;  // one pixel in NDC
  const glm::vec2 center(rng.in(-1.0f, 1.0f), rng.in(-1.0f, 1.0f));
  const float z = rng.in(-0.95f, 0.95f);
  const float w = rng.in(0.5f, 2.0f);
  const float radius = edge_px / std::sqrt(3.0f) * px;
  const float theta = rng.in(0.0f, 6.2831853f);
  for (int k = 0; k < 3; ++k) {
    const float a = theta + float(k) * 2.0943951f + rng.in(-0.3f, 0.3f);
    const float r = radius * rng.in(0.7f, 1.3f);
    const glm::vec3 ndc(center.x + r * std::cos(a), center.y + r * std::sin(a),
                        z + rng.in(-0.01f, 0.01f));
    const float wk = w * rng.in(0.95f, 1.05f);
    out.emplace_back(ndc * wk, wk);
  }
}

const std::vector<glm::vec4>& soup() {
  static const std::vector<glm::vec4> s = [] {
    Rng rng{20240607};
    std::vector<glm::vec4> v;
    v.reserve(3 * (kSmall + kSmall / kLargeEvery));
    for (std::size_t i = 0; i < kSmall; ++i) {
      add_triangle(rng, 0.3f * std::pow(20.0f, rng.uniform()), v);
      if ((i + 1) % kLargeEvery == 0) add_triangle(rng, 32.0f * std::pow(8.0f, rng.uniform()), v);
    }
    return v;
  }();
  return s;
}
std::size_t soup_triangles() { return soup().size() / 3; }

struct ConstantColor : FragmentProgram {
  FragmentOutput shade(const FragmentInput&) const override {
    FragmentOutput o;
    o.color = kColor;
    return o;
  }
};

const Parallel& parallel() {
  static const Parallel p;  // all hardware threads
  return p;
}

const std::vector<TriangleBatch>& batches() {
  static const std::vector<TriangleBatch> b = [] {
    std::vector<TriangleBatch> out;
    const std::vector<glm::vec4>& s = soup();
    for (std::size_t first = 0; first < s.size(); first += 3 * kBatchTriangles) {
      const std::size_t last = std::min(s.size(), first + 3 * kBatchTriangles);
      TriangleBatch batch;
      batch.num_varyings = 0;
      batch.vertices.resize(last - first);
      for (std::size_t i = first; i < last; ++i) batch.vertices[i - first].position = s[i];
      out.push_back(std::move(batch));
    }
    return out;
  }();
  return b;
}

RasterStats tessref_draw(Framebuffer& fb) {
  static const ConstantColor fs;
  fb.clear(kBackground);
  RasterStats stats;
  for (const TriangleBatch& b : batches()) stats += draw_triangles(b, RasterState{}, fs, fb, parallel());
  return stats;
}

// tessref's count of fragments that pass the depth test, for checking llvmpipe's.
std::uint64_t reference_fragments() {
  static const std::uint64_t n = [] {
    Framebuffer fb(kSide, kSide);
    return tessref_draw(fb).fragments_shaded;
  }();
  return n;
}

void set_soup_counters(benchmark::State& state, std::uint64_t fragments) {
  const double triangles = double(soup_triangles()) * double(state.iterations());
  state.counters["triangles_per_s"] = benchmark::Counter(triangles, benchmark::Counter::kIsRate);
  state.counters["fragments_per_s"] =
      benchmark::Counter(double(fragments) * double(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["fragments"] = double(fragments);
  bench::set_work_counters(state, bench::work::raster(soup_triangles(), fragments,
                                                       std::uint64_t(kSide) * kSide));
}

void BM_TessrefRaster(benchmark::State& state) {
  batches();
  Framebuffer fb(kSide, kSide);
  RasterStats stats;
  for (auto _ : state) {
    stats = tessref_draw(fb);
    benchmark::DoNotOptimize(fb.color.data());
  }
  set_soup_counters(state, stats.fragments_shaded);
  state.counters["threads"] = parallel().threads();
  state.SetLabel(std::to_string(stats.triangles_rasterized) + " rasterized");
}
BENCHMARK(BM_TessrefRaster)->Unit(benchmark::kMillisecond)->UseRealTime();

#ifdef TESSREF_HAVE_GLREF

const char* kSoupVertexShader = R"(#version 450 core
layout(location = 0) in vec4 position;
void main() { gl_Position = position; }
)";
const char* kSoupFragmentShader = R"(#version 450 core
layout(location = 0) out vec4 color;
uniform vec4 u_color;
void main() { color = u_color; }
)";

// The same soup through the driver: a static VBO, drawn by one glDrawArrays.
struct GlSoup {
  glref::GlContext& ctx;
  glref::RenderTarget target;
  glref::Program program;
  GLuint vao = 0, vbo = 0, query = 0;

  explicit GlSoup(glref::GlContext& c)
      : ctx(c),
        target(c, {kSide, kSide, {ColorFormat::kRgba32F}, true}),
        program(glref::link_program({{GL_VERTEX_SHADER, kSoupVertexShader, "soup.vert"},
                                     {GL_FRAGMENT_SHADER, kSoupFragmentShader, "soup.frag"}})) {
    const std::vector<glm::vec4>& s = soup();
    glGenVertexArrays(1, &vao);
    glGenBuffers(1, &vbo);
    glGenQueries(1, &query);
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(s.size() * sizeof(glm::vec4)), s.data(), GL_STATIC_DRAW);
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, sizeof(glm::vec4), nullptr);
    glEnableVertexAttribArray(0);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    program.use();
    glUniform4f(program.uniform("u_color"), kColor.r, kColor.g, kColor.b, kColor.a);
    glUseProgram(0);
    glref::check_gl("raster_bench: uploading the soup");
  }
  ~GlSoup() {
    ctx.make_current();
    glDeleteQueries(1, &query);
    glDeleteBuffers(1, &vbo);
    glDeleteVertexArrays(1, &vao);
  }

  // One frame: clear, draw, wait; returns the fragments that passed the depth test.
  std::uint64_t draw() {
    target.clear(kBackground, 1.0f);  // binds the target, viewport = whole target
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glDepthRangef(0.0f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    program.use();
    glBindVertexArray(vao);
    glBeginQuery(GL_SAMPLES_PASSED, query);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(soup().size()));
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint64 passed = 0;
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &passed);  // waits for the draw
    glBindVertexArray(0);
    glUseProgram(0);
    glDisable(GL_DEPTH_TEST);
    return passed;
  }
};

void BM_LlvmpipeRaster(benchmark::State& state) {
  glref::GlContext* ctx = bench::gl_context();
  if (!ctx) return state.SkipWithError("no GL context");
  const std::uint64_t expected = reference_fragments();
  GlSoup gl(*ctx);
  std::uint64_t passed = 0;
  for (auto _ : state) {
    passed = gl.draw();
    benchmark::DoNotOptimize(passed);
  }
  glref::check_gl("raster_bench: drawing the soup");
  set_soup_counters(state, expected);
  state.counters["samples_passed"] = double(passed);
  const long long diff = (long long)passed - (long long)expected;
  state.SetLabel(ctx->renderer() + (diff == 0 ? std::string(", samples passed = tessref's fragments")
                                              : ", samples passed - tessref's fragments = " +
                                                    std::to_string(diff)));
}
BENCHMARK(BM_LlvmpipeRaster)->Unit(benchmark::kMillisecond)->UseRealTime();
#endif

class RatioReporter : public bench::RateReporter {
 public:
  RatioReporter() : RateReporter("triangles_per_s") {}
  void print_ratios() const {
    std::printf("\ntriangle soup: %zu triangles, %dx%d, RGBA32F + depth, constant color\n",
                soup_triangles(), kSide, kSide);
    const double t = rate("BM_TessrefRaster/real_time");
    const double l = rate("BM_LlvmpipeRaster/real_time");
    if (t == 0.0) return;
    std::printf("tessref Mtriangles/s  llvmpipe Mtriangles/s  tessref/llvmpipe\n");
    if (l == 0.0) std::printf("%20.2f  %21s  %16s\n", t / 1e6, "n/a", "n/a");
    else std::printf("%20.2f  %21.2f  %15.2fx\n", t / 1e6, l / 1e6, t / l);
  }
};

}  // namespace

int main(int argc, char** argv) { return tessref::bench::run_benchmarks<RatioReporter>(argc, argv); }
