#!/usr/bin/env python3
"""Relative RMSE against the converged path-traced reference versus wall time, Cornell box 256x256.

In one run: `radiosity render` with --method radiosity at several (gather, spp) settings and
--method path at several sample counts; each render.exr is compared with
data/reference/cornell_box_path.exr (bench/render_compare). Writes render_error_vs_time.csv, a
markdown table (render_error_vs_time.md) and a log-log plot (render_error_vs_time.png, matplotlib)
into --out (default bench/render_results/).

Error: relative RMSE sqrt(sum (a-r)^2 / sum r^2) over all pixels and channels, with the reference's
own noise (data/reference/reference_noise.txt) removed in quadrature. About 99% of sum r^2 lies in
the ~490 pixels that see the light (Ke = 17 against surfaces below 1), so this error is mostly the
antialiasing of the light's outline. The same error over the pixels away from the light
("surfaces", render_compare) is reported too; there the reference's own noise is larger and is
estimated from the path-traced rows of 64 spp and more (error^2 = a/spp + noise^2, least squares)
and removed.

Time: the `total` of render.json (load, mesh, solve, BVH, render, output; not process start).
The first radiosity render solves and keeps its solution (solution.csv/.json); the other radiosity
renders start from a copy of it, as `radiosity render` does when --out holds one, so their wall
time is the render without the solve, and `seconds_with_solve` adds the measured solve time.

    /usr/bin/python3 bench/render_error_vs_time.py [--build build] [--out bench/render_results]
                                                   [--repeats 1] [--solve-sizes]

--solve-sizes adds renders at gather 4, 64 spp from fresh solves of several sizes (elements, rays
per element): the cost and the error of render's solve default.
"""
import argparse
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join(ROOT, "data/cornell_box/cornell_box.obj")
REFERENCE = os.path.join(ROOT, "data/reference/cornell_box_path.exr")
TARGET = 0.02
SURFACE_LEVEL = 0.05  # a level both methods bracket on the surfaces metric, for their time ratio
SOLVE_SIZES = [(1500, 1024), (500, 256), (200, 128)]  # (elements, rays per element)

RADIOSITY = [(1, 4), (1, 8), (1, 16), (1, 32), (1, 64), (4, 4), (4, 16), (16, 16)]  # (gather, spp)
PATH = [4, 8, 16, 32, 64, 128, 256]  # spp


def render(build, method, options, out, repeats):
    """Runs one render (the fastest of `repeats`) and returns its render.json."""
    best = None
    for _ in range(repeats):
        args = [os.path.join(build, "bin/radiosity"), "render", SCENE, "--method", method, "--out", out, "-q"]
        for k, v in options.items():
            args += [k, str(v)]
        subprocess.run(args, check=True)
        report = json.load(open(os.path.join(out, "render.json")))
        if best is None or report["time_seconds"]["total"] < best["time_seconds"]["total"]:
            best = report
            shutil.copy(os.path.join(out, "render.exr"), os.path.join(out, "best.exr"))
    return best


def compare(build, exr, noise):
    rmse, ratio, surface_rmse, surface_ratio = map(float, subprocess.run(
        [os.path.join(build, "bin/render_compare"), "rmse", exr, REFERENCE],
        check=True, capture_output=True, text=True).stdout.split())
    return math.sqrt(max(0.0, rmse * rmse - noise * noise)), rmse, ratio, surface_rmse, surface_ratio


def reference_surface_noise(rows):
    """The reference's own noise on the surfaces metric: fit raw^2 = a/spp + c over the path rows
    of 64 spp and more (below that the stratified error falls faster than 1/spp)."""
    rows = [r for r in rows if r["spp"] >= 64]
    xs = [1.0 / r["spp"] for r in rows]
    ys = [r["surface_rmse_raw"] ** 2 for r in rows]
    n, mx, my = len(xs), sum(xs) / len(xs), sum(ys) / len(ys)
    a = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
    return math.sqrt(max(0.0, my - a * mx))


