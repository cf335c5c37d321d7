/* A small GL 4.5 core application, as a user's would be, for the capture-replay tests: it draws one
 * frame into a framebuffer object over EGL surfaceless, then writes what glReadPixels gives to a
 * binary PPM (top row first).
 *
 *   replay_app [--untessellated | --gles | --label NAME | --compute | --two-frames | --indirect | --geometry] OUT.ppm
 *
 * The frame, in order:
 *   1. glClear of colour and depth;
 *   2. an untessellated ground plane: glDrawArrays(GL_TRIANGLE_STRIP, 0, 4), default-block uniforms;
 *   3. instanced, indexed 3-vertex patches: glDrawElementsInstancedBaseVertex with a non-zero index
 *      offset and base vertex, interleaved float / normalized short / normalized unsigned byte
 *      attributes, a per-instance offset written through glMapBufferRange, a std140 block bound by
 *      glBindBufferRange at offset 256, and a mip-mapped texture (glGenerateMipmap) on unit 1;
 *   4. one 16-vertex bicubic patch: glDrawArrays(GL_PATCHES, 0, 16).
 *
 * --untessellated draws the plane alone; --gles makes an OpenGL ES 3.2 context and only clears;
 * --label names the gem program's vertex shader object with glObjectLabel (the importer's file
 * names come from labels, so a hostile one must be refused); --compute has a compute shader write
 * the per-instance offsets (the same values, the same image): a trace holds the dispatch, not
 * what it wrote, while a RenderDoc capture holds the buffer's bytes. --two-frames ends a frame
 * (eglSwapBuffers on a pbuffer) after the clear and the plane, and captures with RenderDoc only
 * what follows: the last frame then starts from what the earlier one left, colour and depth.
 * --indirect issues the gem draw as glDrawElementsIndirect (its command in a GL_DRAW_INDIRECT_BUFFER)
 * and the bicubic patch as glMultiDrawArrays of two commands (the second draws it again, hidden by
 * the depth test): the same image. --geometry draws the bicubic patch through a geometry shader that
 * gives each tessellated triangle the mean of its corners' normals (a faceted patch).
 *
 * Under RenderDoc (renderdoccmd capture) the frame is bracketed by the in-app API's
 * StartFrameCapture / EndFrameCapture, the only way RenderDoc captures an application without a
 * window. Under apitrace nothing changes. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <epoxy/egl.h>
#include <epoxy/gl.h>
#if __has_include(<renderdoc_app.h>)
#include <renderdoc_app.h>
#define HAVE_RENDERDOC_APP 1
#endif
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { kSize = 256 };

static void fail(const char* what) {
  fprintf(stderr, "replay_app: %s\n", what);
  exit(1);
}

static GLuint compile(GLenum stage, const char* source) {
  GLuint s = glCreateShader(stage);
  glShaderSource(s, 1, &source, NULL);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetShaderInfoLog(s, sizeof log, NULL, log);
    fprintf(stderr, "%s\n", log);
    fail("a shader did not compile");
  }
  return s;
}

static GLuint link_with(const char* vs, const char* tcs, const char* tes, const char* gs, const char* fs) {
  GLuint p = glCreateProgram();
  glAttachShader(p, compile(GL_VERTEX_SHADER, vs));
  if (tcs) glAttachShader(p, compile(GL_TESS_CONTROL_SHADER, tcs));
  if (tes) glAttachShader(p, compile(GL_TESS_EVALUATION_SHADER, tes));
  if (gs) glAttachShader(p, compile(GL_GEOMETRY_SHADER, gs));
  glAttachShader(p, compile(GL_FRAGMENT_SHADER, fs));
  glLinkProgram(p);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) fail("a program did not link");
  return p;
}

static GLuint link(const char* vs, const char* tcs, const char* tes, const char* fs) {
  return link_with(vs, tcs, tes, NULL, fs);
}

/* ---- shaders ---- */
static const char* kPlaneVs =
    "#version 450 core\n"
    "layout(location = 0) in vec3 in_position;\n"
    "uniform mat4 u_mvp;\n"
    "out vec3 v_world;\n"
    "void main() {\n"
    "  v_world = in_position;\n"
    "  gl_Position = u_mvp * vec4(in_position, 1.0);\n"
    "}\n";
