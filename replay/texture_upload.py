"""Texture images as an application uploads them, kept as the scene's raw texel bytes: each level
(each cube face) in its internal format's own layout, rows packed, bottom row first.

An upload whose format and type are the internal format's own layout is copied as it is (rows
unpacked by GL_UNPACK_ALIGNMENT and GL_UNPACK_ROW_LENGTH); one that GL would convert is
reported, not converted by a guess.
"""

from import_error import ImportFailure

# internal format -> (components, bytes per texel, {(format, type)} uploads that are its own layout)
_N = {1: "GL_RED", 2: "GL_RG", 3: "GL_RGB", 4: "GL_RGBA"}
_NI = {1: "GL_RED_INTEGER", 2: "GL_RG_INTEGER", 3: "GL_RGB_INTEGER", 4: "GL_RGBA_INTEGER"}


def _table():
    t = {}
    for prefix, n in (("GL_R", 1), ("GL_RG", 2), ("GL_RGB", 3), ("GL_RGBA", 4)):
        t[prefix + "8"] = (n, n, {(_N[n], "GL_UNSIGNED_BYTE")})
        t[prefix + "8_SNORM"] = (n, n, {(_N[n], "GL_BYTE")})
        t[prefix + "16"] = (n, 2 * n, {(_N[n], "GL_UNSIGNED_SHORT")})
        t[prefix + "16_SNORM"] = (n, 2 * n, {(_N[n], "GL_SHORT")})
        t[prefix + "16F"] = (n, 2 * n, {(_N[n], "GL_HALF_FLOAT")})
        t[prefix + "32F"] = (n, 4 * n, {(_N[n], "GL_FLOAT")})
        for bits, size, signed, unsigned in ((8, 1, "GL_BYTE", "GL_UNSIGNED_BYTE"), (16, 2, "GL_SHORT", "GL_UNSIGNED_SHORT"),
                                             (32, 4, "GL_INT", "GL_UNSIGNED_INT")):
            t["%s%dI" % (prefix, bits)] = (n, size * n, {(_NI[n], signed)})
            t["%s%dUI" % (prefix, bits)] = (n, size * n, {(_NI[n], unsigned)})
    t["GL_SRGB8"] = (3, 3, {("GL_RGB", "GL_UNSIGNED_BYTE")})
    t["GL_SRGB8_ALPHA8"] = (4, 4, {("GL_RGBA", "GL_UNSIGNED_BYTE")})
    t["GL_R11F_G11F_B10F"] = (3, 4, {("GL_RGB", "GL_UNSIGNED_INT_10F_11F_11F_REV")})
    t["GL_RGB9_E5"] = (3, 4, {("GL_RGB", "GL_UNSIGNED_INT_5_9_9_9_REV")})
    t["GL_RGB10_A2UI"] = (4, 4, {("GL_RGBA_INTEGER", "GL_UNSIGNED_INT_2_10_10_10_REV")})
    t["GL_DEPTH_COMPONENT16"] = (1, 2, {("GL_DEPTH_COMPONENT", "GL_UNSIGNED_SHORT")})
    t["GL_DEPTH_COMPONENT24"] = (1, 4, {("GL_DEPTH_COMPONENT", "GL_UNSIGNED_INT")})
    t["GL_DEPTH_COMPONENT32F"] = (1, 4, {("GL_DEPTH_COMPONENT", "GL_FLOAT")})
    t["GL_DEPTH24_STENCIL8"] = (1, 4, {("GL_DEPTH_STENCIL", "GL_UNSIGNED_INT_24_8")})
    return t


FORMATS = _table()
# Unsized internal formats that glTexImage* takes, with the sized format GL picks for their upload.
_UNSIZED = {("GL_RGBA", "GL_UNSIGNED_BYTE"): "GL_RGBA8", ("GL_RGB", "GL_UNSIGNED_BYTE"): "GL_RGB8",
            ("GL_RG", "GL_UNSIGNED_BYTE"): "GL_RG8", ("GL_RED", "GL_UNSIGNED_BYTE"): "GL_R8"}


def _sized(c, internalformat, format_, type_):
    if internalformat in FORMATS:
        return internalformat
    sized = _UNSIZED.get((internalformat, type_)) if internalformat == format_ else None
    if sized is None:
        raise ImportFailure("call %d (%s): internal format %s is not one tessref's scenes take" % (c.no, c.name, internalformat))
    return sized


def _level_size(size, level, target):
    w, h, d = size
    w = max(1, w >> level)
    if target in ("GL_TEXTURE_1D_ARRAY",):
        return (w, h, 1)
    h = max(1, h >> level)
    if target == "GL_TEXTURE_3D":
        d = max(1, d >> level)
    return (w, h, d)


MAX_IMAGE_BYTES = 1 << 28  # one level of one texture; a trace that declares more is refused


def image_bytes(image):
    w, h, d = image["size"]
    return w * h * d * FORMATS[image["internalformat"]][1]


def level_data(image):
    """A level's texels; one never written holds zeros (GL leaves them undefined)."""
    return bytes(image["data"]) if image["data"] is not None else bytes(image_bytes(image))


