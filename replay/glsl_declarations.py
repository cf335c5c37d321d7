"""What the importer needs to know from a program's GLSL that the call stream does not say: which
default-block uniforms are samplers (their glUniform1i value is a texture unit), the bindings
written in layout qualifiers, and the uniform and storage blocks' names.

This reads declarations only, with comments removed; it is not a GLSL parser, and anything it
does not recognise is reported by the importer rather than guessed.
"""

import re

_COMMENTS = re.compile(r"//[^\n]*|/\*.*?\*/", re.S)
_SAMPLER = re.compile(
    r"(?:layout\s*\(([^)]*)\)\s*)?uniform\s+(?:(?:lowp|mediump|highp)\s+)?([iu]?sampler\w+)\s+(\w+)\s*(\[[^\]]*\])?\s*;")
_BLOCK = re.compile(r"(?:layout\s*\(([^)]*)\)\s*)?\b(uniform|buffer)\s+(\w+)\s*\{")
_LOCATION_UNIFORM = re.compile(r"layout\s*\(([^)]*)\)\s*uniform\s+(?:(?:lowp|mediump|highp)\s+)?\w+\s+(\w+)")
_BINDING = re.compile(r"\bbinding\s*=\s*(\d+)")
_LOCATION = re.compile(r"\blocation\s*=\s*(\d+)")


def strip_comments(source):
    """Comments blanked to spaces (newlines kept), so every offset and line stays where it was."""
    return _COMMENTS.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), source)


# sampler type -> the texture target it reads
SAMPLER_TARGETS = {
    "1D": "GL_TEXTURE_1D", "2D": "GL_TEXTURE_2D", "3D": "GL_TEXTURE_3D", "Cube": "GL_TEXTURE_CUBE_MAP",
    "2DRect": "GL_TEXTURE_RECTANGLE", "1DArray": "GL_TEXTURE_1D_ARRAY", "2DArray": "GL_TEXTURE_2D_ARRAY",
    "CubeArray": "GL_TEXTURE_CUBE_MAP_ARRAY", "Buffer": "GL_TEXTURE_BUFFER", "2DMS": "GL_TEXTURE_2D_MULTISAMPLE",
    "2DMSArray": "GL_TEXTURE_2D_MULTISAMPLE_ARRAY",
}


def sampler_target(glsl_type):
    shape = re.sub(r"^[iu]?sampler", "", glsl_type)
    shape = shape[:-len("Shadow")] if shape.endswith("Shadow") else shape
    return SAMPLER_TARGETS.get(shape)


class Declarations:
    def __init__(self, sources):
        self.samplers = {}        # name -> (glsl type, binding or None, array suffix or None)
        self.blocks = {}          # (kind, block name) -> binding or None
        self.uniform_locations = {}  # explicit layout(location = N) uniform -> name
        for source in sources:
            text = strip_comments(source)
            for m in _SAMPLER.finditer(text):
                binding = _BINDING.search(m.group(1) or "")
                self.samplers[m.group(3)] = (m.group(2), int(binding.group(1)) if binding else None, m.group(4))
            for m in _BLOCK.finditer(text):
                binding = _BINDING.search(m.group(1) or "")
                self.blocks[(m.group(2), m.group(3))] = int(binding.group(1)) if binding else None
            for m in _LOCATION_UNIFORM.finditer(text):
                location = _LOCATION.search(m.group(1))
                if location:
                    self.uniform_locations[int(location.group(1))] = m.group(2)


def with_block_binding(source, kind, name, binding):
    """The source with `binding = N` in the layout of block `name` (added to its layout qualifier,
    or as a new one), on the block's own line: line numbers stay the application's."""
    pattern = re.compile(r"(?:layout\s*\(([^)]*)\)\s*)?\b" + kind + r"\s+" + re.escape(name) + r"\s*\{")

    def replace(m):
        qualifiers = [q.strip() for q in (m.group(1) or "").split(",") if q.strip() and not _BINDING.match(q.strip())]
        qualifiers.append("binding = %d" % binding)
        return "layout(%s) %s %s {" % (", ".join(qualifiers), kind, name)
    text = strip_comments(source)
    m = pattern.search(text)
    if not m:
        return source
    # Comments were blanked to find the declaration; the replacement goes into the original text
    # at the same offsets (strip_comments keeps every offset outside comments).
    return source[:m.start()] + replace(m) + source[m.end():]
