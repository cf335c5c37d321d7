"""GL 4.5 core state, tracked over a call stream as a driver tracks it, for one purpose: to say, at
each draw call, everything that draw reads (program, vertex arrays and their buffers' bytes,
uniforms, blocks, textures, framebuffer and fixed-function state).

Calls that change draw state in a way tessref does not model are collected in `unmodelled`;
the importer reports them. Calls that change nothing a draw reads are listed in NO_EFFECT.
"""

import re

from import_error import ImportFailure

MAX_BUFFER_BYTES = 1 << 28  # a buffer the trace declares larger is refused before allocation

STAGES = {
    "GL_VERTEX_SHADER": "vertex", "GL_TESS_CONTROL_SHADER": "tess_control",
    "GL_TESS_EVALUATION_SHADER": "tess_evaluation", "GL_FRAGMENT_SHADER": "fragment",
    "GL_GEOMETRY_SHADER": "geometry", "GL_COMPUTE_SHADER": "compute",
}

# Calls that read state or synchronise, and never change what a later draw reads.
NO_EFFECT = re.compile(
    r"^(glGet\w*|glIs\w*|glCheck\w*Status|glFinish|glFlush|glReadPixels|glReadnPixels|glReadBuffer|glNamedFramebufferReadBuffer|"
    r"glFenceSync|glClientWaitSync|glWaitSync|glDeleteSync|glDebugMessage\w*|glPushDebugGroup|glPopDebugGroup|"
    r"glObjectPtrLabel|glValidateProgram\w*|glShaderBinary|glReleaseShaderCompiler|glHint|glBeginQuery|glEndQuery|glGenQueries|"
    r"glCreateQueries|glDeleteQueries|glQueryCounter|glFlushMappedBufferRange|glFlushMappedNamedBufferRange|glMemoryBarrier|"
    r"glTextureBarrier|glInvalidate\w*|glDetachShader|glDeleteShader|"
    r"glFrameTerminatorGREMEDY|glStringMarkerGREMEDY|glInsertEventMarkerEXT|glPushGroupMarkerEXT|glPopGroupMarkerEXT|"
    r"egl\w*|glX\w*|wgl\w*)$")

# Enables a scene's draws carry, and those that change nothing in a single-sample framebuffer.
CARRIED_CAPS = {"GL_DEPTH_TEST", "GL_CULL_FACE", "GL_SCISSOR_TEST", "GL_BLEND", "GL_FRAMEBUFFER_SRGB",
                "GL_DEPTH_CLAMP", "GL_TEXTURE_CUBE_MAP_SEAMLESS"}
HARMLESS_CAPS = {"GL_DITHER", "GL_MULTISAMPLE", "GL_DEBUG_OUTPUT", "GL_DEBUG_OUTPUT_SYNCHRONOUS",
                 "GL_PRIMITIVE_RESTART", "GL_PRIMITIVE_RESTART_FIXED_INDEX"}
INITIAL_CAPS = {"GL_DITHER", "GL_MULTISAMPLE"}

DRAW_CALLS = {
    "glDrawArrays", "glDrawArraysInstanced", "glDrawArraysInstancedBaseInstance", "glDrawElements",
    "glDrawElementsBaseVertex", "glDrawElementsInstanced", "glDrawElementsInstancedBaseVertex",
    "glDrawElementsInstancedBaseInstance", "glDrawElementsInstancedBaseVertexBaseInstance", "glDrawRangeElements",
    "glDrawRangeElementsBaseVertex", "glMultiDrawArrays", "glMultiDrawElements", "glMultiDrawElementsBaseVertex",
    "glDrawArraysIndirect", "glDrawElementsIndirect", "glMultiDrawArraysIndirect", "glMultiDrawElementsIndirect",
}


class Buffer:
    def __init__(self):
        self.data = bytearray()
        self.label = None


class Binding:
    def __init__(self):
        self.buffer, self.offset, self.stride, self.divisor = 0, 0, 16, 0
        self.explicit_stride = False  # set by glBindVertexBuffer, where stride 0 means 0


class Attrib:
    def __init__(self, index):
        self.enabled = False
        self.size, self.type, self.normalized = 4, "GL_FLOAT", False
        self.pointer = "glVertexAttribPointer"
        self.relative_offset = 0
        self.binding = index


class VertexArray:
    def __init__(self):
        self.attribs = {}
        self.bindings = {}
        self.element_buffer = 0

    def attrib(self, index):
        return self.attribs.setdefault(index, Attrib(index))

    def binding(self, index):
        return self.bindings.setdefault(index, Binding())


class Shader:
    def __init__(self, stage):
        self.stage = stage
        self.source = ""
        self.compiled = None
        self.label = None


class Program:
    def __init__(self):
        self.attached = []
        self.linked = None           # stage -> [sources], at the last glLinkProgram
        self.shader_labels = {}      # stage -> [ids of the linked shader objects, whose labels name files]
        self.bound_attribs = {}      # name -> index, from glBindAttribLocation (apitrace adds the linked ones)
        self.attribs = {}            # after link: name -> index
        self.recorded_attribs = {}   # apitrace's record of the next link's attribute locations
        self.uniform_names = {}      # location -> name as the application asked for it
        self.uniform_values = {}     # location -> (call name, values, count)
        self.block_indices = {}      # (kind, index) -> block name
        self.block_bindings = {}     # (kind, block name) -> binding set by the application
        self.separable = False


class Texture:
    def __init__(self, target):
        self.target = target
        self.images = {}             # (level, face) -> dict(width, height, depth, internalformat, data bytearray)
        self.storage_levels = None   # glTexStorage*'s level count
        self.generated_after = None  # the level-0 upload count when glGenerateMipmap ran
        self.uploads = 0
        self.params = {}
        self.buffer = None           # GL_TEXTURE_BUFFER: (internalformat, buffer, offset, size)
        self.label = None


class Framebuffer:
    def __init__(self):
        self.attachments = {}        # attachment enum -> ("texture", id, level) | ("renderbuffer", id)
        self.draw_buffers = ["GL_COLOR_ATTACHMENT0"]


