#!/usr/bin/env python3
"""Writes cornell_box_mirror_glass.obj/.mtl next to this script: the Cornell box with the tall
block turned into a mirror and the short block replaced by a glass sphere resting on the floor
where the short block stood. Rerun after changing cornell_box.obj."""
import math
import os

here = os.path.dirname(os.path.abspath(__file__))
src = open(os.path.join(here, "cornell_box.obj")).read().splitlines()

# Keep everything up to the short block; the tall block follows with a mirror material.
out, vertices, skip = [], 0, False
for line in src:
    if line.startswith("mtllib"):
        line = "mtllib cornell_box_mirror_glass.mtl"
    if line.startswith("o short_block"):
        skip = True
    elif line.startswith("o tall_block"):
        skip = False
        out.append(line)
        out.append("# a mirror now (illum 3, Ks 0.9)")
        continue
    if line.startswith("v "):
        vertices += 1
        out.append(line)
        continue
    if skip:
        continue
    if line.startswith("usemtl white") and out and out[-1].startswith("# a mirror"):
        line = "usemtl mirror"
    out.append(line)

# Glass sphere: UV sphere, outward normals, counter-clockwise seen from outside.
cx, cy, cz, r = 0.186, 0.09, 0.169, 0.09
rings, segments = 16, 32
first = vertices + 1
out.append("")
out.append("o glass_sphere")
out.append("# radius 0.09 m at (0.186, 0.09, 0.169): where the short block stood, touching the floor")
out.append(f"v {cx:.6f} {cy + r:.6f} {cz:.6f}")  # north pole
for i in range(1, rings):
    theta = math.pi * i / rings
    for j in range(segments):
        phi = 2 * math.pi * j / segments
        out.append(f"v {cx + r * math.sin(theta) * math.cos(phi):.6f} {cy + r * math.cos(theta):.6f} "
                   f"{cz + r * math.sin(theta) * math.sin(phi):.6f}")
out.append(f"v {cx:.6f} {cy - r:.6f} {cz:.6f}")  # south pole
north, south = first, first + 1 + (rings - 1) * segments
ring = lambda i, j: first + 1 + (i - 1) * segments + (j % segments)
out.append("usemtl glass")
for j in range(segments):
    out.append(f"f {north} {ring(1, j + 1)} {ring(1, j)}")
for i in range(1, rings - 1):
    for j in range(segments):
        out.append(f"f {ring(i, j)} {ring(i, j + 1)} {ring(i + 1, j + 1)} {ring(i + 1, j)}")
for j in range(segments):
    out.append(f"f {south} {ring(rings - 1, j)} {ring(rings - 1, j + 1)}")

with open(os.path.join(here, "cornell_box_mirror_glass.obj"), "w") as f:
    f.write("\n".join(out) + "\n")
mtl = open(os.path.join(here, "cornell_box.mtl")).read()
mtl += "\nnewmtl mirror\nKd 0 0 0\nKs 0.9 0.9 0.9\nillum 3\n\nnewmtl glass\nKd 0 0 0\nKs 1 1 1\nTf 1 1 1\nNi 1.5\nillum 7\n"
with open(os.path.join(here, "cornell_box_mirror_glass.mtl"), "w") as f:
    f.write(mtl)
