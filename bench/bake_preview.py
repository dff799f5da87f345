#!/usr/bin/env python3
"""Rasterises a baked scene (scene_baked.obj + lightmap.png from `radiosity bake`) from the
Cornell box camera, texturing each pixel by bilinear lookup in the lightmap: what a game engine
shows with the lightmap alone. Pure Python (zlib for PNG), no renderer needed.

    python3 bench/bake_preview.py OUT_DIR preview.png [size] [--mix GROUP=WEIGHT,...]

With --mix (a bake with --light-groups), the lightmap is the weighted sum of the named groups'
layers (group_GROUP_lightmap.png, decoded from sRGB to linear, summed, encoded again), as an engine
mixes them at run time; groups left out weigh 0.
"""
import math, struct, sys, zlib


def read_png(path):
    data = open(path, "rb").read()
    pos, idat, w = 8, b"", 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, ctype = struct.unpack(">IIBB", chunk[:10])
            assert depth == 8 and ctype == 2, "8-bit RGB PNG expected"
        elif kind == b"IDAT":
            idat += chunk
        pos += 12 + n
    raw, stride, rows, prev = zlib.decompress(idat), 3 * w, [], bytearray(3 * w)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - 3] if i >= 3 else 0
            b, c = prev[i], prev[i - 3] if i >= 3 else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return w, h, rows


def write_png(path, w, h, pixels):
    raw = b"".join(b"\0" + bytes(pixels[y * w * 3:(y + 1) * w * 3]) for y in range(h))
    chunk = lambda k, d: struct.pack(">I", len(d)) + k + d + struct.pack(">I", zlib.crc32(k + d) & 0xffffffff)
    open(path, "wb").write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                           + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def to_linear(c):
    c /= 255
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def to_srgb8(x):
    x = min(max(x, 0.0), 1.0)
    return int(round(255 * (12.92 * x if x <= 0.0031308 else 1.055 * x ** (1 / 2.4) - 0.055)))


def mixed_layers(out_dir, weights):
    """The light groups' lightmap layers summed with `weights` ({group: weight}), in linear light."""
    tw = th = None
    total = None
    for name, weight in weights.items():
        w, h, rows = read_png(out_dir + "/group_" + name + "_lightmap.png")
        if total is None:
            tw, th, total = w, h, [[0.0] * (3 * w) for _ in range(h)]
        assert (w, h) == (tw, th), "layers of different sizes"
        for y in range(h):
            line, acc = rows[y], total[y]
            for i in range(3 * w):
                acc[i] += weight * to_linear(line[i])
    return tw, th, [bytearray(to_srgb8(x) for x in line) for line in total]


def main():
    args = sys.argv[1:]
    mix = None
    if "--mix" in args:
        at = args.index("--mix")
        mix = {k: float(v) for k, v in (item.split("=") for item in args[at + 1].split(","))}
        del args[at:at + 2]
    out_dir, target = args[0], args[1]
    size = int(args[2]) if len(args) > 2 else 384
    tw, th, tex = mixed_layers(out_dir, mix) if mix else read_png(out_dir + "/lightmap.png")
    v, vt, faces = [], [], []
    for line in open(out_dir + "/scene_baked.obj"):
        p = line.split()
        if not p: continue
        if p[0] == "v": v.append(tuple(map(float, p[1:4])))
        elif p[0] == "vt": vt.append((float(p[1]), 1.0 - float(p[2])))  # back to top-left origin
        elif p[0] == "f": faces.append([tuple(int(i) - 1 for i in q.split("/")[:2]) for q in p[1:4]])
    # Cornell camera (REFERENCES.md): eye (0.278, 0.273, -0.8), looking +z, vertical fov 39.3°.
    eye, f = (0.278, 0.273, -0.8), 1 / math.tan(math.radians(39.3) / 2)
    proj = lambda q: ((-(q[0] - eye[0]) * f / (q[2] - eye[2]) + 1) * size / 2,
                      (1 - (q[1] - eye[1]) * f / (q[2] - eye[2])) * size / 2, q[2] - eye[2])
    depth, img = [math.inf] * size * size, [0] * (3 * size * size)

    def texel(u, w_):
        x, y = u * tw - 0.5, w_ * th - 0.5
        x0, y0 = max(0, min(tw - 2, int(math.floor(x)))), max(0, min(th - 2, int(math.floor(y))))
        fx, fy = min(max(x - x0, 0), 1), min(max(y - y0, 0), 1)
        return [(tex[y0][3 * x0 + c] * (1 - fx) + tex[y0][3 * x0 + 3 + c] * fx) * (1 - fy)
                + (tex[y0 + 1][3 * x0 + c] * (1 - fx) + tex[y0 + 1][3 * x0 + 3 + c] * fx) * fy for c in range(3)]

    for face in faces:
        s = [proj(v[i]) for i, _ in face]
        if min(q[2] for q in s) <= 0: continue
        area = (s[1][0] - s[0][0]) * (s[2][1] - s[0][1]) - (s[1][1] - s[0][1]) * (s[2][0] - s[0][0])
        if area == 0: continue
        for y in range(max(0, int(min(q[1] for q in s))), min(size - 1, int(max(q[1] for q in s))) + 1):
            for x in range(max(0, int(min(q[0] for q in s))), min(size - 1, int(max(q[0] for q in s))) + 1):
                px, py = x + 0.5, y + 0.5
                b = [((s[(k + 2) % 3][0] - s[(k + 1) % 3][0]) * (py - s[(k + 1) % 3][1])
                      - (s[(k + 2) % 3][1] - s[(k + 1) % 3][1]) * (px - s[(k + 1) % 3][0])) / area for k in range(3)]
                if min(b) < 0: continue
                iz = sum(b[k] / s[k][2] for k in range(3))  # perspective-correct interpolation
                if 1 / iz >= depth[y * size + x]: continue
                depth[y * size + x] = 1 / iz
                uv = [sum(b[k] / s[k][2] * vt[face[k][1]][c] for k in range(3)) / iz for c in range(2)]
                img[3 * (y * size + x):3 * (y * size + x) + 3] = [int(round(c)) for c in texel(*uv)]
    write_png(target, size, size, img)


if __name__ == "__main__":
    main()
