"""A RenderDoc capture's frame as tessref's scene of draws, through RenderDoc's python module
(Debian package python3-renderdoc, which imports in Debian's /usr/bin/python3 only).

RenderDoc replays the capture on the system's GL driver and says, at each draw, the state the
driver saw: the program's sources per shader object, every active uniform's value, the vertex
input, the bound ranges and textures and the buffers' and textures' bytes as they were then. No
state is tracked here; each draw is read at its own event. The capture's texture levels are
taken as they are (RenderDoc stores a texture's contents, not the glGenerateMipmap that made its
levels).
"""

import json
import os
import struct
import shutil
import subprocess

from frame_scene import Frame, SAFE_NAME, STAGE_FILES
from glsl_declarations import Declarations, with_block_binding
from import_error import ImportFailure

STAGES = (("vertex", "Vertex"), ("tess_control", "Tess_Control"), ("tess_evaluation", "Tess_Eval"),
          ("geometry", "Geometry"), ("fragment", "Fragment"))
_TOPOLOGY = {"PointList": "GL_POINTS", "LineList": "GL_LINES", "LineStrip": "GL_LINE_STRIP", "LineLoop": "GL_LINE_LOOP",
             "TriangleList": "GL_TRIANGLES", "TriangleStrip": "GL_TRIANGLE_STRIP", "TriangleFan": "GL_TRIANGLE_FAN",
             "LineList_Adj": "GL_LINES_ADJACENCY", "LineStrip_Adj": "GL_LINE_STRIP_ADJACENCY",
             "TriangleList_Adj": "GL_TRIANGLES_ADJACENCY", "TriangleStrip_Adj": "GL_TRIANGLE_STRIP_ADJACENCY"}
# What RenderDoc's replay raises when a damaged capture gives a state GL does not reach.
_DAMAGED = (AttributeError, TypeError, KeyError, IndexError, ValueError)
_COMPARE = {"Never": "GL_NEVER", "AlwaysTrue": "GL_ALWAYS", "Less": "GL_LESS", "LessEqual": "GL_LEQUAL",
            "Greater": "GL_GREATER", "GreaterEqual": "GL_GEQUAL", "Equal": "GL_EQUAL", "NotEqual": "GL_NOTEQUAL"}
_ADDRESS = {"Wrap": "repeat", "Mirror": "mirrored_repeat", "MirrorOnce": "mirror_clamp_to_edge",
            "ClampEdge": "clamp_to_edge", "ClampBorder": "clamp_to_border"}
_BLEND_FACTOR = {"Zero": "GL_ZERO", "One": "GL_ONE", "SrcCol": "GL_SRC_COLOR", "InvSrcCol": "GL_ONE_MINUS_SRC_COLOR",
                 "DstCol": "GL_DST_COLOR", "InvDstCol": "GL_ONE_MINUS_DST_COLOR", "SrcAlpha": "GL_SRC_ALPHA",
                 "InvSrcAlpha": "GL_ONE_MINUS_SRC_ALPHA", "DstAlpha": "GL_DST_ALPHA",
                 "InvDstAlpha": "GL_ONE_MINUS_DST_ALPHA", "SrcAlphaSat": "GL_SRC_ALPHA_SATURATE",
                 "FactorRGB": "GL_CONSTANT_COLOR", "InvFactorRGB": "GL_ONE_MINUS_CONSTANT_COLOR",
                 "FactorAlpha": "GL_CONSTANT_ALPHA", "InvFactorAlpha": "GL_ONE_MINUS_CONSTANT_ALPHA"}
_BLEND_OP = {"Add": "GL_FUNC_ADD", "Subtract": "GL_FUNC_SUBTRACT", "ReversedSubtract": "GL_FUNC_REVERSE_SUBTRACT",
             "Minimum": "GL_MIN", "Maximum": "GL_MAX"}
_SWIZZLE = {"Red": "red", "Green": "green", "Blue": "blue", "Alpha": "alpha", "Zero": "zero", "One": "one"}
_TEXTURE_TARGETS = {"Texture1D": "GL_TEXTURE_1D", "Texture1DArray": "GL_TEXTURE_1D_ARRAY", "Texture2D": "GL_TEXTURE_2D",
                    "TextureRect": "GL_TEXTURE_RECTANGLE", "Texture2DArray": "GL_TEXTURE_2D_ARRAY",
                    "Texture3D": "GL_TEXTURE_3D", "TextureCube": "GL_TEXTURE_CUBE_MAP",
                    "TextureCubeArray": "GL_TEXTURE_CUBE_MAP_ARRAY"}


def _rid(resource_id):
    return str(resource_id).rsplit("::", 1)[-1]