static const char* kPlaneFs =
    "#version 450 core\n"
    "in vec3 v_world;\n"
    "uniform vec4 u_tint;\n"
    "layout(location = 0) out vec4 frag;\n"
    "void main() {\n"
    "  float stripe = step(0.5, fract(v_world.x * 2.0));\n"
    "  frag = u_tint * (0.75 + 0.25 * stripe);\n"
    "}\n";

static const char* kGemVs =
    "#version 450 core\n"
    "layout(location = 0) in vec3 in_position;\n"
    "layout(location = 1) in vec3 in_normal;\n"
    "layout(location = 2) in vec4 in_color;\n"
    "layout(location = 3) in vec3 in_offset;\n"
    "out vec3 c_position;\n"
    "out vec3 c_normal;\n"
    "out vec4 c_color;\n"
    "void main() {\n"
    "  c_position = in_position * 0.45 + in_offset;\n"
    "  c_normal = normalize(in_normal);\n"
    "  c_color = in_color;\n"
    "}\n";
static const char* kGemTcs =
    "#version 450 core\n"
    "layout(vertices = 3) out;\n"
    "in vec3 c_position[];\n"
    "in vec3 c_normal[];\n"
    "in vec4 c_color[];\n"
    "out vec3 e_position[];\n"
    "out vec3 e_normal[];\n"
    "out vec4 e_color[];\n"
    "uniform float u_level;\n"
    "void main() {\n"
    "  e_position[gl_InvocationID] = c_position[gl_InvocationID];\n"
    "  e_normal[gl_InvocationID] = c_normal[gl_InvocationID];\n"
    "  e_color[gl_InvocationID] = c_color[gl_InvocationID];\n"
    "  if (gl_InvocationID == 0) {\n"
    "    gl_TessLevelOuter[0] = u_level;\n"
    "    gl_TessLevelOuter[1] = u_level + 1.0;\n"
    "    gl_TessLevelOuter[2] = u_level;\n"
    "    gl_TessLevelInner[0] = u_level;\n"
    "  }\n"
    "}\n";
static const char* kGemTes =
    "#version 450 core\n"
    "layout(triangles, fractional_odd_spacing, ccw) in;\n"
    "in vec3 e_position[];\n"
    "in vec3 e_normal[];\n"
    "in vec4 e_color[];\n"
    "layout(std140, binding = 1) uniform Shading {\n"
    "  mat4 view_proj;\n"
    "  vec4 light_dir;\n"
    "  float bulge;\n"
    "  float uv_scale[2];\n"
    "};\n"
    "out vec3 f_normal;\n"
    "out vec4 f_color;\n"
    "out vec2 f_uv;\n"
    "void main() {\n"
    "  vec3 b = gl_TessCoord;\n"
    "  vec3 n = normalize(b.x * e_normal[0] + b.y * e_normal[1] + b.z * e_normal[2]);\n"
    "  vec3 p = b.x * e_position[0] + b.y * e_position[1] + b.z * e_position[2];\n"
    "  p += n * (bulge * b.x * b.y * b.z);\n"
    "  f_normal = n;\n"
    "  f_color = b.x * e_color[0] + b.y * e_color[1] + b.z * e_color[2];\n"
    "  f_uv = vec2(p.x * uv_scale[0], p.y * uv_scale[1]);\n"
    "  gl_Position = view_proj * vec4(p, 1.0);\n"
    "}\n";
static const char* kGemFs =
    "#version 450 core\n"
    "in vec3 f_normal;\n"
    "in vec4 f_color;\n"
    "in vec2 f_uv;\n"
    "layout(std140, binding = 1) uniform Shading {\n"
    "  mat4 view_proj;\n"
    "  vec4 light_dir;\n"
    "  float bulge;\n"
    "  float uv_scale[2];\n"
    "};\n"
    "uniform sampler2D u_albedo;\n"
    "layout(location = 0) out vec4 frag;\n"
    "void main() {\n"
    "  float diffuse = max(dot(normalize(f_normal), light_dir.xyz), 0.0);\n"
    "  vec4 t = texture(u_albedo, f_uv);\n"
    "  frag = vec4(f_color.rgb * t.rgb * (0.3 + 0.7 * diffuse), 1.0);\n"
    "}\n";

