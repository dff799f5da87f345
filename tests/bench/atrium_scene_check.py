#!/usr/bin/env python3
"""Checks the generated atrium (bench/atrium_scene.py) for what its readers rely on:

- the OBJ: a few thousand triangles (small variant), every face indexes existing v/vt/vn, every
  material of the MTL has a texture file that is a valid PNG, 8-bit RGB, whose mean linear
  reflectance is in (0.02, 0.8) per channel;
- winding: from three points inside the hall, 300 rays each either leave through an opening
  (roof or window) or first hit the FRONT of a surface (one-sided surfaces face the room), except
  for the two-sided banners; some rays leave (the openings are open), most do not;
- the glTF: accessor ranges lie inside their buffer views and the .bin, counts match the OBJ,
  POSITION min/max are the data's bounds, indices are in range, the banners are doubleSided and
  nothing else is, the sun node's rotation takes −Z to the lights sidecar's sun direction;
- the sidecars: a sky and a sun beside the OBJ, the sky alone beside the glTF.

    python3 tests/bench/atrium_scene_check.py SOURCE_DIR WORK_DIR
"""
import json
import math
import os
import random
import struct
import subprocess
import sys
import zlib

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL: " + message, file=sys.stderr)


def read_png(path):
    """Decodes an 8-bit RGB, non-interlaced PNG with filter types 0–4 (what any writer may use)."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path + ": not a PNG"
    pos, idat, header = 8, b"", None
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        assert zlib.crc32(kind + body) & 0xFFFFFFFF == struct.unpack(">I", data[pos + 8 + n:pos + 12 + n])[0], path + ": bad CRC"
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    w, h, depth, colour, _, _, interlace = header
    assert depth == 8 and colour == 2 and interlace == 0, path + ": not 8-bit RGB"
    raw, stride, rows, prev = zlib.decompress(idat), 3 * w, [], bytearray(3 * w)
    for j in range(h):
        f, line = raw[j * (stride + 1)], bytearray(raw[j * (stride + 1) + 1:(j + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - 3] if i >= 3 else 0
            b, c = prev[i], (prev[i - 3] if i >= 3 else 0)
            p = a + b - c
            pred = {0: 0, 1: a, 2: b, 3: (a + b) // 2,
                    4: a if abs(p - a) <= min(abs(p - b), abs(p - c)) else (b if abs(p - b) <= abs(p - c) else c)}[f]
            line[i] = (line[i] + pred) & 255
        rows.append(line)
        prev = line
    return w, h, rows


def linear(byte):
    c = byte / 255.0
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def read_obj(path):
    v, vt, vn, faces, material, materials = [], [], [], [], None, []
    for line in open(path):
        t = line.split()
        if not t or t[0].startswith("#"):
            continue
        if t[0] == "v":
            v.append(tuple(map(float, t[1:4])))
        elif t[0] == "vt":
            vt.append(tuple(map(float, t[1:3])))
        elif t[0] == "vn":
            vn.append(tuple(map(float, t[1:4])))
        elif t[0] == "usemtl":
            material = t[1]
            materials.append(material)
        elif t[0] == "f":
            corners = [tuple(int(x) for x in c.split("/")) for c in t[1:]]
            faces.append((material, corners))
    return v, vt, vn, faces, materials


def ray_triangle(origin, d, a, b, c):
    """Möller–Trumbore: distance along d, or None; and det = −d · (b − a) × (c − a), positive when
    the ray meets the front face (counter-clockwise seen from the ray's origin)."""
    e1 = [b[i] - a[i] for i in range(3)]
    e2 = [c[i] - a[i] for i in range(3)]
    p = [d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2], d[0] * e2[1] - d[1] * e2[0]]
    det = sum(e1[i] * p[i] for i in range(3))
    if abs(det) < 1e-12:
        return None, 0
    s = [origin[i] - a[i] for i in range(3)]
    u = sum(s[i] * p[i] for i in range(3)) / det
    if u < 0 or u > 1:
        return None, 0
    q = [s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]]
    w = sum(d[i] * q[i] for i in range(3)) / det
    if w < 0 or u + w > 1:
        return None, 0
    t = sum(e2[i] * q[i] for i in range(3)) / det
    return (t, det) if t > 1e-9 else (None, 0)