def internal_format(fmt):
    """The GL sized internal format of a RenderDoc ResourceFormat, or None."""
    special = fmt.type.name
    if special == "R11G11B10":
        return "GL_R11F_G11F_B10F"
    if special == "R9G9B9E5":
        return "GL_RGB9_E5"
    if special == "R10G10B10A2" and fmt.compType.name == "UInt":
        return "GL_RGB10_A2UI"
    if special in ("D16S8", "D24S8", "D32S8"):
        return {"D24S8": "GL_DEPTH24_STENCIL8"}.get(special)
    if special != "Regular":
        return None
    comp = fmt.compType.name
    if comp == "Depth":
        return {2: "GL_DEPTH_COMPONENT16", 3: "GL_DEPTH_COMPONENT24", 4: "GL_DEPTH_COMPONENT32F"}.get(fmt.compByteWidth)
    prefix = {1: "GL_R", 2: "GL_RG", 3: "GL_RGB", 4: "GL_RGBA"}[fmt.compCount]
    bits = 8 * fmt.compByteWidth
    if comp == "UNormSRGB" or (comp == "UNorm" and fmt.SRGBCorrected()):
        return {3: "GL_SRGB8", 4: "GL_SRGB8_ALPHA8"}.get(fmt.compCount) if bits == 8 else None
    suffix = {"UNorm": "", "SNorm": "_SNORM", "Float": "F", "UInt": "UI", "SInt": "I"}.get(comp)
    if suffix is None or (suffix == "F" and bits == 8):
        return None
    return "%s%d%s" % (prefix, bits, suffix)


def attribute_format(fmt, float_cast):
    """(size, type, normalized, pointer) of glVertexAttrib*Pointer for a vertex input's format."""
    special = fmt.type.name
    size = "GL_BGRA" if fmt.BGRAOrder() else fmt.compCount
    comp = fmt.compType.name
    if special == "R10G10B10A2":
        signed = comp in ("SNorm", "SInt", "SScaled")
        return size, "GL_INT_2_10_10_10_REV" if signed else "GL_UNSIGNED_INT_2_10_10_10_REV", comp in ("UNorm", "SNorm"), \
            "glVertexAttribPointer"
    if special == "R11G11B10":
        return 3, "GL_UNSIGNED_INT_10F_11F_11F_REV", False, "glVertexAttribPointer"
    if special != "Regular":
        return None
    width = fmt.compByteWidth
    if comp == "Float":
        if width == 8:
            return size, "GL_DOUBLE", False, "glVertexAttribPointer" if float_cast else "glVertexAttribLPointer"
        return size, {2: "GL_HALF_FLOAT", 4: "GL_FLOAT"}[width], False, "glVertexAttribPointer"
    signed = comp in ("SNorm", "SInt", "SScaled")
    gl_type = {1: "GL_BYTE", 2: "GL_SHORT", 4: "GL_INT"}[width]
    if not signed:
        gl_type = gl_type.replace("GL_", "GL_UNSIGNED_")
    if comp in ("UInt", "SInt") and not float_cast:
        return size, gl_type, False, "glVertexAttribIPointer"
    return size, gl_type, comp in ("UNorm", "SNorm"), "glVertexAttribPointer"