static const char* kOffsetsCs =
    "#version 450 core\n"
    "layout(local_size_x = 9) in;\n"
    "layout(std430, binding = 0) buffer Offsets { float offsets[]; };\n"
    "const float k[9] = float[9](-0.85, 0.1, 0.2, 0.0, 0.25, 0.0, 0.85, 0.1, -0.2);\n"
    "void main() { offsets[gl_LocalInvocationIndex] = k[gl_LocalInvocationIndex]; }\n";

static const char* kBicubicVs =
    "#version 450 core\n"
    "layout(location = 0) in vec3 in_position;\n"
    "void main() { gl_Position = vec4(in_position, 1.0); }\n";
static const char* kBicubicTcs =
    "#version 450 core\n"
    "layout(vertices = 16) out;\n"
    "uniform float u_level;\n"
    "void main() {\n"
    "  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;\n"
    "  if (gl_InvocationID == 0) {\n"
    "    gl_TessLevelOuter[0] = u_level;\n"
    "    gl_TessLevelOuter[1] = u_level;\n"
    "    gl_TessLevelOuter[2] = u_level;\n"
    "    gl_TessLevelOuter[3] = u_level;\n"
    "    gl_TessLevelInner[0] = u_level;\n"
    "    gl_TessLevelInner[1] = u_level;\n"
    "  }\n"
    "}\n";
static const char* kBicubicTes =
    "#version 450 core\n"
    "layout(quads, equal_spacing, ccw) in;\n"
    "uniform mat4 u_mvp;\n"
    "out vec3 f_normal;\n"
    "vec4 bernstein(float t) {\n"
    "  float s = 1.0 - t;\n"
    "  return vec4(s * s * s, 3.0 * s * s * t, 3.0 * s * t * t, t * t * t);\n"
    "}\n"
    "vec4 bernstein_d(float t) {\n"
    "  float s = 1.0 - t;\n"
    "  return vec4(-3.0 * s * s, 3.0 * s * s - 6.0 * s * t, 6.0 * s * t - 3.0 * t * t, 3.0 * t * t);\n"
    "}\n"
    "void main() {\n"
    "  vec4 bu = bernstein(gl_TessCoord.x), bv = bernstein(gl_TessCoord.y);\n"
    "  vec4 du = bernstein_d(gl_TessCoord.x), dv = bernstein_d(gl_TessCoord.y);\n"
    "  vec3 p = vec3(0.0), pu = vec3(0.0), pv = vec3(0.0);\n"
    "  for (int j = 0; j < 4; ++j)\n"
    "    for (int i = 0; i < 4; ++i) {\n"
    "      vec3 c = gl_in[j * 4 + i].gl_Position.xyz;\n"
    "      p += bu[i] * bv[j] * c;\n"
    "      pu += du[i] * bv[j] * c;\n"
    "      pv += bu[i] * dv[j] * c;\n"
    "    }\n"
    "  f_normal = normalize(cross(pu, pv));\n"
    "  gl_Position = u_mvp * vec4(p, 1.0);\n"
    "}\n";
static const char* kBicubicGs =
    "#version 450 core\n"
    "layout(triangles) in;\n"
    "layout(triangle_strip, max_vertices = 3) out;\n"
    "in vec3 f_normal[];\n"
    "out vec3 g_normal;\n"
    "void main() {\n"
    "  vec3 n = f_normal[0] + f_normal[1] + f_normal[2];\n"
    "  for (int i = 0; i < 3; ++i) {\n"
    "    gl_Position = gl_in[i].gl_Position;\n"
    "    g_normal = n;\n"
    "    EmitVertex();\n"
    "  }\n"
    "}\n";
static const char* kBicubicGsFs =
    "#version 450 core\n"
    "in vec3 g_normal;\n"
    "layout(location = 0) out vec4 frag;\n"
    "void main() { frag = vec4(normalize(g_normal) * 0.5 + 0.5, 1.0); }\n";