def main():
    source, work = sys.argv[1], sys.argv[2]
    out = os.path.join(work, "atrium")
    subprocess.run([sys.executable, os.path.join(source, "bench", "atrium_scene.py"), out], check=True)

    v, vt, vn, faces, used = read_obj(os.path.join(out, "atrium.obj"))
    check(2000 <= len(faces) <= 10000, f"small variant: {len(faces)} triangles, want a few thousand")
    check(all(len(c) == 3 for _, c in faces), "every face is a triangle")
    check(all(1 <= x[0] <= len(v) and 1 <= x[1] <= len(vt) and 1 <= x[2] <= len(vn) for _, c in faces for x in c),
          "every face indexes existing v/vt/vn")
    mtl, textures = {}, {}
    name = None
    for line in open(os.path.join(out, "atrium.mtl")):
        t = line.split()
        if t and t[0] == "newmtl":
            name = t[1]
            mtl[name] = {}
        elif t and t[0] in ("Kd", "map_Kd"):
            mtl[name][t[0]] = t[1:]
    check(set(used) <= set(mtl), "every usemtl is defined in the MTL")
    for m, entries in mtl.items():
        check("map_Kd" in entries and entries.get("Kd") == ["1", "1", "1"], f"{m}: Kd 1 1 1 with a map_Kd")
        path = os.path.join(out, entries["map_Kd"][0])
        w, h, rows = read_png(path)
        mean = [sum(linear(r[3 * i + k]) for r in rows for i in range(w)) / (w * h) for k in range(3)]
        check(all(0.02 < x < 0.8 for x in mean), f"{path}: mean linear reflectance {mean} outside (0.02, 0.8)")
        textures[m] = path

    # Winding and openings: rays from inside the hall.
    tris = [(m, [v[x[0] - 1] for x in c]) for m, c in faces]
    rng = random.Random(7)
    escaped = back_hits = 0
    origins = [(9.0, 1.5, 5.0), (4.0, 4.0, 3.0), (14.0, 2.5, 7.5)]
    for origin in origins:
        for _ in range(900 // len(origins)):
            z, phi = rng.uniform(-1, 1), rng.uniform(0, 2 * math.pi)
            r = math.sqrt(1 - z * z)
            d = (r * math.cos(phi), z, r * math.sin(phi))
            best, facing, material = None, 0, None
            for m, (a, b, c) in tris:
                t, det = ray_triangle(origin, d, a, b, c)
                if t is not None and (best is None or t < best):
                    best, facing, material = t, det, m
            if best is None:
                escaped += 1
            elif facing < 0 and material != "banner":  # det < 0: the ray meets the back face
                back_hits += 1
    rays = len(origins) * (900 // len(origins))
    check(back_hits == 0, f"{back_hits} of {rays} rays from inside the hall hit the back of a one-sided surface")
    check(0.01 * rays < escaped < 0.5 * rays, f"{escaped} of {rays} rays leave the hall: want some (openings), not most")

    # glTF.
    g = json.load(open(os.path.join(out, "gltf", "atrium.gltf")))
    blob = open(os.path.join(out, "gltf", g["buffers"][0]["uri"]), "rb").read()
    check(len(blob) == g["buffers"][0]["byteLength"], "buffer byteLength equals the .bin's size")
    sizes = {5126: 4, 5125: 4}
    widths = {"SCALAR": 1, "VEC2": 2, "VEC3": 3}
    triangles = 0
    for prim in g["meshes"][0]["primitives"]:
        mat = g["materials"][prim["material"]]
        check(mat["doubleSided"] == (mat["name"] == "banner"), f"{mat['name']}: doubleSided only for the banners")
        image = g["images"][g["textures"][mat["pbrMetallicRoughness"]["baseColorTexture"]["index"]]["source"]]
        check(os.path.samefile(os.path.join(out, "gltf", image["uri"]), textures[mat["name"]]),
              f"{mat['name']}: the glTF's image is the OBJ's map_Kd")
        values = {}
        for key, index in list(prim["attributes"].items()) + [("indices", prim["indices"])]:
            acc = g["accessors"][index]
            view = g["bufferViews"][acc["bufferView"]]
            n = acc["count"] * widths[acc["type"]]
            check(view["byteOffset"] + view["byteLength"] <= len(blob), f"{key}: view inside the buffer")
            check(n * sizes[acc["componentType"]] <= view["byteLength"], f"{key}: accessor inside its view")
            fmt = "<%d%s" % (n, "f" if acc["componentType"] == 5126 else "I")
            values[key] = (acc, struct.unpack_from(fmt, blob, view["byteOffset"]))
        acc, pos = values["POSITION"]
        for k in range(3):
            check(abs(min(pos[k::3]) - acc["min"][k]) < 1e-5 and abs(max(pos[k::3]) - acc["max"][k]) < 1e-5,
                  "POSITION min/max are the data's bounds")
        index_values = values["indices"][1]
        check(max(index_values) < acc["count"], "indices within POSITION's count")
        triangles += len(index_values) // 3
    check(triangles == len(faces), f"glTF has {triangles} triangles, the OBJ {len(faces)}")

    lights = json.load(open(os.path.join(out, "atrium.lights.json")))["lights"]
    check(sorted(x["type"] for x in lights) == ["directional", "sky"], "OBJ sidecar: a sun and a sky")
    gltf_lights = json.load(open(os.path.join(out, "gltf", "atrium.lights.json")))["lights"]
    check([x["type"] for x in gltf_lights] == ["sky"], "glTF sidecar: the sky alone")
    sun = next(x for x in lights if x["type"] == "directional")
    node = next(n for n in g["nodes"] if "extensions" in n)
    x, y, z, w = node["rotation"]
    # R · (0, 0, −1) for the unit quaternion (x, y, z, w): minus the third column of R.
    minus_z = (-(2 * (x * z + w * y)), -(2 * (y * z - w * x)), -(1 - 2 * (x * x + y * y)))
    d = sun["direction"]
    n = math.sqrt(sum(c * c for c in d))
    check(all(abs(minus_z[i] - d[i] / n) < 1e-9 for i in range(3)), f"sun node's −Z {minus_z} is the sun direction {d}")

    if failures:
        print(f"{len(failures)} check(s) failed", file=sys.stderr)
        return 1
    print(f"atrium_scene_check: {len(faces)} triangles, {escaped}/{rays} rays leave, all checks pass")
    return 0


if __name__ == "__main__":
    sys.exit(main())
