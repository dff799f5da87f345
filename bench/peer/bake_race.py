#!/usr/bin/env python3
"""Lightmaps against Cycles' bake, side by side (issue 17, part 2; docs/peer.md, "Lightmaps").

For each scene: `radiosity bake` (the interpolated solution, per-texel final gathers of several
ray counts, and per-texel direct light with the solution's indirect light, --light-rays N) and Cycles baking the same lightmap on the project's own lightmap UVs
(bench/peer/cycles_bake.py, the conventions of cycles_render.py) at several samples per texel,
interleaved in one run and repeated, as bench/peer/race.py does for camera images. Each lightmap is
compared with a high-sample Cycles bake made once as two halves with their own seeds and cached: the
mean is the reference, (A-B)^2/4 per texel the variance of that mean, removed from the error.

- The texels compared are those Cycles bakes (a triangle covers the texel's centre: alpha 1 in both
  halves); the project fills every texel a triangle touches and dilates, which is not compared.
- The error is the plain relative RMSE of issue 17 over those texels: sqrt(mean over texels and
  channels of (x - ref)^2, less the reference's variance) / mean(ref); also over the texels away
  from the emitters (reference below half the brightest), where the light's texels do not dominate,
  and over the interior texels (not at a chart's border), where Cycles' average over a texel's
  footprint and the project's value at its centre differ least.
- Time is the whole process's wall time: for the project loading, meshing, the solve, the bake and
  its exports; for Cycles Blender's start, importing the project's glTF (its UVs) and the bake.
- Every project bake must have the layout the Cycles bakes were made on (bake.json's lightmap block
  and the baked OBJ's texture coordinates): uniform meshing is deterministic, so it has.

Writes into --out (default bench/peer/results/): bake_<scene>.csv (every run), bake_<scene>.png
(error against time) and bake_summary.md / bake_summary.json (times to the level and ratios).

    /usr/bin/python3 bench/peer/bake_race.py [--scenes cornell_box] [--repeats 3]
        [--build build] [--out bench/peer/results] [--cache bench/peer/cache] [--quick] [--replot]

Needs `blender` (scripts/setup.sh --bench) and a Release build (radiosity, render_compare).
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

import numpy as np

import race

BAKE_SCRIPT = os.path.join(race.ROOT, "bench/peer/cycles_bake.py")

# Each scene: the race.SCENES entry it bakes, the lightmap's side (one page), the level, the
# project's per-texel gather rays (0: the interpolated solution), its per-texel shadow rays with
# the solution's indirect light (`direct`: --gather 0 --light-rays N), Cycles' samples per texel,
# and the reference's samples per half.
SCENES = {
    "cornell_box": {"scene": "cornell_box", "lightmap_size": 256, "level": 0.02,
                    "radiosity": [0, 16, 64, 128, 256, 1024], "direct": [4, 16, 64],
                    "cycles": [16, 64, 256, 1024], "reference_cycles": 4096},
}
QUICK = {"radiosity": [0, 16], "direct": [4], "cycles": [4, 16], "reference_cycles": 64}


def project_bake(args, scene, options, gather, seed, directory, light_rays=0):
    """One `radiosity bake` into `directory` (a fresh solve); its wall time."""
    command = [os.path.join(args.build, "bin/radiosity"), "bake", scene["obj"], "--out", directory,
               "--lightmap-size", str(options["lightmap_size"]), "--seed", str(seed), "-q"]
    if gather:
        command += ["--gather", str(gather)]
    if light_rays:
        command += ["--light-rays", str(light_rays)]
    return race.run_timed(command + scene["options"], os.path.join(directory + ".log"))


def cycles_bake(layout, scene, spp, seed, out, work):
    command = ["blender", "-b", "--factory-startup", "--python-exit-code", "1", "--python",
               BAKE_SCRIPT, "--", layout, scene["obj"], "--spp", str(spp), "--out", out, "--seed",
               str(seed), "--threads", str(race.THREADS), "--report", out + ".json"] + scene["options"]
    return race.run_timed(command, os.path.join(work, "cycles_bake.log"))


def layout_of(directory):
    """What fixes which texel is where: the lightmap block's size and counts, the UVs' digest."""
    lightmap = json.load(open(os.path.join(directory, "bake.json")))["lightmap"]
    uvs = race.file_digest(os.path.join(directory, "scene_baked.obj")).hexdigest()
    return {k: lightmap.get(k) for k in ("pages", "width", "height", "charts")}, uvs


def project_lightmap(args, directory, work):
    """The project's lightmap.exr as an H x W x 3 array, row 0 at the top."""
    pfm = os.path.join(work, "lightmap.pfm")
    subprocess.run([os.path.join(args.build, "bin/render_compare"), "pfm",
                    os.path.join(directory, "lightmap.exr"), pfm], check=True, capture_output=True)
    with open(pfm, "rb") as f:
        assert f.readline().strip() == b"PF"
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4")
    return data.reshape(height, width, 3)[::-1].astype(np.float64)  # PFM rows run bottom-up


