"""A frame's draws as tessref's scene of draws (docs/draws.md): each draw call, at the moment it was
issued, becomes one entry of `draws` with its program, vertex arrays, element array, uniforms,
blocks, textures, clear and fixed-function state. Buffer and texture bytes are taken at the draw
(a buffer rewritten between draws is written once per version).

What a draw reads that the scene cannot say is put in the report, naming the draw and the feature.
"""

import hashlib
import re
import struct

from glsl_declarations import Declarations, sampler_target, with_block_binding
from gl_state import CARRIED_CAPS, HARMLESS_CAPS
from import_error import ImportFailure
from texture_upload import level_data

STAGE_FILES = {"vertex": "vert", "tess_control": "tesc", "tess_evaluation": "tese", "geometry": "geom", "fragment": "frag"}
COLOR_FORMATS = {"GL_RGBA8", "GL_SRGB8_ALPHA8", "GL_RGBA16F", "GL_RGBA32F"}
DEPTH_FORMATS = {"GL_DEPTH_COMPONENT24": "GL_DEPTH_COMPONENT24", "GL_DEPTH24_STENCIL8": "GL_DEPTH_COMPONENT24",
                 "GL_DEPTH_COMPONENT32F": "GL_DEPTH_COMPONENT32F", "GL_DEPTH32F_STENCIL8": "GL_DEPTH_COMPONENT32F"}
SAFE_NAME = re.compile(r"^[A-Za-z0-9_][A-Za-z0-9_.-]{0,63}$")


_TYPE_BYTES = {"GL_BYTE": 1, "GL_UNSIGNED_BYTE": 1, "GL_SHORT": 2, "GL_UNSIGNED_SHORT": 2, "GL_HALF_FLOAT": 2,
               "GL_INT": 4, "GL_UNSIGNED_INT": 4, "GL_FLOAT": 4, "GL_FIXED": 4, "GL_DOUBLE": 8}


def _element_bytes(size, gl_type):
    """A vertex array element's bytes: what stride 0 (tightly packed) steps by."""
    if gl_type not in _TYPE_BYTES:  # the packed 32-bit formats
        return 4
    return (4 if size == "GL_BGRA" else size) * _TYPE_BYTES[gl_type]


def gl_name(value, what):
    """An object's GL name (a GLuint), which file names are made of."""
    if isinstance(value, bool) or not isinstance(value, int) or not 0 <= value < 1 << 32:
        raise ImportFailure("%s %r is not a GL object name" % (what, value))
    return value


def _gl_lower(value):
    return str(value).replace("GL_", "").lower()


class GpuWritten(Exception):
    """A draw reads what the GPU wrote: a trace holds the calls, not those bytes."""


class Files:
    """The files a scene refers to, each written once: name -> bytes."""

    def __init__(self):
        self.contents = {}
        self._by_hash = {}
        self._versions = {}

    def add(self, stem, suffix, data):
        if isinstance(data, str):
            data = data.encode("utf-8")
        digest = hashlib.sha256(data).hexdigest()
        key = (stem, suffix, digest)
        if key in self._by_hash:
            return self._by_hash[key]
        version = self._versions.get((stem, suffix), 0)
        self._versions[(stem, suffix)] = version + 1
        name = "%s%s.%s" % (stem, "" if version == 0 else "_v%d" % (version + 1), suffix)
        self.contents[name] = data
        self._by_hash[key] = name
        return name


class Frame:
    """What build_scene reads, from either importer: the frame's draws, the files they name, the report."""

    def __init__(self, capture_name, unit):
        self.capture_name = capture_name
        self.unit = unit              # what numbers a draw in the capture: "call" or "event"
        self.files = Files()
        self.buffers = {}             # scene buffer name -> file
        self.draws = []               # (call number, draw dict, framebuffer id, framebuffer description)
        self.report = []              # (call number or None, text)
        self.call_names = {}          # call number -> the draw call's name
        self.draw_calls = []          # after build_scene: scene draw index -> capture call

    def note(self, call_no, text):
        self.report.append((call_no, text))

    def add_buffer(self, stem, data):
        """A buffer's bytes as a file of the scene; the scene's name for it."""
        name = self.files.add("buffers/" + stem, "bin", data)
        scene_name = name[len("buffers/"):-len(".bin")]
        self.buffers[scene_name] = {"file": name}
        return scene_name


