#!/usr/bin/env python3
"""What advising large arrays onto huge pages gives, side by side (radiosity/app/huge_page_new.cpp).

    python3 bench/huge_pages.py [--build build] [--repeats 3]

On the shared atrium (Sponza under the sky and sun of bench/real_scenes.sh, at the defaults), in
BUILD/huge_pages/: one `solve --keep-factors` (untimed), then per repeat, each command once with
the hint (the default) and once with RADIOSITY_HUGE_PAGES=0 (the kernel's 4 KiB pages), in
alternating order: `solve --keep-factors` afresh (the default progressive solver, and
Gauss-Seidel as bench/incremental_update.py solves), `relight` of the kept solve with the sun and
sky changed, and `bake --solution` of the kept solve. Prints the medians and their ratios, with
each run's peak resident memory; writes bench/results/huge_pages.csv.
"""
import argparse
import csv
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = os.environ.get("RADIOSITY_SCENES", os.path.join(ROOT, "..", "shared", "scenes"))
LIGHTS = ["--sky", "0.35", "0.45", "0.65", "--sun", "0.3", "-1", "0.25", "8", "7.6", "6.8"]
MODES = {"huge pages": {}, "4 KiB pages": {"RADIOSITY_HUGE_PAGES": "0"}}


def run(binary, args, env):
    """Wall seconds and peak resident memory (MB) of one radiosity command."""
    with tempfile.TemporaryFile() as errors:
        start = time.monotonic()
        p = subprocess.Popen([binary] + args + ["--quiet"], stdout=subprocess.DEVNULL,
                             stderr=errors, env=dict(os.environ, **env))
        _, status, usage = os.wait4(p.pid, 0)
        seconds = time.monotonic() - start
        p.returncode = os.waitstatus_to_exitcode(status)
        if p.returncode != 0:
            errors.seek(0)
            sys.exit("huge_pages: radiosity %s failed:\n%s"
                     % (" ".join(args), errors.read().decode(errors="replace")))
    return seconds, usage.ru_maxrss / 1024


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    binary = os.path.join(args.build, "bin", "radiosity")
    scene = os.path.join(SCENES, "sponza-dabrovic", "sponza.obj")
    if not os.path.exists(scene):
        sys.exit("huge_pages: %s is missing (set RADIOSITY_SCENES)" % scene)
    work = os.path.join(args.build, "huge_pages")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    kept = os.path.join(work, "kept")
    override = os.path.join(work, "dusk.json")
    with open(override, "w") as f:
        json.dump({"lights": {"sun": {"scale": [1.2, 0.8, 0.5]}, "sky": {"scale": 0.5}}}, f)
    run(binary, ["solve", scene, "--keep-factors", "--out", kept] + LIGHTS, {})
    commands = {
        "solve --keep-factors": ["solve", scene, "--keep-factors", "--out",
                                 os.path.join(work, "fresh")] + LIGHTS,
        # As bench/incremental_update.py solves: every row cast up front into one table.
        "solve --keep-factors --solver gauss-seidel": [
            "solve", scene, "--keep-factors", "--solver", "gauss-seidel", "--rays", "1024",
            "--element-size", "2.31", "--out", os.path.join(work, "fresh_gs")] + LIGHTS,
        "relight": ["relight", kept, "--override", override, "--out",
                    os.path.join(work, "relit"), "--solver", "gauss-seidel"],
        "bake --solution": ["bake", scene, "--solution", kept, "--out",
                            os.path.join(work, "baked")] + LIGHTS,
    }
    rows = []
    for repeat in range(args.repeats):
        for name, command in commands.items():
            order = list(MODES.items())
            if repeat % 2:
                order.reverse()
            for mode, env in order:
                seconds, peak = run(binary, command, env)
                rows.append({"repeat": repeat + 1, "command": name, "pages": mode,
                             "seconds": round(seconds, 3), "peak_mb": round(peak)})
                print("repeat %d: %s with %s: %.2f s" % (repeat + 1, name, mode, seconds))
    print("medians of %d:" % args.repeats)
    for name in commands:
        median = {mode: statistics.median(r["seconds"] for r in rows
                                          if r["command"] == name and r["pages"] == mode)
                  for mode in MODES}
        print("  %s: %.2f s with huge pages, %.2f s without: %.2fx"
              % (name, median["huge pages"], median["4 KiB pages"],
                 median["4 KiB pages"] / median["huge pages"]))
    os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
    with open(os.path.join(ROOT, "bench", "results", "huge_pages.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main()
