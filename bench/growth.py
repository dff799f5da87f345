#!/usr/bin/env python3
"""Cost growth with scene size: solves the generated room (bench/scene_generator.py) at element
counts from 1e3 to 1e5, and records the form-factor and solve times (summary.json) and the peak
resident memory of the process (/usr/bin/time). Fits time = c · N^k by least squares in log–log
and writes CSV and an SVG plot.

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


def svg_loglog(path, title, series, xlabel, ylabel):
    """Minimal log–log line plot: series = [(label, colour, [(x, y)])]."""
    w, h, m = 640, 420, 60
    pts = [p for _, _, s in series for p in s if p[1] > 0]
    x0, x1 = math.log10(min(p[0] for p in pts)), math.log10(max(p[0] for p in pts))
    y0, y1 = math.floor(math.log10(min(p[1] for p in pts))), math.ceil(math.log10(max(p[1] for p in pts)))
    x0, x1 = math.floor(x0), math.ceil(x1)
    X = lambda x: m + (math.log10(x) - x0) / max(x1 - x0, 1e-9) * (w - 2 * m)
    Y = lambda y: h - m - (math.log10(y) - y0) / max(y1 - y0, 1e-9) * (h - 2 * m)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="12">',
           f'<rect width="{w}" height="{h}" fill="white"/>',
           f'<text x="{w / 2}" y="20" text-anchor="middle" font-size="14">{title}</text>',
           f'<text x="{w / 2}" y="{h - 15}" text-anchor="middle">{xlabel}</text>',
           f'<text x="15" y="{h / 2}" text-anchor="middle" transform="rotate(-90 15 {h / 2})">{ylabel}</text>']
    for d in range(x0, x1 + 1):
        out.append(f'<line x1="{X(10 ** d)}" y1="{m}" x2="{X(10 ** d)}" y2="{h - m}" stroke="#ddd"/>'
                   f'<text x="{X(10 ** d)}" y="{h - m + 15}" text-anchor="middle">1e{d}</text>')
    for d in range(y0, y1 + 1):
        out.append(f'<line x1="{m}" y1="{Y(10 ** d)}" x2="{w - m}" y2="{Y(10 ** d)}" stroke="#ddd"/>'
                   f'<text x="{m - 5}" y="{Y(10 ** d) + 4}" text-anchor="end">1e{d}</text>')
    for k, (label, colour, s) in enumerate(series):
        s = [p for p in s if p[1] > 0]
        out.append('<polyline fill="none" stroke="%s" stroke-width="2" points="%s"/>' %
                   (colour, " ".join(f"{X(x):.1f},{Y(y):.1f}" for x, y in s)))
        out += [f'<circle cx="{X(x):.1f}" cy="{Y(y):.1f}" r="3" fill="{colour}"/>' for x, y in s]
        out.append(f'<text x="{m + 10}" y="{m + 15 + 16 * k}" fill="{colour}">{label}</text>')
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out))


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
                   "rays": s["form_factors"]["rays_cast"], "shots": s["solver"]["iterations"],
                   "threads": s["threads"]}
            print(row, flush=True)
            rows.append(row)
    with open(os.path.join(args.out, "growth.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    n = [r["elements"] for r in rows]
    fits = {k: fit_exponent(n, [r[k] for r in rows]) for k in ("form_factor_s", "solve_s", "total_s", "peak_mib")}
    with open(os.path.join(args.out, "growth_fit.json"), "w") as f:
        json.dump(fits, f, indent=2)
    print("fitted exponents (quantity ~ N^k):", {k: round(v, 2) for k, v in fits.items()})
    svg_loglog(os.path.join(args.out, "growth.svg"), "Cost against element count (generated room)",
               [(f"form factors (k = {fits['form_factor_s']:.2f})", "#1f77b4",
                 [(x, r["form_factor_s"]) for x, r in zip(n, rows)]),
                (f"solve (k = {fits['solve_s']:.2f})", "#d62728", [(x, r["solve_s"]) for x, r in zip(n, rows)]),
                (f"peak memory MiB (k = {fits['peak_mib']:.2f})", "#2ca02c",
                 [(x, r["peak_mib"]) for x, r in zip(n, rows)])],
               "elements", "seconds / MiB")


if __name__ == "__main__":
    main()
