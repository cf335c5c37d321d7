#include "glref/gl_context.h"

#include <epoxy/gl.h>
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "glref/gl_error.h"

namespace tessref::glref {
namespace {

std::string hex(unsigned v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%x", v);
  return buf;
}

std::string egl_error_name(EGLint code) {
  switch (code) {
#define TESSREF_EGL_CASE(c) \
  case c: return std::string(#c " (") + hex(c) + ")";
    TESSREF_EGL_CASE(EGL_SUCCESS)
    TESSREF_EGL_CASE(EGL_NOT_INITIALIZED)
    TESSREF_EGL_CASE(EGL_BAD_ACCESS)
    TESSREF_EGL_CASE(EGL_BAD_ALLOC)
    TESSREF_EGL_CASE(EGL_BAD_ATTRIBUTE)
    TESSREF_EGL_CASE(EGL_BAD_CONFIG)
    TESSREF_EGL_CASE(EGL_BAD_CONTEXT)
    TESSREF_EGL_CASE(EGL_BAD_CURRENT_SURFACE)
    TESSREF_EGL_CASE(EGL_BAD_DISPLAY)
    TESSREF_EGL_CASE(EGL_BAD_MATCH)
    TESSREF_EGL_CASE(EGL_BAD_NATIVE_PIXMAP)
    TESSREF_EGL_CASE(EGL_BAD_NATIVE_WINDOW)
    TESSREF_EGL_CASE(EGL_BAD_PARAMETER)
    TESSREF_EGL_CASE(EGL_BAD_SURFACE)
    TESSREF_EGL_CASE(EGL_CONTEXT_LOST)
#undef TESSREF_EGL_CASE
  }
  return "EGL error " + hex(static_cast<unsigned>(code));
}

[[noreturn]] void egl_fail(const std::string& call) {
  throw GlError(call + " failed: " + egl_error_name(eglGetError()));
}

bool has_extension(const char* list, const char* name) {
  if (!list) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)); p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

template <typename Fn>
Fn egl_proc(const char* name) {
  auto fn = reinterpret_cast<Fn>(eglGetProcAddress(name));
  if (!fn) throw GlError(std::string("eglGetProcAddress(\"") + name + "\") returned null");
  return fn;
}

std::string gl_string(GLenum e) {
  const GLubyte* s = glGetString(e);
  return s ? reinterpret_cast<const char*>(s) : "";
}

EGLDisplay surfaceless_display(const char* client_ext) {
  if (!has_extension(client_ext, "EGL_MESA_platform_surfaceless"))
    throw GlError("EGL client extension EGL_MESA_platform_surfaceless is not available");
  auto get_display = egl_proc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  EGLDisplay d = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (d == EGL_NO_DISPLAY) egl_fail("eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA)");
  return d;
}

EGLDisplay device_display(const char* client_ext, int index) {
  if (!has_extension(client_ext, "EGL_EXT_platform_device") ||
      !has_extension(client_ext, "EGL_EXT_device_enumeration"))
    throw GlError("EGL client extensions EGL_EXT_platform_device / EGL_EXT_device_enumeration are not available");
  auto query_devices = egl_proc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  auto query_string = egl_proc<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
  auto get_display = egl_proc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  EGLint count = 0;
  if (!query_devices(0, nullptr, &count)) egl_fail("eglQueryDevicesEXT");
  if (count <= 0) throw GlError("eglQueryDevicesEXT found no EGL device");
  std::vector<EGLDeviceEXT> devices(count);
  if (!query_devices(count, devices.data(), &count)) egl_fail("eglQueryDevicesEXT");
  if (index >= count)
    throw GlError("EGL device " + std::to_string(index) + " requested, " + std::to_string(count) + " found");
  if (index < 0) {
    // Prefer a hardware device: Mesa lists its software device too.
    index = 0;
    for (EGLint i = 0; i < count; ++i)
      if (!has_extension(query_string(devices[i], EGL_EXTENSIONS), "EGL_MESA_device_software")) {
        index = i;
        break;
      }
  }
  EGLDisplay d = get_display(EGL_PLATFORM_DEVICE_EXT, devices[index], nullptr);
  if (d == EGL_NO_DISPLAY) egl_fail("eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device " + std::to_string(index) + ")");
  return d;
}

}  // namespace

const char* to_string(EglPlatform p) {
  switch (p) {
    case EglPlatform::Auto: return "auto";
    case EglPlatform::Surfaceless: return "surfaceless";
    case EglPlatform::Device: return "device";
  }
  return "?";
}

bool parse(const std::string& s, EglPlatform& out) {
  for (EglPlatform p : {EglPlatform::Auto, EglPlatform::Surfaceless, EglPlatform::Device})
    if (s == to_string(p)) return out = p, true;
  return false;
}

GlContext::GlContext(const GlContextOptions& options) {
  EglPlatform p = options.platform;
  if (p == EglPlatform::Auto)
    if (const char* env = std::getenv("TESSREF_EGL_PLATFORM"); env && *env && !parse(env, p))
      throw GlError(std::string("TESSREF_EGL_PLATFORM=") + env + ": expected auto, surfaceless or device");
  int device = options.device_index;
  if (device < 0)
    if (const char* env = std::getenv("TESSREF_EGL_DEVICE"); env && *env) device = std::atoi(env);

  if (p != EglPlatform::Auto) {
    try {
      create(p, device, options.debug_context);
    } catch (...) {
      destroy();  // the destructor does not run for a throwing constructor
      throw;
    }
    return;
  }
  try {
    create(EglPlatform::Surfaceless, device, options.debug_context);
  } catch (const GlError& first) {
    destroy();
    try {
      create(EglPlatform::Device, device, options.debug_context);
    } catch (const GlError& second) {
      destroy();
      throw GlError(std::string("no GL 4.5 context: surfaceless: ") + first.what() +
                    "; device: " + second.what());
    }
  }
}

GlContext::~GlContext() { destroy(); }

void GlContext::create(EglPlatform p, int device_index, bool debug) {
  platform_ = p;
  const char* client_ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!client_ext) egl_fail("eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS)");
  EGLDisplay dpy = p == EglPlatform::Device ? device_display(client_ext, device_index)
                                             : surfaceless_display(client_ext);
  EGLint major = 0, minor = 0;
  if (!eglInitialize(dpy, &major, &minor)) egl_fail(std::string("eglInitialize (") + to_string(p) + ")");
  display_ = dpy;
  if (const char* v = eglQueryString(dpy, EGL_VENDOR)) egl_vendor_ = v;
  const char* dpy_ext = eglQueryString(dpy, EGL_EXTENSIONS);
  if (!has_extension(dpy_ext, "EGL_KHR_surfaceless_context"))
    throw GlError("EGL display lacks EGL_KHR_surfaceless_context (vendor " + egl_vendor_ + ")");
  if (!eglBindAPI(EGL_OPENGL_API)) egl_fail("eglBindAPI(EGL_OPENGL_API)");

  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!has_extension(dpy_ext, "EGL_KHR_no_config_context")) {
    const EGLint attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0, EGL_NONE};
    EGLint n = 0;
    if (!eglChooseConfig(dpy, attribs, &config, 1, &n)) egl_fail("eglChooseConfig");
    if (n < 1) throw GlError("eglChooseConfig found no config with EGL_OPENGL_BIT");
  }
  // The debug attribute only when asked for: it is EGL 1.5, other attributes also exist in
  // EGL_KHR_create_context.
  std::vector<EGLint> ctx_attribs = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT};
  if (debug) ctx_attribs.insert(ctx_attribs.end(), {EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE});
  ctx_attribs.push_back(EGL_NONE);
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, ctx_attribs.data());
  if (ctx == EGL_NO_CONTEXT) egl_fail("eglCreateContext(OpenGL 4.5 core)");
  context_ = ctx;
  make_current();

  renderer_ = gl_string(GL_RENDERER);
  version_ = gl_string(GL_VERSION);
  vendor_ = gl_string(GL_VENDOR);
  GLint gl_major = 0, gl_minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &gl_major);
  glGetIntegerv(GL_MINOR_VERSION, &gl_minor);
  if (gl_major * 10 + gl_minor < 45)
    throw GlError("context is OpenGL " + version_ + ", 4.5 core is required (" + renderer_ + ")");
  glGetIntegerv(GL_MAX_TESS_GEN_LEVEL, &max_tess_gen_level_);

  // Surfaceless: no default framebuffer, and draws fail with GL_INVALID_FRAMEBUFFER_OPERATION
  // even under GL_RASTERIZER_DISCARD unless an FBO is bound.
  glGenFramebuffers(1, &fbo_);
  glGenRenderbuffers(1, &color_rb_);
  glBindRenderbuffer(GL_RENDERBUFFER, color_rb_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 1, 1);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_rb_);
  if (GLenum s = glCheckFramebufferStatus(GL_FRAMEBUFFER); s != GL_FRAMEBUFFER_COMPLETE)
    throw GlError("default 1x1 FBO incomplete: status " + hex(s));
  check_gl("creating the default FBO");
}

