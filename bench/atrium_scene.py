#!/usr/bin/env python3
"""Writes the project's own realistic test scene: a textured atrium (metres, +Y up) lit by a sun
and a sky through an opening in its roof and the windows of its long walls. Thick plaster walls
with window reveals, a tiled floor, two rows of marble columns, wooden tables and benches, and
fabric banners that hang free (seen from both sides). Five procedural textures (PNG).

    python3 bench/atrium_scene.py OUT_DIR [--size small|large] [--cell METRES] [--flat]

writes
    OUT_DIR/atrium.obj, atrium.mtl          OBJ + MTL (map_Kd, Kd 1 1 1: the texture is the colour)
    OUT_DIR/atrium.lights.json              sky and sun (docs/physics.md, lights besides emissive polygons)
    OUT_DIR/atrium.camera.json              a view along the hall
    OUT_DIR/textures/*.png
    OUT_DIR/gltf/atrium.gltf, atrium.bin    glTF 2.0: baseColorTexture, TEXCOORD_0, doubleSided
                                            banners, the sun as a KHR_lights_punctual directional
                                            light, the camera; its own atrium.lights.json holds the
                                            sky only (glTF cannot say "sky") and atrium.camera.json

`--size small` (the default) gives a few thousand triangles for tests; `--size large` a few
hundred thousand for the benchmark; `--cell` sets the longest grid edge directly. `--flat` writes
Kd = each texture's mean linear colour and no map_Kd (for readers without textures, and to
compare methods independently of texture look-ups).

A script (not a C++ tool) because it needs nothing built, like bench/scene_generator.py, and
runs in a second for the small variant; the standard library only (zlib for the PNGs).
"""
import argparse
import json
import math
import os
import struct

import atrium_textures

# The hall's interior: x ∈ [0, LENGTH], y ∈ [0, HEIGHT], z ∈ [0, WIDTH]; walls and roof THICK.
LENGTH, WIDTH, HEIGHT, THICK = 18.0, 10.0, 7.0, 0.4
ROOF_OPENING = ((5.0, 13.0), (3.5, 6.5))  # x and z ranges of the open roof
TEXTURE_SIZE = 256
# Metres covered by one repeat of each material's texture.
MATERIALS = {  # name: (texture, metres per repeat, two-sided)
    "floor": ("tiles", 1.0, False),
    "plaster": ("plaster", 3.0, False),
    "stone": ("stone", 1.5, False),
    "wood": ("wood", 1.0, False),
    "banner": ("fabric", 1.0, True),
}
SUN_DIRECTION = (0.35, -0.85, 0.40)  # the way the sunlight travels: down, through the roof opening
SUN_IRRADIANCE = [8.0, 7.6, 6.8]  # W·m⁻² on a surface facing the sun
SKY_RADIANCE = [0.35, 0.45, 0.65]  # W·m⁻²·sr⁻¹
SIZES = {"small": 1.2, "large": 0.1}  # longest grid edge in metres


def sub(a, b):
    return tuple(a[i] - b[i] for i in range(3))


def add(a, b):
    return tuple(a[i] + b[i] for i in range(3))


def scale(a, s):
    return tuple(x * s for x in a)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def length(a):
    return math.sqrt(sum(x * x for x in a))


def normalised(a):
    return scale(a, 1.0 / length(a))