class Renderbuffer:
    def __init__(self):
        self.internalformat, self.width, self.height, self.samples = None, 0, 0, 0


class GlState:
    def __init__(self):
        self.buffers = {}
        self.bound = {}                  # buffer target -> id
        self.indexed = {}                # (target, index) -> (buffer, offset, size or None)
        self.maps = []                   # (address, buffer id, offset, length)
        self.vertex_arrays = {0: VertexArray()}
        self.vao = 0
        self.current_attrib = {}
        self.shaders, self.programs = {}, {}
        self.program = 0
        self.pipeline_bound = False
        self.textures = {}
        self.active_unit = 0
        self.units = {}                  # (unit, target) -> texture id
        self.samplers, self.sampler_units = {}, {}
        self.framebuffers = {0: Framebuffer()}
        self.draw_framebuffer = 0
        self.renderbuffers = {}
        self.renderbuffer = 0
        self.caps = set(INITIAL_CAPS)
        self.clear_color, self.clear_depth = [0.0, 0.0, 0.0, 0.0], 1.0
        self.depth_func, self.depth_mask = "GL_LESS", True
        self.cull_face, self.front_face, self.polygon_mode = "GL_BACK", "GL_CCW", "GL_FILL"
        self.scissor = None
        self.viewport = None
        self.largest_viewport = None
        self.depth_range = [0.0, 1.0]
        self.color_mask = [True, True, True, True]
        self.blend = {"equation": "GL_FUNC_ADD", "equation_alpha": "GL_FUNC_ADD", "src": "GL_ONE", "dst": "GL_ZERO",
                      "src_alpha": "GL_ONE", "dst_alpha": "GL_ZERO", "color": [0.0, 0.0, 0.0, 0.0]}
        self.patch_vertices = 3
        self.patch_outer, self.patch_inner = [1.0] * 4, [1.0] * 2
        self.restart_index = 0
        self.unpack = {"GL_UNPACK_ALIGNMENT": 4}
        # What the GPU wrote, which a trace's calls cannot rebuild: object id -> (call number, how).
        self.gpu_written_buffers, self.gpu_written_textures = {}, {}
        self.image_units = {}
        self.unmodelled = {}             # call name -> [first call number, count]
        self.notes = []                  # (call number, text): things carried with a caveat
        self.api = None                  # "gl" or "gles" from the EGL calls
        self.egl_api = "EGL_OPENGL_ES_API"
        self.handlers = {}
        for name in dir(self):
            if name.startswith("gl") or name.startswith("egl") or name == "memcpy":
                self.handlers[name] = getattr(self, name)

    # ---- entry ----
    def apply(self, call):
        handler = self.handlers.get(call.name) or _vertex_attrib_handler(self, call.name)
        if handler is not None:
            handler(call)
        elif call.name not in DRAW_CALLS and not NO_EFFECT.match(call.name):
            entry = self.unmodelled.setdefault(call.name, [call.no, 0])
            entry[1] += 1
        if call.name in DRAW_CALLS or call.name == "glClear" or call.name.startswith("glClearBuffer"):
            self._rendered_into(call, "rendered into")

    # ---- what the GPU writes ----
    def _rendered_into(self, c, how):
        """The draw framebuffer's texture attachments now hold what the GPU drew."""
        fb = self.framebuffers.get(self.draw_framebuffer)
        for a in (fb.attachments.values() if fb else []):
            if a[0] == "texture":
                self.gpu_written_textures[a[1]] = (c.no, "%s by %s" % (how, c.name))

    def _gpu_wrote(self, c, targets, how):
        for (target, _), (buffer, _, _) in list(self.indexed.items()):
            if target in targets and buffer:
                self.gpu_written_buffers[buffer] = (c.no, how)

    def glDispatchCompute(self, c):
        self._gpu_wrote(c, ("GL_SHADER_STORAGE_BUFFER", "GL_ATOMIC_COUNTER_BUFFER"), "written by a compute shader (%s)" % c.name)
        for unit, texture in self.image_units.items():
            self.gpu_written_textures[texture] = (c.no, "written by a compute shader's images (%s)" % c.name)

    glDispatchComputeIndirect = glDispatchCompute

    def glBindImageTexture(self, c):
        self.image_units[c.arg("unit")] = c.arg("texture")

    def glBeginTransformFeedback(self, c):
        self._gpu_wrote(c, ("GL_TRANSFORM_FEEDBACK_BUFFER",), "written by transform feedback (%s)" % c.name)

    def glBlitFramebuffer(self, c):
        self._rendered_into(c, "written")

    glBlitNamedFramebuffer = glBlitFramebuffer

    def glCopyTexSubImage2D(self, c):
        target = c.arg("target")
        tid = self.units.get((self.active_unit, "GL_TEXTURE_CUBE_MAP" if "CUBE_MAP_" in str(target) else target), 0)
        if tid:
            self.gpu_written_textures[tid] = (c.no, "copied from the framebuffer (%s)" % c.name)

    glCopyTexImage2D = glCopyTexSubImage2D
    glCopyTexSubImage1D = glCopyTexSubImage2D
    glCopyTexSubImage3D = glCopyTexSubImage2D
    glCopyTexImage1D = glCopyTexSubImage2D

    def unmodelled_call(self, call, why=""):
        entry = self.unmodelled.setdefault(call.name + why, [call.no, 0])
        entry[1] += 1

    # ---- EGL: which API the context speaks ----
    def eglBindAPI(self, c):
        self.egl_api = c.arg("api")

    def eglCreateContext(self, c):
        self.api = "gl" if self.egl_api == "EGL_OPENGL_API" else "gles"

    def glXCreateContextAttribsARB(self, c):
        attribs = c.arg("attrib_list") or []
        self.api = "gles" if "GLX_CONTEXT_ES2_PROFILE_BIT_EXT" in str(attribs) else "gl"

    # ---- buffers ----
    def _new_buffers(self, ids):
        for i in ids or []:
            self.buffers[i] = Buffer()

    def glGenBuffers(self, c):
        self._new_buffers(c.arg("buffers"))

    def glCreateBuffers(self, c):
        self._new_buffers(c.arg("buffers"))

    def glDeleteBuffers(self, c):
        for i in c.arg("buffers") or []:
            self.buffers.pop(i, None)

    def glBindBuffer(self, c):
        target, buffer = c.arg("target"), c.arg("buffer")
        if buffer and buffer not in self.buffers:
            self.buffers[buffer] = Buffer()
        if target == "GL_ELEMENT_ARRAY_BUFFER":
            self.vertex_arrays[self.vao].element_buffer = buffer
        else:
            self.bound[target] = buffer

    def glBindBufferBase(self, c):
        self.bound[c.arg("target")] = c.arg("buffer")
        self.indexed[(c.arg("target"), c.arg("index"))] = (c.arg("buffer"), 0, None)

    def glBindBufferRange(self, c):
        self.bound[c.arg("target")] = c.arg("buffer")
        self.indexed[(c.arg("target"), c.arg("index"))] = (c.arg("buffer"), c.arg("offset"), c.arg("size"))

    def _target_buffer(self, c, target_key="target"):
        target = c.arg(target_key)
        buffer = self.vertex_arrays[self.vao].element_buffer if target == "GL_ELEMENT_ARRAY_BUFFER" else \
            self.bound.get(target, 0)
        if not buffer or buffer not in self.buffers:
            raise ImportFailure("call %d (%s): no buffer is bound to %s" % (c.no, c.name, target))
        return buffer

    def _named(self, c):
        buffer = c.arg("buffer")
        if buffer not in self.buffers:
            raise ImportFailure("call %d (%s): buffer %s does not exist" % (c.no, c.name, buffer))
        return buffer

    def _store(self, c, buffer, size, data):
        if not isinstance(size, int) or size < 0 or size > MAX_BUFFER_BYTES:
            raise ImportFailure("call %d (%s): the buffer size %r is not one tessref takes (at most %d bytes)"
                                % (c.no, c.name, size, MAX_BUFFER_BYTES))
        self.gpu_written_buffers.pop(buffer, None)
        if isinstance(data, (bytes, bytearray)):
            if len(data) != size:
                raise ImportFailure("call %d (%s): it declares %d bytes but the trace holds %d: the trace is damaged"
                                    % (c.no, c.name, size, len(data)))
            self.buffers[buffer].data = bytearray(data)
        else:
            self.buffers[buffer].data = bytearray(size)

    def glBufferData(self, c):
        self._store(c, self._target_buffer(c), c.arg("size"), c.arg("data"))

    def glBufferStorage(self, c):
        self._store(c, self._target_buffer(c), c.arg("size"), c.arg("data"))

    def glNamedBufferData(self, c):
        self._store(c, self._named(c), c.arg("size"), c.arg("data"))

    def glNamedBufferStorage(self, c):
        self._store(c, self._named(c), c.arg("size"), c.arg("data"))

    def _sub(self, c, buffer, offset, size, data):
        target = self.buffers[buffer].data
        if not isinstance(data, (bytes, bytearray)) or len(data) != size:
            raise ImportFailure("call %d (%s): it declares %r bytes but the trace holds %s: the trace is damaged"
                                % (c.no, c.name, size, len(data) if isinstance(data, (bytes, bytearray)) else "none"))
        if offset < 0 or offset + size > len(target):
            raise ImportFailure("call %d (%s): bytes [%d, %d) lie outside the buffer's %d bytes"
                                % (c.no, c.name, offset, offset + size, len(target)))
        target[offset:offset + size] = data

    def glBufferSubData(self, c):
        self._sub(c, self._target_buffer(c), c.arg("offset"), c.arg("size"), c.arg("data"))

    def glNamedBufferSubData(self, c):
        self._sub(c, self._named(c), c.arg("offset"), c.arg("size"), c.arg("data"))

    def _map(self, c, buffer, offset, length):
        if c.ret:
            self.maps.append((int(c.ret), buffer, offset, length))

    def glMapBufferRange(self, c):
        self._map(c, self._target_buffer(c), c.arg("offset"), c.arg("length"))

    def glMapBuffer(self, c):
        b = self._target_buffer(c)
        self._map(c, b, 0, len(self.buffers[b].data))

    def glMapNamedBufferRange(self, c):
        self._map(c, self._named(c), c.arg("offset"), c.arg("length"))

    def glMapNamedBuffer(self, c):
        b = self._named(c)
        self._map(c, b, 0, len(self.buffers[b].data))

    def memcpy(self, c):
        dest, data, n = int(c.arg("dest") or 0), c.arg("src"), c.arg("n")
        if not isinstance(data, (bytes, bytearray)) or len(data) != n:
            raise ImportFailure("call %d (memcpy): it declares %r bytes but the trace holds %s: the trace is damaged"
                                % (c.no, n, len(data) if isinstance(data, (bytes, bytearray)) else "none"))
        for address, buffer, offset, length in reversed(self.maps):
            if address <= dest and dest + n <= address + length and buffer in self.buffers:
                start = offset + dest - address
                self.buffers[buffer].data[start:start + n] = data
                return
        self.unmodelled_call(c, " (into memory that is not a mapped buffer)")

    def _unmap(self, buffer):
        self.maps = [m for m in self.maps if m[1] != buffer]

    def glUnmapBuffer(self, c):
        self._unmap(self._target_buffer(c))

    def glUnmapNamedBuffer(self, c):
        self._unmap(self._named(c))

    def _copy(self, c, read, write, read_offset, write_offset, size):
        src, dst = self.buffers[read].data, self.buffers[write].data
        if read_offset + size > len(src) or write_offset + size > len(dst):
            raise ImportFailure("call %d (%s): the copy runs past a buffer's end" % (c.no, c.name))
        dst[write_offset:write_offset + size] = bytes(src[read_offset:read_offset + size])
        if read in self.gpu_written_buffers:
            self.gpu_written_buffers[write] = self.gpu_written_buffers[read]

    def glCopyBufferSubData(self, c):
        self._copy(c, self._target_buffer(c, "readTarget"), self._target_buffer(c, "writeTarget"),
                   c.arg("readOffset"), c.arg("writeOffset"), c.arg("size"))

    def glCopyNamedBufferSubData(self, c):
        self._copy(c, c.arg("readBuffer"), c.arg("writeBuffer"), c.arg("readOffset"), c.arg("writeOffset"),
                   c.arg("size"))

    # ---- vertex arrays ----
    def glGenVertexArrays(self, c):
        for i in c.arg("arrays") or []:
            self.vertex_arrays[i] = VertexArray()

    glCreateVertexArrays = glGenVertexArrays

    def glBindVertexArray(self, c):
        self.vao = c.arg("array")
        self.vertex_arrays.setdefault(self.vao, VertexArray())

    def _pointer(self, c, kind):
        vao = self.vertex_arrays[self.vao]
        index = c.arg("index")
        a = vao.attrib(index)
        a.size, a.type = c.arg("size"), c.arg("type")
        a.normalized = c.arg("normalized") == "GL_TRUE"
        a.pointer, a.relative_offset, a.binding = kind, 0, index
        b = vao.binding(index)
        b.buffer = self.bound.get("GL_ARRAY_BUFFER", 0)
        if not b.buffer:
            self.notes.append((c.no, "attribute %d reads client memory (no GL_ARRAY_BUFFER bound): not carried" % index))
        b.offset = int(c.arg("pointer") or 0)
        b.stride = c.arg("stride")  # 0: tightly packed, as the scene's stride 0

    def glVertexAttribPointer(self, c):
        self._pointer(c, "glVertexAttribPointer")

    def glVertexAttribIPointer(self, c):
        self._pointer(c, "glVertexAttribIPointer")

    def glVertexAttribLPointer(self, c):
        self._pointer(c, "glVertexAttribLPointer")

    def glEnableVertexAttribArray(self, c):
        self.vertex_arrays[self.vao].attrib(c.arg("index")).enabled = True

    def glDisableVertexAttribArray(self, c):
        self.vertex_arrays[self.vao].attrib(c.arg("index")).enabled = False

    def glEnableVertexArrayAttrib(self, c):
        self.vertex_arrays.setdefault(c.arg("vaobj"), VertexArray()).attrib(c.arg("index")).enabled = True

    def glDisableVertexArrayAttrib(self, c):
        self.vertex_arrays.setdefault(c.arg("vaobj"), VertexArray()).attrib(c.arg("index")).enabled = False

    def glVertexAttribDivisor(self, c):
        vao = self.vertex_arrays[self.vao]
        vao.attrib(c.arg("index")).binding = c.arg("index")
        vao.binding(c.arg("index")).divisor = c.arg("divisor")

    def _format(self, vao, index, size, type_, normalized, relative, kind):
        a = vao.attrib(index)
        a.size, a.type, a.normalized, a.relative_offset, a.pointer = size, type_, normalized == "GL_TRUE", relative, kind

    def glVertexAttribFormat(self, c):
        self._format(self.vertex_arrays[self.vao], c.arg("attribindex"), c.arg("size"), c.arg("type"),
                     c.arg("normalized"), c.arg("relativeoffset"), "glVertexAttribPointer")

    def glVertexAttribIFormat(self, c):
        self._format(self.vertex_arrays[self.vao], c.arg("attribindex"), c.arg("size"), c.arg("type"), None,
                     c.arg("relativeoffset"), "glVertexAttribIPointer")

    def glVertexAttribLFormat(self, c):
        self._format(self.vertex_arrays[self.vao], c.arg("attribindex"), c.arg("size"), c.arg("type"), None,
                     c.arg("relativeoffset"), "glVertexAttribLPointer")

    def glVertexArrayAttribFormat(self, c):
        self._format(self.vertex_arrays.setdefault(c.arg("vaobj"), VertexArray()), c.arg("attribindex"), c.arg("size"),
                     c.arg("type"), c.arg("normalized"), c.arg("relativeoffset"), "glVertexAttribPointer")

    def glVertexArrayAttribIFormat(self, c):
        self._format(self.vertex_arrays.setdefault(c.arg("vaobj"), VertexArray()), c.arg("attribindex"), c.arg("size"),
                     c.arg("type"), None, c.arg("relativeoffset"), "glVertexAttribIPointer")

    def glVertexAttribBinding(self, c):
        self.vertex_arrays[self.vao].attrib(c.arg("attribindex")).binding = c.arg("bindingindex")

    def glVertexArrayAttribBinding(self, c):
        self.vertex_arrays.setdefault(c.arg("vaobj"), VertexArray()).attrib(c.arg("attribindex")).binding = \
            c.arg("bindingindex")

    def _bind_vertex_buffer(self, vao, index, buffer, offset, stride):
        b = vao.binding(index)
        b.buffer, b.offset, b.stride = buffer, offset, stride
        b.explicit_stride = True

    def glBindVertexBuffer(self, c):
        self._bind_vertex_buffer(self.vertex_arrays[self.vao], c.arg("bindingindex"), c.arg("buffer"), c.arg("offset"),
                                 c.arg("stride"))

    def glVertexArrayVertexBuffer(self, c):
        self._bind_vertex_buffer(self.vertex_arrays.setdefault(c.arg("vaobj"), VertexArray()), c.arg("bindingindex"),
                                 c.arg("buffer"), c.arg("offset"), c.arg("stride"))

    def glVertexBindingDivisor(self, c):
        self.vertex_arrays[self.vao].binding(c.arg("bindingindex")).divisor = c.arg("divisor")

    def glVertexArrayBindingDivisor(self, c):
        self.vertex_arrays.setdefault(c.arg("vaobj"), VertexArray()).binding(c.arg("bindingindex")).divisor = \
            c.arg("divisor")

    def glVertexArrayElementBuffer(self, c):
        self.vertex_arrays.setdefault(c.arg("vaobj"), VertexArray()).element_buffer = c.arg("buffer")

    # ---- shaders and programs ----
    def glCreateShader(self, c):
        stage = STAGES.get(c.arg("type"))
        self.shaders[c.ret] = Shader(stage or c.arg("type"))

    def glShaderSource(self, c):
        shader = self.shaders.get(c.arg("shader"))
        if shader is None:
            raise ImportFailure("call %d (glShaderSource): shader %s does not exist" % (c.no, c.arg("shader")))
        strings = c.arg("string") or []
        lengths = c.arg("length")
        parts = []
        for i, s in enumerate(strings):
            if isinstance(s, bytes):
                s = s.decode("utf-8", "replace")
            if not isinstance(s, str):
                raise ImportFailure("call %d (glShaderSource): string %d is not text" % (c.no, i))
            if isinstance(lengths, list) and i < len(lengths) and lengths[i] is not None and lengths[i] >= 0:
                s = s[:lengths[i]]
            parts.append(s)
        shader.source = "".join(parts)

    def glCompileShader(self, c):
        shader = self.shaders.get(c.arg("shader"))
        if shader is not None:
            shader.compiled = shader.source

    def glCreateProgram(self, c):
        self.programs[c.ret] = Program()

    def glDeleteProgram(self, c):
        pass  # GL keeps a program in use until it is unbound; ids are not reused in a trace's lifetime

    def glAttachShader(self, c):
        p = self.programs.get(c.arg("program"))
        if p is not None:
            p.attached.append(c.arg("shader"))

    def glDetachShader(self, c):
        p = self.programs.get(c.arg("program"))
        if p is not None and c.arg("shader") in p.attached:
            p.attached.remove(c.arg("shader"))

    def glBindAttribLocation(self, c):
        p = self.programs.get(c.arg("program"))
        if p is None:
            return
        if c.flags & 1:  # apitrace's record, just before glLinkProgram, of where the link puts an attribute
            p.recorded_attribs[c.arg("name")] = c.arg("index")
        else:
            p.bound_attribs[c.arg("name")] = c.arg("index")

    def glProgramParameteri(self, c):
        p = self.programs.get(c.arg("program"))
        if p is not None and c.arg("pname") == "GL_PROGRAM_SEPARABLE":
            p.separable = bool(c.arg("value"))

    def glLinkProgram(self, c):
        p = self.programs.get(c.arg("program"))
        if p is None:
            return
        p.linked, p.shader_labels = {}, {}
        for sid in p.attached:
            s = self.shaders.get(sid)
            if s is None:
                continue
            p.linked.setdefault(s.stage, []).append(s.compiled if s.compiled is not None else s.source)
            p.shader_labels.setdefault(s.stage, []).append(sid)
        p.uniform_names, p.uniform_values = {}, {}
        p.attribs, p.recorded_attribs = p.recorded_attribs, {}
        p.block_indices = {}

    def glUseProgram(self, c):
        self.program = c.arg("program")

    def glBindProgramPipeline(self, c):
        self.pipeline_bound = bool(c.arg("pipeline"))
        if self.pipeline_bound:
            self.unmodelled_call(c, " (program pipelines: separable programs are not in tessref's scenes yet)")

    def glCreateShaderProgramv(self, c):
        self.unmodelled_call(c, " (separable programs are not in tessref's scenes yet)")

    def glGetUniformLocation(self, c):
        p = self.programs.get(c.arg("program"))
        if p is not None and isinstance(c.ret, int) and c.ret >= 0:
            p.uniform_names[c.ret] = c.arg("name")

    def glGetUniformBlockIndex(self, c):
        p = self.programs.get(c.arg("program"))
        if p is not None and isinstance(c.ret, int):
            p.block_indices[("uniform", c.ret)] = c.arg("uniformBlockName")

    def glGetProgramResourceIndex(self, c):
        p = self.programs.get(c.arg("program"))
        kinds = {"GL_UNIFORM_BLOCK": "uniform", "GL_SHADER_STORAGE_BLOCK": "buffer"}
        if p is not None and c.arg("programInterface") in kinds and isinstance(c.ret, int):
            p.block_indices[(kinds[c.arg("programInterface")], c.ret)] = c.arg("name")

    def glUniformBlockBinding(self, c):
        p = self.programs.get(c.arg("program"))
        if p is None:
            return
        name = p.block_indices.get(("uniform", c.arg("uniformBlockIndex")))
        if name is None:
            self.unmodelled_call(c, " (a block index the application never asked glGetUniformBlockIndex for)")
        else:
            p.block_bindings[("uniform", name)] = c.arg("uniformBlockBinding")

    def glShaderStorageBlockBinding(self, c):
        p = self.programs.get(c.arg("program"))
        if p is None:
            return
        name = p.block_indices.get(("buffer", c.arg("storageBlockIndex")))
        if name is None:
            self.unmodelled_call(c, " (a block index the application never asked for by name)")
        else:
            p.block_bindings[("buffer", name)] = c.arg("storageBlockBinding")

    def _uniform(self, c, program_id):
        p = self.programs.get(program_id)
        if p is None:
            raise ImportFailure("call %d (%s): no program is in use" % (c.no, c.name))
        location = c.arg("location")
        if location is None or location < 0:
            return  # GL ignores location -1
        m = re.match(r"^gl(?:Program)?Uniform(Matrix)?([234](?:x[234])?)?(f|d|i|ui)?v?$", c.name)
        if "value" in c.args:
            values = list(c.arg("value") or [])
            count = c.arg("count", 1)
        else:
            values = [c.arg(k) for k in ("v0", "v1", "v2", "v3") if k in c.args]
            count = 1
        transpose = c.arg("transpose") == "GL_TRUE"
        if m and m.group(1) and transpose:
            values = _transpose(values, m.group(2), count)
        p.uniform_values[location] = (c.name, values, count)

    def glUseProgramStages(self, c):
        self.unmodelled_call(c, " (program pipelines are not in tessref's scenes yet)")

    # ---- textures and samplers ----
    def glActiveTexture(self, c):
        self.active_unit = int(str(c.arg("texture")).replace("GL_TEXTURE", "") or 0)

    def glGenTextures(self, c):
        for i in c.arg("textures") or []:
            self.textures.setdefault(i, Texture(None))

    def glCreateTextures(self, c):
        for i in c.arg("textures") or []:
            self.textures[i] = Texture(c.arg("target"))

    def glDeleteTextures(self, c):
        for i in c.arg("textures") or []:
            self.textures.pop(i, None)

    def glBindTexture(self, c):
        tid = c.arg("texture")
        if tid:
            t = self.textures.setdefault(tid, Texture(c.arg("target")))
            t.target = t.target or c.arg("target")
        self.units[(self.active_unit, c.arg("target"))] = tid

    def glBindTextureUnit(self, c):
        tid = c.arg("texture")
        t = self.textures.get(tid)
        if t is not None and t.target:
            self.units[(c.arg("unit"), t.target)] = tid

    def _bound_texture(self, c, target):
        if target and target.startswith("GL_TEXTURE_CUBE_MAP_") and target != "GL_TEXTURE_CUBE_MAP_ARRAY":
            target = "GL_TEXTURE_CUBE_MAP"
        tid = self.units.get((self.active_unit, target), 0)
        if not tid or tid not in self.textures:
            raise ImportFailure("call %d (%s): no texture is bound to %s on unit %d"
                                % (c.no, c.name, target, self.active_unit))
        return self.textures[tid]

    def glPixelStorei(self, c):
        self.unpack[c.arg("pname")] = c.arg("param")

    def _pixels(self, c, key="pixels"):
        data = c.arg(key)
        unpack_buffer = self.bound.get("GL_PIXEL_UNPACK_BUFFER", 0)
        if unpack_buffer:
            offset = int(data or 0)
            return bytes(self.buffers[unpack_buffer].data[offset:])
        if data is None or isinstance(data, int):
            return None
        return bytes(data)

    def _image(self, c, texture, target, level, internalformat, size, data, format_, type_):
        from texture_upload import store_image
        face = _FACES.index(target) if target in _FACES else 0
        texture.target = texture.target or target
        store_image(self, c, texture, level, face, internalformat, size, data, format_, type_)

    def glTexImage1D(self, c):
        t = self._bound_texture(c, c.arg("target"))
        self._image(c, t, c.arg("target"), c.arg("level"), c.arg("internalformat"), (c.arg("width"), 1, 1),
                    self._pixels(c), c.arg("format"), c.arg("type"))

    def glTexImage2D(self, c):
        t = self._bound_texture(c, c.arg("target"))
        self._image(c, t, c.arg("target"), c.arg("level"), c.arg("internalformat"),
                    (c.arg("width"), c.arg("height"), 1), self._pixels(c), c.arg("format"), c.arg("type"))

    def glTexImage3D(self, c):
        t = self._bound_texture(c, c.arg("target"))
        self._image(c, t, c.arg("target"), c.arg("level"), c.arg("internalformat"),
                    (c.arg("width"), c.arg("height"), c.arg("depth")), self._pixels(c), c.arg("format"), c.arg("type"))

    def _storage(self, c, t, levels, internalformat, size):
        from texture_upload import allocate_storage
        allocate_storage(self, c, t, levels, internalformat, size)

    def glTexStorage1D(self, c):
        self._storage(c, self._bound_texture(c, c.arg("target")), c.arg("levels"), c.arg("internalformat"),
                      (c.arg("width"), 1, 1))

    def glTexStorage2D(self, c):
        self._storage(c, self._bound_texture(c, c.arg("target")), c.arg("levels"), c.arg("internalformat"),
                      (c.arg("width"), c.arg("height"), 1))

    def glTexStorage3D(self, c):
        self._storage(c, self._bound_texture(c, c.arg("target")), c.arg("levels"), c.arg("internalformat"),
                      (c.arg("width"), c.arg("height"), c.arg("depth")))

    def glTextureStorage2D(self, c):
        self._storage(c, self._texture_named(c), c.arg("levels"), c.arg("internalformat"),
                      (c.arg("width"), c.arg("height"), 1))

    def glTextureStorage3D(self, c):
        self._storage(c, self._texture_named(c), c.arg("levels"), c.arg("internalformat"),
                      (c.arg("width"), c.arg("height"), c.arg("depth")))

    def _texture_named(self, c):
        t = self.textures.get(c.arg("texture"))
        if t is None:
            raise ImportFailure("call %d (%s): texture %s does not exist" % (c.no, c.name, c.arg("texture")))
        return t

    def _sub_image(self, c, t, target, offset, size):
        from texture_upload import store_sub_image
        face = _FACES.index(target) if target in _FACES else 0
        store_sub_image(self, c, t, c.arg("level"), face, offset, size, self._pixels(c), c.arg("format"), c.arg("type"))

    def glTexSubImage1D(self, c):
        self._sub_image(c, self._bound_texture(c, c.arg("target")), c.arg("target"), (c.arg("xoffset"), 0, 0),
                        (c.arg("width"), 1, 1))

    def glTexSubImage2D(self, c):
        self._sub_image(c, self._bound_texture(c, c.arg("target")), c.arg("target"),
                        (c.arg("xoffset"), c.arg("yoffset"), 0), (c.arg("width"), c.arg("height"), 1))

    def glTexSubImage3D(self, c):
        self._sub_image(c, self._bound_texture(c, c.arg("target")), c.arg("target"),
                        (c.arg("xoffset"), c.arg("yoffset"), c.arg("zoffset")),
                        (c.arg("width"), c.arg("height"), c.arg("depth")))

    def glTextureSubImage2D(self, c):
        self._sub_image(c, self._texture_named(c), None, (c.arg("xoffset"), c.arg("yoffset"), 0),
                        (c.arg("width"), c.arg("height"), 1))

    def glTextureSubImage3D(self, c):
        self._sub_image(c, self._texture_named(c), None, (c.arg("xoffset"), c.arg("yoffset"), c.arg("zoffset")),
                        (c.arg("width"), c.arg("height"), c.arg("depth")))

    def glGenerateMipmap(self, c):
        t = self._bound_texture(c, c.arg("target"))
        t.generated_after = t.uploads

    def glGenerateTextureMipmap(self, c):
        t = self._texture_named(c)
        t.generated_after = t.uploads

    def glTexBuffer(self, c):
        t = self._bound_texture(c, c.arg("target"))
        t.buffer = (c.arg("internalformat"), c.arg("buffer"), 0, None)

    def glTexBufferRange(self, c):
        t = self._bound_texture(c, c.arg("target"))
        t.buffer = (c.arg("internalformat"), c.arg("buffer"), c.arg("offset"), c.arg("size"))

    def _param(self, c, params):
        pname = c.arg("pname")
        value = c.arg("param") if "param" in c.args else c.arg("params")
        if isinstance(value, list) and pname not in ("GL_TEXTURE_BORDER_COLOR", "GL_TEXTURE_SWIZZLE_RGBA"):
            value = value[0]
        params[pname] = value

    def glTexParameteri(self, c):
        self._param(c, self._bound_texture(c, c.arg("target")).params)

    glTexParameterf = glTexParameteri
    glTexParameteriv = glTexParameteri
    glTexParameterfv = glTexParameteri
    glTexParameterIiv = glTexParameteri
    glTexParameterIuiv = glTexParameteri

    def glTextureParameteri(self, c):
        self._param(c, self._texture_named(c).params)

    glTextureParameterf = glTextureParameteri
    glTextureParameteriv = glTextureParameteri
    glTextureParameterfv = glTextureParameteri

    def glGenSamplers(self, c):
        for i in c.arg("samplers") or []:
            self.samplers[i] = {}

    glCreateSamplers = glGenSamplers

    def glBindSampler(self, c):
        self.sampler_units[c.arg("unit")] = c.arg("sampler")

    def glSamplerParameteri(self, c):
        self._param(c, self.samplers.setdefault(c.arg("sampler"), {}))

    glSamplerParameterf = glSamplerParameteri
    glSamplerParameteriv = glSamplerParameteri
    glSamplerParameterfv = glSamplerParameteri
    glSamplerParameterIiv = glSamplerParameteri
    glSamplerParameterIuiv = glSamplerParameteri

    def glObjectLabel(self, c):
        kinds = {"GL_SHADER": self.shaders, "GL_BUFFER": self.buffers, "GL_TEXTURE": self.textures}
        objects = kinds.get(c.arg("identifier"))
        if objects is not None and c.arg("name") in objects:
            label = c.arg("label")
            objects[c.arg("name")].label = label.decode("utf-8", "replace") if isinstance(label, bytes) else label

    # ---- framebuffers ----
    def glGenFramebuffers(self, c):
        for i in c.arg("framebuffers") or []:
            self.framebuffers[i] = Framebuffer()

    glCreateFramebuffers = glGenFramebuffers

    def glBindFramebuffer(self, c):
        if c.arg("target") in ("GL_FRAMEBUFFER", "GL_DRAW_FRAMEBUFFER"):
            self.draw_framebuffer = c.arg("framebuffer")
            self.framebuffers.setdefault(self.draw_framebuffer, Framebuffer())

    def _fb_for(self, c):
        if c.arg("target") == "GL_READ_FRAMEBUFFER":
            return None
        return self.framebuffers[self.draw_framebuffer]

    def glFramebufferTexture2D(self, c):
        fb = self._fb_for(c)
        if fb is not None:
            fb.attachments[c.arg("attachment")] = ("texture", c.arg("texture"), c.arg("level"))

    glFramebufferTexture = glFramebufferTexture2D

    def glNamedFramebufferTexture(self, c):
        self.framebuffers.setdefault(c.arg("framebuffer"), Framebuffer()).attachments[c.arg("attachment")] = \
            ("texture", c.arg("texture"), c.arg("level"))

    def glFramebufferRenderbuffer(self, c):
        fb = self._fb_for(c)
        if fb is not None:
            fb.attachments[c.arg("attachment")] = ("renderbuffer", c.arg("renderbuffer"))

    def glNamedFramebufferRenderbuffer(self, c):
        self.framebuffers.setdefault(c.arg("framebuffer"), Framebuffer()).attachments[c.arg("attachment")] = \
            ("renderbuffer", c.arg("renderbuffer"))

    def glDrawBuffers(self, c):
        self.framebuffers[self.draw_framebuffer].draw_buffers = list(c.arg("bufs") or [])

    def glDrawBuffer(self, c):
        self.framebuffers[self.draw_framebuffer].draw_buffers = [c.arg("buf")]

    def glNamedFramebufferDrawBuffers(self, c):
        self.framebuffers.setdefault(c.arg("framebuffer"), Framebuffer()).draw_buffers = list(c.arg("bufs") or [])

    def glGenRenderbuffers(self, c):
        for i in c.arg("renderbuffers") or []:
            self.renderbuffers[i] = Renderbuffer()

    glCreateRenderbuffers = glGenRenderbuffers

    def glBindRenderbuffer(self, c):
        self.renderbuffer = c.arg("renderbuffer")
        self.renderbuffers.setdefault(self.renderbuffer, Renderbuffer())

    def glRenderbufferStorage(self, c):
        r = self.renderbuffers[self.renderbuffer]
        r.internalformat, r.width, r.height, r.samples = c.arg("internalformat"), c.arg("width"), c.arg("height"), 0

    def glRenderbufferStorageMultisample(self, c):
        self.glRenderbufferStorage(c)
        self.renderbuffers[self.renderbuffer].samples = c.arg("samples")

    def glNamedRenderbufferStorage(self, c):
        r = self.renderbuffers.setdefault(c.arg("renderbuffer"), Renderbuffer())
        r.internalformat, r.width, r.height, r.samples = c.arg("internalformat"), c.arg("width"), c.arg("height"), 0

    # ---- fixed-function state ----
    def glEnable(self, c):
        self.caps.add(c.arg("cap"))

    def glDisable(self, c):
        self.caps.discard(c.arg("cap"))

    def glEnablei(self, c):
        self.unmodelled_call(c, " (per-draw-buffer enables)")

    glDisablei = glEnablei

    def glClearColor(self, c):
        self.clear_color = [c.arg("red"), c.arg("green"), c.arg("blue"), c.arg("alpha")]

    def glClearDepth(self, c):
        self.clear_depth = c.arg("depth")

    glClearDepthf = glClearDepth

    def glClear(self, c):
        pass  # the frame reader attaches a clear to the next draw

    def glClearStencil(self, c):
        pass

    def glDepthFunc(self, c):
        self.depth_func = c.arg("func")

    def glDepthMask(self, c):
        self.depth_mask = c.arg("flag") == "GL_TRUE"

    def glCullFace(self, c):
        self.cull_face = c.arg("mode")

    def glFrontFace(self, c):
        self.front_face = c.arg("mode")

    def glPolygonMode(self, c):
        if c.arg("face") != "GL_FRONT_AND_BACK":
            self.unmodelled_call(c, " (a face other than GL_FRONT_AND_BACK)")
        self.polygon_mode = c.arg("mode")

    def glScissor(self, c):
        self.scissor = [c.arg("x"), c.arg("y"), c.arg("width"), c.arg("height")]

    def glViewport(self, c):
        self.viewport = [c.arg("x"), c.arg("y"), c.arg("width"), c.arg("height")]
        w, h = c.arg("x") + c.arg("width"), c.arg("y") + c.arg("height")
        if self.largest_viewport is None or w * h > self.largest_viewport[0] * self.largest_viewport[1]:
            self.largest_viewport = (w, h)

    def glDepthRange(self, c):
        self.depth_range = [c.arg("nearVal", c.arg("n")), c.arg("farVal", c.arg("f"))]

    glDepthRangef = glDepthRange

    def glColorMask(self, c):
        self.color_mask = [c.arg(k) == "GL_TRUE" for k in ("red", "green", "blue", "alpha")]

    def glBlendFunc(self, c):
        self.blend.update(src=c.arg("sfactor"), dst=c.arg("dfactor"), src_alpha=c.arg("sfactor"),
                          dst_alpha=c.arg("dfactor"))

    def glBlendFuncSeparate(self, c):
        self.blend.update(src=c.arg("sfactorRGB"), dst=c.arg("dfactorRGB"), src_alpha=c.arg("sfactorAlpha"),
                          dst_alpha=c.arg("dfactorAlpha"))

    def glBlendEquation(self, c):
        self.blend.update(equation=c.arg("mode"), equation_alpha=c.arg("mode"))

    def glBlendEquationSeparate(self, c):
        self.blend.update(equation=c.arg("modeRGB"), equation_alpha=c.arg("modeAlpha"))

    def glBlendColor(self, c):
        self.blend["color"] = [c.arg("red"), c.arg("green"), c.arg("blue"), c.arg("alpha")]

    def glPatchParameteri(self, c):
        if c.arg("pname") == "GL_PATCH_VERTICES":
            self.patch_vertices = c.arg("value")

    def glPatchParameterfv(self, c):
        values = list(c.arg("values") or [])
        if c.arg("pname") == "GL_PATCH_DEFAULT_OUTER_LEVEL":
            self.patch_outer = values[:4]
        elif c.arg("pname") == "GL_PATCH_DEFAULT_INNER_LEVEL":
            self.patch_inner = values[:2]

    def glPrimitiveRestartIndex(self, c):
        self.restart_index = c.arg("index")