class _Reader:
    def __init__(self, rd, ctl, frame):
        self.rd, self.ctl, self.frame = rd, ctl, frame
        self.textures = {_rid(t.resourceId): t for t in ctl.GetTextures()}
        self.resources = {_rid(r.resourceId): r for r in ctl.GetResources()}

    def buffer(self, resource_id, offset=0, size=None):
        data = bytes(self.ctl.GetBufferData(resource_id, 0, 0))
        if offset or size is not None:
            data = data[offset:offset + size if size is not None else None]
        return self.frame.add_buffer("b%s" % _rid(resource_id) + ("_at%d" % offset if offset else ""), data)

    # ---- one draw, at its event ----
    def draw(self, action, name, clear):
        rd, ctl, frame = self.rd, self.ctl, self.frame
        event = action.eventId
        ctl.SetFrameEvent(event, True)
        pipe, gl = ctl.GetPipelineState(), ctl.GetGLPipelineState()
        d = {}
        topology = gl.vertexInput.topology.name
        if topology.startswith("PatchList"):
            d["mode"] = "GL_PATCHES"
            patch_vertices = 1 if topology == "PatchList" else int(topology[len("PatchList_"):-len("CPs")])
        elif topology in _TOPOLOGY:
            d["mode"] = _TOPOLOGY[topology]
        else:
            frame.note(event, "%s: topology %s is not in tessref's scenes: not carried" % (name, topology))
            return
        shaders = self._program(event, pipe, gl, d)
        if shaders is None:
            return
        d["shaders"] = shaders
        if not self._vertex_input(event, pipe, gl, d):
            return
        flags = action.flags
        if flags & rd.ActionFlags.Indexed:
            stride = gl.vertexInput.indexByteStride
            d["elements"] = {"buffer": self.buffer(gl.vertexInput.indexBuffer),
                             "type": {1: "GL_UNSIGNED_BYTE", 2: "GL_UNSIGNED_SHORT", 4: "GL_UNSIGNED_INT"}[stride],
                             "offset": action.indexOffset * stride}
            if gl.vertexInput.primitiveRestart:
                restart = gl.vertexInput.restartIndex
                d["primitive_restart"] = "fixed_index" if restart == (1 << (8 * stride)) - 1 else restart
        else:
            d["first"] = action.vertexOffset
        d["count"] = action.numIndices
        # RenderDoc gives a multi-draw's commands as child actions with numInstances 0 and no
        # Instanced flag: they draw one instance.
        if flags & rd.ActionFlags.Instanced and action.numInstances != 1:
            d["instancecount"] = action.numInstances
        if flags & rd.ActionFlags.Indexed and action.baseVertex:
            d["basevertex"] = action.baseVertex
        if action.instanceOffset:
            d["baseinstance"] = action.instanceOffset
        if d["mode"] == "GL_PATCHES":
            d["patch_vertices"] = patch_vertices
            d["patch_default_outer_level"] = list(gl.vertexProcessing.defaultOuterLevel)
            d["patch_default_inner_level"] = list(gl.vertexProcessing.defaultInnerLevel)
        self._fixed_function(event, gl, d)
        if clear:
            d["clear"] = clear
        fb = self._framebuffer(event, gl)
        frame.draws.append((event, d, _rid(gl.framebuffer.drawFBO.resourceId), fb))
        frame.call_names[event] = name

    def _program(self, event, pipe, gl, d):
        rd, frame = self.rd, self.frame
        sources, reflections = {}, {}
        for stage, rd_name in STAGES:
            refl = pipe.GetShaderReflection(getattr(rd.ShaderStage, rd_name))
            if refl is None:
                continue
            files = refl.debugInfo.files
            if len(files) != 1:
                frame.note(event, "the %s stage links %d shader objects; tessref's scenes take one per stage: not "
                           "carried" % (stage, len(files)))
                return None
            sources[stage] = files[0].contents
            reflections[stage] = refl
        declarations = Declarations(sources.values())
        shaders, uniforms, textures = {}, {}, {}
        ranges = {}
        for stage, rd_name in STAGES:
            if stage not in sources:
                continue
            rd_stage = getattr(rd.ShaderStage, rd_name)
            refl = reflections[stage]
            mapping = pipe.GetBindpointMapping(rd_stage)
            source = sources[stage]
            for i, block in enumerate(refl.constantBlocks):
                if not block.bufferBacked:
                    for v in self.ctl.GetCBufferVariableContents(pipe.GetGraphicsPipelineObject(), refl.resourceId,
                                                                 rd_stage, pipe.GetShaderEntryPoint(rd_stage), i,
                                                                 rd.ResourceId.Null(), 0, 0):
                        _uniform_values(v, v.name, uniforms)
                    continue
                binding = mapping.constantBlocks[block.bindPoint].bind
                declared = declarations.blocks.get(("uniform", block.name))
                if declared != binding and ("uniform", block.name) in declarations.blocks:
                    source = with_block_binding(source, "uniform", block.name, binding)
                    frame.note(event, "uniform block %s is at binding %d: the scene's copy of the %s shader says "
                               "layout(binding = %d) on the block's line" % (block.name, binding, stage, binding))
                bound = pipe.GetConstantBuffer(rd_stage, i, 0)
                ranges[binding] = (bound.resourceId, bound.byteOffset, bound.byteSize)
            for resource in refl.readOnlyResources:
                unit = mapping.readOnlyResources[resource.bindPoint].bind
                if not resource.isTexture:
                    continue
                texture = self._texture(event, gl, unit, resource)
                if texture is not None:
                    textures[resource.name] = texture
            if refl.readWriteResources:
                frame.note(event, "the %s shader writes images or storage buffers: not carried" % stage)
                return None
            label = self._label(refl.resourceId)
            stem = "p%s" % _rid(self._stage_state(gl, stage).programResourceId)
            if label:
                if not SAFE_NAME.match(label) or ".." in label:
                    raise ImportFailure("shader %s's label %r names a path outside the output folder: refused"
                                        % (_rid(refl.resourceId), label))
                stem = label.rsplit(".", 1)[0]
            shaders[stage] = self.frame.files.add("shaders/" + stem, STAGE_FILES[stage], source)
        if uniforms:
            shaders["uniforms"] = uniforms
        if textures:
            shaders["textures"] = textures
        if ranges:
            d["uniform_buffers"] = []
            for binding, (resource_id, offset, size) in sorted(ranges.items()):
                if offset % 256:
                    d["uniform_buffers"].append({"binding": binding, "buffer": self.buffer(resource_id, offset, size),
                                                 "offset": 0, "size": size})
                else:
                    d["uniform_buffers"].append({"binding": binding, "buffer": self.buffer(resource_id),
                                                 "offset": offset, "size": size})
        return shaders

    @staticmethod
    def _stage_state(gl, stage):
        return {"vertex": gl.vertexShader, "tess_control": gl.tessControlShader,
                "tess_evaluation": gl.tessEvalShader, "geometry": gl.geometryShader, "fragment": gl.fragmentShader}[stage]

    def _label(self, resource_id):
        r = self.resources.get(_rid(resource_id))
        return None if r is None or r.autogeneratedName else r.name

    def _texture(self, event, gl, unit, resource):
        rd, frame = self.rd, self.frame
        bound = gl.textures[unit]
        description = self.textures.get(_rid(bound.resourceId))
        target = _TEXTURE_TARGETS.get(resource.resType.name)
        if description is None or target is None:
            frame.note(event, "sampler %s on unit %d: no texture tessref's scenes take (%s)"
                       % (resource.name, unit, resource.resType.name))
            return None
        fmt = internal_format(description.format)
        if fmt is None or fmt.startswith("GL_DEPTH"):
            frame.note(event, "sampler %s: texture format %s is not carried from RenderDoc captures yet"
                       % (resource.name, description.format.Name()))
            return None
        layers = description.arraysize
        entry = {"target": target, "internalformat": fmt}
        w, h, depth = description.width, description.height, description.depth
        entry["raw_size"] = {"GL_TEXTURE_1D": [w], "GL_TEXTURE_1D_ARRAY": [w, layers],
                             "GL_TEXTURE_2D_ARRAY": [w, h, layers], "GL_TEXTURE_3D": [w, h, depth],
                             "GL_TEXTURE_CUBE_MAP_ARRAY": [w, h, layers]}.get(target, [w, h])
        levels = []
        for mip in range(description.mips):
            data = b"".join(bytes(self.ctl.GetTextureData(bound.resourceId, rd.Subresource(mip, s, 0)))
                            for s in range(max(1, layers) if target not in ("GL_TEXTURE_3D",) else 1))
            levels.append(frame.files.add("textures/t%s_level%d" % (_rid(bound.resourceId), mip), "raw", data))
        if len(levels) == 1:
            entry["path"] = levels[0]
        else:
            entry["levels"] = levels
        sampler = gl.samplers[unit]
        minify, magnify, mip = (sampler.filter.minify.name, sampler.filter.magnify.name, sampler.filter.mip.name)
        base = "nearest" if minify == "Point" else "linear"
        entry["min_filter"] = base if mip == "NoFilter" else base + ("_mipmap_nearest" if mip == "Point" else "_mipmap_linear")
        entry["mag_filter"] = "nearest" if magnify == "Point" else "linear"
        for key, mode in (("wrap_s", sampler.addressS), ("wrap_t", sampler.addressT), ("wrap_r", sampler.addressR)):
            entry[key] = _ADDRESS.get(mode.name, "repeat")
        if "clamp_to_border" in (entry["wrap_s"], entry["wrap_t"], entry["wrap_r"]):
            entry["border_color"] = list(sampler.borderColor)
        if sampler.minLOD != -1000.0:
            entry["min_lod"] = sampler.minLOD
        if sampler.maxLOD != 1000.0:
            entry["max_lod"] = sampler.maxLOD
        if sampler.mipLODBias:
            entry["lod_bias"] = sampler.mipLODBias
        if sampler.filter.filter.name == "Comparison":
            entry["compare_mode"] = "compare_ref_to_texture"
            entry["compare_func"] = _COMPARE[sampler.compareFunction.name].replace("GL_", "").lower()
        if sampler.maxAnisotropy > 1.0:
            frame.note(event, "sampler %s: anisotropic filtering (%g) is not carried" % (resource.name,
                                                                                        sampler.maxAnisotropy))
        if bound.firstMip:
            entry["base_level"] = bound.firstMip
        if bound.numMips and bound.firstMip + bound.numMips - 1 < 1000:
            entry["max_level"] = bound.firstMip + bound.numMips - 1
        swizzle = bound.swizzle
        names = [_SWIZZLE[c.name] for c in (swizzle.red, swizzle.green, swizzle.blue, swizzle.alpha)]
        if names != ["red", "green", "blue", "alpha"]:
            entry["swizzle"] = names
        return entry

    def _vertex_input(self, event, pipe, gl, d):
        rd, frame = self.rd, self.frame
        refl = pipe.GetShaderReflection(rd.ShaderStage.Vertex)
        arrays = {}
        for signature in refl.inputSignature:
            if signature.varName.startswith("gl_"):
                continue
            location = signature.regIndex
            a = gl.vertexInput.attributes[location]
            if not a.enabled:
                arrays[signature.varName] = {"enabled": False, "current": list(a.genericValue.floatValue)}
                continue
            vb = gl.vertexInput.vertexBuffers[a.vertexBufferSlot]
            layout = attribute_format(a.format, a.floatCast)
            if layout is None:
                frame.note(event, "input %s: format %s is not carried" % (signature.varName, a.format.Name()))
                return False
            size, gl_type, normalized, pointer = layout
            entry = {"buffer": self.buffer(vb.resourceId), "size": size, "type": gl_type}
            if normalized:
                entry["normalized"] = True
            element = a.format.ElementSize()
            if vb.byteStride and vb.byteStride != element:
                entry["stride"] = vb.byteStride
            if vb.byteOffset + a.byteOffset:
                entry["offset"] = vb.byteOffset + a.byteOffset
            if pointer != "glVertexAttribPointer":
                entry["pointer"] = pointer
            if vb.instanceDivisor:
                entry["divisor"] = vb.instanceDivisor
            arrays[signature.varName] = entry
        if arrays:
            d["vertex_arrays"] = arrays
        return True

    def _fixed_function(self, event, gl, d):
        frame = self.frame
        enable = []
        depth = gl.depthState
        if depth.depthEnable:
            enable.append("GL_DEPTH_TEST")
        if _COMPARE[depth.depthFunction.name] != "GL_LESS":
            d["depth_func"] = _COMPARE[depth.depthFunction.name]
        if not depth.depthWrites:
            d["depth_mask"] = False
        state = gl.rasterizer.state
        if state.cullMode.name != "NoCull":
            enable.append("GL_CULL_FACE")
            cull = {"Front": "GL_FRONT", "Back": "GL_BACK", "FrontAndBack": "GL_FRONT_AND_BACK"}[state.cullMode.name]
            if cull != "GL_BACK":
                d["cull_face"] = cull
        if not state.frontCCW:
            d["front_face"] = "GL_CW"
        if state.fillMode.name != "Solid":
            d["polygon_mode"] = {"Wireframe": "GL_LINE", "Point": "GL_POINT"}[state.fillMode.name]
        if state.depthClamp:
            enable.append("GL_DEPTH_CLAMP")
        if state.depthBias or state.slopeScaledDepthBias:
            frame.note(event, "polygon offset is not carried")
        scissor = gl.rasterizer.scissors[0]
        if scissor.enabled:
            enable.append("GL_SCISSOR_TEST")
            d["scissor"] = [scissor.x, scissor.y, scissor.width, scissor.height]
        viewport = gl.rasterizer.viewports[0]
        d["viewport"] = [int(viewport.x), int(viewport.y), int(viewport.width), int(viewport.height)]
        if (viewport.minDepth, viewport.maxDepth) != (0.0, 1.0):
            d["depth_range"] = [viewport.minDepth, viewport.maxDepth]
        blend = gl.framebuffer.blendState.blends[0]
        mask = blend.writeMask
        if mask != 15:
            d["color_mask"] = [bool(mask & 1), bool(mask & 2), bool(mask & 4), bool(mask & 8)]
        if blend.enabled:
            enable.append("GL_BLEND")
            d["blend"] = {"equation": _BLEND_OP[blend.colorBlend.operation.name],
                          "equation_alpha": _BLEND_OP[blend.alphaBlend.operation.name],
                          "src": _BLEND_FACTOR[blend.colorBlend.source.name],
                          "dst": _BLEND_FACTOR[blend.colorBlend.destination.name],
                          "src_alpha": _BLEND_FACTOR[blend.alphaBlend.source.name],
                          "dst_alpha": _BLEND_FACTOR[blend.alphaBlend.destination.name],
                          "color": list(gl.framebuffer.blendState.blendFactor)}
        if gl.framebuffer.framebufferSRGB:
            enable.append("GL_FRAMEBUFFER_SRGB")
        if any(s.seamlessCubeMap for s in gl.samplers):
            enable.append("GL_TEXTURE_CUBE_MAP_SEAMLESS")
        if gl.stencilState.stencilEnable:
            frame.note(event, "the stencil test is not carried")
        if enable:
            d["enable"] = sorted(enable)

    def _framebuffer(self, event, gl):
        fbo = gl.framebuffer.drawFBO
        description = {"color": [], "depth": None, "size": None}
        for index in fbo.drawBuffers:
            if index < 0:
                break
            attachment = fbo.colorAttachments[index]
            t = self.textures.get(_rid(attachment.resourceId))
            if t is None:
                description["color"].append(None)
                continue
            description["color"].append(internal_format(t.format))
            description["size"] = description["size"] or (t.width, t.height)
        t = self.textures.get(_rid(fbo.depthAttachment.resourceId))
        if t is not None:
            description["depth"] = internal_format(t.format)
            description["size"] = description["size"] or (t.width, t.height)
        return description