class Mesh:
    """Triangles grouped by material; each grid shares its vertices (position, normal, uv)."""

    def __init__(self, cell):
        self.cell = cell
        self.parts = {name: {"v": [], "n": [], "uv": [], "tri": []} for name in MATERIALS}

    def quad(self, material, origin, a, b, uv_origin=(0.0, 0.0)):
        """The parallelogram origin + s·a + t·b (s, t ∈ [0, 1]), front face along a × b, split into
        a grid whose edges are at most `cell` long. UVs in texture repeats: planar, in metres."""
        part = self.parts[material]
        repeat = MATERIALS[material][1]
        la, lb = length(a), length(b)
        na, nb = max(1, math.ceil(la / self.cell - 1e-9)), max(1, math.ceil(lb / self.cell - 1e-9))
        normal = normalised(cross(a, b))
        base = len(part["v"])
        for j in range(nb + 1):
            for i in range(na + 1):
                s, t = i / na, j / nb
                part["v"].append(add(origin, add(scale(a, s), scale(b, t))))
                part["n"].append(normal)
                part["uv"].append((uv_origin[0] + s * la / repeat, uv_origin[1] + t * lb / repeat))
        for j in range(nb):
            for i in range(na):
                p00 = base + j * (na + 1) + i
                p10, p01, p11 = p00 + 1, p00 + na + 1, p00 + na + 2
                part["tri"] += [(p00, p10, p11), (p00, p11, p01)]

    def box(self, material, lo, hi, skip=()):
        """An axis-aligned box, faces out; `skip` names faces not written (e.g. "-y" on the floor)."""
        dx, dy, dz = hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]
        X, Y, Z = (dx, 0, 0), (0, dy, 0), (0, 0, dz)
        faces = {
            "-x": (lo, Z, Y), "+x": ((hi[0], lo[1], lo[2]), Y, Z),
            "-y": (lo, X, Z), "+y": ((lo[0], hi[1], lo[2]), Z, X),
            "-z": (lo, Y, X), "+z": ((lo[0], lo[1], hi[2]), X, Y),
        }
        for name, (o, a, b) in faces.items():
            if name not in skip:
                self.quad(material, o, a, b)

    def prism(self, material, centre, radius, y0, y1, sides):
        """A vertical prism (a column), side faces out, no caps (it stands on a plinth)."""
        for k in range(sides):
            a0, a1 = 2 * math.pi * k / sides, 2 * math.pi * (k + 1) / sides
            p0 = (centre[0] + radius * math.cos(a0), y0, centre[1] - radius * math.sin(a0))
            p1 = (centre[0] + radius * math.cos(a1), y0, centre[1] - radius * math.sin(a1))
            self.quad(material, p0, sub(p1, p0), (0, y1 - y0, 0), uv_origin=(k * length(sub(p1, p0)) / 1.5, 0))

    def triangle_count(self):
        return sum(len(p["tri"]) for p in self.parts.values())


def wall_with_windows(mesh, axis_origin, along, inward, width, windows):
    """A wall of thickness THICK: the inner face in the plane through `axis_origin`, spanning
    `width` along the unit vector `along` and HEIGHT up, with its front towards the unit vector
    `inward`; the outer face THICK behind it, reaching the roof's top; window reveals between them.
    windows: (s0, s1, y0, y1) rectangles in (along, up) coordinates."""
    up = (0.0, 1.0, 0.0)
    outer_origin = add(axis_origin, scale(inward, -THICK))
    # Cut both faces into rectangles on the grid of the windows' edges, leaving the windows out.
    for face_origin, top, facing_in in ((axis_origin, HEIGHT, True), (outer_origin, HEIGHT + THICK, False)):
        s_cuts = sorted({0.0, width} | {w[0] for w in windows} | {w[1] for w in windows})
        y_cuts = sorted({0.0, top} | {w[2] for w in windows} | {w[3] for w in windows})
        for s0, s1 in zip(s_cuts, s_cuts[1:]):
            for y0, y1 in zip(y_cuts, y_cuts[1:]):
                if any(w[0] <= s0 and s1 <= w[1] and w[2] <= y0 and y1 <= w[3] for w in windows):
                    continue
                o = add(face_origin, add(scale(along, s0), scale(up, y0)))
                a, b = scale(along, s1 - s0), scale(up, y1 - y0)
                # Front along a × b = along × up; flip where that is not the wanted side.
                want = inward if facing_in else scale(inward, -1)
                if sum(cross(along, up)[i] * want[i] for i in range(3)) > 0:
                    mesh.quad("plaster", o, a, b, uv_origin=(s0 / 3.0, y0 / 3.0))
                else:
                    mesh.quad("plaster", add(o, b), a, scale(b, -1), uv_origin=(s0 / 3.0, y0 / 3.0))
    # Reveals: the four sides of each opening, facing into the opening.
    depth = scale(inward, -THICK)
    for s0, s1, y0, y1 in windows:
        p = lambda s, y: add(axis_origin, add(scale(along, s), scale(up, y)))  # noqa: E731
        for o, a in ((p(s0, y0), scale(along, s1 - s0)), (p(s1, y1), scale(along, s0 - s1)),
                     (p(s1, y0), scale(up, y1 - y0)), (p(s0, y1), scale(up, y0 - y1))):
            # Reveal quad spans a and the wall depth; orient its front towards the opening's centre.
            centre = p((s0 + s1) / 2, (y0 + y1) / 2)
            n = cross(a, depth)
            towards = sub(centre, o)
            if sum(n[i] * towards[i] for i in range(3)) > 0:
                mesh.quad("plaster", o, a, depth)
            else:
                mesh.quad("plaster", o, depth, a)


