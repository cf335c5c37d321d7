#pragma once
// A headless OpenGL 4.5 core context through EGL: Mesa's surfaceless platform (llvmpipe) or an EGL
// device (the NVIDIA driver's EGL vendor library). GL entry points come from libepoxy.
#include <string>

namespace tessref::glref {

enum class EglPlatform { Auto, Surfaceless, Device };
const char* to_string(EglPlatform p);
bool parse(const std::string& s, EglPlatform& out);  // "auto" | "surfaceless" | "device"

struct GlContextOptions {
  // Auto tries surfaceless, then device. The environment variable TESSREF_EGL_PLATFORM
  // (auto|surfaceless|device) overrides Auto; an explicit choice here wins over the variable.
  EglPlatform platform = EglPlatform::Auto;
  // Device platform: which EGL device; -1 = the first that is not Mesa's software device
  // (falls back to device 0). TESSREF_EGL_DEVICE overrides -1.
  int device_index = -1;
  bool debug_context = false;
};

// Owns the EGL display and context and is current on the creating thread while it lives.
// Surfaceless contexts have no default framebuffer, so the context keeps a 1x1 FBO bound whenever
// nothing else is (bind_default_framebuffer()). Throws GlError naming the failing call.
class GlContext {
 public:
  explicit GlContext(const GlContextOptions& options = {});
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  void make_current();
  // Binds the context's own 1x1 FBO (draw and read): a valid target for rasterizer-discard work.
  void bind_default_framebuffer();

  EglPlatform platform() const { return platform_; }  // the one actually used
  const std::string& renderer() const { return renderer_; }  // GL_RENDERER
  const std::string& version() const { return version_; }    // GL_VERSION
  const std::string& vendor() const { return vendor_; }      // GL_VENDOR
  const std::string& egl_vendor() const { return egl_vendor_; }
  int max_tess_gen_level() const { return max_tess_gen_level_; }
  bool is_llvmpipe() const;

 private:
  void create(EglPlatform p, int device_index, bool debug);
  void destroy() noexcept;

  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
  unsigned fbo_ = 0, color_rb_ = 0;
  EglPlatform platform_ = EglPlatform::Auto;
  std::string renderer_, version_, vendor_, egl_vendor_;
  int max_tess_gen_level_ = 0;
};

}  // namespace tessref::glref
