#!/usr/bin/env python3
"""Monte Carlo noise of a solve: run the same scene with two seeds and report the area-weighted
relative RMS difference of B per non-emitting element, divided by sqrt(2) (the noise of one run).

    python3 bench/seed_noise.py [--solver progressive] [extra radiosity options...]

Uses build/bin/radiosity and data/cornell_box/cornell_box.obj by default."""
import argparse
import csv
import math
import subprocess
import sys
import tempfile


def solve(binary, scene, out, seed, extra):
    subprocess.run([binary, "solve", scene, "--out", out, "--seed", str(seed), "--quiet"] + extra,
                   check=True)
    with open(f"{out}/elements.csv") as f:
        rows = list(csv.DictReader(f))
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--binary", default="build/bin/radiosity")
    parser.add_argument("--scene", default="data/cornell_box/cornell_box.obj")
    args, extra = parser.parse_known_args()
    with tempfile.TemporaryDirectory() as tmp:
        a = solve(args.binary, args.scene, f"{tmp}/a", 1, extra)
        b = solve(args.binary, args.scene, f"{tmp}/b", 2, extra)
    # Emitters are far brighter than anything they light and their own E is the same in both
    # runs; elements above half the brightest are left out so they do not dilute the figure.
    brightest = max(float(r["B_g"]) for r in a)
    num = den = 0.0
    for ra, rb in zip(a, b):
        if ra["element"] != rb["element"]:
            sys.exit("element lists differ between runs")
        if float(ra["B_g"]) > 0.5 * brightest:
            continue
        area = float(ra["area"])
        for c in ("B_r", "B_g", "B_b"):
            num += area * (float(ra[c]) - float(rb[c])) ** 2
            den += area * float(ra[c]) ** 2
    print(f"relative RMS noise per run (area-weighted, all channels, emitters excluded): "
          f"{math.sqrt(num / den) / math.sqrt(2):.4f}  [options: {' '.join(extra) or 'defaults'}]")

if __name__ == "__main__":
    main()