def build(cell):
    mesh = Mesh(cell)
    # Floor (tiles), facing up.
    mesh.quad("floor", (0, 0, 0), (0, 0, WIDTH), (LENGTH, 0, 0))
    # Long walls with windows, short walls with one tall doorway-like window each.
    bays = [(2.3 + 3.0 * k, 3.7 + 3.0 * k) for k in range(5)]  # five windows per long wall
    long_windows = [(s0, s1, 2.2, 4.6) for s0, s1 in bays]
    short_windows = [(WIDTH / 2 - 1.0, WIDTH / 2 + 1.0, 1.0, 5.0)]
    wall_with_windows(mesh, (0, 0, 0), (1, 0, 0), (0, 0, 1), LENGTH, long_windows)  # z = 0
    wall_with_windows(mesh, (0, 0, WIDTH), (1, 0, 0), (0, 0, -1), LENGTH, long_windows)  # z = W
    wall_with_windows(mesh, (0, 0, 0), (0, 0, 1), (1, 0, 0), WIDTH, short_windows)  # x = 0
    wall_with_windows(mesh, (LENGTH, 0, 0), (0, 0, 1), (-1, 0, 0), WIDTH, short_windows)  # x = L
    # Outer corners: the outer faces of the long walls stop at x = 0 and L; close the corners.
    for x, sx in ((0.0, -1.0), (LENGTH, 1.0)):
        for z, sz in ((0.0, -1.0), (WIDTH, 1.0)):
            lo = (min(x, x + sx * THICK), 0.0, min(z, z + sz * THICK))
            hi = (max(x, x + sx * THICK), HEIGHT + THICK, max(z, z + sz * THICK))
            mesh.box("plaster", lo, hi, skip=("-y", "+y", "+x" if sx < 0 else "-x", "+z" if sz < 0 else "-z"))
    # Roof: a slab over the walls with the opening; ceiling (facing down) over the interior.
    (ox0, ox1), (oz0, oz1) = ROOF_OPENING
    for y, down in ((HEIGHT, True), (HEIGHT + THICK, False)):
        x0, x1, z0, z1 = (0.0, LENGTH, 0.0, WIDTH) if down else (-THICK, LENGTH + THICK, -THICK, WIDTH + THICK)
        for (a0, a1, b0, b1) in ((x0, ox0, z0, z1), (ox1, x1, z0, z1), (ox0, ox1, z0, oz0), (ox0, ox1, oz1, z1)):
            if down:
                mesh.quad("plaster", (a0, y, b0), (a1 - a0, 0, 0), (0, 0, b1 - b0))
            else:
                mesh.quad("plaster", (a0, y, b0), (0, 0, b1 - b0), (a1 - a0, 0, 0))
    # The opening's reveals, facing into it.
    t = (0, THICK, 0)
    mesh.quad("plaster", (ox0, HEIGHT, oz0), t, (0, 0, oz1 - oz0))
    mesh.quad("plaster", (ox1, HEIGHT, oz0), (0, 0, oz1 - oz0), t)
    mesh.quad("plaster", (ox0, HEIGHT, oz0), (ox1 - ox0, 0, 0), t)
    mesh.quad("plaster", (ox0, HEIGHT, oz1), t, (ox1 - ox0, 0, 0))
    # Two rows of columns on plinths, between the windows.
    sides = max(8, min(48, round(2 * math.pi * 0.3 / cell * 4)))
    for z in (2.2, WIDTH - 2.2):
        for k in range(6):
            x = 1.5 + 3.0 * k  # in line with the piers between the windows
            mesh.box("stone", (x - 0.45, 0.0, z - 0.45), (x + 0.45, 0.5, z + 0.45), skip=("-y",))
            mesh.prism("stone", (x, z), 0.3, 0.5, HEIGHT, sides)
    # Tables (a top and four legs) with two benches each, along the middle.
    for k, x in enumerate((4.0, 9.0, 14.0)):
        z = WIDTH / 2
        mesh.box("wood", (x - 1.2, 0.72, z - 0.45), (x + 1.2, 0.78, z + 0.45))
        for lx in (x - 1.1, x + 1.05):
            for lz in (z - 0.4, z + 0.35):
                mesh.box("wood", (lx, 0.0, lz), (lx + 0.05, 0.72, lz + 0.05), skip=("-y", "+y"))
        for bz in (z - 0.9, z + 0.6):
            mesh.box("wood", (x - 1.1, 0.0, bz), (x + 1.1, 0.45, bz + 0.3), skip=("-y",))
    # Banners hanging across the hall from the ceiling, free in the air: seen from both sides.
    for x in (3.2, 14.8):
        mesh.quad("banner", (x, HEIGHT - 0.3, WIDTH / 2 - 0.8), (0, 0, 1.6), (0, -3.2, 0))
    return mesh


