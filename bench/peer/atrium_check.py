#!/usr/bin/env python3
"""Why the atrium is not raced: the project and Cycles disagree on its indirect light, and a third,
independent estimate sides with the project where they differ most (docs/peer.md, "The atrium").

First the sky and the sun themselves, on three small grey scenes it writes (an open floor, a room
open at the top, the room roofed but for a hole). Then the atrium under the race's sky alone,
one-sided grey surfaces as the scene ships: it renders, with the same seed
and samples in both tools, the light seen and direct light (Cycles `--max-bounces 0`, the project's
`bounce_sum_1`), the same plus one diffuse bounce (`--max-bounces 1`, `bounce_sum_2`) and everything;
prints the mean ratio project / Cycles of each and of the first-bounce term alone. Then the same two
terms in a close view of a door recess on the south arcade, where the two differ most, with
bench/peer/first_bounce.py's brute-force estimate at two of its pixels.

    /usr/bin/python3 bench/peer/atrium_check.py [--build build] [--out out/atrium_check] [--spp 128]

About 8 minutes here (2 cores). Needs blender (scripts/setup.sh --bench) and a Release build.
"""
import argparse
import json
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import first_bounce  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENE = os.path.normpath(os.path.join(ROOT, "..", "shared", "scenes", "sponza-dabrovic", "sponza.obj"))
CAMERA = os.path.join(os.path.dirname(SCENE), "sponza.camera.json")
SKY = [0.35, 0.45, 0.65]  # the race's sky (bench/peer/race.py)
# Looking at the door panel of the recess at x = -4.4, z = 7.47 (the south arcade).
DOOR_CAMERA = {"position": [-4.4, 2.3, 5.8], "look_at": [-4.4, 2.3, 7.466], "up": [0, 1, 0],
               "vfov_degrees": 60, "width": 128, "height": 128}
DOOR_PIXELS = [(55, 85), (72, 85)]
SUN = [0.3, -1, 0.25, 8, 7.6, 6.8]  # the race's sun
# Small scenes that check the sky and the sun themselves, grey and one-sided with inward faces: an
# open floor (direct light only), a 4 m room open at the top, and the same room roofed but for a
# 1 m hole (light that bounces many times). Quads as (corner, corner, corner, corner), y up.
FLOOR = [[(-50, 0, -50), (-50, 0, 50), (50, 0, 50), (50, 0, -50)]]
WALLS = [[(-2, 0, -2), (-2, 0, 2), (2, 0, 2), (2, 0, -2)], [(-2, 0, -2), (2, 0, -2), (2, 4, -2), (-2, 4, -2)],
         [(-2, 0, 2), (2, 0, 2), (2, 4, 2), (-2, 4, 2)], [(-2, 0, -2), (-2, 0, 2), (-2, 4, 2), (-2, 4, -2)],
         [(2, 0, -2), (2, 0, 2), (2, 4, 2), (2, 4, -2)]]
ROOF_WITH_HOLE = [[(-2, 4, -2), (2, 4, -2), (2, 4, -0.5), (-2, 4, -0.5)],
                  [(-2, 4, 0.5), (2, 4, 0.5), (2, 4, 2), (-2, 4, 2)],
                  [(-2, 4, -0.5), (-0.5, 4, -0.5), (-0.5, 4, 0.5), (-2, 4, 0.5)],
                  [(0.5, 4, -0.5), (2, 4, -0.5), (2, 4, 0.5), (0.5, 4, 0.5)]]
SMALL_SCENES = {
    "floor": (FLOOR, {"position": [0, 3, 6], "look_at": [0, 0, 0]}),
    "open_room": (WALLS, {"position": [1.5, 3.5, 1.5], "look_at": [-1, 0.5, -1]}),
    "room_with_hole": (WALLS + ROOF_WITH_HOLE, {"position": [1.5, 3.5, 1.5], "look_at": [-1, 0.5, -1]}),
}


def write_small_scene(quads, inside, path):
    """An OBJ of the quads, each wound so that its normal faces `inside` (or up, for a floor)."""
    with open(path, "w") as f:
        for k, quad in enumerate(quads):
            q = [np.array(p, float) for p in quad]
            normal = np.cross(q[1] - q[0], q[2] - q[0])
            if normal @ (inside - sum(q) / 4) < 0:
                q = q[::-1]
            f.writelines(f"v {p[0]:g} {p[1]:g} {p[2]:g}\n" for p in q)
            f.write(f"f {4 * k + 1} {4 * k + 2} {4 * k + 3} {4 * k + 4}\n")
BLOCK = 5  # the images' values at a pixel: the mean over the (2 BLOCK + 1)^2 pixels around it


def run(args):
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"atrium_check: {' '.join(args)} failed:\n{done.stdout[-2000:]}{done.stderr[-2000:]}")


def read_exr(build, path):
    """The image as the sum of its channels per pixel, rows from the top (via render_compare pfm)."""
    pfm = path + ".pfm"
    run([os.path.join(build, "bin/render_compare"), "pfm", path, pfm])
    with open(pfm, "rb") as f:
        f.readline()
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        pixels = np.fromfile(f, dtype="<f4" if scale < 0 else ">f4").reshape(height, width, 3)
    return pixels[::-1].sum(2).astype(float)


def cycles(scene, camera, spp, image, light, bounces=None):
    command = ["blender", "-b", "--factory-startup", "--python-exit-code", "1", "--python",
               os.path.join(ROOT, "bench/peer/cycles_render.py"), "--", scene, "--camera", camera,
               "--spp", str(spp), "--out", image, "--seed", "1", "--threads", "2", *light]
    if bounces is not None:
        command += ["--max-bounces", str(bounces)]
    run(command)


