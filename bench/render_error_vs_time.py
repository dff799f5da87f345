#!/usr/bin/env python3
"""Relative error against the converged path-traced reference versus wall time, Cornell box 256x256.

In one run: `radiosity render` with --method radiosity at several (gather, light rays, spp) settings and
--method path at several sample counts, interleaved (path, radiosity, path, ...) so that both
methods run under the same load of this shared machine; each render.exr is compared with
data/reference/cornell_box_path.exr (bench/render_compare). Writes render_error_vs_time.csv, a
markdown table (render_error_vs_time.md) and a log-log plot (render_error_vs_time.png, matplotlib)
into --out (default bench/render_results/).

Errors, each with the reference's own noise removed:
- per-pixel relative RMSE (the target's metric), sqrt(mean over pixels and channels of
  ((x-r)^2 - v)/(r^2 + eps)), eps = (0.1 mean(r))^2 (render_compare relmse): the relMSE of
  Rousselle et al. 2011, every pixel weighted alike. v is the variance of the reference's pixel
  mean, data/reference/cornell_box_path_variance.exr ((A-B)^2/4 from its two independent halves):
  for an image independent of the reference, E[(x-ref)^2] = E[(x-r)^2] + Var(ref).
- image-wide relative RMSE sqrt(sum (x-r)^2 / sum r^2), with the reference's image-wide noise
  (data/reference/reference_noise.txt) removed in quadrature. About 99% of sum r^2 lies in the
  ~490 pixels that see the light (Ke = 17 against surfaces below 1), so this one is mostly the
  antialiasing of the light's outline.
- the image-wide one over the pixels away from the light ("surfaces", render_compare rmse), the
  reference's noise there (from the variance image) removed in quadrature.

Time to a level: the samples per pixel it takes, times the method's seconds per sample. The
samples come from the error against samples, which the machine's load does not touch
(log-log interpolation between the two rows around the level); the seconds per sample are the
smaller seconds/spp of the method's two largest rows. Wall times on this shared 2-core machine
moved by 2x between neighbouring rows of one run, which made interpolating error against wall
time as noisy as that. Where the path tracer's rows stop above the level (rendering it to 2% per
pixel would take minutes), its samples are extrapolated along its last two rows' slope or along
the Monte Carlo rate error ~ spp^-1/2, whichever needs fewer.

Time: the `total` of render.json (load, mesh, solve, BVH, render, output; not process start).
The first radiosity render solves and keeps its solution (solution.csv/.json); the other radiosity
renders start from a copy of it, as `radiosity render` does when --out holds one, so their wall
time is the render without the solve, and `seconds_with_solve` adds the measured solve time.

    /usr/bin/python3 bench/render_error_vs_time.py [--build build] [--out bench/render_results]
                                                   [--repeats 2] [--solve-sizes]

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
REFERENCE_VARIANCE = os.path.join(ROOT, "data/reference/cornell_box_path_variance.exr")
TARGET = 0.02
SURFACE_LEVEL = 0.05  # a level both methods bracket on the surfaces metric, for their time ratio
SOLVE_SIZES = [(1500, 1024), (500, 256), (200, 128)]  # (elements, rays per element)

# (gather rays, light rays per eye hit (0: as many as gather rays, the default), spp)
RADIOSITY = [(1, 0, 16), (1, 0, 64), (1, 0, 256), (1, 0, 512), (4, 0, 16), (4, 0, 64), (4, 0, 128),
             (4, 2, 16), (4, 2, 64), (4, 2, 128)]
PATH = [4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048]  # spp: the last ones bracket 2% per pixel


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
    """Image-wide relative RMSE (noise removed), the same raw, mean ratio, surfaces' raw relative
    RMSE and mean ratio, per-pixel relative RMSE (noise removed) and the same raw."""
    tool = os.path.join(build, "bin/render_compare")
    rmse, ratio, surface_rmse, surface_ratio = map(float, subprocess.run(
        [tool, "rmse", exr, REFERENCE], check=True, capture_output=True, text=True).stdout.split())
    pixel, pixel_raw, _, _ = map(float, subprocess.run(
        [tool, "relmse", exr, REFERENCE, REFERENCE_VARIANCE], check=True, capture_output=True,
        text=True).stdout.split())
    return (math.sqrt(max(0.0, rmse * rmse - noise * noise)), rmse, ratio, surface_rmse, surface_ratio,
            pixel, pixel_raw)


def epsilon_and_surface_noise(build):
    """The per-pixel metric's ε, and the reference's own noise on the surfaces metric."""
    _, _, eps, surface_noise = map(float, subprocess.run(
        [os.path.join(build, "bin/render_compare"), "relmse", REFERENCE, REFERENCE, REFERENCE_VARIANCE],
        check=True, capture_output=True, text=True).stdout.split())
    return eps, surface_noise


def samples_to_target(rows, target, key):
    """Samples per pixel at which the error reaches `target`, interpolated log-log between the two
    rows around it (error against samples falls as a power law); None if not bracketed."""
    pts = sorted((r["spp"], r[key]) for r in rows)
    best = None
    for (n0, e0), (n1, e1) in zip(pts, pts[1:]):
        if e0 >= target >= e1 and e0 > e1:
            f = math.log(e0 / target) / math.log(e0 / e1)
            n = math.exp(math.log(n0) + f * (math.log(n1) - math.log(n0)))
            best = n if best is None else min(best, n)
    reached = [n for n, e in pts if e <= target]
    if best is None and reached:
        best = min(reached)
    return best


def extrapolated_samples(rows, target, key):
    """For rows that stop above `target`: the samples per pixel at which it would be reached,
    going on from the last row (a) along the slope of the last two rows (None when they do not
    fall) and (b) along the Monte Carlo slope, error ~ samples^-1/2."""
    pts = sorted((r["spp"], r[key]) for r in rows)
    (n0, e0), (n1, e1) = pts[-2], pts[-1]
    own = None
    if e1 < e0:
        own = n1 * (e1 / target) ** (math.log(n1 / n0) / math.log(e0 / e1))
    return own, n1 * (e1 / target) ** 2


def seconds_per_sample(rows):
    """The method's cost of one sample per pixel: the smaller seconds / spp of its two largest
    rows (the less loaded of the two; the small rows also carry loading and output)."""
    big = sorted(rows, key=lambda r: r["spp"])[-2:]
    return min(r["seconds"] / r["spp"] for r in big)


def time_to_level(rows, target, key, extrapolate):
    """(seconds, samples, how) for one method: samples needed × seconds per sample; with
    `extrapolate`, past the last row along the smaller (the faster) of the two slopes."""
    n = samples_to_target(rows, target, key)
    how = "measured"
    if n is None:
        if not extrapolate:
            return None, None, "not reached"
        own, mc = extrapolated_samples(rows, target, key)
        n = min(x for x in (own, mc) if x)
        how = (f"extrapolated along the last two rows' slope ({own:.0f} spp) or error ∝ spp^-1/2 "
               f"({mc:.0f} spp), whichever is fewer" if own else f"extrapolated along error ∝ spp^-1/2")
    return n * seconds_per_sample(rows), n, how


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(18, 5.4))
    panels = (("pixel_relative_rmse", TARGET, "per-pixel relative RMSE (the target's metric)"),
              ("relative_rmse", TARGET, "image-wide relative RMSE (mostly the light's outline)"),
              ("surface_rmse", SURFACE_LEVEL, "image-wide over the pixels away from the light"))
    gathers = sorted({r["gather"] for r in rows if r["method"] == "radiosity"})
    colours = ["#c0392b", "#e67e22", "#8e44ad", "#16a085", "#2980b9"]
    for ax, (key, level, title) in zip(axes, panels):
        path_rows = sorted((r for r in rows if r["method"] == "path"), key=lambda r: r["seconds"])
        ax.plot([r["seconds"] for r in path_rows], [r[key] for r in path_rows], "o-", color="#2c3e50",
                label="path tracing")
        for r in path_rows:
            ax.annotate(f'{r["spp"]}', (r["seconds"], r[key]), textcoords="offset points", xytext=(4, 4),
                        fontsize=8, color="#2c3e50")
        for gather, colour in zip(gathers, colours):
            g_rows = sorted((r for r in rows if r["method"] == "radiosity" and r["gather"] == gather),
                            key=lambda r: r["seconds"])
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
        ax.set_title(title, fontsize=10)
        ax.grid(True, which="both", alpha=0.25)
    axes[0].legend(fontsize=7)
    fig.suptitle("Cornell box 256×256, error against time, both methods interleaved in one run "
                 "(labels: samples per pixel)")
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def level_line(rows, name, level, key):
    """One line: time to `level` on `key` for the path tracer and each gather count, and ratios."""
    path_rows = [r for r in rows if r["method"] == "path"]
    t_path, n_path, how = time_to_level(path_rows, level, key, extrapolate=True)
    text = (f"{name}, time to {level:.0%}: path tracing {t_path:.2f} s ({n_path:.0f} spp, {how}; "
            f"{seconds_per_sample(path_rows):.4f} s per spp)")
    for gather in sorted({r["gather"] for r in rows if r["method"] == "radiosity"}):
        g_rows = [r for r in rows if r["method"] == "radiosity" and r["gather"] == gather]
        t, n, how = time_to_level(g_rows, level, key, extrapolate=False)
        if t is None:
            text += f"; radiosity gather {gather}: not reached"
            continue
        solve = g_rows[0]["seconds_with_solve"] - g_rows[0]["seconds"]
        text += (f"; radiosity gather {gather}: {t:.2f} s reusing the solution ({n:.0f} spp, "
                 f"{seconds_per_sample(g_rows):.4f} s per spp; {t_path / t:.1f}× sooner), "
                 f"{t + solve:.2f} s with the solve ({t_path / (t + solve):.1f}×)")
    return text + "."


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--build", default=os.path.join(ROOT, "build"))
    p.add_argument("--out", default=os.path.join(ROOT, "bench/render_results"))
    p.add_argument("--repeats", type=int, default=2,
                   help="runs per setting, one after the other; the fastest counts (the machine's load "
                        "comes and goes)")
    p.add_argument("--solve-sizes", action="store_true", help="also measure render's solve sizes")
    a = p.parse_args()
    try:  # before the renders, not after them
        import matplotlib  # noqa: F401
    except ImportError:
        sys.exit("matplotlib is missing: run with /usr/bin/python3 (Debian's), or scripts/setup.sh --bench")
    noise = float(open(os.path.join(ROOT, "data/reference/reference_noise.txt")).read().split()[0])
    eps, surface_noise = epsilon_and_surface_noise(a.build)
    os.makedirs(a.out, exist_ok=True)
    start = time.time()
    rows = []

    def add(method, gather, spp, report, exr, solve_seconds):
        error, raw, ratio, surface_raw, surface_ratio, pixel, pixel_raw = compare(a.build, exr, noise)
        seconds = report["time_seconds"]["total"]
        row = {"method": method, "gather": gather, "spp": spp, "seconds": seconds,
               "seconds_with_solve": seconds + solve_seconds,
               "solve_seconds": report["time_seconds"]["solve"],
               "render_seconds": report["time_seconds"]["render"], "rays": report["rays"]["total"],
               "pixel_relative_rmse": pixel, "pixel_relative_rmse_raw": pixel_raw,
               "rmse_raw": raw, "relative_rmse": error, "mean_ratio": ratio,
               "surface_rmse_raw": surface_raw, "surface_mean_ratio": surface_ratio,
               "reused_solution": bool(report.get("radiosity", {}).get("reused_saved_solution", False))}
        rows.append(row)
        print(f'{method:9s} gather {str(gather):>3s} spp {spp:4d}: {seconds:7.2f} s '
              f'({row["seconds_with_solve"]:6.2f} s with solve), per-pixel {pixel:.4f}, '
              f'image-wide {error:.4f}, mean ratio {ratio:.4f}', file=sys.stderr)

    with tempfile.TemporaryDirectory() as work:
        # The solve, once: a fresh render that keeps its solution.
        solved_dir = os.path.join(work, "solved")
        first_g, _, first_spp = RADIOSITY[0]
        fresh = render(a.build, "radiosity", {"--gather": first_g, "--spp": first_spp},
                       solved_dir, 1)
        solve_seconds = fresh["time_seconds"]["solve"]
        print(f"solve (fresh, kept for reuse): {solve_seconds:.2f} s, "
              f'{fresh["radiosity"]["elements"]} elements', file=sys.stderr)

        def radiosity_row(gather, light_rays, spp):
            out = os.path.join(work, f"radiosity_g{gather}_l{light_rays}_s{spp}")
            os.makedirs(out)
            for name in ("solution.csv", "solution.json"):
                shutil.copy(os.path.join(solved_dir, name), out)
            options = {"--gather": gather, "--spp": spp}
            if light_rays:
                options["--light-rays"] = light_rays
            report = render(a.build, "radiosity", options, out, a.repeats)
            if not report["radiosity"]["reused_saved_solution"]:
                sys.exit("the saved solution was not reused")
            # The setting's label groups its rows (tables, plot, times to a level).
            label = f"{gather}" if not light_rays else f"{gather}, {light_rays} light rays"
            add("radiosity", label, spp, report, os.path.join(out, "best.exr"), solve_seconds)

        def path_row(spp):
            out = os.path.join(work, f"path_s{spp}")
            report = render(a.build, "path", {"--spp": spp}, out, a.repeats)
            add("path", 0, spp, report, os.path.join(out, "best.exr"), 0.0)

        # Interleaved, so that a change in the machine's load falls on both methods alike.
        for k in range(max(len(RADIOSITY), len(PATH))):
            if k < len(PATH):
                path_row(PATH[k])
            if k < len(RADIOSITY):
                radiosity_row(*RADIOSITY[k])
        sizes = []
        if a.solve_sizes:
            for elements, rays in SOLVE_SIZES:
                out = os.path.join(work, f"size_{elements}_{rays}")
                report = render(a.build, "radiosity", {"--gather": 4, "--spp": 64, "--elements": elements,
                                                       "--rays": rays}, out, 1)
                _, raw, ratio, surface_raw, surface_ratio, _, pixel_raw = compare(
                    a.build, os.path.join(out, "best.exr"), noise)
                sizes.append((elements, rays, report["radiosity"]["elements"], report["time_seconds"]["solve"],
                              pixel_raw, raw, ratio, surface_raw, surface_ratio))
                print(f"solve size {elements}/{rays}: {sizes[-1]}", file=sys.stderr)

    for r in rows:
        r["surface_rmse"] = math.sqrt(max(0.0, r["surface_rmse_raw"] ** 2 - surface_noise ** 2))
    rows.sort(key=lambda r: (r["method"] != "radiosity", r["gather"], r["spp"]))

    with open(os.path.join(a.out, "render_error_vs_time.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)

    lines = ["| method | gather | spp | wall s (solution reused) | wall s with solve | per-pixel rel. RMSE "
             "| image-wide rel. RMSE | mean ratio | surfaces: rel. RMSE | surfaces: mean ratio |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f'| {r["method"]} | {r["gather"] if r["method"] == "radiosity" else "–"} | {r["spp"]} | '
                     f'{r["seconds"]:.2f} | {r["seconds_with_solve"]:.2f} | {r["pixel_relative_rmse"]:.4f} | '
                     f'{r["relative_rmse"]:.4f} | {r["mean_ratio"]:.4f} | {r["surface_rmse"]:.4f} | '
                     f'{r["surface_mean_ratio"]:.4f} |')
    lines.append("")
    lines.append(f"Solve (fresh, {fresh['radiosity']['elements']} elements): {solve_seconds:.2f} s. "
                 f"Per-pixel ε = {eps:.3g} (= (0.1 × the reference's mean)²).")
    lines.append("")
    lines.append(level_line(rows, "Per-pixel relative RMSE (the target's metric)", TARGET, "pixel_relative_rmse"))
    lines.append("")
    lines.append(level_line(rows, "Image-wide relative RMSE", TARGET, "relative_rmse"))
    lines.append("")
    lines.append(level_line(rows, f"Surfaces (image-wide over the pixels away from the light, reference noise "
                                  f"{surface_noise:.4f} removed)", SURFACE_LEVEL, "surface_rmse"))
    if sizes:
        lines += ["", "| solve: elements asked | rays/element | elements | solve s | per-pixel rel. RMSE (raw) "
                  "| image-wide rel. RMSE | mean ratio | surfaces: rel. RMSE (raw) | surfaces: mean ratio |",
                  "|---|---|---|---|---|---|---|---|---|"]
        for e, rays, got, sec, praw, raw, ratio, sraw, sratio in sizes:
            lines.append(f"| {e} | {rays} | {got} | {sec:.2f} | {praw:.4f} | {raw:.4f} | {ratio:.4f} | "
                         f"{sraw:.4f} | {sratio:.4f} |")
    open(os.path.join(a.out, "render_error_vs_time.md"), "w").write("\n".join(lines) + "\n")
    plot(rows, os.path.join(a.out, "render_error_vs_time.png"))
    print("\n".join(lines), file=sys.stderr)
    print(f"wrote {a.out}/render_error_vs_time.{{csv,md,png}} in {time.time() - start:.0f} s", file=sys.stderr)


if __name__ == "__main__":
    main()