def _check_size(c, size, internalformat=None):
    for v in size:
        if not isinstance(v, int) or v < 1 or v > 16384:
            raise ImportFailure("call %d (%s): image size %r is not one GL takes" % (c.no, c.name, size))
    texel = FORMATS[internalformat][1] if internalformat in FORMATS else 16
    if size[0] * size[1] * size[2] * texel > MAX_IMAGE_BYTES:
        raise ImportFailure("call %d (%s): an image of %r texels is more than the %d MiB a level may hold in an import"
                            % (c.no, c.name, size, MAX_IMAGE_BYTES >> 20))


def _faces(target):
    return 6 if target == "GL_TEXTURE_CUBE_MAP" else 1


def allocate_storage(state, c, texture, levels, internalformat, size):
    _check_size(c, size, internalformat)
    if internalformat not in FORMATS:
        raise ImportFailure("call %d (%s): internal format %s is not one tessref's scenes take" % (c.no, c.name, internalformat))
    if not isinstance(levels, int) or levels < 1 or levels > 16:
        raise ImportFailure("call %d (%s): %r levels" % (c.no, c.name, levels))
    texture.storage_levels = levels
    for level in range(levels):
        w, h, d = _level_size(size, level, texture.target)
        for face in range(_faces(texture.target)):
            texture.images[(level, face)] = {"size": (w, h, d), "internalformat": internalformat,
                                             "data": None, "written": False}


def _unpacked_rows(state, c, data, width, rows, texel):
    """The upload's rows as packed bytes (unpack alignment and row length applied)."""
    for key in ("GL_UNPACK_SKIP_PIXELS", "GL_UNPACK_SKIP_ROWS", "GL_UNPACK_SKIP_IMAGES", "GL_UNPACK_IMAGE_HEIGHT",
                "GL_UNPACK_SWAP_BYTES", "GL_UNPACK_LSB_FIRST"):
        if state.unpack.get(key, 0):
            raise ImportFailure("call %d (%s): %s is %r, which the importer does not model yet"
                                % (c.no, c.name, key, state.unpack[key]))
    alignment = state.unpack.get("GL_UNPACK_ALIGNMENT", 4)
    row_length = state.unpack.get("GL_UNPACK_ROW_LENGTH", 0) or width
    stride = (row_length * texel + alignment - 1) // alignment * alignment
    need = stride * (rows - 1) + width * texel
    if data is None or len(data) < need:
        raise ImportFailure("call %d (%s): the upload needs %d bytes but the trace holds %d: the trace is damaged"
                            % (c.no, c.name, need, 0 if data is None else len(data)))
    if stride == width * texel:
        return bytes(data[:width * texel * rows])
    return b"".join(bytes(data[r * stride:r * stride + width * texel]) for r in range(rows))


def _check_layout(c, internalformat, format_, type_):
    if (format_, type_) not in FORMATS[internalformat][2]:
        raise ImportFailure("call %d (%s): %s data of %s into %s asks GL to convert the texels, which the importer "
                            "does not do yet (upload the format's own layout: %s)"
                            % (c.no, c.name, format_, type_, internalformat,
                               ", ".join("%s/%s" % p for p in sorted(FORMATS[internalformat][2]))))


def store_image(state, c, texture, level, face, internalformat, size, data, format_, type_):
    internalformat = _sized(c, internalformat, format_, type_)
    _check_size(c, size, internalformat)
    texel = FORMATS[internalformat][1]
    w, h, d = size
    image = {"size": size, "internalformat": internalformat, "data": None, "written": data is not None}
    if data is not None:
        _check_layout(c, internalformat, format_, type_)
        image["data"] = bytearray(_unpacked_rows(state, c, data, w, h * d, texel))
    texture.images[(level, face)] = image
    if level == 0:
        texture.uploads += 1


def store_sub_image(state, c, texture, level, face, offset, size, data, format_, type_):
    image = texture.images.get((level, face))
    if image is None:
        raise ImportFailure("call %d (%s): level %d has no storage" % (c.no, c.name, level))
    _check_size(c, size)
    _check_layout(c, image["internalformat"], format_, type_)
    texel = FORMATS[image["internalformat"]][1]
    (x, y, z), (w, h, d) = offset, size
    fw, fh, fd = image["size"]
    if x < 0 or y < 0 or z < 0 or x + w > fw or y + h > fh or z + d > fd:
        raise ImportFailure("call %d (%s): the region lies outside level %d" % (c.no, c.name, level))
    rows = _unpacked_rows(state, c, data, w, h * d, texel)
    if image["data"] is None:
        image["data"] = bytearray(image_bytes(image))
    target = image["data"]
    for k in range(d):
        for r in range(h):
            src = (k * h + r) * w * texel
            dst = (((z + k) * fh) + y + r) * fw * texel + x * texel
            target[dst:dst + w * texel] = rows[src:src + w * texel]
    image["written"] = True
    if level == 0:
        texture.uploads += 1