def time_to_target(rows, target=TARGET, key="relative_rmse"):
    """Seconds at which the error reaches `target`, interpolated log-log between the two
    measurements around it (error against time falls as a power law); None if not bracketed."""
    pts = sorted((r["seconds"], r[key]) for r in rows)
    best = None
    for (t0, e0), (t1, e1) in zip(pts, pts[1:]):
        if e0 >= target >= e1 and e0 > e1:
            f = math.log(e0 / target) / math.log(e0 / e1)
            t = math.exp(math.log(t0) + f * (math.log(t1) - math.log(t0)))
            best = t if best is None else min(best, t)
    reached = [t for t, e in pts if e <= target]
    if best is None and reached:
        best = min(reached)
    return best


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(13, 5.2))
    panels = (("relative_rmse", TARGET, "all pixels (the target's metric)"),
              ("surface_rmse", SURFACE_LEVEL, "surfaces: pixels away from the light"))
    for ax, (key, level, title) in zip(axes, panels):
        path_rows = sorted((r for r in rows if r["method"] == "path"), key=lambda r: r["seconds"])
        ax.plot([r["seconds"] for r in path_rows], [r[key] for r in path_rows], "o-", color="#2c3e50",
                label="path tracing")
        for r in path_rows:
            ax.annotate(f'{r["spp"]}', (r["seconds"], r[key]), textcoords="offset points", xytext=(4, 4),
                        fontsize=8, color="#2c3e50")
        for gather, colour in ((1, "#c0392b"), (4, "#e67e22"), (16, "#8e44ad")):
            g_rows = sorted((r for r in rows if r["method"] == "radiosity" and r["gather"] == gather),
                            key=lambda r: r["seconds"])
            if not g_rows:
                continue
            ax.plot([r["seconds"] for r in g_rows], [r[key] for r in g_rows], "s-", color=colour,
                    label=f"radiosity, gather {gather}, solution reused")
            ax.plot([r["seconds_with_solve"] for r in g_rows], [r[key] for r in g_rows], "s--", color=colour,
                    alpha=0.4, label=f"radiosity, gather {gather}, with the solve")
            for r in g_rows:
                ax.annotate(f'{r["spp"]}', (r["seconds"], r[key]), textcoords="offset points",
                            xytext=(4, -10), fontsize=8, color=colour)
        ax.axhline(level, color="gray", linestyle=":", linewidth=1)
        ax.text(min(r["seconds"] for r in rows), level * 1.05, f"{level:.0%}", color="gray")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("wall time, s")
        ax.set_ylabel("relative RMSE against the reference")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.25)
    axes[0].legend(fontsize=7)
    fig.suptitle("Cornell box 256×256, error against time (labels: samples per pixel)")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--build", default=os.path.join(ROOT, "build"))
    p.add_argument("--out", default=os.path.join(ROOT, "bench/render_results"))
    p.add_argument("--repeats", type=int, default=1, help="runs per setting; the fastest counts")
    p.add_argument("--solve-sizes", action="store_true", help="also measure render's solve sizes")
    a = p.parse_args()
    try:  # before the renders, not after them
        import matplotlib  # noqa: F401
    except ImportError:
        sys.exit("matplotlib is missing: run with /usr/bin/python3 (Debian's), or scripts/setup.sh --bench")
    noise = float(open(os.path.join(ROOT, "data/reference/reference_noise.txt")).read().split()[0])
    os.makedirs(a.out, exist_ok=True)
    start = time.time()
    rows = []

    def add(method, gather, spp, report, exr, solve_seconds):
        error, raw, ratio, surface_raw, surface_ratio = compare(a.build, exr, noise)
        seconds = report["time_seconds"]["total"]
        row = {"method": method, "gather": gather, "spp": spp, "seconds": seconds,
               "seconds_with_solve": seconds + solve_seconds,
               "solve_seconds": report["time_seconds"]["solve"],
               "render_seconds": report["time_seconds"]["render"], "rays": report["rays"]["total"],
               "rmse_raw": raw, "relative_rmse": error, "mean_ratio": ratio,
               "surface_rmse_raw": surface_raw, "surface_mean_ratio": surface_ratio,
               "reused_solution": bool(report.get("radiosity", {}).get("reused_saved_solution", False))}
        rows.append(row)
        print(f'{method:9s} gather {gather:3d} spp {spp:4d}: {seconds:7.2f} s '
              f'({row["seconds_with_solve"]:6.2f} s with solve), relative RMSE {error:.4f}, '
              f'mean ratio {ratio:.4f}', file=sys.stderr)

    with tempfile.TemporaryDirectory() as work:
        # The solve, once: a fresh render that keeps its solution.
        solved_dir = os.path.join(work, "solved")
        first_g, first_spp = RADIOSITY[0]
        fresh = render(a.build, "radiosity", {"--gather": first_g, "--spp": first_spp},
                       solved_dir, 1)
        solve_seconds = fresh["time_seconds"]["solve"]
        print(f"solve (fresh, kept for reuse): {solve_seconds:.2f} s, "
              f'{fresh["radiosity"]["elements"]} elements', file=sys.stderr)
        for gather, spp in RADIOSITY:
            out = os.path.join(work, f"radiosity_g{gather}_s{spp}")
            os.makedirs(out)
            for name in ("solution.csv", "solution.json"):
                shutil.copy(os.path.join(solved_dir, name), out)
            report = render(a.build, "radiosity", {"--gather": gather, "--spp": spp}, out, a.repeats)
            if not report["radiosity"]["reused_saved_solution"]:
                sys.exit("the saved solution was not reused")
            add("radiosity", gather, spp, report, os.path.join(out, "best.exr"), solve_seconds)
        for spp in PATH:
            out = os.path.join(work, f"path_s{spp}")
            report = render(a.build, "path", {"--spp": spp}, out, a.repeats)
            add("path", 0, spp, report, os.path.join(out, "best.exr"), 0.0)
        sizes = []
        if a.solve_sizes:
            for elements, rays in SOLVE_SIZES:
                out = os.path.join(work, f"size_{elements}_{rays}")
                report = render(a.build, "radiosity", {"--gather": 4, "--spp": 64, "--elements": elements,
                                                       "--rays": rays}, out, 1)
                _, raw, ratio, surface_raw, surface_ratio = compare(a.build, os.path.join(out, "best.exr"), noise)
                sizes.append((elements, rays, report["radiosity"]["elements"], report["time_seconds"]["solve"],
                              raw, ratio, surface_raw, surface_ratio))
                print(f"solve size {elements}/{rays}: {sizes[-1]}", file=sys.stderr)

    surface_noise = reference_surface_noise([r for r in rows if r["method"] == "path"])
    for r in rows:
        r["surface_rmse"] = math.sqrt(max(0.0, r["surface_rmse_raw"] ** 2 - surface_noise ** 2))

    with open(os.path.join(a.out, "render_error_vs_time.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)

    t_path = time_to_target([r for r in rows if r["method"] == "path"])
    lines = ["| method | gather | spp | wall s (solution reused) | wall s with solve | rel. RMSE | mean ratio "
             "| surfaces: rel. RMSE | surfaces: mean ratio |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f'| {r["method"]} | {r["gather"] if r["method"] == "radiosity" else "–"} | {r["spp"]} | '
                     f'{r["seconds"]:.2f} | {r["seconds_with_solve"]:.2f} | {r["relative_rmse"]:.4f} | '
                     f'{r["mean_ratio"]:.4f} | {r["surface_rmse"]:.4f} | {r["surface_mean_ratio"]:.4f} |')
    lines.append("")
    lines.append(f"Solve (fresh, {fresh['radiosity']['elements']} elements): {solve_seconds:.2f} s.")
    lines.append(f"Time to {TARGET:.0%} relative RMSE (log-log interpolation): path tracing "
                 + (f"{t_path:.2f} s" if t_path else "not reached"))
    for gather in sorted({r["gather"] for r in rows if r["method"] == "radiosity"}):
        g_rows = [r for r in rows if r["method"] == "radiosity" and r["gather"] == gather]
        t_reuse = time_to_target(g_rows)
        t_solve = time_to_target([dict(r, seconds=r["seconds_with_solve"]) for r in g_rows])
        if t_reuse:
            text = f"; radiosity gather {gather}: {t_reuse:.2f} s reusing the solution"
            if t_path:
                text += f" ({t_path / t_reuse:.1f}× sooner)"
            if t_solve:
                text += f", {t_solve:.2f} s with the solve" + (f" ({t_path / t_solve:.1f}×)" if t_path else "")
            lines[-1] += text
        else:
            lines[-1] += f"; radiosity gather {gather}: not bracketed"
    lines[-1] += "."
    lines.append(f"Surfaces (reference noise {surface_noise:.4f} removed): time to {SURFACE_LEVEL:.0%}")
    s_path = time_to_target([r for r in rows if r["method"] == "path"], SURFACE_LEVEL, "surface_rmse")
    lines[-1] += ": path tracing " + (f"{s_path:.2f} s" if s_path else "not bracketed")
    for gather in sorted({r["gather"] for r in rows if r["method"] == "radiosity"}):
        g_rows = [r for r in rows if r["method"] == "radiosity" and r["gather"] == gather]
        s_reuse = time_to_target(g_rows, SURFACE_LEVEL, "surface_rmse")
        s_solve = time_to_target([dict(r, seconds=r["seconds_with_solve"]) for r in g_rows], SURFACE_LEVEL,
                                 "surface_rmse")
        if s_reuse and s_path:
            lines[-1] += (f"; radiosity gather {gather}: {s_reuse:.2f} s reusing ({s_path / s_reuse:.1f}×)"
                          + (f", {s_solve:.2f} s with the solve ({s_path / s_solve:.1f}×)" if s_solve else ""))
    lines[-1] += "."
    if sizes:
        lines += ["", "| solve: elements asked | rays/element | elements | solve s | rel. RMSE | mean ratio "
                  "| surfaces: rel. RMSE (raw) | surfaces: mean ratio |", "|---|---|---|---|---|---|---|---|"]
        for e, rays, got, sec, raw, ratio, sraw, sratio in sizes:
            lines.append(f"| {e} | {rays} | {got} | {sec:.2f} | {raw:.4f} | {ratio:.4f} | {sraw:.4f} | {sratio:.4f} |")
    open(os.path.join(a.out, "render_error_vs_time.md"), "w").write("\n".join(lines) + "\n")
    plot(rows, os.path.join(a.out, "render_error_vs_time.png"))
    stale = os.path.join(a.out, "render_error_vs_time.svg")
    if os.path.exists(stale):
        os.remove(stale)
    print("\n".join(lines), file=sys.stderr)
    print(f"wrote {a.out}/render_error_vs_time.{{csv,md,png}} in {time.time() - start:.0f} s", file=sys.stderr)


if __name__ == "__main__":
    main()
