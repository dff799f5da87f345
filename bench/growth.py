#!/usr/bin/python3
"""Cost growth with scene size: solves the generated room (bench/scene_generator.py) at element
counts from 1e3 to 1e5, and records the form-factor and solve times (summary.json) and the peak
resident memory of the process (/usr/bin/time). Fits time = c · N^k by least squares in log–log
and writes CSV and a PNG plot (matplotlib: Debian's /usr/bin/python3 with python3-matplotlib).

    python3 bench/growth.py [--build build] [--out bench/results] [--sizes 1000,3000,...] [--threads 0]
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def fit_exponent(xs, ys):
    """Least-squares slope of log y against log x."""
    lx = [math.log(x) for x in xs]
    ly = [math.log(max(y, 1e-9)) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    sxx = sum((a - mx) ** 2 for a in lx)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sxx if sxx > 0 else float("nan")


def plot_png(path, rows, fits):
    """Time (form factors, solve) and peak memory against N, log-log, with the fitted exponents."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    n = [r["elements"] for r in rows]
    fig, ax = plt.subplots(figsize=(7.5, 5), dpi=110)
    for key, label, colour in (("form_factor_s", "form factors (s)", "#1f77b4"), ("solve_s", "solve (s)", "#d62728"),
                               ("total_s", "total (s)", "#7f7f7f")):
        ax.plot(n, [r[key] for r in rows], "o-", color=colour, label="%s, k = %.2f" % (label, fits[key]))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("elements N")
    ax.set_ylabel("seconds")
    ax.grid(True, which="both", alpha=0.3)
    mem = ax.twinx()
    mem.plot(n, [r["peak_mib"] for r in rows], "s--", color="#2ca02c",
             label="peak memory (MiB), k = %.2f" % fits["peak_mib"])
    mem.set_yscale("log")
    mem.set_ylabel("peak resident memory (MiB)")
    lines = ax.get_legend_handles_labels()
    more = mem.get_legend_handles_labels()
    ax.legend(lines[0] + more[0], lines[1] + more[1], loc="upper left", fontsize=8)
    ax.set_title("Cost against element count (generated room, %d rays, %d threads)" % (rows[0]["rays_per_element"],
                                                                                       rows[0]["threads"]))
    fig.tight_layout()
    tmp = path + ".tmp"
    fig.savefig(tmp, format="png")
    os.replace(tmp, path)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--out", default=os.path.join(ROOT, "bench/results"))
    parser.add_argument("--sizes", default="1000,3000,10000,30000,100000")
    parser.add_argument("--rays", type=int, default=256)
    parser.add_argument("--threads", type=int, default=0)
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    binary = os.path.join(args.build, "bin/radiosity")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        scene = os.path.join(tmp, "room.obj")
        subprocess.run([sys.executable, os.path.join(ROOT, "bench/scene_generator.py"), scene, "--boxes", "16"],
                       check=True)
        for n in [int(s) for s in args.sizes.split(",")]:
            out = os.path.join(tmp, f"out{n}")
            cmd = ["/usr/bin/time", "-f", "%M", binary, "solve", scene, "--elements", str(n), "--rays",
                   str(args.rays), "--threads", str(args.threads), "--out", out, "--quiet"]
            run = subprocess.run(cmd, capture_output=True, text=True)
            if run.returncode != 0:
                print(run.stderr, file=sys.stderr)
                sys.exit(f"growth: solve with {n} elements failed")
            peak_kib = int(run.stderr.strip().splitlines()[-1])
            s = json.load(open(os.path.join(out, "summary.json")))
            row = {"target_elements": n, "elements": s["scene"]["elements"],
                   "form_factor_s": s["time_seconds"]["form_factors"], "solve_s": s["time_seconds"]["solve"],
                   "total_s": s["time_seconds"]["total"], "peak_mib": peak_kib / 1024,
                   "rays_per_element": args.rays, "rays": s["form_factors"]["rays_cast"], "shots": s["solver"]["iterations"],
                   "threads": s["threads"]}
            print(row, flush=True)
            rows.append(row)
    tmp = os.path.join(args.out, "growth.csv.tmp")
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    os.replace(tmp, os.path.join(args.out, "growth.csv"))
    n = [r["elements"] for r in rows]
    keys = ("form_factor_s", "solve_s", "total_s", "peak_mib")
    fits = {k: fit_exponent(n, [r[k] for r in rows]) for k in keys}
    # Over the largest sizes only: fixed costs (process start, libraries, thread pools) hide the
    # growth at small N, memory most of all.
    large = [r for r in rows if r["elements"] >= 1e4]
    fits_large = ({k: fit_exponent([r["elements"] for r in large], [r[k] for r in large]) for k in keys}
                  if len(large) >= 2 else {})
    tmp = os.path.join(args.out, "growth_fit.json.tmp")
    with open(tmp, "w") as f:
        json.dump({"all_sizes": fits, "n_at_least_1e4": fits_large}, f, indent=2)
    os.replace(tmp, os.path.join(args.out, "growth_fit.json"))
    print("fitted exponents (quantity ~ N^k), all sizes:", {k: round(v, 2) for k, v in fits.items()})
    if fits_large:
        print("fitted exponents, N >= 1e4:", {k: round(v, 2) for k, v in fits_large.items()})
    plot_png(os.path.join(args.out, "growth.png"), rows, fits)

if __name__ == "__main__":
    main()
