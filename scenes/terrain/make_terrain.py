# Writes the terrain scene's inputs (scenes/terrain.json): python3 make_terrain.py
#   height.pfm  128 x 128 heights in [0, 1], smooth hills (a sum of sines, no randomness); then
#               oiiotool height.pfm -d half --compression zip -o height.exr
#   albedo.png  64 x 64 RGB: grass with rock streaks, repeated 4 times across the ground
# and prints the light's view-projection matrix (columns) for u_light_view_proj in both scenes.
# The shadow map (shadow_depth.exr) is the light pass's depth:
#   tessref render scenes/terrain_light.json -o /tmp/light.png --depth scenes/terrain/shadow_depth.exr
import math, struct, zlib

def pfm(path, w, h, value):
    rows = b''.join(struct.pack('<%df' % w, *[value(x, y) for x in range(w)]) for y in range(h))
    open(path, 'wb').write(b'Pf\n%d %d\n-1.0\n' % (w, h) + rows)

def png_rgb(path, w, h, pixel):
    raw = b''.join(b'\x00' + bytes(v for x in range(w) for v in pixel(x, y)) for y in range(h))
    def chunk(t, d): return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
    open(path, 'wb').write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0)) +
                           chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b''))

def height(x, y):
    u, v = x / 127.0, y / 127.0
    h = 0.45 * math.sin(5.1 * u + 1.3) * math.sin(4.3 * v + 0.4) + 0.25 * math.sin(11.7 * u - 7.9 * v) \
        + 0.12 * math.sin(23.0 * u + 2.0) * math.cos(19.0 * v) + 0.5 * math.exp(-((u - 0.62) ** 2 + (v - 0.55) ** 2) * 18.0)
    return min(1.0, max(0.0, 0.35 + 0.6 * h))

def albedo(x, y):
    streak = 0.5 + 0.5 * math.sin(x * 0.7 + 2.1 * math.sin(y * 0.31))
    grain = ((x * 37 + y * 91) * 2654435761 >> 7) % 23
    grass = (70 + grain, 120 + grain * 2, 40 + grain)
    rock = (140 + grain, 132 + grain, 120 + grain)
    return [int(g + (r - g) * streak ** 4) for g, r in zip(grass, rock)]

def look_at(eye, target, up):
    f = [t - e for t, e in zip(target, eye)]; n = math.sqrt(sum(c * c for c in f)); f = [c / n for c in f]
    s = [f[1] * up[2] - f[2] * up[1], f[2] * up[0] - f[0] * up[2], f[0] * up[1] - f[1] * up[0]]
    n = math.sqrt(sum(c * c for c in s)); s = [c / n for c in s]
    u = [s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2], s[0] * f[1] - s[1] * f[0]]
    dot = lambda a, b: sum(x * y for x, y in zip(a, b))
    return [[s[0], s[1], s[2], -dot(s, eye)], [u[0], u[1], u[2], -dot(u, eye)],
            [-f[0], -f[1], -f[2], dot(f, eye)], [0, 0, 0, 1]]

def perspective(fov_y, aspect, near, far):
    t = 1.0 / math.tan(fov_y / 2)
    return [[t / aspect, 0, 0, 0], [0, t, 0, 0], [0, 0, (far + near) / (near - far), 2 * far * near / (near - far)], [0, 0, -1, 0]]

pfm('height.pfm', 128, 128, height)
png_rgb('albedo.png', 64, 64, albedo)
p, v = perspective(math.radians(50), 1.0, 2.0, 12.0), look_at([-2.6, 2.8, 1.2], [2.0, 0.5, 2.0], [0, 1, 0])
m = [[sum(p[r][k] * v[k][c] for k in range(4)) for c in range(4)] for r in range(4)]
print('"u_light_view_proj": [' + ', '.join('[' + ', '.join('%.9g' % m[r][c] for r in range(4)) + ']' for c in range(4)) + ']')
