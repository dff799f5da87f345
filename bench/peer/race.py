#!/usr/bin/env python3
"""The project against Blender's Cycles, side by side (issue 17, docs/peer.md).

For each scene: Cycles (bench/peer/cycles_render.py, the project's conventions) and the project's
`radiosity render` (--method radiosity at several gather settings, and --gather 0 --light-rays N:
the direct light per pixel, the indirect light the solution's; --method path) at several samples
per pixel, interleaved in one run (Cycles, radiosity, path, Cycles, ...) and repeated, so that
every tool runs under the same load of this shared machine. Each image is compared with

- a high-sample Cycles reference that the command renders once, as two halves with their own
  seeds, and caches (--cache): their mean is the reference and (A-B)^2/4 per pixel the variance of
  that mean, so the reference's own noise is removed from the error (render_compare plain); and
- a high-sample reference of the project's own path tracer, made and cached the same way.

The error is the plain relative RMSE of issue 17: sqrt(mean over pixels and channels of
(x - ref)^2) / mean(ref), the reference's noise removed. Time is the whole process's wall time,
start to exit, as a user waits for it: Blender's start and scene conversion for Cycles; loading,
meshing, the radiosity solve (every radiosity run solves afresh) and output for the project.
Medians over the repeats of both. A method's time to an error level is interpolated log-log between
the two median rows around it, or extrapolated from its last row along error ~ time^-1/2 (said so).

Writes into --out (default bench/peer/results/): <scene>.csv (every run), <scene>.png (error against
time, every method), and summary.md / summary.json (times to the scene's level and their ratios).

    /usr/bin/python3 bench/peer/race.py [--scenes cornell_box,mirror_glass,staircase,atrium]
        [--repeats 3] [--build build] [--out bench/peer/results] [--cache bench/peer/cache]
        [--quick] [--no-lightmaps]

Then, unless --no-lightmaps, the lightmap race (bench/peer/bake_race.py) with the same options.

Needs `blender` (scripts/setup.sh --bench installs it) and a Release build (render_compare too).
--quick: one repeat, small sample counts and references, into out/peer_quick: a smoke run.
--replot: no runs, the plots and summaries again from the CSVs already in --out.
"""
import argparse
import csv
import hashlib
import json
import math
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SHARED = os.path.normpath(os.path.join(ROOT, "..", "shared", "scenes"))
CYCLES_SCRIPT = os.path.join(ROOT, "bench/peer/cycles_render.py")
THREADS = 2  # this machine's cores; both tools get all of them

# Each scene: files, options both tools take, the error level the issue sets, the sample counts.
# radiosity: (gather rays, light rays, spp). Reference sample counts: per half.
SCENES = {
    "cornell_box": {
        "obj": os.path.join(ROOT, "data/cornell_box/cornell_box.obj"),
        "camera": os.path.join(ROOT, "data/cornell_box/cornell_box.camera.json"),
        "options": [], "level": 0.02,
        "cycles": [16, 64, 256, 1024], "path": [16, 64, 256],
        "radiosity": [(1, 0, 16), (1, 0, 64), (1, 0, 256), (4, 2, 16), (4, 2, 64), (4, 2, 256)],
        "adaptive": [(1, 0, 16), (1, 0, 64), (1, 0, 256), (0, 1, 16), (0, 1, 32), (0, 1, 64),
                     (0, 1, 256)],
        "reference_cycles": 2048, "reference_path": 1024},
    "mirror_glass": {
        "obj": os.path.join(ROOT, "data/cornell_box/cornell_box_mirror_glass.obj"),
        "camera": os.path.join(ROOT, "data/cornell_box/cornell_box.camera.json"),
        "options": [], "level": 0.05,
        "cycles": [16, 64, 256, 1024], "path": [16, 64, 256],
        "radiosity": [(1, 0, 16), (1, 0, 64), (1, 0, 256), (4, 2, 16), (4, 2, 64), (0, 1, 16),
                      (0, 1, 64)],
        "reference_cycles": 2048, "reference_path": 1024},
    "staircase": {
        "obj": os.path.join(SHARED, "staircase2/staircase2.obj"),
        "camera": os.path.join(SHARED, "staircase2/staircase2.camera.json"),
        "options": ["--two-sided"], "level": 0.05,
        "cycles": [16, 64, 256, 1024], "path": [16, 64, 256],
        "radiosity": [(1, 0, 16), (1, 0, 64), (1, 0, 256), (4, 2, 16), (4, 2, 64), (0, 4, 16),
                      (0, 4, 64), (0, 4, 256)],
        "reference_cycles": 1024, "reference_path": 512},
    "atrium": {
        "obj": os.path.join(SHARED, "sponza-dabrovic/sponza.obj"),
        "camera": os.path.join(SHARED, "sponza-dabrovic/sponza.camera.json"),
        "options": ["--sky", "0.35", "0.45", "0.65", "--sun", "0.3", "-1", "0.25", "8", "7.6", "6.8"],
        "level": 0.05,
        "cycles": [16, 64, 256], "path": [16, 64, 256],
        "radiosity": [(1, 0, 16), (1, 0, 64), (4, 2, 16), (4, 2, 64)],
        "reference_cycles": 1024, "reference_path": 1024},
}
QUICK = {"cycles": [4, 16], "path": [4, 16], "radiosity": [(1, 0, 4), (1, 0, 16)],
         "adaptive": [(1, 0, 16)], "reference_cycles": 64, "reference_path": 64}