static const char* kBicubicFs =
    "#version 450 core\n"
    "in vec3 f_normal;\n"
    "layout(location = 0) out vec4 frag;\n"
    "void main() { frag = vec4(normalize(f_normal) * 0.5 + 0.5, 1.0); }\n";

/* ---- data ---- */
/* A column-major view-projection: a slight tilt and a perspective divide by (z + 3). */
static const float kMvp[16] = {0.9f, 0.0f, 0.0f,  0.0f, 0.0f, 0.85f, 0.25f, 0.25f,
                               0.0f, 0.3f, -0.5f, 1.0f, 0.0f, -0.1f, 1.5f,  2.5f};

struct GemVertex { /* 24 bytes, interleaved */
  float position[3];
  int16_t normal[3];
  uint8_t color[4];
  uint8_t pad[2];
};

/* A vertex array with one float3 position array at location 0, of its own buffer. The stride is
 * given either way (12 or 0: both tightly packed), as applications do. */
static GLuint position_array(const float* data, GLsizeiptr bytes, GLsizei stride) {
  GLuint vao, vbo;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, bytes, data, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, (void*)0);
  glEnableVertexAttribArray(0);
  return vao;
}

static void write_ppm(const char* path, const uint8_t* rgba) {
  FILE* f = fopen(path, "wb");
  if (!f) fail("cannot open the output image");
  fprintf(f, "P6\n%d %d\n255\n", kSize, kSize);
  for (int y = kSize - 1; y >= 0; --y)
    for (int x = 0; x < kSize; ++x) fwrite(rgba + (y * kSize + x) * 4, 1, 3, f);
  if (fclose(f) != 0) fail("cannot write the output image");
}

#ifdef HAVE_RENDERDOC_APP
static RENDERDOC_API_1_1_2* renderdoc(void) {
  void* lib = dlopen("librenderdoc.so", RTLD_NOW | RTLD_NOLOAD);
  if (!lib) return NULL;
  pRENDERDOC_GetAPI get = (pRENDERDOC_GetAPI)dlsym(lib, "RENDERDOC_GetAPI");
  RENDERDOC_API_1_1_2* api = NULL;
  if (!get || !get(eRENDERDOC_API_Version_1_1_2, (void**)&api)) return NULL;
  return api;
}
#endif

/* --gles: an OpenGL ES 3.2 context that clears and reads back, nothing more. */
static int gles_frame(EGLDisplay display, const char* out) {
  const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_SURFACE_TYPE, 0, EGL_NONE};
  EGLConfig config;
  EGLint configs = 0;
  if (!eglChooseConfig(display, config_attribs, &config, 1, &configs) || configs < 1) fail("no EGL ES config");
  if (!eglBindAPI(EGL_OPENGL_ES_API)) fail("eglBindAPI(EGL_OPENGL_ES_API) failed");
  const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 2, EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attribs);
  if (context == EGL_NO_CONTEXT || !eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
    fail("no OpenGL ES 3.2 context");
  GLuint color, fbo;
  glGenRenderbuffers(1, &color);
  glBindRenderbuffer(GL_RENDERBUFFER, color);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, kSize, kSize);
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
  glClearColor(0.2f, 0.4f, 0.6f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  static uint8_t pixels[kSize * kSize * 4];
  glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  write_ppm(out, pixels);
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display, context);
  eglTerminate(display);
  return 0;
}