def write_obj(mesh, out, flat, means):
    with open(os.path.join(out, "atrium.mtl"), "w") as m:
        m.write("# generated by bench/atrium_scene.py\n")
        for name, (texture, _, two_sided) in MATERIALS.items():
            m.write(f"newmtl {name}\n")
            if two_sided:
                m.write("# two-sided: hangs free in the air, seen from both sides (radiosity --two-sided)\n")
            if flat:
                m.write("Kd %.4f %.4f %.4f\n" % means[texture])
            else:
                m.write(f"Kd 1 1 1\nmap_Kd textures/{texture}.png\n")
    with open(os.path.join(out, "atrium.obj"), "w") as o:
        o.write("# generated by bench/atrium_scene.py: metres, +Y up\nmtllib atrium.mtl\n")
        offset = 0
        for name, part in mesh.parts.items():
            if not part["tri"]:
                continue
            o.write(f"o {name}\nusemtl {name}\n")
            o.writelines("v %.6f %.6f %.6f\n" % p for p in part["v"])
            o.writelines("vt %.6f %.6f\n" % uv for uv in part["uv"])
            o.writelines("vn %.6f %.6f %.6f\n" % n for n in part["n"])
            for tri in part["tri"]:
                o.write("f " + " ".join("%d/%d/%d" % ((offset + k + 1,) * 3) for k in tri) + "\n")
            offset += len(part["v"])


def quaternion_from_minus_z(direction):
    """The rotation that takes −Z (a glTF light's direction) to the unit vector `direction`."""
    d = normalised(direction)
    f = (0.0, 0.0, -1.0)
    c = sum(f[i] * d[i] for i in range(3))
    axis = cross(f, d)
    if length(axis) < 1e-12:
        return [0.0, 1.0, 0.0, 0.0] if c < 0 else [0.0, 0.0, 0.0, 1.0]
    half = math.acos(max(-1.0, min(1.0, c))) / 2
    axis = normalised(axis)
    return [axis[0] * math.sin(half), axis[1] * math.sin(half), axis[2] * math.sin(half), math.cos(half)]


