#!/usr/bin/env python3
"""Relative RMSE against the converged path-traced reference versus wall time, Cornell box 256x256.

Runs `radiosity render` with --method radiosity at several gather counts and --method path at
several sample counts, compares each render.exr with data/reference/cornell_box_path.exr
(bench/render_compare), and writes a CSV and an SVG plot (log-log). The reference's own noise
(data/reference/README.md) is removed in quadrature: error = sqrt(rmse^2 - noise_ref^2).

    python3 bench/render_error_vs_time.py [--build build] [--out bench/render_results]
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
SCENE = os.path.join(ROOT, "data/cornell_box/cornell_box.obj")
REFERENCE = os.path.join(ROOT, "data/reference/cornell_box_path.exr")
REFERENCE_NOISE = 0.0  # filled from data/reference/reference_noise.txt

RUNS = [("radiosity", {"--gather": g, "--spp": 4}) for g in (4, 16, 64)] + [
    ("radiosity", {"--gather": g, "--spp": s}) for g, s in ((1, 16), (4, 16), (1, 64), (4, 64), (64, 16))] + [
    ("path", {"--spp": s}) for s in (4, 16, 64, 256)]


def run(build, method, options, workdir):
    out = os.path.join(workdir, method + "_" + "_".join(f"{k[2:]}{v}" for k, v in options.items()))
    args = [os.path.join(build, "bin/radiosity"), "render", SCENE, "--method", method, "--out", out, "-q"]
    for k, v in options.items():
        args += [k, str(v)]
    subprocess.run(args, check=True)
    report = json.load(open(os.path.join(out, "render.json")))
    rmse, ratio = map(float, subprocess.run(
        [os.path.join(build, "bin/render_compare"), "rmse", os.path.join(out, "render.exr"), REFERENCE],
        check=True, capture_output=True, text=True).stdout.split())
    error = math.sqrt(max(0.0, rmse * rmse - REFERENCE_NOISE ** 2))
    return {"method": method, "gather": options.get("--gather", 0), "spp": options["--spp"],
            "seconds": report["time_seconds"]["total"], "render_seconds": report["time_seconds"]["render"],
            "rays": report["rays"]["total"], "rmse_raw": rmse, "relative_rmse": error,
            "mean_ratio": ratio}


def svg_plot(rows, path):
    w, h, m = 640, 420, 60
    xs = [r["seconds"] for r in rows]
    ys = [r["relative_rmse"] for r in rows]
    x0, x1 = math.log10(min(xs)) - 0.1, math.log10(max(xs)) + 0.1
    y0, y1 = math.log10(min(ys + [0.01])) - 0.1, math.log10(max(ys)) + 0.1
    px = lambda x: m + (math.log10(x) - x0) / (x1 - x0) * (w - 2 * m)
    py = lambda y: h - m - (math.log10(y) - y0) / (y1 - y0) * (h - 2 * m)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="12">',
           f'<rect width="{w}" height="{h}" fill="white"/>',
           f'<line x1="{m}" y1="{h-m}" x2="{w-m}" y2="{h-m}" stroke="black"/>',
           f'<line x1="{m}" y1="{m}" x2="{m}" y2="{h-m}" stroke="black"/>',
           f'<text x="{w/2}" y="{h-15}" text-anchor="middle">wall time, s (log)</text>',
           f'<text x="15" y="{h/2}" transform="rotate(-90 15 {h/2})" text-anchor="middle">relative RMSE vs reference (log)</text>',
           f'<text x="{w/2}" y="25" text-anchor="middle">Cornell box 256x256: error against time</text>']
    for e in range(math.floor(x0), math.ceil(x1) + 1):
        for k in (1, 2, 5):
            v = k * 10 ** e
            if x0 <= math.log10(v) <= x1:
                out.append(f'<line x1="{px(v):.1f}" y1="{h-m}" x2="{px(v):.1f}" y2="{h-m+5}" stroke="black"/>')
                out.append(f'<text x="{px(v):.1f}" y="{h-m+18}" text-anchor="middle">{v:g}</text>')
    for e in range(math.floor(y0), math.ceil(y1) + 1):
        for k in (1, 2, 5):
            v = k * 10 ** e
            if y0 <= math.log10(v) <= y1:
                out.append(f'<line x1="{m-5}" y1="{py(v):.1f}" x2="{m}" y2="{py(v):.1f}" stroke="black"/>')
                out.append(f'<text x="{m-8}" y="{py(v)+4:.1f}" text-anchor="end">{v:g}</text>')
    out.append(f'<line x1="{m}" y1="{py(0.02):.1f}" x2="{w-m}" y2="{py(0.02):.1f}" stroke="gray" stroke-dasharray="4 4"/>')
    out.append(f'<text x="{w-m}" y="{py(0.02)-4:.1f}" text-anchor="end" fill="gray">2%</text>')
    for method, colour in (("radiosity", "#c0392b"), ("path", "#2c3e50")):
        pts = sorted((r["seconds"], r["relative_rmse"], r) for r in rows if r["method"] == method)
        out.append('<polyline fill="none" stroke="%s" stroke-width="2" points="%s"/>' % (
            colour, " ".join(f"{px(x):.1f},{py(y):.1f}" for x, y, _ in pts)))
        for x, y, r in pts:
            label = f'g{r["gather"]}/{r["spp"]}spp' if method == "radiosity" else f'{r["spp"]}spp'
            out.append(f'<circle cx="{px(x):.1f}" cy="{py(y):.1f}" r="3" fill="{colour}"/>')
            out.append(f'<text x="{px(x)+5:.1f}" y="{py(y)-5:.1f}" fill="{colour}" font-size="10">{label}</text>')
    out.append(f'<text x="{w-m-150}" y="{m+10}" fill="#c0392b">radiosity + final gather</text>')
    out.append(f'<text x="{w-m-150}" y="{m+26}" fill="#2c3e50">path tracing</text>')
    out.append("</svg>")
    open(path, "w").write("\n".join(out) + "\n")


def main():
    global REFERENCE_NOISE
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--build", default=os.path.join(ROOT, "build"))
    p.add_argument("--out", default=os.path.join(ROOT, "bench/render_results"))
    a = p.parse_args()
    REFERENCE_NOISE = float(open(os.path.join(ROOT, "data/reference/reference_noise.txt")).read().split()[0])
    os.makedirs(a.out, exist_ok=True)
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for method, options in RUNS:
            r = run(a.build, method, options, work)
            rows.append(r)
            print(f'{r["method"]:9s} gather {r["gather"]:3d} spp {r["spp"]:4d}: {r["seconds"]:7.2f} s, '
                  f'relative RMSE {r["relative_rmse"]:.4f} (raw {r["rmse_raw"]:.4f}), mean ratio {r["mean_ratio"]:.4f}',
                  file=sys.stderr)
    with open(os.path.join(a.out, "render_error_vs_time.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    svg_plot(rows, os.path.join(a.out, "render_error_vs_time.svg"))
    print(f"wrote {a.out}/render_error_vs_time.csv and .svg", file=sys.stderr)


if __name__ == "__main__":
    main()