def reference(args, name, scene, options, layout, work):
    """(mean, variance, mask) of two Cycles bakes of `reference_cycles` samples, cached under a key
    of the scene's files, the layout (the baked OBJ), the scripts and Blender."""
    mtl = [os.path.join(os.path.dirname(scene["obj"]), line.split(None, 1)[1].strip())
           for line in open(scene["obj"], errors="replace") if line.startswith("mtllib")]
    digest = race.file_digest(scene["obj"], *mtl, os.path.join(layout, "scene_baked.obj"),
                              BAKE_SCRIPT, race.CYCLES_SCRIPT, shutil.which("blender"))
    digest.update(" ".join(scene["options"]).encode())
    spp = options["reference_cycles"]
    path = os.path.join(args.cache, f"bake_{name}_{spp}_{digest.hexdigest()[:12]}.npz")
    if not os.path.isfile(path):
        os.makedirs(args.cache, exist_ok=True)
        halves = []
        for half, seed in enumerate((1000001, 1000002)):
            out = os.path.join(work, f"reference_{half}.exr")
            print(f"bake_race: {name}: baking the Cycles reference, half {half + 1} of 2, {spp} "
                  f"samples", file=sys.stderr)
            seconds = cycles_bake(layout, scene, spp, seed, out, work)
            print(f"bake_race: {name}: {seconds:.0f} s", file=sys.stderr)
            halves.append(np.load(os.path.splitext(out)[0] + ".npy").astype(np.float64))
        a, b = halves
        np.savez_compressed(path + ".tmp.npz", mean=(a[..., :3] + b[..., :3]) / 2,
                            variance=(a[..., :3] - b[..., :3]) ** 2 / 4,
                            mask=(a[..., 3] > 0) & (b[..., 3] > 0))
        os.replace(path + ".tmp.npz", path)
    else:
        print(f"bake_race: {name}: Cycles reference from the cache ({os.path.basename(path)})",
              file=sys.stderr)
    ref = np.load(path)
    return ref["mean"], ref["variance"], ref["mask"]


def texel_error(lightmap, ref):
    """Plain relative RMSE over the compared texels (reference noise removed), the mean ratio, the
    error over the texels away from the emitters, and over the interior texels (not at a chart's
    border: their 4 neighbours baked too), where Cycles' average over the texel's footprint and
    the project's value at its centre are alike unless the light bends within a texel."""
    mean, variance, mask = ref
    away = mask & (mean.max(axis=2) < 0.5 * mean[mask].max())
    interior = mask.copy()
    interior[1:, :] &= mask[:-1, :]
    interior[:-1, :] &= mask[1:, :]
    interior[:, 1:] &= mask[:, :-1]
    interior[:, :-1] &= mask[:, 1:]

    def error(where):
        d2 = ((lightmap[where] - mean[where]) ** 2).mean() - variance[where].mean()
        return float(np.sqrt(max(d2, 0.0)) / mean[where].mean())

    return {"error": error(mask), "mean_ratio": float(lightmap[mask].mean() / mean[mask].mean()),
            "error_away_from_emitters": error(away), "error_interior": error(interior),
            "texels": int(mask.sum()), "texels_interior": int(interior.sum())}


def jobs(options):
    return race.interleave([[("cycles", n) for n in options["cycles"]],
                            [("radiosity", n) for n in options["radiosity"]],
                            [("direct", n) for n in options.get("direct", [])]])


def label(method, n):
    if method == "cycles":
        return "Cycles bake"
    if method == "direct":
        return f"radiosity bake --light-rays {n}"
    return "radiosity bake" + (f" --gather {n}" if n else " (interpolated)")