def write_gltf(mesh, out, camera):
    """glTF 2.0 with one mesh (a primitive per material) and a binary buffer: float32 POSITION,
    NORMAL, TEXCOORD_0 (glTF's v runs down the image: v = 1 − the OBJ's v) and uint32 indices."""
    blob = bytearray()
    views, accessors, primitives, materials, textures, images = [], [], [], [], [], []

    def add_view(data, target):
        while len(blob) % 4:
            blob.append(0)
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data), "target": target})
        blob.extend(data)
        return len(views) - 1

    def add_accessor(values, kind, component, target, with_bounds=False):
        width = {"VEC2": 2, "VEC3": 3, "SCALAR": 1}[kind]
        flat = [c for v in values for c in (v if width > 1 else (v,))]
        data = struct.pack("<%d%s" % (len(flat), "f" if component == 5126 else "I"), *flat)
        acc = {"bufferView": add_view(data, target), "componentType": component, "count": len(values), "type": kind}
        if with_bounds:
            acc["min"] = [min(v[i] for v in values) for i in range(width)]
            acc["max"] = [max(v[i] for v in values) for i in range(width)]
        accessors.append(acc)
        return len(accessors) - 1

    for name, (texture, _, two_sided) in MATERIALS.items():
        part = mesh.parts[name]
        images.append({"uri": f"../textures/{texture}.png"})
        textures.append({"source": len(images) - 1, "sampler": 0})
        materials.append({"name": name, "doubleSided": two_sided,
                          "pbrMetallicRoughness": {"baseColorTexture": {"index": len(textures) - 1},
                                                   "metallicFactor": 0.0, "roughnessFactor": 1.0}})
        if not part["tri"]:
            continue
        attributes = {
            "POSITION": add_accessor(part["v"], "VEC3", 5126, 34962, with_bounds=True),
            "NORMAL": add_accessor(part["n"], "VEC3", 5126, 34962),
            "TEXCOORD_0": add_accessor([(u, 1.0 - v) for u, v in part["uv"]], "VEC2", 5126, 34962),
        }
        indices = add_accessor([i for t in part["tri"] for i in t], "SCALAR", 5125, 34963)
        primitives.append({"attributes": attributes, "indices": indices, "material": len(materials) - 1})
    with open(os.path.join(out, "atrium.bin"), "wb") as b:
        b.write(blob)
    # The camera node: glTF cameras look along their local −Z with +Y up.
    forward = normalised(sub(camera["look_at"], camera["position"]))
    right = normalised(cross(forward, (0.0, 1.0, 0.0)))
    up = cross(right, forward)
    # Rotation matrix columns (right, up, −forward) → quaternion.
    m = [[right[0], up[0], -forward[0]], [right[1], up[1], -forward[1]], [right[2], up[2], -forward[2]]]
    w = math.sqrt(max(0.0, 1 + m[0][0] + m[1][1] + m[2][2])) / 2
    camera_rotation = [(m[2][1] - m[1][2]) / (4 * w), (m[0][2] - m[2][0]) / (4 * w), (m[1][0] - m[0][1]) / (4 * w), w]
    # The sun: lux = 683 lm/W × the irradiance's largest channel, colour = irradiance / that channel
    # (the sidecar beside the OBJ holds the same sun in W·m⁻²).
    peak = max(SUN_IRRADIANCE)
    document = {
        "asset": {"version": "2.0", "generator": "radiosity bench/atrium_scene.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"name": "sun", "type": "directional", "color": [c / peak for c in SUN_IRRADIANCE], "intensity": 683.0 * peak}]}},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2]}],
        "nodes": [{"name": "atrium", "mesh": 0},
                  {"name": "camera", "camera": 0, "translation": list(camera["position"]), "rotation": camera_rotation},
                  {"name": "sun", "rotation": quaternion_from_minus_z(SUN_DIRECTION),
                   "extensions": {"KHR_lights_punctual": {"light": 0}}}],
        "cameras": [{"type": "perspective", "perspective": {
            "yfov": math.radians(camera["vfov_degrees"]), "aspectRatio": camera["width"] / camera["height"],
            "znear": 0.05}}],
        "meshes": [{"name": "atrium", "primitives": primitives}],
        "materials": materials,
        "textures": textures,
        "images": images,
        "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}],
        "buffers": [{"uri": "atrium.bin", "byteLength": len(blob)}],
        "bufferViews": views,
        "accessors": accessors,
    }
    with open(os.path.join(out, "atrium.gltf"), "w") as g:
        json.dump(document, g, indent=1)


def write_json(path, value):
    with open(path, "w") as f:
        json.dump(value, f, indent=1)
        f.write("\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out", help="output folder (created)")
    parser.add_argument("--size", choices=sorted(SIZES), default="small")
    parser.add_argument("--cell", type=float, help="longest grid edge in metres (overrides --size)")
    parser.add_argument("--flat", action="store_true", help="Kd = mean texture colour, no map_Kd")
    args = parser.parse_args()
    cell = args.cell if args.cell is not None else SIZES[args.size]
    if not (cell > 0.01):
        parser.error("--cell must be above 0.01 m")
    out = args.out
    os.makedirs(os.path.join(out, "textures"), exist_ok=True)
    os.makedirs(os.path.join(out, "gltf"), exist_ok=True)
    means = {}
    for texture in sorted({t for t, _, _ in MATERIALS.values()}):
        rows, means[texture] = atrium_textures.render(texture, TEXTURE_SIZE)
        atrium_textures.write_png(os.path.join(out, "textures", texture + ".png"), TEXTURE_SIZE, TEXTURE_SIZE, rows)
    mesh = build(cell)
    write_obj(mesh, out, args.flat, means)
    camera = {"comment": "from the west end of the hall, looking east along +x under the roof opening",
              "position": [0.8, 1.7, WIDTH / 2 - 0.6], "look_at": [LENGTH, 3.2, WIDTH / 2],
              "up": [0, 1, 0], "vfov_degrees": 60, "width": 320, "height": 200}
    sun = {"type": "directional", "direction": list(SUN_DIRECTION), "irradiance": SUN_IRRADIANCE,
           "angular_diameter_degrees": 0.53}
    sky = {"type": "sky", "radiance": SKY_RADIANCE, "up": [0, 1, 0]}
    write_json(os.path.join(out, "atrium.lights.json"), {"lights": [sun, sky]})
    write_json(os.path.join(out, "atrium.camera.json"), camera)
    write_gltf(mesh, os.path.join(out, "gltf"), camera)
    write_json(os.path.join(out, "gltf", "atrium.lights.json"),
               {"lights": [dict(sky, comment="the sun is in atrium.gltf (KHR_lights_punctual)")]})
    write_json(os.path.join(out, "gltf", "atrium.camera.json"), camera)
    print(f"atrium_scene: {mesh.triangle_count()} triangles (cell {cell:g} m) in {out}")


if __name__ == "__main__":
    main()