_FACES = ["GL_TEXTURE_CUBE_MAP_POSITIVE_X", "GL_TEXTURE_CUBE_MAP_NEGATIVE_X", "GL_TEXTURE_CUBE_MAP_POSITIVE_Y",
          "GL_TEXTURE_CUBE_MAP_NEGATIVE_Y", "GL_TEXTURE_CUBE_MAP_POSITIVE_Z", "GL_TEXTURE_CUBE_MAP_NEGATIVE_Z"]


def _vertex_attrib_handler(state, name):
    """glVertexAttrib{1,2,3,4}{f,d,s,i,ui,...}[v] and the I and L forms: the value a disabled array reads."""
    m = re.match(r"^glVertexAttrib(I|L)?([1-4])N?(f|d|s|i|ui|b|ub|us|bv|sv|iv|ubv|usv|uiv|fv|dv)$", name)
    if not m:
        return None
    count = int(m.group(2))

    def set_current(c):
        if "v" in c.args:
            values = list(c.arg("v"))[:count]
        else:
            values = [c.arg(k) for k in ("x", "y", "z", "w")[:count] if k in c.args]
        state.current_attrib[c.arg("index")] = values
    return set_current


def _transpose(values, shape, count):
    if "x" in shape:
        columns, rows = (int(x) for x in shape.split("x"))
    else:
        columns = rows = int(shape)
    # With transpose, the application's values are row after row: rows of `columns` numbers.
    out = []
    per = columns * rows
    for k in range(count):
        m = values[k * per:(k + 1) * per]
        for col in range(columns):
            for row in range(rows):
                out.append(m[row * columns + col])
    return out


def _uniform_handler(self, c):
    program = c.arg("program") if c.name.startswith("glProgramUniform") else self.program
    self._uniform(c, program)


for _n in ["1f", "2f", "3f", "4f", "1i", "2i", "3i", "4i", "1ui", "2ui", "3ui", "4ui", "1d", "2d", "3d", "4d",
           "1fv", "2fv", "3fv", "4fv", "1iv", "2iv", "3iv", "4iv", "1uiv", "2uiv", "3uiv", "4uiv", "1dv", "2dv", "3dv",
           "4dv", "Matrix2fv", "Matrix3fv", "Matrix4fv", "Matrix2x3fv", "Matrix3x2fv", "Matrix2x4fv", "Matrix4x2fv",
           "Matrix3x4fv", "Matrix4x3fv", "Matrix2dv", "Matrix3dv", "Matrix4dv", "Matrix2x3dv", "Matrix3x2dv",
           "Matrix2x4dv", "Matrix4x2dv", "Matrix3x4dv", "Matrix4x3dv"]:
    setattr(GlState, "glUniform" + _n, _uniform_handler)
    setattr(GlState, "glProgramUniform" + _n, _uniform_handler)