def race_scene(args, name, options, work):
    scene = race.SCENES[options["scene"]]
    layout = os.path.join(work, "layout")
    project_bake(args, scene, options, 0, 1, layout)
    expected = layout_of(layout)
    ref = reference(args, name, scene, options, layout, work)
    raced_with = race.provenance(args)
    rows, order = [], jobs(options)
    total = args.repeats * len(order)
    for repeat in range(args.repeats):
        seed = 1 + repeat
        for method, n in order:
            if method == "cycles":
                out = os.path.join(work, "cycles.exr")
                seconds = cycles_bake(layout, scene, n, seed, out, work)
                lightmap = np.load(os.path.join(work, "cycles.npy"))[..., :3].astype(np.float64)
            else:
                directory = tempfile.mkdtemp(dir=work)
                seconds = (project_bake(args, scene, options, 0, seed, directory, light_rays=n)
                           if method == "direct" else
                           project_bake(args, scene, options, n, seed, directory))
                if layout_of(directory) != expected:
                    sys.exit(f"bake_race: {name}: the bake in {directory} has another lightmap "
                             "layout than the one Cycles baked on")
                lightmap = project_lightmap(args, directory, work)
                shutil.rmtree(directory)
            row = {"scene": name, "repeat": repeat, "label": label(method, n), "method": method,
                   "samples": n, "seed": seed, "seconds": seconds}
            row.update(texel_error(lightmap, ref))
            rows.append(row)
            print(f"bake_race: {name} [{len(rows)}/{total}] {row['label']} {n}: {seconds:.1f} s, "
                  f"error {row['error']:.4f} (away from emitters "
                  f"{row['error_away_from_emitters']:.4f}), mean ratio {row['mean_ratio']:.4f}",
                  file=sys.stderr)
    with open(os.path.join(args.out, f"bake_{name}.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    with open(os.path.join(args.out, f"bake_{name}.meta.json"), "w") as f:
        json.dump(dict(raced_with, reference_samples=options["reference_cycles"],
                       lightmap_size=options["lightmap_size"]), f, indent=1)
    return summarise(name, options, rows, args.out)


def medians(rows):
    groups = {}
    for r in rows:
        groups.setdefault((r["label"], r["samples"]), []).append(r)
    return [dict({"label": lab, "samples": n, "repeats": len(g)},
                 **{k: statistics.median(r[k] for r in g)
                    for k in ("seconds", "error", "mean_ratio", "error_away_from_emitters",
                              "error_interior")})
            for (lab, n), g in groups.items()]


def plot(name, options, rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(19, 5.4))
    for ax, (key, title) in zip(axes, (("error", "all texels Cycles bakes"),
                                       ("error_away_from_emitters", "texels away from the emitters"),
                                       ("error_interior", "interior texels (not at a chart border)"))):
        for lab, marker, colour in (("Cycles bake", "o-", "#e67e22"),
                                    ("radiosity bake --gather", "s-", "#c0392b"),
                                    ("radiosity bake --light-rays", "v-", "#8e44ad"),
                                    ("radiosity bake (interpolated)", "D", "#16a085")):
            line = sorted((r for r in rows if r["label"].startswith(lab)), key=lambda r: r["seconds"])
            if not line:
                continue
            race.plot_line(ax, line, key, "samples", marker, colour,
                           lab + (" N" if lab.endswith(("gather", "rays")) else ""))
        race.style_error_axes(ax, options["level"],
                              "plain relative RMSE of the texels, reference noise removed",
                              f"{name} lightmap ({options['lightmap_size']}²): {title}")
    axes[0].legend(fontsize=8)
    fig.suptitle(f"{name}: lightmap error against time, Cycles' bake and the project's, "
                 f"{race.THREADS} threads (labels: samples per texel, gather rays)")
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)


def summarise(name, options, rows, out):
    summary = medians(rows)
    plot(name, options, summary, os.path.join(out, f"bake_{name}.png"))
    times = {}
    groups = {"Cycles bake": [r for r in summary if r["label"] == "Cycles bake"],
              "radiosity bake --gather N": [r for r in summary if "--gather" in r["label"]],
              "radiosity bake --light-rays N": [r for r in summary
                                                if "--light-rays" in r["label"]]}
    for lab, group in groups.items():
        if group:
            seconds, how = race.time_to_level(group, options["level"])
            times[lab] = {"seconds": seconds, "how": how}
    for r in summary:
        if "interpolated" in r["label"]:
            times[r["label"]] = {"seconds": r["seconds"], "how": f"one run, error {r['error']:.4f}"
                                 + (" (above the level)" if r["error"] > options["level"] else "")}
    for t in times.values():
        race.settle_ratio(t, times["Cycles bake"]["seconds"])
    meta = os.path.join(out, f"bake_{name}.meta.json")
    return {"level": options["level"], "rows": summary, "time_to_level": times,
            "provenance": json.load(open(meta)) if os.path.isfile(meta) else None}


def write_summary(results, out):
    with open(os.path.join(out, "bake_summary.json"), "w") as f:
        json.dump(results, f, indent=1)
    lines = ["# Lightmaps side by side with Cycles' bake", "",
             "Written by `/usr/bin/python3 bench/peer/bake_race.py`; see docs/peer.md.", ""]
    for name, result in results.items():
        lines += [f"## {name}", ""]
        p = result.get("provenance")
        if p:
            lines += [f"Raced {p['date']} at commit {p['commit']}, {p['repeats']} repeats, "
                      f"{p['threads']} threads, {p['blender']}; lightmap {p['lightmap_size']}², "
                      f"reference 2 × {p['reference_samples']} samples per texel.", ""]
        lines += ["| method | samples / rays | wall s (median) | texel error | away from emitters | "
                  "interior texels | mean ratio |", "| --- | --- | --- | --- | --- | --- | --- |"]
        for r in sorted(result["rows"], key=lambda r: (r["label"], r["samples"])):
            lines.append(f"| {r['label']} | {r['samples']} | {r['seconds']:.1f} | {r['error']:.4f} | "
                         f"{r['error_away_from_emitters']:.4f} | {r['error_interior']:.4f} | "
                         f"{r['mean_ratio']:.4f} |")
        lines += ["", f"Time to {result['level']:.0%} texel error:", "",
                  "| method | seconds | Cycles' time / this | how |", "| --- | --- | --- | --- |"]
        for lab, t in result["time_to_level"].items():
            lines.append(f"| {lab} | {race.seconds_text(t)} | {race.ratio_text(t)} | "
                         f"{t['how']} |")
        lines.append("")
    with open(os.path.join(out, "bake_summary.md"), "w") as f:
        f.write("\n".join(lines))


def read_runs(path):
    rows = race.read_runs(path)
    for r in rows:
        r["samples"] = int(r["samples"])
    return rows


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scenes", default=",".join(SCENES))
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--build", default=os.path.join(race.ROOT, "build"))
    parser.add_argument("--out", default=os.path.join(race.ROOT, "bench/peer/results"))
    parser.add_argument("--cache", default=os.path.join(race.ROOT, "bench/peer/cache"))
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--replot", action="store_true",
                        help="no runs: the plots and summary again from the CSVs in --out")
    args = parser.parse_args(argv)
    if args.quick:
        args.repeats = 1
        args.out = os.path.join(race.ROOT, "out/peer_quick")
        args.cache = os.path.join(race.ROOT, "out/peer_quick/cache")
    names = args.scenes.split(",")
    for name in names:
        if name not in SCENES:
            sys.exit(f"bake_race: unknown scene '{name}' (known: {', '.join(SCENES)})")
    if args.replot:
        results = {n: summarise(n, SCENES[n], read_runs(os.path.join(args.out, f"bake_{n}.csv")),
                                args.out) for n in names}
        write_summary(results, args.out)
        return
    if not shutil.which("blender"):
        sys.exit("bake_race: blender not found (scripts/setup.sh --bench installs it)")
    for tool in ("radiosity", "render_compare"):
        if not os.path.isfile(os.path.join(args.build, "bin", tool)):
            sys.exit(f"bake_race: {args.build}/bin/{tool} not found: build first (scripts/build.sh)")
    os.makedirs(args.out, exist_ok=True)
    results = {}
    with tempfile.TemporaryDirectory() as work:
        for name in names:
            options = dict(SCENES[name], **(QUICK if args.quick else {}))
            results[name] = race_scene(args, name, options, work)
            write_summary(results, args.out)
    print(f"bake_race: wrote {args.out}/bake_summary.md", file=sys.stderr)


if __name__ == "__main__":
    main()