def run_timed(args, log):
    """Runs a process to completion; its wall time in seconds (output to `log`)."""
    start = time.perf_counter()
    with open(log, "w") as f:
        done = subprocess.run(args, stdout=f, stderr=subprocess.STDOUT)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"race: {' '.join(args)} failed (exit {done.returncode}); see {log}")
    return seconds


def cycles(scene, spp, seed, out, work):
    args = ["blender", "-b", "--factory-startup", "--python-exit-code", "1", "--python", CYCLES_SCRIPT,
            "--", scene["obj"], "--camera", scene["camera"], "--spp", str(spp), "--out", out,
            "--seed", str(seed), "--threads", str(THREADS), "--report", out + ".json"] + scene["options"]
    return run_timed(args, os.path.join(work, "cycles.log"))


def project(build, scene, method, spp, seed, out, work, gather=1, light_rays=0):
    """One `radiosity render` into a fresh directory (so radiosity solves afresh); its render.exr
    is moved to `out`. Method "adaptive" is `--method radiosity --adaptive`."""
    directory = tempfile.mkdtemp(dir=work)
    args = [os.path.join(build, "bin/radiosity"), "render", scene["obj"], "--camera", scene["camera"],
            "--method", "path" if method == "path" else "radiosity", "--spp", str(spp), "--seed",
            str(seed), "--out", directory, "-q"]
    if method != "path":
        args += ["--gather", str(gather), "--light-rays", str(light_rays)]
    if method == "adaptive":
        args.append("--adaptive")
    seconds = run_timed(args + scene["options"], os.path.join(work, "project.log"))
    shutil.move(os.path.join(directory, "render.exr"), out)
    shutil.rmtree(directory)
    return seconds


def file_digest(*paths):
    digest = hashlib.sha1()
    for path in paths:
        with open(path, "rb") as f:
            digest.update(f.read())
    return digest


def reference(build, name, scene, tool, spp, cache, work):
    """(mean.exr, variance.exr) of two independent halves of `spp` samples each, cached under a key
    of everything that makes them: the scene's OBJ, MTL and camera files, the options, the tool's
    own code (the Cycles script and Blender's version, or the project's binary)."""
    mtl = [os.path.join(os.path.dirname(scene["obj"]), line.split(None, 1)[1].strip())
           for line in open(scene["obj"], errors="replace") if line.startswith("mtllib")]
    code = [CYCLES_SCRIPT, shutil.which("blender")] if tool == "cycles" else [
        os.path.join(build, "bin/radiosity")]
    digest = file_digest(scene["obj"], scene["camera"], *mtl, *code)
    digest.update(" ".join(scene["options"]).encode())
    key = f"{name}_{tool}_{spp}_{digest.hexdigest()[:12]}"
    mean, variance = (os.path.join(cache, f"{key}{suffix}.exr") for suffix in ("", "_variance"))
    if os.path.isfile(mean) and os.path.isfile(variance):
        print(f"race: {name}: {tool} reference from the cache ({key})", file=sys.stderr)
        return mean, variance
    os.makedirs(cache, exist_ok=True)
    halves = []
    for half, seed in enumerate((1000001, 1000002)):
        out = os.path.join(work, f"reference_{tool}_{half}.exr")
        print(f"race: {name}: rendering the {tool} reference, half {half + 1} of 2, {spp} spp",
              file=sys.stderr)
        seconds = (cycles(scene, spp, seed, out, work) if tool == "cycles" else
                   project(build, scene, "path", spp, seed, out, work))
        print(f"race: {name}: {seconds:.0f} s", file=sys.stderr)
        halves.append(out)
    subprocess.run([os.path.join(build, "bin/render_compare"), "halves", *halves, mean + ".tmp.exr",
                    variance + ".tmp.exr"], check=True, capture_output=True)
    os.replace(variance + ".tmp.exr", variance)
    os.replace(mean + ".tmp.exr", mean)
    return mean, variance