def _uniform_values(v, name, out):
    """Every leaf of a $Globals ShaderVariable, by the name glGetUniformLocation takes."""
    if v.members:
        is_array = all(m.name.startswith("[") or m.name.startswith(v.name + "[") for m in v.members)
        for k, m in enumerate(v.members):
            _uniform_values(m, "%s[%d]" % (name, k) if is_array else "%s.%s" % (name, m.name), out)
        return
    count = v.rows * v.columns
    kind = v.type.name
    if kind in ("SInt", "SShort", "SByte", "SLong"):
        values = list(v.value.s32v[:count])
    elif kind in ("UInt", "Bool", "UShort", "UByte", "ULong"):
        values = list(v.value.u32v[:count])
    elif kind == "Double":
        values = list(v.value.f64v[:count])
    else:
        values = list(v.value.f32v[:count])
    if v.rows > 1 and v.columns > 1:  # RenderDoc gives matrices row by row; GL's order is column by column
        values = [values[r * v.columns + c] for c in range(v.columns) for r in range(v.rows)]
    out[name] = values


def _clear_values(ctl, action, state):
    """glClearColor / glClearDepth as the frame's calls set them, from the structured chunks up to the clear."""
    chunks = ctl.GetStructuredFile().chunks
    for event in action.events:
        ch = chunks[event.chunkIndex]
        if ch.name == "glClearColor":
            state["color"] = [ch.GetChild(k).data.basic.d for k in range(4)]
        elif ch.name in ("glClearDepth", "glClearDepthf"):
            state["depth"] = ch.GetChild(0).data.basic.d