class FrameScene(Frame):
    """A frame of apitrace calls, each draw taken from the tracked GL state as it is issued."""

    def __init__(self, state, capture_name):
        super().__init__(capture_name, "call")
        self.state = state
        self.pending_clear = None
        self.gpu_refusals = []        # (call number, what the draw read that the GPU wrote)

    # ---- clears ----
    def clear(self, call):
        mask = call.arg("mask")
        bits = set(mask) if isinstance(mask, (tuple, list)) else {mask}
        clear = dict(self.pending_clear or {})
        if "GL_COLOR_BUFFER_BIT" in bits:
            clear["color"] = list(self.state.clear_color)
        if "GL_DEPTH_BUFFER_BIT" in bits:
            clear["depth"] = self.state.clear_depth
        if "GL_STENCIL_BUFFER_BIT" in bits:
            self.note(call.no, "glClear of the stencil buffer: tessref has no stencil buffer")
        clear["_state"] = self._clear_state()
        clear["_framebuffer"] = self.state.draw_framebuffer
        self.pending_clear = clear

    def _clear_state(self):
        s = self.state
        return ("GL_SCISSOR_TEST" in s.caps, s.scissor, s.color_mask, s.depth_mask)

    # ---- buffers ----
    def buffer(self, call_no, buffer_id, what, offset=0, size=None):
        written = self.state.gpu_written_buffers.get(buffer_id)
        if written is not None:
            raise GpuWritten("%s reads buffer %s, which was %s at call %d" % (what, buffer_id, written[1], written[0]))
        b = self.state.buffers.get(buffer_id)
        if b is None:
            raise ImportFailure("call %d: %s reads buffer %s, which does not exist" % (call_no, what, buffer_id))
        data = bytes(b.data if size is None and offset == 0 else b.data[offset:offset + size if size else None])
        return self.add_buffer("b%d" % gl_name(buffer_id, "buffer") + ("_at%d" % offset if offset else ""), data)

    # ---- one draw ----
    def draw(self, call):
        s = self.state
        program = s.programs.get(s.program)
        if s.pipeline_bound or program is None or not program.linked:
            self.note(call.no, "%s without a linked program in use (program pipelines are not in tessref's scenes yet): "
                      "not carried" % call.name)
            return
        stages = program.linked
        for stage in stages:
            if stage not in STAGE_FILES:
                self.note(call.no, "%s: the program has a %s shader, which tessref does not run yet: not carried"
                          % (call.name, stage))
                return
            if len(stages[stage]) != 1:
                self.note(call.no, "%s: the program links %d %s shader objects; tessref's scenes take one per stage: "
                          "not carried" % (call.name, len(stages[stage]), stage))
                return
        sources = {stage: stages[stage][0] for stage in stages}
        declarations = Declarations(sources.values())
        d = {}
        mode = call.arg("mode")
        d["mode"] = mode
        try:
            shaders = self._shaders(call, program, sources, declarations, d)
            if shaders is None:
                return
            d["shaders"] = shaders
            if not self._vertex_input(call, program, d):
                return
            if not self._call(call, d):
                return
        except GpuWritten as e:
            self.gpu_refusals.append((call.no, str(e)))
            self.note(call.no, "%s: %s: not carried" % (call.name, e))
            return
        self._fixed_function(call, d)
        fb = self._framebuffer(call)
        if self.pending_clear is not None:
            clear = self.pending_clear
            self.pending_clear = None
            if clear["_framebuffer"] == s.draw_framebuffer:
                if clear["_state"] != self._clear_state():
                    self.note(call.no, "the glClear before this draw ran with another scissor box or write mask than "
                              "the draw's: the scene clears with the draw's")
                d["clear"] = {k: v for k, v in clear.items() if not k.startswith("_")}
        self.draws.append((call.no, d, s.draw_framebuffer, fb))
        self.call_names[call.no] = call.name

    def _shaders(self, call, program, sources, declarations, d):
        s = self.state
        shaders = {}
        for stage, source in sources.items():
            for (kind, block), declared in declarations.blocks.items():
                bound = program.block_bindings.get((kind, block))
                if bound is not None and bound != declared:
                    source = with_block_binding(source, kind, block, bound)
                    self.note(call.no, "%s block %s: glUniformBlockBinding / glShaderStorageBlockBinding set binding %d; "
                              "the scene's copy of the %s shader says layout(binding = %d) on the block's line"
                              % (kind, block, bound, stage, bound))
                elif declared is None:
                    source = with_block_binding(source, kind, block, 0)
                    self.note(call.no, "%s block %s has no binding: GL's default 0, written as layout(binding = 0) "
                              "in the scene's copy of the %s shader" % (kind, block, stage))
            shader_ids = program.shader_labels.get(stage, [None])
            shader_id = shader_ids[0]
            label = s.shaders[shader_id].label if shader_id in s.shaders else None
            stem = "p%d" % gl_name(s.program, "program")
            if label:
                if not SAFE_NAME.match(label) or ".." in label:
                    raise ImportFailure("shader %s's label %r names a path outside the output folder: refused"
                                        % (shader_id, label))
                stem = label.rsplit(".", 1)[0]
            shaders[stage] = self.files.add("shaders/" + stem, STAGE_FILES[stage], source)
        uniforms, textures = {}, {}
        names = dict(program.uniform_names)
        for location, name in declarations.uniform_locations.items():
            names.setdefault(location, name)
        sampler_units = {}
        for location, (fname, values, count) in sorted(program.uniform_values.items()):
            name = names.get(location)
            if name is None:
                self.note(call.no, "%s at location %d: the application never asked glGetUniformLocation for its name "
                          "and the GLSL gives it no layout(location): not carried" % (fname, location))
                continue
            base = name.split("[")[0]
            if base in declarations.samplers:
                sampler_units[base] = values[0]
                continue
            uniforms[name] = values
        for name, (glsl_type, binding, array) in sorted(declarations.samplers.items()):
            if array:
                self.note(call.no, "sampler array %s: not carried yet" % name)
                continue
            unit = sampler_units.get(name, binding if binding is not None else 0)
            target = sampler_target(glsl_type)
            texture = self._texture(call, unit, target, name)
            if texture is not None:
                textures[name] = texture
        if uniforms:
            shaders["uniforms"] = uniforms
        if textures:
            shaders["textures"] = textures
        for kind, key, target in (("uniform", "uniform_buffers", "GL_UNIFORM_BUFFER"),
                                  ("buffer", "shader_storage_buffers", "GL_SHADER_STORAGE_BUFFER")):
            ranges = []
            for (block_kind, block), declared in sorted(declarations.blocks.items()):
                if block_kind != kind:
                    continue
                binding = program.block_bindings.get((kind, block), declared if declared is not None else 0)
                bound = s.indexed.get((target, binding))
                if bound is None or not bound[0]:
                    self.note(call.no, "%s block %s: nothing is bound at binding %d" % (kind, block, binding))
                    continue
                buffer_id, offset, size = bound
                length = len(s.buffers[buffer_id].data) if buffer_id in s.buffers else 0
                if size is None:
                    size = length - offset
                if offset % 256:
                    # tessref's scenes take offsets that every driver's alignment allows; the range's
                    # bytes, cut out, read the same.
                    name = self.buffer(call.no, buffer_id, "%s block %s" % (kind, block), offset, size)
                    ranges.append({"binding": binding, "buffer": name, "offset": 0, "size": size})
                else:
                    name = self.buffer(call.no, buffer_id, "%s block %s" % (kind, block))
                    ranges.append({"binding": binding, "buffer": name, "offset": offset, "size": size})
            if ranges:
                d[key] = ranges
        return shaders

    def _texture(self, call, unit, target, sampler):
        s = self.state
        if target is None:
            self.note(call.no, "sampler %s: its type is not one tessref's scenes take" % sampler)
            return None
        tid = s.units.get((unit, target), 0)
        t = s.textures.get(tid)
        if not tid or t is None:
            self.note(call.no, "sampler %s reads unit %d, where no %s texture is bound (GL: an incomplete texture): "
                      "not carried" % (sampler, unit, target))
            return None
        entry = {"target": target}
        if tid in s.gpu_written_textures:
            at, how = s.gpu_written_textures[tid]
            raise GpuWritten("sampler %s reads texture %d, which was %s at call %d" % (sampler, tid, how, at))
        if target == "GL_TEXTURE_BUFFER":
            if t.buffer is None:
                self.note(call.no, "sampler %s: buffer texture %d has no buffer" % (sampler, tid))
                return None
            internalformat, buffer_id, offset, size = t.buffer
            if offset % 256:
                entry["buffer"] = self.buffer(call.no, buffer_id, "sampler " + sampler, offset, size)
            else:
                entry["buffer"] = self.buffer(call.no, buffer_id, "sampler " + sampler)
                entry["offset"] = offset
                if size is not None:
                    entry["size"] = size
            entry["internalformat"] = internalformat
            return entry
        faces = 6 if target == "GL_TEXTURE_CUBE_MAP" else 1
        base = t.images.get((0, 0))
        if base is None:
            self.note(call.no, "sampler %s: texture %d has no level 0 (GL: incomplete): not carried" % (sampler, tid))
            return None
        internalformat = base["internalformat"]
        w, h, depth = base["size"]
        entry["internalformat"] = internalformat
        entry["raw_size"] = {"GL_TEXTURE_1D": [w], "GL_TEXTURE_1D_ARRAY": [w, h], "GL_TEXTURE_2D_ARRAY": [w, h, depth],
                             "GL_TEXTURE_3D": [w, h, depth], "GL_TEXTURE_CUBE_MAP_ARRAY": [w, h, depth]}.get(target, [w, h])
        levels = []
        level = 0
        while all((level, f) in t.images for f in range(faces)):
            images = [t.images[(level, f)] for f in range(faces)]
            if any(i["internalformat"] != internalformat for i in images):
                self.note(call.no, "sampler %s: texture %d's level %d has another internal format (GL: incomplete)"
                          % (sampler, tid, level))
                break
            levels.append(b"".join(level_data(i) for i in images))
            level += 1
        generated = t.generated_after is not None and t.generated_after == t.uploads
        stem = "textures/t%d" % gl_name(tid, "texture")
        if generated:
            entry["path"] = self.files.add(stem + "_level0", "raw", levels[0])
            entry["generate_mipmap"] = True
        elif target == "GL_TEXTURE_RECTANGLE" or len(levels) == 1:
            entry["path"] = self.files.add(stem + "_level0", "raw", levels[0])
        else:
            entry["levels"] = [self.files.add("%s_level%d" % (stem, k), "raw", data) for k, data in enumerate(levels)]
        entry.update(self._sampler_keys(call, t.params, target, sampler, initial=True))
        sampler_object = s.sampler_units.get(unit, 0)
        if sampler_object:
            entry["sampler"] = self._sampler_keys(call, s.samplers.get(sampler_object, {}), target, sampler, initial=False)
        if generated and t.storage_levels is not None and entry.get("max_level", 1000) > t.storage_levels - 1:
            # glTexStorage's levels end the chain that glGenerateMipmap fills; the scene's generated
            # chain runs to 1 x 1, so it stops where the storage does.
            entry["max_level"] = t.storage_levels - 1
        return entry

    def _sampler_keys(self, call, params, target, sampler, initial):
        out = {}
        if initial:  # the scene's own defaults differ from GL's initial state: say GL's
            rectangle = target == "GL_TEXTURE_RECTANGLE"
            out["min_filter"] = "linear" if rectangle else "nearest_mipmap_linear"
            out["mag_filter"] = "linear"
            for k in ("wrap_s", "wrap_t", "wrap_r"):
                out[k] = "clamp_to_edge" if rectangle else "repeat"
        keys = {"GL_TEXTURE_MIN_FILTER": "min_filter", "GL_TEXTURE_MAG_FILTER": "mag_filter",
                "GL_TEXTURE_WRAP_S": "wrap_s", "GL_TEXTURE_WRAP_T": "wrap_t", "GL_TEXTURE_WRAP_R": "wrap_r",
                "GL_TEXTURE_COMPARE_MODE": "compare_mode", "GL_TEXTURE_COMPARE_FUNC": "compare_func"}
        numbers = {"GL_TEXTURE_MIN_LOD": "min_lod", "GL_TEXTURE_MAX_LOD": "max_lod", "GL_TEXTURE_LOD_BIAS": "lod_bias",
                   "GL_TEXTURE_BASE_LEVEL": "base_level", "GL_TEXTURE_MAX_LEVEL": "max_level"}
        swizzle = {}
        for pname, value in params.items():
            if pname in keys:
                out[keys[pname]] = _gl_lower(value)
            elif pname in numbers:
                out[numbers[pname]] = value
            elif pname == "GL_TEXTURE_BORDER_COLOR":
                out["border_color"] = list(value)
            elif pname.startswith("GL_TEXTURE_SWIZZLE_"):
                if pname == "GL_TEXTURE_SWIZZLE_RGBA":
                    swizzle.update(zip("rgba", value))
                else:
                    swizzle[pname[-1].lower()] = value
            elif pname == "GL_TEXTURE_MAX_ANISOTROPY" and float(value) <= 1.0:
                pass
            else:
                self.note(call.no, "sampler %s: %s = %r is not carried" % (sampler, pname, value))
        if swizzle:
            names = {"GL_RED": "red", "GL_GREEN": "green", "GL_BLUE": "blue", "GL_ALPHA": "alpha", "GL_ZERO": "zero",
                     "GL_ONE": "one"}
            defaults = {"r": "GL_RED", "g": "GL_GREEN", "b": "GL_BLUE", "a": "GL_ALPHA"}
            out["swizzle"] = [names.get(swizzle.get(c, defaults[c]), "red") for c in "rgba"]
        return out

    def _vertex_input(self, call, program, d):
        s = self.state
        vao = s.vertex_arrays.get(s.vao)
        arrays = {}
        inputs = sorted(program.attribs.items(), key=lambda kv: kv[1])
        if not inputs:  # no record of the linked attributes: every enabled array, by location
            inputs = [(str(i), i) for i, a in sorted(vao.attribs.items()) if a.enabled]
        for name, index in inputs:
            a = vao.attribs.get(index)
            if a is None or not a.enabled:
                current = s.current_attrib.get(index)
                arrays[name] = {"enabled": False, "current": list(current) if current else [0.0, 0.0, 0.0, 1.0]}
                continue
            b = vao.binding(a.binding)
            if not b.buffer:
                self.note(call.no, "input %s reads client memory: not carried" % name)
                return False
            if b.explicit_stride and b.stride == 0:
                self.note(call.no, "input %s: glBindVertexBuffer with stride 0 (every vertex reads one element) is "
                          "not in tessref's scenes: not carried" % name)
                return False
            entry = {"buffer": self.buffer(call.no, b.buffer, "input " + name),
                     "size": a.size if a.size != "GL_BGRA" else "GL_BGRA", "type": a.type}
            if a.normalized:
                entry["normalized"] = True
            if b.stride and b.stride != _element_bytes(a.size, a.type):  # the packed stride is the scene's default
                entry["stride"] = b.stride
            if b.offset + a.relative_offset:
                entry["offset"] = b.offset + a.relative_offset
            if a.pointer != "glVertexAttribPointer":
                entry["pointer"] = a.pointer
            if b.divisor:
                entry["divisor"] = b.divisor
            arrays[name] = entry
        if arrays:
            d["vertex_arrays"] = arrays
        return True

    def _indirect_commands(self, call, elements):
        """The commands an indirect draw reads from GL_DRAW_INDIRECT_BUFFER: (count, instancecount,
        first or firstIndex, basevertex, baseinstance) each, as GL 4.5 10.4 lays them out."""
        s = self.state
        buffer_id = s.bound.get("GL_DRAW_INDIRECT_BUFFER", 0)
        if not buffer_id or buffer_id not in s.buffers:
            raise ImportFailure("call %d (%s): no GL_DRAW_INDIRECT_BUFFER is bound" % (call.no, call.name))
        if buffer_id in s.gpu_written_buffers:
            at, how = s.gpu_written_buffers[buffer_id]
            raise GpuWritten("its commands come from buffer %d, which was %s at call %d" % (buffer_id, how, at))
        size = 20 if elements else 16
        draws = call.arg("drawcount", 1)
        stride = call.arg("stride", 0) or size
        offset = int(call.arg("indirect") or 0)
        data = s.buffers[buffer_id].data
        if not isinstance(draws, int) or draws < 1 or draws > 1 << 16 or offset + stride * (draws - 1) + size > len(data):
            raise ImportFailure("call %d (%s): %r commands from byte %d run past the indirect buffer's %d bytes"
                                % (call.no, call.name, draws, offset, len(data)))
        commands = []
        for k in range(draws):
            at = offset + k * stride
            if elements:
                count, instances, first, base_vertex, base_instance = struct.unpack_from("<IIIiI", data, at)
            else:
                count, instances, first, base_instance = struct.unpack_from("<IIII", data, at)
                base_vertex = 0
            commands.append((count, instances, first, base_vertex, base_instance))
        return commands

    def _commands(self, call, elements):
        """Every command of a draw call: (count, instancecount, first or index byte offset,
        basevertex, baseinstance), or None for a form not carried."""
        name = call.name
        if "Indirect" in name:
            size = {"GL_UNSIGNED_BYTE": 1, "GL_UNSIGNED_SHORT": 2, "GL_UNSIGNED_INT": 4}.get(call.arg("type"), 1)
            return [(n, i, f * size if elements else f, v, b) for n, i, f, v, b in self._indirect_commands(call, elements)]
        if name.startswith("glMultiDraw"):
            counts = list(call.arg("count") or [])
            starts = list(call.arg("indices" if elements else "first") or [])
            bases = list(call.arg("basevertex") or [0] * len(counts))
            if not (len(counts) == len(starts) == len(bases)):
                raise ImportFailure("call %d (%s): its arrays differ in length" % (call.no, name))
            return [(n, 1, int(f or 0), v, 0) for n, f, v in zip(counts, starts, bases)]
        return [(call.arg("count"), call.arg("instancecount", 1), int(call.arg("indices" if elements else "first") or 0),
                 call.arg("basevertex", 0), call.arg("baseinstance", 0))]

    def _call(self, call, d):
        s = self.state
        name = call.name
        elements = "Elements" in name
        commands = self._commands(call, elements)
        if elements:
            vao = s.vertex_arrays.get(s.vao)
            if not vao.element_buffer:
                self.note(call.no, "%s reads indices from client memory: not carried" % name)
                return False
            # One element offset a draw: commands that start elsewhere are not one draw of the scene.
            if len({c[2] for c in commands}) != 1:
                self.note(call.no, "%s: its commands start at different indices, which one draw of the scene cannot "
                          "say: not carried" % name)
                return False
            d["elements"] = {"buffer": self.buffer(call.no, vao.element_buffer, "the element array"),
                             "type": call.arg("type"), "offset": commands[0][2]}
            if "GL_PRIMITIVE_RESTART_FIXED_INDEX" in s.caps:
                d["primitive_restart"] = "fixed_index"
            elif "GL_PRIMITIVE_RESTART" in s.caps:
                d["primitive_restart"] = s.restart_index
        calls = []
        for count, instances, first, base_vertex, base_instance in commands:
            c = {"count": count}
            if not elements:
                c["first"] = first
            if instances != 1:
                c["instancecount"] = instances
            if elements and base_vertex:
                c["basevertex"] = base_vertex
            if base_instance:
                c["baseinstance"] = base_instance
            calls.append(c)
        if len(calls) == 1:
            d.update(calls[0])
        else:
            d["calls"] = calls
        if d["mode"] == "GL_PATCHES":
            d["patch_vertices"] = s.patch_vertices
            d["patch_default_outer_level"] = list(s.patch_outer)
            d["patch_default_inner_level"] = list(s.patch_inner)
        return True

    def _fixed_function(self, call, d):
        s = self.state
        enable = sorted(c for c in s.caps if c in CARRIED_CAPS)
        for cap in sorted(s.caps - CARRIED_CAPS - HARMLESS_CAPS):
            self.note(call.no, "glEnable(%s) is not carried" % cap)
        if enable:
            d["enable"] = enable
        if s.depth_func != "GL_LESS":
            d["depth_func"] = s.depth_func
        if not s.depth_mask:
            d["depth_mask"] = False
        if s.cull_face != "GL_BACK":
            d["cull_face"] = s.cull_face
        if s.front_face != "GL_CCW":
            d["front_face"] = s.front_face
        if s.polygon_mode != "GL_FILL":
            d["polygon_mode"] = s.polygon_mode
        if "GL_SCISSOR_TEST" in s.caps:
            if s.scissor is None:
                self.note(call.no, "GL_SCISSOR_TEST without glScissor: the initial box is the first surface's size, "
                          "which the trace does not say; the scene's box is the whole image")
            else:
                d["scissor"] = list(s.scissor)
        if s.viewport is not None:
            d["viewport"] = list(s.viewport)
        if s.depth_range != [0.0, 1.0]:
            d["depth_range"] = list(s.depth_range)
        if s.color_mask != [True, True, True, True]:
            d["color_mask"] = list(s.color_mask)
        if "GL_BLEND" in s.caps:
            d["blend"] = dict(s.blend)

    def _framebuffer(self, call):
        s = self.state
        fb = s.framebuffers.get(s.draw_framebuffer)
        if s.draw_framebuffer == 0:
            size = s.largest_viewport or (0, 0)
            return {"size": size, "color": ["GL_RGBA8"], "depth": "GL_DEPTH_COMPONENT24", "default": True}
        description = {"color": [], "depth": None, "size": None, "color_names": list(fb.draw_buffers)}
        for buf in fb.draw_buffers:
            if buf == "GL_NONE":
                description["color"].append(None)
                continue
            description["color"].append(self._attachment_format(call, fb, buf, description))
        if "GL_DEPTH_ATTACHMENT" in fb.attachments or "GL_DEPTH_STENCIL_ATTACHMENT" in fb.attachments:
            key = "GL_DEPTH_ATTACHMENT" if "GL_DEPTH_ATTACHMENT" in fb.attachments else "GL_DEPTH_STENCIL_ATTACHMENT"
            description["depth"] = self._attachment_format(call, fb, key, description)
        return description

    def _attachment_format(self, call, fb, attachment, description):
        s = self.state
        a = fb.attachments.get(attachment)
        if a is None:
            return None
        if a[0] == "renderbuffer":
            r = s.renderbuffers.get(a[1])
            if r is None:
                return None
            if r.samples:
                self.note(call.no, "%s is a %d-sample renderbuffer: tessref renders one sample" % (attachment, r.samples))
            fmt, size = r.internalformat, (r.width, r.height)
        else:
            t = s.textures.get(a[1])
            image = t.images.get((a[2] or 0, 0)) if t else None
            if image is None:
                return None
            fmt, size = image["internalformat"], image["size"][:2]
        description["size"] = description["size"] or size
        return fmt