int main(int argc, char** argv) {
  int untessellated = 0, gles = 0, compute = 0, two_frames = 0, indirect = 0, geometry = 0;
  const char* label = NULL;
  int arg = 1;
  for (; arg < argc - 1; ++arg) {
    if (strcmp(argv[arg], "--untessellated") == 0) untessellated = 1;
    else if (strcmp(argv[arg], "--gles") == 0) gles = 1;
    else if (strcmp(argv[arg], "--compute") == 0) compute = 1;
    else if (strcmp(argv[arg], "--two-frames") == 0) two_frames = 1;
    else if (strcmp(argv[arg], "--indirect") == 0) indirect = 1;
    else if (strcmp(argv[arg], "--geometry") == 0) geometry = 1;
    else if (strcmp(argv[arg], "--label") == 0 && arg + 1 < argc - 1) label = argv[++arg];
    else break;
  }
  if (arg != argc - 1) {
    fprintf(stderr, "usage: replay_app [--untessellated | --gles | --label NAME | --compute | --two-frames | --indirect | --geometry] "
                    "OUT.ppm\n");
    return 2;
  }
  const char* out = argv[arg];
  EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, NULL, NULL)) fail("no EGL surfaceless display");
  if (gles) return gles_frame(display, out);
  /* --two-frames: a pbuffer, for eglSwapBuffers to end a frame (the drawing goes to the FBO). */
  const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE,
                                   two_frames ? EGL_PBUFFER_BIT : 0, EGL_NONE};
  EGLConfig config;
  EGLint configs = 0;
  if (!eglChooseConfig(display, config_attribs, &config, 1, &configs) || configs < 1) fail("no EGL config");
  if (!eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API) failed");
  const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                    EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attribs);
  EGLSurface surface = EGL_NO_SURFACE;
  if (two_frames) {
    const EGLint pbuffer_attribs[] = {EGL_WIDTH, 16, EGL_HEIGHT, 16, EGL_NONE};
    surface = eglCreatePbufferSurface(display, config, pbuffer_attribs);
    if (surface == EGL_NO_SURFACE) fail("no pbuffer");
  }
  if (context == EGL_NO_CONTEXT || !eglMakeCurrent(display, surface, surface, context)) fail("no GL 4.5 core context");
#ifdef HAVE_RENDERDOC_APP
  RENDERDOC_API_1_1_2* rdoc = renderdoc();