def import_renderdoc(path, event, images):
    """The frame up to the draw; the driver's images after it are written into `images`."""
    os.environ.setdefault("EGL_PLATFORM", "surfaceless")
    try:
        import renderdoc as rd
    except ImportError:
        raise ImportFailure("RenderDoc's python module is missing (Debian package python3-renderdoc, for "
                            "/usr/bin/python3): it reads .rdc captures")
    rd.InitialiseReplay(rd.GlobalEnvironment(), [])
    cap = rd.OpenCaptureFile()
    try:
        result = cap.OpenFile(path, "", None)
        if result != rd.ResultCode.Succeeded:
            raise ImportFailure("RenderDoc cannot open %s: %s" % (path, result))
        driver = cap.DriverName()
        if driver != "OpenGL":
            raise ImportFailure("%s is a %s capture: tessref replays OpenGL draws" % (path, driver))
        if not cap.LocalReplaySupport():
            raise ImportFailure("RenderDoc cannot replay %s on this machine" % path)
        result, ctl = cap.OpenCapture(rd.ReplayOptions(), None)
        if result != rd.ResultCode.Succeeded:
            raise ImportFailure("RenderDoc cannot replay %s: %s" % (path, result))
        try:
            frame, event = _read_frame(rd, ctl, path, event)
            try:
                _save_driver_images(rd, ctl, frame, event, images)
            except _DAMAGED as e:
                raise ImportFailure("RenderDoc's replay after event %d gives a framebuffer GL does not reach (%s: %s): "
                                    "the capture is damaged" % (event, type(e).__name__, e))
            return frame
        finally:
            ctl.Shutdown()
    finally:
        cap.Shutdown()
        rd.ShutdownReplay()


