#!/usr/bin/env python3
"""Relighting from kept form factors against solving and baking the changed scene afresh.

    python3 bench/relight_speed.py [--build build] [--repeats 3]

On the shared atrium (Sponza under the sky and sun of bench/real_scenes.sh, at the defaults):
  1. once: `solve --keep-factors` of the scene as lit (the kept solve);
  2. the change: the sun warmer and dimmer (× [1.2, 0.8, 0.5]) and the sky at half (out/dusk.json
     in docs/relight.md), given to relight as an override file and to the fresh side as the
     changed --sky/--sun values;
  3. per repeat, interleaved: `bake` of the changed scene from scratch (its solve and its
     lightmap: what a baker without kept factors runs), `relight KEPT --solver gauss-seidel`, and
     `bake --solution RELIT` (the relit lightmap).
Prints the medians and two ratios: the fresh bake against relight alone (the solution and the
solve's outputs), and against relight + bake --solution (the lightmap too). Writes
bench/results/relight_speed.csv (every run) under the scratch directory BUILD/relight_speed/.
"""
import argparse
import csv
import json
import os
import shutil
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = os.environ.get("RADIOSITY_SCENES", os.path.join(ROOT, "..", "shared", "scenes"))
SKY, SUN_DIRECTION, SUN = (0.35, 0.45, 0.65), (0.3, -1, 0.25), (8, 7.6, 6.8)
SKY_SCALE, SUN_SCALE = 0.5, (1.2, 0.8, 0.5)


def lights(sky, sun):
    return (["--sky"] + ["%.17g" % v for v in sky] + ["--sun"]
            + ["%.17g" % v for v in SUN_DIRECTION + tuple(sun)])


def run(binary, args):
    start = time.monotonic()
    p = subprocess.run([binary] + args + ["--quiet"], capture_output=True, text=True)
    seconds = time.monotonic() - start
    if p.returncode != 0:
        sys.exit("relight_speed: radiosity %s failed:\n%s" % (" ".join(args), p.stderr))
    return seconds


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    binary = os.path.join(args.build, "bin", "radiosity")
    scene = os.path.join(SCENES, "sponza-dabrovic", "sponza.obj")
    if not os.path.exists(scene):
        sys.exit("relight_speed: %s is missing (set RADIOSITY_SCENES)" % scene)
    work = os.path.join(args.build, "relight_speed")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    kept, relit = os.path.join(work, "kept"), os.path.join(work, "relit")
    override = os.path.join(work, "dusk.json")
    with open(override, "w") as f:
        json.dump({"lights": {"sun": {"scale": list(SUN_SCALE)}, "sky": {"scale": SKY_SCALE}}}, f)
    lit = lights(SKY, SUN)
    changed = lights(tuple(SKY_SCALE * v for v in SKY), tuple(s * v for s, v in zip(SUN_SCALE, SUN)))

    t_kept = run(binary, ["solve", scene, "--keep-factors", "--out", kept] + lit)
    print("kept solve (solve --keep-factors, once): %.1f s" % t_kept)
    rows = []
    for repeat in range(args.repeats):
        fresh = run(binary, ["bake", scene, "--out", os.path.join(work, "fresh")] + changed)
        relight = run(binary, ["relight", kept, "--override", override, "--out", relit,
                               "--solver", "gauss-seidel"])
        summary = json.load(open(os.path.join(relit, "summary.json")))
        if summary["relight"]["rays_cast"] != 0:
            sys.exit("relight_speed: relight cast rays")
        rebake = run(binary, ["bake", scene, "--solution", relit, "--solver", "gauss-seidel",
                              "--out", os.path.join(work, "relit_baked")] + lit)
        baked = json.load(open(os.path.join(work, "relit_baked", "bake.json")))
        if not baked["reused_saved_solution"]:
            sys.exit("relight_speed: bake --solution did not reuse the relit solution")
        rows.append({"repeat": repeat + 1, "fresh_solve_and_bake_s": round(fresh, 2),
                     "relight_s": round(relight, 2), "bake_relit_solution_s": round(rebake, 2)})
        print("repeat %d: fresh bake %.1f s, relight %.2f s, bake --solution %.2f s"
              % (repeat + 1, fresh, relight, rebake))
    fresh = statistics.median(r["fresh_solve_and_bake_s"] for r in rows)
    relight = statistics.median(r["relight_s"] for r in rows)
    both = statistics.median(r["relight_s"] + r["bake_relit_solution_s"] for r in rows)
    print("medians of %d: fresh solve + bake %.1f s; relight %.2f s (%.1fx faster); relight + "
          "bake --solution %.2f s (%.1fx faster)"
          % (len(rows), fresh, relight, fresh / relight, both, fresh / both))
    os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
    with open(os.path.join(ROOT, "bench", "results", "relight_speed.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main()
