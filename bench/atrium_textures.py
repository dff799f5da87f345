"""Procedural, seamlessly tiling textures for the generated atrium (bench/atrium_scene.py), and a
PNG writer, in the Python standard library only (no numpy or PIL on the development machine).

Each texture is a function of (x, y) in [0, 1)² returning sRGB bytes; its lattice noise is
periodic over the image, so a repeat-wrapped texture shows no seams. Colours are chosen so that
the decoded linear reflectance stays below 0.8 (no surface of the atrium is near-white).
"""
import math
import struct
import zlib


def write_png(path, width, height, rgb_rows):
    """Writes an 8-bit RGB PNG. rgb_rows: `height` byte strings of 3·width bytes, top row first."""
    raw = b"".join(b"\x00" + row for row in rgb_rows)  # filter type 0 on every row

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw, 9)))
        f.write(chunk(b"IEND", b""))


def srgb_to_linear(c):
    c /= 255.0
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


class PeriodicNoise:
    """Value noise on a `period`×`period` lattice that wraps, smoothstep-interpolated, in [0, 1]."""

    def __init__(self, period, seed):
        self.period = period
        self.values = [((i * 7919 + seed * 104729) * 2654435761 % 4294967296) / 4294967296.0 for i in range(period * period)]

    def at(self, x, y):  # x, y in lattice units
        p = self.period
        xi, yi = math.floor(x), math.floor(y)
        fx, fy = x - xi, y - yi
        sx, sy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)
        x0, y0, x1, y1 = xi % p, yi % p, (xi + 1) % p, (yi + 1) % p
        v = self.values
        top = v[y0 * p + x0] * (1 - sx) + v[y0 * p + x1] * sx
        bottom = v[y1 * p + x0] * (1 - sx) + v[y1 * p + x1] * sx
        return top * (1 - sy) + bottom * sy


def fractal(noises, x, y):
    """Sum of octaves (each noise has twice the previous period), normalised to [0, 1]."""
    total, weight, amplitude = 0.0, 0.0, 1.0
    for n in noises:
        total += amplitude * n.at(x * n.period, y * n.period)
        weight += amplitude
        amplitude *= 0.5
    return total / weight


def octaves(base_period, count, seed):
    return [PeriodicNoise(base_period << k, seed + k) for k in range(count)]


def mix(a, b, t):
    return tuple(a[i] + (b[i] - a[i]) * t for i in range(3))


def tiles(seed):
    """Floor: 2×2 stone tiles per image in two tones (a checker), grout lines, mottled surface."""
    n = octaves(4, 4, seed)
    light, dark, grout = (196, 184, 160), (120, 92, 70), (70, 66, 60)

    def f(x, y):
        tx, ty = x * 2, y * 2
        fx, fy = tx - math.floor(tx), ty - math.floor(ty)
        if min(fx, fy, 1 - fx, 1 - fy) < 0.025:
            return grout
        base = light if (int(tx) + int(ty)) % 2 == 0 else dark
        return mix(base, (base[0] * 0.8, base[1] * 0.8, base[2] * 0.8), fractal(n, x, y))

    return f


def plaster(seed):
    """Walls and ceiling: warm off-white with soft blotches."""
    n = octaves(4, 5, seed)
    a, b = (214, 200, 176), (178, 160, 134)
    return lambda x, y: mix(a, b, fractal(n, x, y) ** 1.5)


def wood(seed):
    """Furniture: grain along x, rings bent by noise, two browns."""
    n = octaves(2, 4, seed)
    a, b = (150, 98, 56), (96, 56, 30)

    def f(x, y):
        t = 0.5 + 0.5 * math.sin(2 * math.pi * (12 * y + 2.5 * fractal(n, x, y)))
        return mix(a, b, t ** 3)

    return f


def stone(seed):
    """Columns: grey marble with dark veins."""
    n = octaves(2, 5, seed)
    a, b = (186, 182, 174), (92, 90, 88)

    def f(x, y):
        vein = abs(math.sin(2 * math.pi * (x + y + 1.5 * fractal(n, x, y))))
        return mix(a, b, (1 - vein) ** 8)

    return f


def fabric(seed):
    """Banners: red and ochre stripes with a fine weave."""
    red, ochre = (156, 42, 48), (196, 146, 72)

    def f(x, y):
        base = red if int(x * 6) % 3 else ochre
        weave = 0.9 + 0.1 * (((int(x * 128) + int(y * 128)) % 2))
        return tuple(c * weave for c in base)

    return f


TEXTURES = {"tiles": tiles, "plaster": plaster, "wood": wood, "stone": stone, "fabric": fabric}


def render(name, size, seed=1):
    """The named texture as PNG rows (top row = v 1) and its mean linear colour."""
    f = TEXTURES[name](seed)
    rows, total = [], [0.0, 0.0, 0.0]
    for j in range(size):
        row = bytearray()
        for i in range(size):
            c = f((i + 0.5) / size, (j + 0.5) / size)
            for k in range(3):
                b = max(0, min(255, int(round(c[k]))))
                row.append(b)
                total[k] += srgb_to_linear(b)
        rows.append(bytes(row))
    return rows, tuple(t / (size * size) for t in total)