def _save_driver_images(rd, ctl, frame, event, images):
    ctl.SetFrameEvent(event, True)
    fbo = ctl.GetGLPipelineState().framebuffer.drawFBO
    color = fbo.colorAttachments[fbo.drawBuffers[0]].resourceId if fbo.drawBuffers[0] >= 0 else None
    depth = fbo.depthAttachment.resourceId if _rid(fbo.depthAttachment.resourceId) != "0" else None
    frame.gpu_images = save_gpu_images(rd, ctl, event, color, depth, images, frame.report)
    frame.gpu_images += save_tes_outputs(rd, ctl, event, images)
    frame.initial_images = save_initial_images(rd, ctl, frame, images)


def _flatten(actions):
    for a in actions:
        yield a
        yield from _flatten(a.children)


def _read_frame(rd, ctl, path, event):
    frame = Frame(os.path.basename(path), "event")
    reader = _Reader(rd, ctl, frame)
    frame.gpu_images = []
    frame.initial_images = None
    structured = ctl.GetStructuredFile()
    actions = [a for a in _flatten(ctl.GetRootActions())]
    draws = [a for a in actions if a.flags & rd.ActionFlags.Drawcall]
    if event is None:
        patches = []
        for a in draws:
            ctl.SetFrameEvent(a.eventId, True)
            if ctl.GetGLPipelineState().vertexInput.topology.name.startswith("PatchList"):
                patches.append(a.eventId)
        if not draws:
            raise ImportFailure("the capture has no draw call")
        if not patches:
            raise ImportFailure("the capture's frame has no GL_PATCHES draw (it has %d draw%s of other modes); name a "
                                "draw with --event" % (len(draws), "" if len(draws) == 1 else "s"))
        event = patches[-1]
    else:
        target = [a for a in actions if a.eventId == event]
        if not target:
            calls = [structured.chunks[e.chunkIndex].name for a in actions for e in a.events if e.eventId == event]
            if calls:
                raise ImportFailure("event %d is %s, not a draw call" % (event, calls[0]))
            last = actions[-1].eventId if actions else 0
            raise ImportFailure("the capture has no event %d (its events end at %d)" % (event, last))
        if not target[0].flags & rd.ActionFlags.Drawcall:
            raise ImportFailure("event %d is %s, not a draw call" % (event, target[0].GetName(structured)))
    clear_state, pending = {}, None
    for a in actions:
        if a.eventId > event:
            break
        _clear_values(ctl, a, clear_state)
        name = structured.chunks[a.events[-1].chunkIndex].name if a.events else a.GetName(structured)
        if a.flags & rd.ActionFlags.Clear:
            pending = dict(pending or {})
            if a.flags & rd.ActionFlags.ClearColor or name == "glClear" and "Color" in a.GetName(structured):
                pending["color"] = list(clear_state.get("color", [0.0, 0.0, 0.0, 0.0]))
                if "color" not in clear_state:
                    frame.note(a.eventId, "glClearColor was set before the capture began: the clear colour is read "
                               "from the action's name, to 6 decimals")
                    pending["color"] = _name_values(a.GetName(structured), "Color")
            if a.flags & rd.ActionFlags.ClearDepthStencil or "Depth" in a.GetName(structured):
                pending["depth"] = clear_state.get("depth", 1.0)
        elif a.flags & rd.ActionFlags.Drawcall:
            try:
                reader.draw(a, name, pending)
            except _DAMAGED as e:
                # RenderDoc's replay answered with something no GL state has: a damaged capture.
                raise ImportFailure("RenderDoc's replay of event %d (%s) gives a state GL does not reach (%s: %s): "
                                    "the capture is damaged" % (a.eventId, name, type(e).__name__, e))
            pending = None
    if not frame.draws or frame.draws[-1][0] != event:
        reasons = "; ".join(text for no, text in frame.report if no == event)
        raise ImportFailure("draw %d cannot be replayed: %s" % (event, reasons or "see the report"))
    return frame, event


