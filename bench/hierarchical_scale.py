#!/usr/bin/python3
"""Hierarchical radiosity against the element-row solvers as scenes grow (issue 16): solves the
generated room (bench/scene_generator.py) at each element count with --solver hierarchical,
gauss-seidel and progressive, one after the other at each size (so the machine's load affects
all three alike), and records the whole-process wall time and peak resident memory
(/usr/bin/time), the links and bytes per element of the hierarchy (summary.json), the relative
RMS difference of each solution from Gauss–Seidel's on the same elements (area-weighted, over the
three channels), and each solution's error against a reference no solver took part in: the
per-element radiosity of a random sample of the elements, path traced (bench/element_reference,
made once per size and cached in --out/reference_cache, which git ignores). That error is the relative RMS over the
sampled elements with the reference's own variance (its standard errors squared) taken out.
Fits time and memory = c · N^k per solver and writes CSV, JSON and one PNG (time and memory
against elements, all solvers).

    /usr/bin/python3 bench/hierarchical_scale.py [--build build] [--out bench/results]
        [--sizes 10000,30000,100000] [--rays 256] [--hierarchical-rays N] [--threads 0]
        [--boxes 64] [--row-solvers-up-to 300000] [--reference-sample 2000]
        [--reference-paths 16384] [--no-reference] [--name hierarchical_scale]
        [--scene SCENE --lights LIGHTS.json]

--hierarchical-rays gives the hierarchical solve its own --rays (default: --rays), to compare
the solvers at equal error rather than equal rays; --name names the CSV, JSON and PNG written.
--scene solves a scene of one's own instead of the generated room (e.g. the atrium of
../shared/scenes/, refined to each size), lit by --lights (a lights file, as radiosity solve
--lights; the reference samples the same lights).

The row solvers keep one form-factor row per element (about 9 KB each at 1024 rays): above
--row-solvers-up-to elements only the hierarchical solve runs.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import zlib

from growth import fit_exponent  # bench/growth.py: least-squares slope in log–log

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOLVERS = ("hierarchical", "gauss-seidel", "progressive")


def read_radiosity(path):
    """(area, B_r, B_g, B_b) per element from elements.csv."""
    rows = []
    with open(path) as f:
        for r in csv.DictReader(f):
            rows.append((float(r["area"]), float(r["B_r"]), float(r["B_g"]), float(r["B_b"])))
    return rows


def relative_rms(rows, reference):
    num = den = 0.0
    for a, b in zip(rows, reference):
        for c in (1, 2, 3):
            num += a[0] * (a[c] - b[c]) ** 2
            den += a[0] * b[c] ** 2
    return math.sqrt(num / den) if den > 0 else float("nan")


def read_reference(path):
    """{element: (cx, cy, cz, B_r, B_g, B_b, se_r, se_g, se_b)} from bench/element_reference."""
    with open(path) as f:
        return {int(r["element"]): tuple(float(r[k]) for k in
                                         ("cx", "cy", "cz", "B_r", "B_g", "B_b", "se_r", "se_g", "se_b"))
                for r in csv.DictReader(f)}


def read_centroids(path):
    with open(path) as f:
        return [(float(r["cx"]), float(r["cy"]), float(r["cz"])) for r in csv.DictReader(f)]


def same_elements(centroids, reference):
    """Whether the solve's elements are the reference's (centroids within 1e-6): a cached reference
    made before the mesher changed is not."""
    return all(e < len(centroids) and max(abs(a - b) for a, b in zip(centroids[e], ref[:3])) <= 1e-6
               for e, ref in reference.items())


def error_against_reference(rows, centroids, reference):
    """Relative RMS of B over the reference's elements (area-weighted, three channels), with the
    reference's own variance removed: E[(B − B_ref)²] = (B − B_true)² + se²."""
    if not same_elements(centroids, reference):
        sys.exit("hierarchical_scale: the solve's elements are not the reference's")
    num = den = noise = 0.0
    for e, ref in reference.items():
        area = rows[e][0]
        for c in range(3):
            num += area * (rows[e][c + 1] - ref[3 + c]) ** 2
            noise += area * ref[6 + c] ** 2
            den += area * ref[3 + c] ** 2
    return math.sqrt(max(0.0, num - noise) / den), math.sqrt(noise / den)