def compare(build, image, ref):
    """Plain relative RMSE (noise removed), raw, mean ratio; the same on the surfaces."""
    values = subprocess.run([os.path.join(build, "bin/render_compare"), "plain", image, *ref],
                            check=True, capture_output=True, text=True).stdout.split()
    return dict(zip(("error", "error_raw", "mean_ratio", "surface_error", "surface_error_raw",
                     "surface_mean_ratio"), map(float, values)))


def jobs(scene):
    """The runs of one repeat, interleaved: one of each method in turn."""
    lists = [[("cycles", spp, 0, 0) for spp in scene["cycles"]],
             [("radiosity", spp, g, l) for g, l, spp in scene["radiosity"]],
             [("adaptive", spp, g, l) for g, l, spp in scene.get("adaptive", [])],
             [("path", spp, 0, 0) for spp in scene["path"]]]
    return interleave(lists)


def interleave(lists):
    """One of each list in turn until all are empty: every tool runs under the same load."""
    order = []
    while any(lists):
        for queue in lists:
            if queue:
                order.append(queue.pop(0))
    return order


def method_label(method, gather, light_rays):
    if method == "cycles":
        return "Cycles"
    if method == "path":
        return "radiosity render --method path"
    adaptive = " --adaptive" if method == "adaptive" else ""
    return f"radiosity render --method radiosity{adaptive} --gather {gather}" + (
        f" --light-rays {light_rays}" if light_rays else "")


def medians(rows):
    """One row per (method, spp): median wall time and median errors over the repeats."""
    groups = {}
    for r in rows:
        groups.setdefault((r["label"], r["spp"]), []).append(r)
    out = []
    for (label, spp), group in groups.items():
        row = {"label": label, "spp": spp, "repeats": len(group)}
        for key in ("seconds", "error", "mean_ratio", "surface_error", "error_vs_path",
                    "mean_ratio_vs_path"):
            row[key] = statistics.median(r[key] for r in group)
        out.append(row)
    return out


def time_to_level(rows, level, key="error"):
    """(seconds, how) at which one method's median rows reach `level`."""
    pts = sorted((r["seconds"], r[key]) for r in rows)
    for (t0, e0), (t1, e1) in zip(pts, pts[1:]):
        if e0 >= level >= e1 and e0 > e1:
            f = math.log(e0 / level) / math.log(e0 / e1)
            return math.exp(math.log(t0) + f * (math.log(t1) - math.log(t0))), "interpolated"
    reached = [t for t, e in pts if e <= level]
    if reached:
        return min(reached), "first row already below"
    t1, e1 = min(pts, key=lambda p: p[1])
    # An error that has stopped falling (a bias: the solution's mesh) is not extrapolated: it
    # falls slower than time^-1/4 between the last two rows.
    if len(pts) >= 2:
        (ta, ea), (tb, eb) = pts[-2], pts[-1]
        if eb > ea * (ta / tb) ** 0.25:
            return math.inf, f"not reached: the error levels off ({eb:.3f} at {tb:.1f} s)"
    return t1 * (e1 / level) ** 2, "extrapolated (error ~ time^-1/2)"


def plot_line(ax, line, key, count_key, marker, colour, label):
    """One method's median rows: error `key` against time, each point labelled by its count."""
    ax.plot([r["seconds"] for r in line], [max(r[key], 1e-4) for r in line], marker, color=colour,
            label=label)
    for r in line:
        ax.annotate(str(r[count_key]), (r["seconds"], max(r[key], 1e-4)), textcoords="offset points",
                    xytext=(4, 4), fontsize=8, color=colour)


def style_error_axes(ax, level, ylabel, title):
    """Log-log error against wall time, the level dotted."""
    ax.axhline(level, color="gray", linestyle=":", linewidth=1)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("wall time of the whole process, s (median of the repeats)")
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=9)
    ax.grid(True, which="both", alpha=0.25)