def build_scene(frame):
    """The scene JSON of the frame's draws (those into the target draw's framebuffer)."""
    target_no, target, target_fb, fb = frame.draws[-1]
    draws = []
    frame.draw_calls = []
    for no, d, fb_id, _ in frame.draws:
        if fb_id != target_fb:
            frame.note(no, "this draw renders into framebuffer %d, not into framebuffer %d where the chosen draw "
                       "renders: not carried (a frame of several render targets is not in tessref's scenes)"
                       % (fb_id, target_fb))
            continue
        draws.append(d)
        frame.draw_calls.append({"draw": len(draws) - 1, frame.unit: no, "name": frame.call_names.get(no, "")})
    size = fb["size"]
    if not size or not size[0]:
        raise ImportFailure("the framebuffer of call %d has no size the trace gives" % target_no)
    if fb.get("default"):
        frame.note(None, "the draws render into the default framebuffer: the scene takes it as GL_RGBA8 with "
                   "24-bit depth of %d x %d (the largest viewport)" % tuple(size))
    color = []
    for k, fmt in enumerate(fb["color"]):
        if fmt is None:
            raise ImportFailure("draw buffer %d of call %d's framebuffer is GL_NONE or unattached: not in tessref's "
                                "scenes" % (k, target_no))
        if fmt not in COLOR_FORMATS:
            frame.note(None, "colour attachment format %s is not one tessref renders into: the scene uses GL_RGBA32F"
                       % fmt)
            fmt = "GL_RGBA32F"
        color.append({"internalformat": fmt})
    scene = {
        "description": "imported from %s: %d draws of the frame up to call %d" % (frame.capture_name, len(draws), target_no),
        "image": {"width": size[0], "height": size[1]},
        "background": [0, 0, 0, 0],
        "shaders": {"scene_uniforms": False},
        "buffers": frame.buffers,
        "framebuffer": {"color": color},
        "draws": draws,
    }
    if fb["depth"] is not None:
        depth = DEPTH_FORMATS.get(fb["depth"])
        if depth is None:
            frame.note(None, "depth format %s is not one tessref renders into: the scene uses GL_DEPTH_COMPONENT32F"
                       % fb["depth"])
            depth = "GL_DEPTH_COMPONENT32F"
        scene["framebuffer"]["depth"] = {"internalformat": depth}
    # The framebuffer's contents before the frame's first draw matter unless that draw first
    # clears all of colour and depth.
    first = draws[0] if draws else {}
    clear = first.get("clear", {})
    whole = "scissor" not in first and first.get("color_mask", [True] * 4) == [True] * 4 and first.get("depth_mask", True)
    frame.first_draw = None if ("color" in clear and "depth" in clear and whole) else \
        next(no for no, d, fb_id, _ in frame.draws if d is first)
    return scene


def set_initial_images(frame, scene, color_files, depth_file):
    """The framebuffer's contents before the frame's first draw, as image files in DIR."""
    if color_files:
        for attachment, name in zip(scene["framebuffer"]["color"], color_files):
            if name:
                attachment["file"] = name
    if depth_file and "depth" in scene["framebuffer"]:
        scene["framebuffer"]["depth"]["file"] = depth_file
    missing = [what for what, have in (("colour", color_files and all(color_files)), ("depth", depth_file)) if not have]
    if missing:
        frame.note(None, "the frame's first draw does not begin with a clear, and the capture does not give the %s "
                   "before it: the scene starts from (0, 0, 0, 0) and depth 1 there" % " and ".join(missing))

