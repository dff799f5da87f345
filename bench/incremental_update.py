#!/usr/bin/env python3
"""Incremental re-bake after a geometry edit, against solving and baking again, side by side.

    python3 bench/incremental_update.py [--build build] [--rays N] [--repeats 3]

On the shared atrium (Sponza under the sky and sun of bench/real_scenes.sh), in a scratch copy
under BUILD/incremental_update/ (the shared scene itself is never written):
  1. `solve --keep-factors --solver gauss-seidel` of the scene as shipped (the kept solve);
  2. the edit: a 1 m crate added on the courtyard floor, then (second round) moved 2 m along x;
  3. per round, interleaved and repeated (medians): `update KEPT` + `bake --solution KEPT`
     (incremental; KEPT restored before each repeat) against `solve --keep-factors` +
     `bake --solution` of the edited scene from scratch (fresh);
and prints the wall times, the rows reused, and the relative RMS difference of the two solutions
per element, beside that of the fresh solve and one with another seed (untimed): the Monte Carlo
noise floor. The update draws every ray from the streams a fresh solve draws (keyed by the element,
not its index), so its solution differs from the fresh one by the solvers' tolerance only, far
below that floor. Writes bench/results/incremental_update.csv.
"""
import argparse
import csv
import json
import math
import os
import shutil
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = os.environ.get("RADIOSITY_SCENES", os.path.join(ROOT, "..", "shared", "scenes"))
LIGHTS = ["--sky", "0.35", "0.45", "0.65", "--sun", "0.3", "-1", "0.25", "8", "7.6", "6.8"]


def crate(x0, y0, z0, size, first_vertex):
    """OBJ lines of a closed cube (outward faces) in its own group."""
    lines = ["g crate"]  # Sponza has no MTL: the default material, as the rest
    corners = [(x0 + dx * size, y0 + dy * size, z0 + dz * size)
               for dx in (0, 1) for dy in (0, 1) for dz in (0, 1)]
    lines += ["v %.6f %.6f %.6f" % c for c in corners]
    v = lambda dx, dy, dz: first_vertex + 4 * dx + 2 * dy + dz
    quads = [(v(0, 0, 0), v(0, 0, 1), v(0, 1, 1), v(0, 1, 0)),  # -x
             (v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1)),  # +x
             (v(0, 0, 0), v(1, 0, 0), v(1, 0, 1), v(0, 0, 1)),  # -y
             (v(0, 1, 0), v(0, 1, 1), v(1, 1, 1), v(1, 1, 0)),  # +y
             (v(0, 0, 0), v(0, 1, 0), v(1, 1, 0), v(1, 0, 0)),  # -z
             (v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1))]  # +z
    lines += ["f %d %d %d %d" % q for q in quads]
    return lines


def write_scene(path, original, crate_x):
    with open(original) as f:
        text = f.read()
    if crate_x is not None:
        vertices = sum(1 for line in text.splitlines() if line.startswith("v "))
        text += "\n" + "\n".join(crate(crate_x, 0.093, -0.5, 1.0, vertices + 1)) + "\n"
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def run(binary, args):
    start = time.monotonic()
    p = subprocess.run([binary] + args + ["--quiet"], capture_output=True, text=True)
    seconds = time.monotonic() - start
    if p.returncode != 0:
        sys.exit("incremental_update: radiosity %s failed:\n%s" % (" ".join(args), p.stderr))
    return seconds


def radiosity(csv_path):
    with open(csv_path) as f:
        rows = list(csv.DictReader(f))
    return [(float(r["B_r"]), float(r["B_g"]), float(r["B_b"])) for r in rows]