def plot(name, scene, rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(14, 5.4))
    styles = {"Cycles": ("o-", "#e67e22"), method_label("path", 0, 0): ("^-", "#2c3e50")}
    gathers = sorted({r["label"] for r in rows if "radiosity --" in r["label"]})
    for label, colour in zip(gathers, ["#c0392b", "#8e44ad", "#16a085", "#2980b9", "#d35400"]):
        styles[label] = ("s-", colour)
    for ax, (key, title) in zip(axes, (("error", "against a Cycles reference"),
                                       ("error_vs_path", "against the project's path tracer"))):
        for label, (marker, colour) in styles.items():
            line = sorted((r for r in rows if r["label"] == label), key=lambda r: r["spp"])
            if not line:
                continue
            plot_line(ax, line, key, "spp", marker, colour, label)
        style_error_axes(ax, scene["level"], "plain relative RMSE (RMSE / mean), reference noise removed",
                         f"{name}: {title}")
    axes[0].legend(fontsize=8)
    fig.suptitle(f"{name}: error against time, Cycles and the project interleaved in one run, "
                 f"{THREADS} threads (labels: samples per pixel)")
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)


def read_runs(path):
    """The runs of an earlier race from its CSV, numbers as numbers."""
    rows = []
    for row in csv.DictReader(open(path)):
        for key, value in row.items():
            if key not in ("scene", "label", "method"):
                row[key] = float(value) if "." in value or "e" in value else int(value)
        rows.append(row)
    return rows


def summarise(name, scene, rows, out):
    """Medians, the plot and the times to the scene's level, from the runs."""
    summary = medians(rows)
    plot(name, scene, summary, os.path.join(out, f"{name}.png"))
    times = {}
    for label in sorted({r["label"] for r in summary}):
        seconds, how = time_to_level([r for r in summary if r["label"] == label], scene["level"])
        times[label] = {"seconds": seconds, "how": how}
    for t in times.values():
        settle_ratio(t, times["Cycles"]["seconds"])
    meta = os.path.join(out, f"{name}.meta.json")
    return {"level": scene["level"], "rows": summary, "time_to_level": times,
            "provenance": json.load(open(meta)) if os.path.isfile(meta) else None}