#endif

  /* The framebuffer: RGBA8 colour and 24-bit depth. */
  GLuint color, depth, fbo;
  glGenTextures(1, &color);
  glBindTexture(GL_TEXTURE_2D, color);
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, kSize, kSize);
  glGenRenderbuffers(1, &depth);
  glBindRenderbuffer(GL_RENDERBUFFER, depth);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, kSize, kSize);
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) fail("incomplete framebuffer");

  const GLuint plane_program = link(kPlaneVs, NULL, NULL, kPlaneFs);
  const GLuint gem_program = link(kGemVs, kGemTcs, kGemTes, kGemFs);
  if (label) {
    GLuint shaders[4];
    GLsizei count = 0;
    glGetAttachedShaders(gem_program, 4, &count, shaders);
    for (GLsizei i = 0; i < count; ++i) {
      GLint type = 0;
      glGetShaderiv(shaders[i], GL_SHADER_TYPE, &type);
      if (type == GL_VERTEX_SHADER) glObjectLabel(GL_SHADER, shaders[i], -1, label);
    }
  }
  const GLuint bicubic_program = geometry ? link_with(kBicubicVs, kBicubicTcs, kBicubicTes, kBicubicGs, kBicubicGsFs)
                                          : link(kBicubicVs, kBicubicTcs, kBicubicTes, kBicubicFs);

  /* Ground plane. */
  const float plane[] = {-1.6f, -1.0f, -1.2f, 1.6f, -1.0f, -1.2f, -1.6f, 1.0f, 1.4f, 1.6f, 1.0f, 1.4f};
  const GLuint plane_vao = position_array(plane, sizeof plane, 12);

  /* Gems: an octahedron's 8 faces as 3-vertex patches, behind 3 unused vertices (base vertex 3)
   * and 5 unused indices (index offset 10 bytes), drawn 3 times at per-instance offsets. */
  struct GemVertex vertices[9];
  memset(vertices, 0, sizeof vertices);
  const float corners[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int i = 0; i < 9; ++i) {
    const float* c = corners[i < 3 ? 0 : i - 3];
    for (int k = 0; k < 3; ++k) {
      vertices[i].position[k] = c[k] * (k == 1 ? 1.2f : 1.0f);
      vertices[i].normal[k] = (int16_t)(c[k] * 32767.0f);
    }
    vertices[i].color[0] = (uint8_t)(120 + 20 * i);
    vertices[i].color[1] = (uint8_t)(250 - 25 * i);
    vertices[i].color[2] = (uint8_t)(60 + 21 * i);
    vertices[i].color[3] = 255;
  }
  const uint16_t indices[5 + 24] = {9, 9, 9, 9, 9, 0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                                    2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
  GLuint gem_vao, gem_vbo, gem_ibo, instance_vbo, block_buffer;
  glGenVertexArrays(1, &gem_vao);
  glBindVertexArray(gem_vao);
  glGenBuffers(1, &gem_vbo);
  glBindBuffer(GL_ARRAY_BUFFER, gem_vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof vertices, vertices, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(struct GemVertex), (void*)0);
  glVertexAttribPointer(1, 3, GL_SHORT, GL_TRUE, sizeof(struct GemVertex), (void*)12);
  glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(struct GemVertex), (void*)18);
  for (int i = 0; i < 3; ++i) glEnableVertexAttribArray(i);
  glGenBuffers(1, &instance_vbo);
  glBindBuffer(GL_ARRAY_BUFFER, instance_vbo);
  glBufferData(GL_ARRAY_BUFFER, 3 * 3 * sizeof(float), NULL, GL_DYNAMIC_DRAW);
  float* offsets = glMapBufferRange(GL_ARRAY_BUFFER, 0, 3 * 3 * sizeof(float), GL_MAP_WRITE_BIT);
  if (!offsets) fail("glMapBufferRange failed");
  const float instance_offsets[9] = {-0.85f, 0.1f, 0.2f, 0.0f, 0.25f, 0.0f, 0.85f, 0.1f, -0.2f};
  memcpy(offsets, instance_offsets, sizeof instance_offsets);
  if (compute) memset(offsets, 0, sizeof instance_offsets);
  glUnmapBuffer(GL_ARRAY_BUFFER);
  if (compute) {
    GLuint cs = glCreateShader(GL_COMPUTE_SHADER);
    glShaderSource(cs, 1, &kOffsetsCs, NULL);
    glCompileShader(cs);
    GLuint cp = glCreateProgram();
    glAttachShader(cp, cs);
    glLinkProgram(cp);
    GLint ok = 0;
    glGetProgramiv(cp, GL_LINK_STATUS, &ok);
    if (!ok) fail("the compute program did not link");
    glUseProgram(cp);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, instance_vbo);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT);
    glUseProgram(0);
  }
  glVertexAttribPointer(3, 3, GL_FLOAT, GL_FALSE, 0, (void*)0);
  glVertexAttribDivisor(3, 1);
  glEnableVertexAttribArray(3);
  glGenBuffers(1, &gem_ibo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gem_ibo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof indices, indices, GL_STATIC_DRAW);

  /* The std140 block, at offset 256 of its buffer (the first 256 bytes are another block's):
   * view_proj at 0, light_dir at 64, bulge at 80, uv_scale[0] at 96 and [1] at 112 (std140 gives
   * a float array a 16-byte stride; the padding holds values that must not be read). */
  uint8_t block[256 + 128];
  memset(block, 0x4d, sizeof block);
  float shading[32];
  for (int i = 0; i < 32; ++i) shading[i] = -7.0f;
  memcpy(shading, kMvp, sizeof kMvp);
  shading[16] = 0.3f;
  shading[17] = 0.55f;
  shading[18] = 0.78f;
  shading[19] = 0.0f;
  shading[20] = 0.9f;
  shading[24] = 3.0f;
  shading[28] = 2.0f;
  memcpy(block + 256, shading, sizeof shading);
  glGenBuffers(1, &block_buffer);
  glBindBuffer(GL_UNIFORM_BUFFER, block_buffer);
  glBufferData(GL_UNIFORM_BUFFER, sizeof block, block, GL_STATIC_DRAW);

  /* A 16 x 16 RGBA8 texture with its mip chain from glGenerateMipmap, on unit 1. */
  uint8_t texels[16 * 16 * 4];
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      uint8_t* t = texels + (y * 16 + x) * 4;
      const int check = ((x >> 2) + (y >> 2)) & 1;
      t[0] = (uint8_t)(check ? 255 : 90 + 8 * x);
      t[1] = (uint8_t)(check ? 230 : 60 + 10 * y);
      t[2] = (uint8_t)(check ? 200 : 120);
      t[3] = 255;
    }
  GLuint texture;
  glActiveTexture(GL_TEXTURE1);
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT);
  glGenerateMipmap(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE0);

  /* The bicubic patch: a 4 x 4 grid of control points, raised in the middle. */
  float bicubic[16 * 3];
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      float* c = bicubic + (j * 4 + i) * 3;
      c[0] = -0.6f + 0.4f * (float)i;
      c[1] = -0.95f + 0.3f * (float)j;
      c[2] = ((i == 1 || i == 2) && (j == 1 || j == 2)) ? -0.9f : -0.2f;
    }
  const GLuint bicubic_vao = position_array(bicubic, sizeof bicubic, 0);

  /* ---- the frame ---- */