def relative_rms(a, b):
    num = sum((x - y) ** 2 for p, q in zip(a, b) for x, y in zip(p, q))
    den = sum(y ** 2 for q in b for y in q)
    return math.sqrt(num / den)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--rays", default="1024")
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    binary = os.path.join(args.build, "bin", "radiosity")
    original = os.path.join(SCENES, "sponza-dabrovic", "sponza.obj")
    if not os.path.exists(original):
        sys.exit("incremental_update: %s is missing (set RADIOSITY_SCENES)" % original)
    work = os.path.join(args.build, "incremental_update")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(os.path.join(work, "edited"))
    os.makedirs(os.path.join(work, "fresh"))
    scene = os.path.join(work, "edited", "sponza.obj")
    fresh_scene = os.path.join(work, "fresh", "sponza.obj")
    kept = os.path.join(work, "kept")
    # The element size Sponza gets by default (2.31), given, so that the edits keep it.
    solve = ["--solver", "gauss-seidel", "--rays", args.rays, "--element-size", "2.31"] + LIGHTS
    write_scene(scene, original, None)
    t_kept = run(binary, ["solve", scene, "--out", kept, "--keep-factors"] + solve)
    print("kept solve of the scene as shipped: %.1f s" % t_kept)

    results = []
    for edit, crate_x in (("crate added", -0.5), ("crate moved 2 m", 1.5)):
        write_scene(scene, original, crate_x)
        write_scene(fresh_scene, original, crate_x)
        # Each repeat updates the same kept solve (restored from a copy, untimed), interleaved
        # with the fresh solve and bake; the medians are reported.
        before = kept + "_before_edit"
        shutil.rmtree(before, ignore_errors=True)
        shutil.copytree(kept, before)
        bake = solve
        out = os.path.join(work, "fresh_out")
        times = {"update": [], "rebake": [], "solve": [], "bake": []}
        for repeat in range(args.repeats):
            shutil.rmtree(kept)
            shutil.copytree(before, kept)
            # The restored copy (330 MB on Sponza) written back now, not during the timed update.
            os.sync()
            times["update"].append(run(binary, ["update", kept]))
            times["rebake"].append(run(binary, ["bake", scene, "--out",
                                                os.path.join(work, "rebaked"), "--solution",
                                                kept] + bake))
            baked = json.load(open(os.path.join(work, "rebaked", "bake.json")))
            if not baked["reused_saved_solution"]:
                sys.exit("incremental_update: the re-bake did not reuse the updated solution")
            times["solve"].append(run(binary, ["solve", fresh_scene, "--out", out,
                                               "--keep-factors"] + bake))
            times["bake"].append(run(binary, ["bake", fresh_scene, "--out",
                                              os.path.join(work, "fresh_baked"), "--solution",
                                              out] + bake))
        shutil.rmtree(before)
        summary = json.load(open(os.path.join(kept, "summary.json")))
        t_update, t_rebake, t_solve, t_bake = (statistics.median(times[k])
                                               for k in ("update", "rebake", "solve", "bake"))
        u = summary["update"]
        difference = relative_rms(radiosity(os.path.join(kept, "elements.csv")),
                                  radiosity(os.path.join(out, "elements.csv")))
        # The Monte Carlo noise floor: the fresh solve against one with other random streams
        # (untimed), beside which the update's difference from the fresh solve is to be read.
        other_seed = os.path.join(work, "fresh_seed2")
        run(binary, ["solve", fresh_scene, "--out", other_seed, "--seed", "2"] + bake)
        noise = relative_rms(radiosity(os.path.join(other_seed, "elements.csv")),
                             radiosity(os.path.join(out, "elements.csv")))
        row = {"edit": edit, "elements": summary["scene"]["elements"],
               "rows_reused": u["rows_reused"], "rows_cast_again": u["rows_cast_again"],
               "update_s": round(t_update, 2), "rebake_s": round(t_rebake, 2),
               "fresh_solve_s": round(t_solve, 2), "fresh_bake_s": round(t_bake, 2),
               "speedup": round((t_solve + t_bake) / (t_update + t_rebake), 2),
               "relative_rms_difference": "%.2e" % difference,
               "other_seed_relative_rms_difference": "%.2e" % noise,
               "direct_light_kept": u.get("direct_light_kept", 0)}
        results.append(row)
        print("%s: update %.1f s + re-bake %.1f s against solve %.1f s + bake %.1f s: %.2fx; "
              "%d of %d rows reused; solutions differ by %.2e (relative RMS; a fresh solve with "
              "another seed: %.2e)"
              % (edit, t_update, t_rebake, t_solve, t_bake, row["speedup"], u["rows_reused"],
                 row["elements"], difference, noise))
    os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
    with open(os.path.join(ROOT, "bench", "results", "incremental_update.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(results[0].keys()))
        w.writeheader()
        w.writerows(results)


if __name__ == "__main__":
    main()
