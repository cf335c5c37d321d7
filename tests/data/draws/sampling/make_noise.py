# Writes the sampling sweep's noise images (8-bit PNG, deterministic): python3 make_noise.py DIR.
# noise_64x64.exr is noise_64x64.png times 6.1 less 3, as float: oiiotool noise_64x64.png --mulc 6.1 --subc 3 -d float --compression zip -o noise_64x64.exr
# noise_64x64_signed.exr (for the signed normalized formats): oiiotool noise_64x64.png --mulc 2 --subc 1 -d float --compression zip -o noise_64x64_signed.exr
# noise_64x64_hdr.exr (for the packed float formats): oiiotool noise_64x64_rgb.png --mulc 40 -d float --compression zip -o noise_64x64_hdr.exr
import struct, zlib, sys
def png(path, w, h, channels, pixel):
    raw = b''
    for y in range(h):
        raw += b'\x00' + bytes(v for x in range(w) for v in pixel(x, y)[:channels])
    color = {1: 0, 2: 4, 3: 2, 4: 6}[channels]
    def chunk(t, d): return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
    data = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, color, 0, 0, 0)) + chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b'')
    open(path, 'wb').write(data)
def h(x):
    x &= 0xffffffff
    x ^= x >> 16; x = (x * 0x7feb352d) & 0xffffffff; x ^= x >> 15; x = (x * 0x846ca68b) & 0xffffffff; x ^= x >> 16
    return x
def noise(seed):
    return lambda x, y: [h(x * 73856093 ^ y * 19349663 ^ seed * 83492791 ^ c * 2654435761) & 255 for c in range(4)]
d = sys.argv[1]
png(d + '/noise_64x64.png', 64, 64, 4, noise(1))
png(d + '/noise_24x10.png', 24, 10, 4, noise(2))
png(d + '/noise_64x64_rgb.png', 64, 64, 3, noise(3))
png(d + '/noise_64x64_gray.png', 64, 64, 1, noise(4))
# Layers 1 and 2 of the 2D array cases (layer 0 is noise_64x64.png).
png(d + '/noise_64x64_layer1.png', 64, 64, 4, noise(5))
png(d + '/noise_64x64_layer2.png', 64, 64, 4, noise(6))
# Slice 3 of the 3D texture cases (slices 0 to 2 are noise_64x64.png and the two layers above).
png(d + '/noise_64x64_layer3.png', 64, 64, 4, noise(9))
# depth_64x64.exr: depths k / 64 (k in 0..64, exact in every depth format's float reading only at
# 0 and 1, exact in float everywhere), written as a gray PFM (bottom row first):
#   oiiotool depth_64x64.pfm -d float --compression zip -o depth_64x64.exr
def pfm(path, w, h, value):
    rows = b''.join(struct.pack('<%df' % w, *[value(x, y) for x in range(w)]) for y in range(h))
    open(path, 'wb').write(b'Pf\n%d %d\n-1.0\n' % (w, h) + rows)
pfm(d + '/depth_64x64.pfm', 64, 64, lambda x, y: (h(x * 7 + y * 131 + 5) % 65) / 64.0)
# depth_64x64_layer1.exr, layer 1 of the shadow array cases (layer 0 is depth_64x64.exr), likewise.
pfm(d + '/depth_64x64_layer1.pfm', 64, 64, lambda x, y: (h(x * 7 + y * 131 + 9) % 65) / 64.0)
# Raw texel bytes for the integer formats, whose every bit pattern is a value: six levels of random
# bytes, 65536 >> 2k bytes (levels 0..5 of a 64x64 texture of 16-byte texels, 128x64 of 8-byte
# ones, 128x128 of 4-byte ones, 256x128 of 2-byte and 256x256 of 1-byte ones), and for the RGB
# formats 49152 >> 2k bytes (64x64 of 12-byte texels, 128x64 of 6-byte, 128x128 of 3-byte ones).
for chain, size in (('noise_bytes', 65536), ('noise_bytes3', 49152)):
    for k in range(6):
        n = size >> (2 * k)
        open('%s/%s_%d.raw' % (d, chain, k), 'wb').write(bytes(h(i * 2654435761 ^ k * 40503 ^ size) & 255 for i in range(n)))
# 1D textures: 256 texels (one row), and a 1D array of five 64-texel layers (the image's rows, bottom first).
png(d + '/noise_1d_256.png', 256, 1, 4, noise(7))
png(d + '/noise_1d_array_64x5.png', 64, 5, 4, noise(8))
# Buffer texture data for the float formats, whose random bit patterns would include NaNs: 4096
# finite float32 values (multiples of 2^-10 in [-512, 512)) and 8192 finite half-float patterns.
open(d + '/noise_floats.raw', 'wb').write(struct.pack('<4096f', *[((h(i * 97 + 11) & 0xfffff) - 0x80000) / 1024.0 for i in range(4096)]))
def finite_half(v):
    return v & ~0x4000 if (v >> 10) & 31 == 31 else v
open(d + '/noise_halfs.raw', 'wb').write(struct.pack('<8192H', *[finite_half(h(i * 131 + 3) & 0xffff) for i in range(8192)]))
# A 1D depth texture of 256 texels as raw bytes: GL_DEPTH_COMPONENT32F depths k / 64, and
# GL_DEPTH_COMPONENT16 words k * 1024 (k in 0..64; 65536 clamped to 65535).
depths = [h(x * 7 + 13) % 65 for x in range(256)]
open(d + '/depth_1d_256.raw', 'wb').write(struct.pack('<256f', *[k / 64.0 for k in depths]))
open(d + '/depth16_1d_256.raw', 'wb').write(struct.pack('<256H', *[min(k * 1024, 65535) for k in depths]))
# Cube maps: twelve 16 x 16 RGBA faces (a cube map's six, +X to -Z, are cube_16_face0..5; a cube
# map array's two cubes all twelve), and six gray ones for the depth formats.
for k in range(12):
    png(d + '/cube_16_face%d.png' % k, 16, 16, 4, noise(20 + k))
for k in range(6):
    png(d + '/cube_16_depth%d.png' % k, 16, 16, 1, noise(40 + k))