def race(args, name, scene, work):
    if not os.path.isfile(scene["obj"]):
        sys.exit(f"race: {name}: {scene['obj']} not found")
    cycles_ref = reference(args.build, name, scene, "cycles", scene["reference_cycles"], args.cache, work)
    path_ref = reference(args.build, name, scene, "path", scene["reference_path"], args.cache, work)
    raced_with = provenance(args)  # before the runs: the tree as it was when they started
    rows = []
    order = jobs(scene)
    total = args.repeats * len(order)
    for repeat in range(args.repeats):
        for method, spp, gather, light_rays in order:
            image = os.path.join(work, "image.exr")
            seed = 1 + repeat
            if method == "cycles":
                seconds = cycles(scene, spp, seed, image, work)
            else:
                seconds = project(args.build, scene, method, spp, seed, image, work, gather, light_rays)
            row = {"scene": name, "repeat": repeat, "label": method_label(method, gather, light_rays),
                   "method": method, "gather": gather, "light_rays": light_rays, "spp": spp,
                   "seed": seed, "seconds": seconds}
            row.update(compare(args.build, image, cycles_ref))
            versus_path = compare(args.build, image, path_ref)
            row["error_vs_path"] = versus_path["error"]
            row["mean_ratio_vs_path"] = versus_path["mean_ratio"]
            rows.append(row)
            print(f"race: {name} [{len(rows)}/{total}] {row['label']} {spp} spp: {seconds:.1f} s, "
                  f"error {row['error']:.4f} (vs path {row['error_vs_path']:.4f}), "
                  f"mean ratio {row['mean_ratio']:.4f}", file=sys.stderr)
    with open(os.path.join(args.out, f"{name}.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    with open(os.path.join(args.out, f"{name}.meta.json"), "w") as f:
        json.dump(raced_with, f, indent=1)
    return summarise(name, scene, rows, args.out)


def provenance(args):
    """What a scene's CSV was raced with, so that results from different code are not mixed."""
    commit = subprocess.run(["git", "-C", ROOT, "describe", "--always", "--dirty"],
                            capture_output=True, text=True).stdout.strip() or "unknown"
    blender = subprocess.run(["blender", "--version"], capture_output=True,
                             text=True).stdout.split("\n")[0].strip()
    return {"commit": commit, "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
            "repeats": args.repeats, "threads": THREADS, "blender": blender}


def settle_ratio(t, cycles_seconds):
    """Cycles' time over this method's; both null (JSON) where the method does not reach the level."""
    if math.isfinite(t["seconds"]):
        t["cycles_over_this"] = cycles_seconds / t["seconds"]
    else:
        t["seconds"] = t["cycles_over_this"] = None


def seconds_text(t):
    """A time to the level for the tables: `not reached` where the error levels off above it."""
    return "not reached" if t["seconds"] is None else f"{t['seconds']:.1f}"


def ratio_text(t):
    return "" if t["cycles_over_this"] is None else f"{t['cycles_over_this']:.2f}"


def write_summary(results, out):
    with open(os.path.join(out, "summary.json"), "w") as f:
        json.dump(results, f, indent=1)
    lines = ["# Side by side with Cycles", "",
             "Written by `/usr/bin/python3 bench/peer/race.py`; see docs/peer.md.", ""]
    for name, result in results.items():
        lines += [f"## {name}", ""]
        if result.get("provenance"):
            p = result["provenance"]
            lines += [f"Raced {p['date']} at commit {p['commit']}, {p['repeats']} repeats, "
                      f"{p['threads']} threads, {p['blender']}.", ""]
        lines += ["| method | spp | wall s (median) | error vs Cycles ref | "
                  "mean ratio | error vs path ref |", "| --- | --- | --- | --- | --- | --- |"]
        for r in sorted(result["rows"], key=lambda r: (r["label"], r["spp"])):
            lines.append(f"| {r['label']} | {r['spp']} | {r['seconds']:.1f} | {r['error']:.4f} | "
                         f"{r['mean_ratio']:.4f} | {r['error_vs_path']:.4f} |")
        lines += ["", f"Time to {result['level']:.0%} plain relative RMSE against the Cycles reference:",
                  "", "| method | seconds | Cycles' time / this | how |", "| --- | --- | --- | --- |"]
        for label, t in result["time_to_level"].items():
            lines.append(f"| {label} | {seconds_text(t)} | {ratio_text(t)} | {t['how']} |")
        lines.append("")
    with open(os.path.join(out, "summary.md"), "w") as f:
        f.write("\n".join(lines))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scenes", default="cornell_box,mirror_glass,staircase")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--out", default=os.path.join(ROOT, "bench/peer/results"))
    parser.add_argument("--cache", default=os.path.join(ROOT, "bench/peer/cache"))
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--replot", action="store_true",
                        help="no runs: the plots and summary again from the CSVs in --out")
    parser.add_argument("--no-lightmaps", action="store_true",
                        help="images only: not the lightmap race (bake_race.py) after them")
    args = parser.parse_args()
    if args.quick:
        args.repeats = 1
        args.out = os.path.join(ROOT, "out/peer_quick")
        args.cache = os.path.join(ROOT, "out/peer_quick/cache")
    if args.replot:
        results = {name: summarise(name, SCENES[name], read_runs(os.path.join(args.out, f"{name}.csv")),
                                   args.out) for name in args.scenes.split(",")}
        write_summary(results, args.out)
        return
    if not shutil.which("blender"):
        sys.exit("race: blender not found (scripts/setup.sh --bench installs it)")
    for tool in ("radiosity", "render_compare"):
        if not os.path.isfile(os.path.join(args.build, "bin", tool)):
            sys.exit(f"race: {args.build}/bin/{tool} not found: build first (scripts/build.sh)")
    os.makedirs(args.out, exist_ok=True)
    results = {}
    with tempfile.TemporaryDirectory() as work:
        for name in args.scenes.split(","):
            if name not in SCENES:
                sys.exit(f"race: unknown scene '{name}' (known: {', '.join(SCENES)})")
            scene = dict(SCENES[name], **(QUICK if args.quick else {}))
            results[name] = race(args, name, scene, work)
            write_summary(results, args.out)
    print(f"race: wrote {args.out}/summary.md", file=sys.stderr)
    if not args.no_lightmaps:
        import bake_race  # the lightmaps, with the same repeats, build and directories
        bake_race.main(["--repeats", str(args.repeats), "--build", args.build, "--out", args.out,
                        "--cache", args.cache] + (["--quick"] if args.quick else []))


if __name__ == "__main__":  # bake_race.py imports the helpers
    main()
