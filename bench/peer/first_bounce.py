#!/usr/bin/env python3
"""An independent estimate of one pixel's first diffuse bounce of sky light (docs/peer.md, "The atrium").

When the project and Cycles disagree, a third opinion that shares no code with either settles
which one is off. This one is deliberately simple: numpy, double precision, every ray against every
triangle (no BVH), no ray offsets (a ray skips only the triangle it leaves), uniform grey Lambert
surfaces, one-sided (a back face absorbs), a uniform sky above the horizon (y > 0) as the only light.

For the camera ray through the pixel's centre it finds the surface point A and estimates

    L1(A) = rho^2 * E[ L_sky * V(B, w') ],   w ~ cos at A, B = hit(A, w), w' ~ cos at B,

the radiance A sends to the camera after exactly one diffuse bounce (camera -> A -> B -> sky): the
project's `bounce_2` of `render --method path --bounces-separate 2`, and Cycles' image at
`--max-bounces 1` minus its image at `--max-bounces 0`. Printed as the sum of the RGB channels with
its standard error. About 40 s per 1,000 ray pairs on a 66k-triangle scene.

    /usr/bin/python3 bench/peer/first_bounce.py SCENE.obj CAMERA.json --sky R G B \\
        --pixel X Y [--pixel X Y ...] [--pairs 2000] [--rho 0.5] [--seed 1]
"""
import argparse
import json
import math
import sys

import numpy as np


def read_obj_triangles(path):
    """The OBJ's faces as triangles (fans), vertex positions only; materials are ignored."""
    vertices, faces = [], []
    with open(path, errors="replace") as f:
        for number, line in enumerate(f, 1):
            fields = line.split()
            if not fields:
                continue
            if fields[0] == "v":
                vertices.append([float(x) for x in fields[1:4]])
            elif fields[0] == "f":
                corners = []
                for token in fields[1:]:
                    index = int(token.split("/")[0])
                    corners.append(index - 1 if index > 0 else len(vertices) + index)
                if len(corners) < 3:
                    sys.exit(f"{path}:{number}: a face needs 3 vertices")
                faces += [[corners[0], corners[k], corners[k + 1]] for k in range(1, len(corners) - 1)]
    return np.array(vertices), np.array(faces)


class BruteForceTracer:
    """Closest hits by testing every triangle (Moller-Trumbore), in double precision."""

    def __init__(self, vertices, faces):
        self.a = vertices[faces[:, 0]]
        self.e1 = vertices[faces[:, 1]] - self.a
        self.e2 = vertices[faces[:, 2]] - self.a
        normals = np.cross(self.e1, self.e2)
        length = np.linalg.norm(normals, axis=1)
        self.valid = length > 0
        self.normals = normals / np.where(self.valid, length, 1.0)[:, None]

    def closest(self, origin, direction, skip=-1):
        p = np.cross(direction, self.e2)
        det = (self.e1 * p).sum(1)
        with np.errstate(divide="ignore", invalid="ignore"):
            inverse = 1.0 / det
            s = origin - self.a
            u = (s * p).sum(1) * inverse
            q = np.cross(s, self.e1)
            v = (q * direction).sum(1) * inverse
            t = (self.e2 * q).sum(1) * inverse
            hit = self.valid & (det != 0) & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0)
        if skip >= 0:
            hit[skip] = False
        t = np.where(hit, t, np.inf)
        index = int(np.argmin(t))
        return (index, float(t[index])) if math.isfinite(t[index]) else (-1, math.inf)


def cosine_direction(normal, rng):
    helper = np.array([1.0, 0, 0]) if abs(normal[0]) < 0.9 else np.array([0, 1.0, 0])
    tangent = np.cross(normal, helper)
    tangent /= np.linalg.norm(tangent)
    bitangent = np.cross(normal, tangent)
    u1, u2 = rng.random(2)
    r, phi = math.sqrt(u1), 2 * math.pi * u2
    return r * math.cos(phi) * tangent + r * math.sin(phi) * bitangent + math.sqrt(1 - u1) * normal


def camera_ray(camera, x, y):
    """The project's pinhole camera (radiosity/render/camera.cpp) through pixel (x, y)'s centre."""
    position = np.array(camera["position"], float)
    forward = np.array(camera["look_at"], float) - position
    forward /= np.linalg.norm(forward)
    right = np.cross(forward, np.array(camera["up"], float))
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    tan_y = math.tan(math.radians(camera["vfov_degrees"]) / 2)
    tan_x = tan_y * camera["width"] / camera["height"]
    sx = (2 * (x + 0.5) / camera["width"] - 1) * tan_x
    sy = (1 - 2 * (y + 0.5) / camera["height"]) * tan_y
    direction = forward + sx * right + sy * up
    return position, direction / np.linalg.norm(direction)


def first_bounce(tracer, camera, x, y, sky, rho, pairs, rng):
    """(point A, its radiance after one bounce, standard error), radiance as the sum of channels."""
    origin, direction = camera_ray(camera, x, y)
    a_index, t = tracer.closest(origin, direction)
    if a_index < 0 or tracer.normals[a_index] @ direction >= 0:
        return None, 0.0, 0.0  # the sky or a back face: no bounce term
    point_a, normal_a = origin + t * direction, tracer.normals[a_index]
    samples = np.zeros(pairs)
    for k in range(pairs):
        w = cosine_direction(normal_a, rng)
        b_index, t_b = tracer.closest(point_a, w, skip=a_index)
        if b_index < 0 or tracer.normals[b_index] @ w >= 0:
            continue  # the sky seen directly (direct light, not this term) or a back face
        w2 = cosine_direction(tracer.normals[b_index], rng)
        if w2[1] > 0 and tracer.closest(point_a + t_b * w, w2, skip=b_index)[0] < 0:
            samples[k] = sky
    scale = rho * rho
    return point_a, scale * samples.mean(), scale * samples.std(ddof=1) / math.sqrt(pairs)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("scene")
    parser.add_argument("camera")
    parser.add_argument("--sky", type=float, nargs=3, required=True)
    parser.add_argument("--pixel", type=float, nargs=2, action="append", required=True)
    parser.add_argument("--pairs", type=int, default=2000)
    parser.add_argument("--rho", type=float, default=0.5)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    if args.pairs < 2:
        sys.exit("first_bounce: --pairs must be at least 2")
    vertices, faces = read_obj_triangles(args.scene)
    tracer = BruteForceTracer(vertices, faces)
    camera = json.load(open(args.camera))
    rng = np.random.default_rng(args.seed)
    for x, y in args.pixel:
        point, value, error = first_bounce(tracer, camera, x, y, sum(args.sky), args.rho, args.pairs, rng)
        where = "no surface" if point is None else "at " + " ".join(f"{c:.3f}" for c in point)
        print(f"pixel {x:g} {y:g} {where}: first bounce {value:.5f} +- {error:.5f}")


if __name__ == "__main__":
    main()