#ifdef HAVE_RENDERDOC_APP
  if (rdoc && !two_frames) rdoc->StartFrameCapture(NULL, NULL);
#endif
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, kSize, kSize);
  glClearColor(0.05f, 0.07f, 0.12f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);

  glUseProgram(plane_program);
  glUniformMatrix4fv(glGetUniformLocation(plane_program, "u_mvp"), 1, GL_FALSE, kMvp);
  glUniform4f(glGetUniformLocation(plane_program, "u_tint"), 0.35f, 0.42f, 0.3f, 1.0f);
  glBindVertexArray(plane_vao);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);

  if (untessellated) goto read_back;
  if (two_frames) {
    eglSwapBuffers(display, surface);
#ifdef HAVE_RENDERDOC_APP
    if (rdoc) rdoc->StartFrameCapture(NULL, NULL);
#endif
  }

  glUseProgram(gem_program);
  glUniform1f(glGetUniformLocation(gem_program, "u_level"), 5.0f);
  glUniform1i(glGetUniformLocation(gem_program, "u_albedo"), 1);
  glBindBufferRange(GL_UNIFORM_BUFFER, 1, block_buffer, 256, 128);
  glPatchParameteri(GL_PATCH_VERTICES, 3);
  glEnable(GL_CULL_FACE);
  glBindVertexArray(gem_vao);
  if (indirect) {
    /* count, instancecount, firstIndex, basevertex, baseinstance (GL 4.5 10.4), after 8 unused bytes */
    const GLuint command[2 + 5] = {0xdead, 0xbeef, 24, 3, 5, 3, 0};
    GLuint indirect_buffer;
    glGenBuffers(1, &indirect_buffer);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, indirect_buffer);
    glBufferData(GL_DRAW_INDIRECT_BUFFER, sizeof command, command, GL_STATIC_DRAW);
    glDrawElementsIndirect(GL_PATCHES, GL_UNSIGNED_SHORT, (void*)8);
  } else {
    glDrawElementsInstancedBaseVertex(GL_PATCHES, 24, GL_UNSIGNED_SHORT, (void*)10, 3, 3);
  }
  glDisable(GL_CULL_FACE);

  glUseProgram(bicubic_program);
  glUniformMatrix4fv(glGetUniformLocation(bicubic_program, "u_mvp"), 1, GL_FALSE, kMvp);
  glUniform1f(glGetUniformLocation(bicubic_program, "u_level"), 8.0f);
  glPatchParameteri(GL_PATCH_VERTICES, 16);
  glBindVertexArray(bicubic_vao);
  if (indirect) {
    const GLint firsts[2] = {0, 0};
    const GLsizei counts[2] = {16, 16};
    glMultiDrawArrays(GL_PATCHES, firsts, counts, 2);
  } else {
    glDrawArrays(GL_PATCHES, 0, 16);
  }

read_back:;
  static uint8_t pixels[kSize * kSize * 4];
  glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  /* Before EndFrameCapture: RenderDoc 1.24 leaves an error of its own behind on this context. */
  if (glGetError() != GL_NO_ERROR) fail("a GL call failed");
#ifdef HAVE_RENDERDOC_APP
  if (rdoc) rdoc->EndFrameCapture(NULL, NULL);
#endif
  write_ppm(out, pixels);
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (surface != EGL_NO_SURFACE) eglDestroySurface(display, surface);
  eglDestroyContext(display, context);
  eglTerminate(display);
  return 0;
}