def _name_values(action_name, key):
    start = action_name.find(key + " = <")
    if start < 0:
        return [0.0, 0.0, 0.0, 0.0]
    inner = action_name[start + len(key) + 4:action_name.index(">", start)]
    return [float(x) for x in inner.split(",")]


def _texture(ctl, resource_id):
    """The description of a texture the pipeline state names; a damaged capture can name one its
    resource list lacks."""
    for t in ctl.GetTextures():
        if _rid(t.resourceId) == _rid(resource_id):
            return t
    raise ImportFailure("the framebuffer names texture %s, which the capture's resource list lacks: the capture "
                        "is damaged" % _rid(resource_id))


def _action(ctl, event):
    for a in _flatten(ctl.GetRootActions()):
        if a.eventId == event:
            return a
    raise ImportFailure("event %d is not among the capture's actions on a second look: the capture is damaged" % event)


def _save_rgba8(ctl, rd, resource_id, path):
    """An RGBA8 attachment's bytes as the application's glReadPixels gives them, as a PNG (through
    a binary PPM and OpenImageIO's oiiotool: RenderDoc's own PNG export is display-processed)."""
    description = _texture(ctl, resource_id)
    if internal_format(description.format) not in ("GL_RGBA8", "GL_SRGB8_ALPHA8"):
        return False
    w, h = description.width, description.height
    data = bytes(ctl.GetTextureData(resource_id, rd.Subresource(0, 0, 0)))
    if len(data) != w * h * 4 or not shutil.which("oiiotool"):
        return False
    ppm = path + ".ppm"
    with open(ppm, "wb") as f:
        f.write(b"P6\n%d %d\n255\n" % (w, h))
        for y in range(h - 1, -1, -1):  # GL's rows run bottom to top; an image file's top to bottom
            row = data[y * w * 4:(y + 1) * w * 4]
            f.write(b"".join(row[x * 4:x * 4 + 3] for x in range(w)))
    converted = subprocess.run(["oiiotool", ppm, "-o", path], capture_output=True).returncode == 0
    os.remove(ppm)
    return converted


def save_initial_images(rd, ctl, frame, out_dir):
    """The colour and depth attachments before the frame's first draw (its first event, which
    changes no pixel), when that draw does not begin by clearing them: (colour files, depth file)."""
    first = frame.draws[0][0] if frame.draws else None
    if first is None or "clear" in frame.draws[0][1] and {"color", "depth"} <= set(frame.draws[0][1]["clear"]):
        return None
    action = _action(ctl, first)
    ctl.SetFrameEvent(action.events[0].eventId, True)
    fbo = ctl.GetGLPipelineState().framebuffer.drawFBO
    os.makedirs(os.path.join(out_dir, "initial"), exist_ok=True)
    colors = []
    for k, index in enumerate(fbo.drawBuffers):
        if index < 0:
            break
        name = "initial/color%d.png" % k
        ok = _save_rgba8(ctl, rd, fbo.colorAttachments[index].resourceId, os.path.join(out_dir, name))
        colors.append(name if ok else None)
    depth = None
    if _rid(fbo.depthAttachment.resourceId) != "0":
        if _save_depth(ctl, rd, fbo.depthAttachment.resourceId, os.path.join(out_dir, "initial", "depth.exr")):
            depth = "initial/depth.exr"
            frame.note(first, "the depth before the frame's first draw is RenderDoc's replay's; RenderDoc 1.24 does not "
                       "restore a depth renderbuffer's contents from before the capture (measured: its replay starts "
                       "from depth 0), so its image, gpu.png and the scene may all differ from the application's")
    return colors, depth