def project(build, scene, camera, spp, directory, light, extra=()):
    run([os.path.join(build, "bin/radiosity"), "render", scene, "--camera", camera, "--method", "path",
         "--spp", str(spp), "--seed", "1", "--out", directory, "-q", *light, *extra])


def small_scenes(build, spp, out):
    """Mean ratio project / Cycles of each small scene under the sky and under the sun."""
    for name, (quads, view) in SMALL_SCENES.items():
        scene = os.path.join(out, f"{name}.obj")
        write_small_scene(quads, np.array([0, 2.0, 0]), scene)
        camera = os.path.join(out, f"{name}.camera.json")
        with open(camera, "w") as f:
            json.dump(dict(view, up=[0, 1, 0], vfov_degrees=60, width=96, height=96), f)
        ratios = []
        for light in (["--sky", *map(str, SKY)], ["--sun", *map(str, SUN)]):
            tag = f"{name}_{light[0][2:]}"
            cycles(scene, camera, spp, os.path.join(out, f"{tag}_cycles.exr"), light)
            project(build, scene, camera, spp, os.path.join(out, f"{tag}_project"), light)
            ratios.append(ratio(read_exr(build, os.path.join(out, f"{tag}_project", "render.exr")),
                                read_exr(build, os.path.join(out, f"{tag}_cycles.exr"))))
        print(f"  {name:15s} sky {ratios[0]:.4f}   sun {ratios[1]:.4f}")


def render_both(build, camera, spp, out, tag):
    """Cycles at 0, 1 and all bounces; the project's path tracer with its bounces separated."""
    images = {}
    light = ["--sky", *map(str, SKY)]
    for bounces in (0, 1, None):
        image = os.path.join(out, f"{tag}_cycles_{'all' if bounces is None else bounces}.exr")
        cycles(SCENE, camera, spp, image, light, bounces)
        images[f"cycles_{bounces}"] = read_exr(build, image)
    directory = os.path.join(out, f"{tag}_project")
    project(build, SCENE, camera, spp, directory, light, ["--bounces-separate", "2"])
    for name, file in (("project_0", "bounce_sum_1"), ("project_1", "bounce_sum_2"),
                       ("project_None", "render")):
        images[name] = read_exr(build, os.path.join(directory, file + ".exr"))
    return images


def ratio(a, b):
    return a.mean() / b.mean() if b.mean() > 0 else float("nan")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--out", default=os.path.join(ROOT, "out/atrium_check"))
    parser.add_argument("--spp", type=int, default=128)
    parser.add_argument("--pairs", type=int, default=2000)
    args = parser.parse_args()
    if not os.path.isfile(SCENE):
        sys.exit(f"atrium_check: {SCENE} not found")
    os.makedirs(args.out, exist_ok=True)

    print(f"Small scenes, {4 * args.spp} spp: mean ratio project / Cycles")
    small_scenes(args.build, 4 * args.spp, args.out)

    whole = render_both(args.build, CAMERA, args.spp, args.out, "atrium")
    print(f"The atrium from its camera, sky only, {args.spp} spp: mean ratio project / Cycles")
    print(f"  light seen + direct light:    {ratio(whole['project_0'], whole['cycles_0']):.4f}")
    print(f"  + one diffuse bounce:         {ratio(whole['project_1'], whole['cycles_1']):.4f}")
    print(f"  everything:                   {ratio(whole['project_None'], whole['cycles_None']):.4f}")
    print(f"  the first-bounce term alone:  "
          f"{ratio(whole['project_1'] - whole['project_0'], whole['cycles_1'] - whole['cycles_0']):.4f}")

    sun = ["--sun", *map(str, SUN)]
    cycles(SCENE, CAMERA, args.spp, os.path.join(args.out, "atrium_sun_cycles.exr"), sun)
    project(args.build, SCENE, CAMERA, args.spp, os.path.join(args.out, "atrium_sun_project"), sun)
    sun_ratio = ratio(read_exr(args.build, os.path.join(args.out, "atrium_sun_project", "render.exr")),
                      read_exr(args.build, os.path.join(args.out, "atrium_sun_cycles.exr")))
    print(f"  everything, under the sun alone: {sun_ratio:.4f}")

    door_camera = os.path.join(args.out, "door.camera.json")
    with open(door_camera, "w") as f:
        json.dump(DOOR_CAMERA, f)
    door = render_both(args.build, door_camera, 2 * args.spp, args.out, "door")
    project_term = door["project_1"] - door["project_0"]
    cycles_term = door["cycles_1"] - door["cycles_0"]
    print(f"The door recess (x -4.4, z 7.47), first-bounce term, {2 * args.spp} spp "
          f"(sum of channels, mean of {2 * BLOCK + 1}^2 pixels) against the brute-force estimate:")
    print(f"  whole view: project / Cycles {ratio(project_term, cycles_term):.3f}")
    vertices, faces = first_bounce.read_obj_triangles(SCENE)
    tracer = first_bounce.BruteForceTracer(vertices, faces)
    rng = np.random.default_rng(1)
    for x, y in DOOR_PIXELS:
        block = (slice(y - BLOCK, y + BLOCK + 1), slice(x - BLOCK, x + BLOCK + 1))
        _, value, error = first_bounce.first_bounce(tracer, DOOR_CAMERA, x, y, sum(SKY), 0.5,
                                                    args.pairs, rng)
        print(f"  pixel {x} {y}: project {project_term[block].mean():.5f}, "
              f"Cycles {cycles_term[block].mean():.5f}, brute force {value:.5f} +- {error:.5f}")


if __name__ == "__main__":
    main()