void GlContext::destroy() noexcept {
  if (!display_) return;
  auto dpy = static_cast<EGLDisplay>(display_);
  if (context_) {
    if (eglGetCurrentContext() == static_cast<EGLContext>(context_)) {
      if (fbo_) glDeleteFramebuffers(1, &fbo_);
      if (color_rb_) glDeleteRenderbuffers(1, &color_rb_);
    }
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(dpy, static_cast<EGLContext>(context_));
  }
  // No eglTerminate: EGL hands every caller the same display for a platform, so terminating it
  // would pull the rug from other contexts in the process.
  fbo_ = color_rb_ = 0;
  context_ = nullptr;
  display_ = nullptr;
}

void GlContext::make_current() {
  if (!eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE,
                      static_cast<EGLContext>(context_)))
    egl_fail("eglMakeCurrent(surfaceless)");
}

void GlContext::bind_default_framebuffer() { glBindFramebuffer(GL_FRAMEBUFFER, fbo_); }

bool GlContext::is_llvmpipe() const { return renderer_.find("llvmpipe") != std::string::npos; }

std::string gl_error_name(unsigned code) {
  const char* name = nullptr;
  switch (code) {
    case GL_INVALID_ENUM: name = "GL_INVALID_ENUM"; break;
    case GL_INVALID_VALUE: name = "GL_INVALID_VALUE"; break;
    case GL_INVALID_OPERATION: name = "GL_INVALID_OPERATION"; break;
    case GL_INVALID_FRAMEBUFFER_OPERATION: name = "GL_INVALID_FRAMEBUFFER_OPERATION"; break;
    case GL_OUT_OF_MEMORY: name = "GL_OUT_OF_MEMORY"; break;
    case GL_STACK_OVERFLOW: name = "GL_STACK_OVERFLOW"; break;
    case GL_STACK_UNDERFLOW: name = "GL_STACK_UNDERFLOW"; break;
    default: name = "GL error"; break;
  }
  return std::string(name) + " (" + hex(code) + ")";
}

void check_gl(const char* what) {
  std::string errors;
  // Bounded: a lost context may report errors forever.
  for (int i = 0; i < 16; ++i) {
    GLenum e = glGetError();
    if (e == GL_NO_ERROR) break;
    if (!errors.empty()) errors += ", ";
    errors += gl_error_name(e);
  }
  if (!errors.empty()) throw GlError(std::string(what) + ": " + errors);
}

}  // namespace tessref::glref