def plot_png(path, rows, fits, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.5), dpi=110)
    colours = {"hierarchical": "#d62728", "gauss-seidel": "#1f77b4", "progressive": "#2ca02c"}
    for solver in SOLVERS:
        mine = [r for r in rows if r["solver"] == solver]
        if not mine:
            continue
        n = [r["elements"] for r in mine]
        left.plot(n, [r["wall_s"] for r in mine], "o-", color=colours[solver],
                  label="%s, k = %.2f" % (solver, fits[solver]["wall_s"]))
        right.plot(n, [r["peak_mib"] for r in mine], "s-", color=colours[solver],
                   label="%s, k = %.2f" % (solver, fits[solver]["peak_mib"]))
    for ax, label in ((left, "wall time (s)"), (right, "peak resident memory (MiB)")):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("elements N")
        ax.set_ylabel(label)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8, loc="upper left")
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    tmp = path + ".tmp"
    fig.savefig(tmp, format="png")
    os.replace(tmp, path)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--out", default=os.path.join(ROOT, "bench/results"))
    parser.add_argument("--sizes", default="10000,30000,100000")
    parser.add_argument("--rays", type=int, default=256)
    parser.add_argument("--hierarchical-rays", type=int, default=0)
    parser.add_argument("--name", default="hierarchical_scale")
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--boxes", type=int, default=64)
    parser.add_argument("--row-solvers-up-to", type=int, default=300000)
    parser.add_argument("--reference-sample", type=int, default=2000)
    parser.add_argument("--reference-paths", type=int, default=16384)
    parser.add_argument("--no-reference", action="store_true")
    parser.add_argument("--scene", help="a scene file instead of the generated room")
    parser.add_argument("--lights", help="a lights file for --scene")
    args = parser.parse_args()
    if args.lights and not args.scene:
        parser.error("--lights needs --scene (the generated room has its own lamp)")
    lights = ["--lights", os.path.abspath(args.lights)] if args.lights else []
    os.makedirs(args.out, exist_ok=True)
    binary = os.path.join(args.build, "bin/radiosity")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        if args.scene:
            scene = os.path.abspath(args.scene)
            # The lights file's contents name the cached reference, so an edited file makes a new one.
            light_tag = ("_lights%08x" % (zlib.crc32(open(args.lights, "rb").read()))) if args.lights else ""
            scene_tag = os.path.splitext(os.path.basename(scene))[0] + light_tag
        else:
            scene = os.path.join(tmp, "room.obj")
            subprocess.run([sys.executable, os.path.join(ROOT, "bench/scene_generator.py"), scene, "--boxes",
                            str(args.boxes)], check=True)
            scene_tag = "room%d" % args.boxes
        cache = os.path.join(args.out, "reference_cache")
        os.makedirs(cache, exist_ok=True)
        for n in [int(s) for s in args.sizes.split(",")]:
            solutions = {}
            reference = None
            if not args.no_reference:
                ref_path = os.path.join(cache, "%s_%d_sample%d_paths%d.csv"
                                        % (scene_tag, n, args.reference_sample, args.reference_paths))
                def make_reference():
                    subprocess.run([os.path.join(args.build, "bin/element_reference"), scene, "--elements",
                                    str(n), "--sample", str(args.reference_sample), "--paths",
                                    str(args.reference_paths), "--threads", str(args.threads), "--out",
                                    ref_path] + lights, check=True)
                    return read_reference(ref_path)
                reference = read_reference(ref_path) if os.path.exists(ref_path) else make_reference()
            for solver in SOLVERS:
                if solver != "hierarchical" and n > args.row_solvers_up_to:
                    continue
                out = os.path.join(tmp, f"{solver}_{n}")
                rays = args.hierarchical_rays if solver == "hierarchical" and args.hierarchical_rays else args.rays
                cmd = ["/usr/bin/time", "-f", "%e %M", binary, "solve", scene, "--elements", str(n), "--rays",
                       str(rays), "--threads", str(args.threads), "--solver", solver, "--out", out] + lights
                run = subprocess.run(cmd, capture_output=True, text=True)
                if run.returncode != 0:
                    print(run.stderr, file=sys.stderr)
                    sys.exit(f"hierarchical_scale: {solver} with {n} elements failed")
                wall, peak_kib = run.stderr.strip().splitlines()[-1].split()
                s = json.load(open(os.path.join(out, "summary.json")))
                h = s.get("hierarchy") or {}
                solutions[solver] = read_radiosity(os.path.join(out, "elements.csv"))
                error = reference_noise = ""
                if reference is not None:
                    centroids = read_centroids(os.path.join(out, "elements.csv"))
                    if not same_elements(centroids, reference):
                        print(f"hierarchical_scale: {ref_path} was made on another mesh; making it again",
                              file=sys.stderr)
                        reference = make_reference()
                    error, reference_noise = error_against_reference(solutions[solver], centroids, reference)
                rows.append({"solver": solver, "target_elements": n, "elements": s["scene"]["elements"],
                             "wall_s": float(wall), "peak_mib": int(peak_kib) / 1024,
                             "form_factor_s": s["time_seconds"]["form_factors"],
                             "solve_s": s["time_seconds"]["solve"], "rays": s["form_factors"]["rays_cast"],
                             "links": h.get("links", ""), "bytes_per_element": h.get("bytes_per_element", ""),
                             "threads": s["threads"], "rays_per_element": rays,
                             "relative_rms_vs_gauss_seidel": "", "relative_rms_vs_reference": error,
                             "reference_noise": reference_noise})
                print(rows[-1], flush=True)
            if "gauss-seidel" in solutions:
                for r in rows:
                    if r["target_elements"] == n and r["solver"] != "gauss-seidel":
                        r["relative_rms_vs_gauss_seidel"] = relative_rms(solutions[r["solver"]],
                                                                         solutions["gauss-seidel"])
    tmp = os.path.join(args.out, args.name + ".csv.tmp")
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    os.replace(tmp, os.path.join(args.out, args.name + ".csv"))
    fits = {}
    for solver in SOLVERS:
        mine = [r for r in rows if r["solver"] == solver]
        if len(mine) >= 2:
            fits[solver] = {k: fit_exponent([r["elements"] for r in mine], [r[k] for r in mine])
                            for k in ("wall_s", "peak_mib")}
    with open(os.path.join(args.out, args.name + "_fit.json"), "w") as f:
        json.dump(fits, f, indent=2)
    print("fitted exponents (quantity ~ N^k):", json.dumps(fits))
    if all(s in fits for s in SOLVERS if any(r["solver"] == s for r in rows)):
        plot_png(os.path.join(args.out, args.name + ".png"), rows, fits,
                 "%s, %d rays, %d threads: hierarchical against the row solvers"
                 % (os.path.basename(args.scene) if args.scene else "Generated room (%d boxes)" % args.boxes,
                    args.rays, rows[0]["threads"]))


if __name__ == "__main__":
    main()
