#!/usr/bin/env python3
# Run from the repository root: python3 examples/three_spheres/make_sky.py examples/three_spheres/sky.png
# Writes examples/three_spheres/sky.png: a 1024x512 equirectangular sky (sRGB PNG), made procedurally:
# a blue gradient above the horizon, a sun at longitude 40 degrees right of -z, elevation 20 degrees,
# a ridge of hills whose height varies with longitude, and brownish ground below.
import math, struct, zlib, sys
W, H = 1024, 512
def srgb(x):
    x = max(0.0, min(1.0, x))
    return 12.92 * x if x <= 0.0031308 else 1.055 * x ** (1 / 2.4) - 0.055
rows = []
sun_lon, sun_lat = math.radians(40), math.radians(20)
sd = (math.sin(sun_lon) * math.cos(sun_lat), math.sin(sun_lat), -math.cos(sun_lon) * math.cos(sun_lat))
for y in range(H):
    row = bytearray([0])
    lat = math.pi / 2 - (y + 0.5) / H * math.pi          # +pi/2 at the top row
    for x in range(W):
        lon = ((x + 0.5) / W - 0.5) * 2 * math.pi        # 0 at the centre column, looking along -z
        d = (math.sin(lon) * math.cos(lat), math.sin(lat), -math.cos(lon) * math.cos(lat))
        hill = 0.03 + 0.02 * math.sin(3 * lon) + 0.012 * math.sin(7 * lon + 1.0)
        t = math.sqrt(min(max(lat, 0.0) / (math.pi / 2), 1.0))
        sky = tuple(h * (1 - t) + z * t for h, z in zip((0.85, 0.9, 0.95), (0.2, 0.4, 0.85)))
        if sum(a * b for a, b in zip(d, sd)) > math.cos(math.radians(4)):
            sky = (1.0, 0.95, 0.8)
        # The hills' edge is antialiased: the fraction of the texel above the ridge is sky.
        cover = min(max((lat - hill) / (math.pi / H) + 0.5, 0.0), 1.0)
        c = tuple(g * (1 - cover) + s * cover for g, s in zip((0.12, 0.22, 0.12), sky))
        if lat < 0:
            c = (0.25, 0.2, 0.15)
        row += bytes(int(srgb(v) * 255 + 0.5) for v in c)
    rows.append(bytes(row))
raw = zlib.compress(b"".join(rows), 9)
def chunk(t, data):
    return struct.pack(">I", len(data)) + t + data + struct.pack(">I", zlib.crc32(t + data) & 0xffffffff)
png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", W, H, 8, 2, 0, 0, 0)) + chunk(b"IDAT", raw) + chunk(b"IEND", b"")
open(sys.argv[1], "wb").write(png)