def save_tes_outputs(rd, ctl, event, out_dir):
    """What the driver's evaluation shader emitted for the draw (RenderDoc's post-tessellation
    mesh data, which it records on GL by transform feedback): gpu_tes.bin, the vertices of every
    instance's triangles in emission order, and gpu_tes.json, their layout."""
    ctl.SetFrameEvent(event, True)
    pipe = ctl.GetPipelineState()
    tes = pipe.GetShaderReflection(rd.ShaderStage.Tess_Eval)
    # With a geometry shader, RenderDoc's post-transform data is that shader's output, not the
    # evaluation stage's that verify --gpu compares.
    if tes is None or pipe.GetShaderReflection(rd.ShaderStage.Geometry) is not None:
        return []
    action = _action(ctl, event)
    chunks, counts, stride = [], [], None
    for instance in range(max(1, action.numInstances)):
        mesh = ctl.GetPostVSData(instance, 0, rd.MeshDataStage.GSOut)
        if mesh.vertexResourceId == rd.ResourceId.Null() or not mesh.numIndices:
            return []
        stride = mesh.vertexByteStride
        chunks.append(bytes(ctl.GetBufferData(mesh.vertexResourceId, mesh.vertexByteOffset, mesh.numIndices * stride)))
        counts.append(mesh.numIndices)
    with open(os.path.join(out_dir, "gpu_tes.bin"), "wb") as f:
        f.write(b"".join(chunks))
    outputs = [{"name": s.varName, "components": s.compCount} for s in tes.outputSignature]
    with open(os.path.join(out_dir, "gpu_tes.json"), "w") as f:
        json.dump({"stride_bytes": stride, "vertices_per_instance": counts, "primitive": mesh.topology.name,
                   "outputs": outputs, "note": "float32 vertices of the evaluation shader's emitted primitives, "
                   "in the driver's emission order, instance after instance (RenderDoc GetPostVSData, GSOut)"},
                  f, indent=1)
    return ["gpu_tes.bin", "gpu_tes.json"]


def _save_depth(ctl, rd, resource_id, path):
    """A depth attachment's stored values as a one-channel float EXR (through a float map and
    oiiotool: RenderDoc's own EXR export is half precision, 2^-11, coarser than 24-bit depth)."""
    description = _texture(ctl, resource_id)
    fmt = internal_format(description.format)
    w, h = description.width, description.height
    data = bytes(ctl.GetTextureData(resource_id, rd.Subresource(0, 0, 0)))
    if fmt in ("GL_DEPTH_COMPONENT24", "GL_DEPTH24_STENCIL8") and len(data) == w * h * 4:
        # 32 bits a texel: the depth in the top 24 (measured on llvmpipe), the stencil below.
        words = struct.unpack("<%dI" % (w * h), data)
        values = [(v >> 8) / float((1 << 24) - 1) for v in words]
    elif fmt == "GL_DEPTH_COMPONENT32F" and len(data) == w * h * 4:
        values = list(struct.unpack("<%df" % (w * h), data))
    else:
        return False
    if not shutil.which("oiiotool"):
        return False
    pfm = path + ".pfm"
    with open(pfm, "wb") as f:
        f.write(b"Pf\n%d %d\n-1.0\n" % (w, h))
        # A float map's rows run bottom to top, as GL's do.
        f.write(struct.pack("<%df" % (w * h), *values))
    converted = subprocess.run(["oiiotool", pfm, "-d", "float", "-o", path], capture_output=True).returncode == 0
    os.remove(pfm)
    return converted


def save_gpu_images(rd, ctl, event, fbo_color, fbo_depth, out_dir, report):
    """The colour (gpu.png) and depth (gpu_depth.exr) the driver left after the draw."""
    ctl.SetFrameEvent(event, True)
    written = []
    if fbo_color is not None and _save_rgba8(ctl, rd, fbo_color, os.path.join(out_dir, "gpu.png")):
        written.append("gpu.png")
        fbo_color = None
    if fbo_depth is not None and _save_depth(ctl, rd, fbo_depth, os.path.join(out_dir, "gpu_depth.exr")):
        written.append("gpu_depth.exr")
        fbo_depth = None
    for resource_id, name, dest in ((fbo_color, "gpu.png", rd.FileType.PNG), (fbo_depth, "gpu_depth.exr", rd.FileType.EXR)):
        if resource_id is None:
            continue
        save = rd.TextureSave()
        save.resourceId = resource_id
        save.destType = dest
        if dest == rd.FileType.PNG:
            save.alpha = rd.AlphaMapping.Discard
        result = ctl.SaveTexture(save, os.path.join(out_dir, name))
        if result == rd.ResultCode.Succeeded:
            written.append(name)
        else:
            report.append((event, "RenderDoc could not save %s: %s" % (name, result)))
    return written

