#!/usr/bin/python3
"""Plots run time against error from bench/time_vs_error's CSVs: one log-log PNG per scene, wall
time on x, relative RMS radiance error on y, each configuration a point (marker: form-factor
method and meshing, colour: solver, label: element count; black edge: not converged), the Pareto front (no other point is both faster and more
accurate) drawn as a step line, and the reference's own noise as a dotted line (errors near it
are not resolved). Also writes the front of each scene to DIR/pareto_NAME.csv.

    /usr/bin/python3 bench/plot_time_vs_error.py DIR      (reads DIR/time_vs_error_*.csv)
"""
import csv
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLOURS = {"progressive": "#1f77b4", "southwell": "#ff7f0e", "gauss-seidel": "#2ca02c", "jacobi": "#d62728"}


def kind(row):
    if row["form_factors"] == "analytic":
        return "analytic, adaptive" if float(row["refine_threshold"]) > 0 else "analytic, uniform"
    return "hemisphere %s rays" % row["rays"]


MARKERS = {"analytic, uniform": "s", "analytic, adaptive": "D"}
RAY_MARKERS = ["o", "^", "v", "P", "X", "*"]


def pareto(rows):
    """Points no other point beats in both time and error, by increasing time."""
    front, best = [], float("inf")
    for r in sorted(rows, key=lambda r: (r["seconds"], r["relative_rmse"])):
        if r["relative_rmse"] < best:
            front.append(r)
            best = r["relative_rmse"]
    return front


def write_atomically(path, write):
    tmp = path + ".tmp"
    write(tmp)
    os.replace(tmp, path)


def plot(name, rows, out_dir):
    for r in rows:
        r["seconds"] = float(r["seconds"])
        r["relative_rmse"] = float(r["relative_rmse"])
    ray_kinds = sorted({kind(r) for r in rows if r["form_factors"] == "hemisphere"},
                       key=lambda k: int(k.split()[1]))
    markers = dict(MARKERS, **{k: RAY_MARKERS[i % len(RAY_MARKERS)] for i, k in enumerate(ray_kinds)})
    fig, ax = plt.subplots(figsize=(9.5, 5.5), dpi=110)
    for r in rows:
        ax.scatter(r["seconds"], r["relative_rmse"], marker=markers[kind(r)], s=36,
                   color=COLOURS.get(r["solver"], "black"), alpha=0.85,
                   edgecolors="black" if r["converged"] == "0" else "none")
        ax.annotate(r["elements"], (r["seconds"], r["relative_rmse"]), textcoords="offset points", xytext=(4, 3),
                    fontsize=6, color="#555555")
    front = pareto(rows)
    ax.step([r["seconds"] for r in front], [r["relative_rmse"] for r in front], where="post", color="black",
            linewidth=1.2, label="Pareto front")
    noise = float(rows[0]["reference_noise"])
    if noise > 0:
        ax.axhline(noise, color="grey", linestyle=":", linewidth=1, label="reference noise")
    handles = [plt.Line2D([], [], color="black", linewidth=1.2, label="Pareto front")]
    if noise > 0:
        handles.append(plt.Line2D([], [], color="grey", linestyle=":", label="reference's own noise"))
    handles += [plt.Line2D([], [], marker=markers[k], linestyle="", color="grey", label=k)
                for k in ray_kinds + [k for k in MARKERS if any(kind(r) == k for r in rows)]]
    handles += [plt.Line2D([], [], marker="o", linestyle="", color=c, label=s) for s, c in COLOURS.items()
                if any(r["solver"] == s for r in rows)]
    ax.legend(handles=handles, fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("wall time of the solve (s, 2 threads unless stated)")
    ax.set_ylabel("relative RMS radiance error per element")
    ax.set_title("%s: run time against error (reference %s elements)" % (name, rows[0]["reference_elements"]))
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    png = os.path.join(out_dir, "time_vs_error_%s.png" % name)
    write_atomically(png, lambda p: fig.savefig(p, format="png"))
    plt.close(fig)

    def write_front(path):
        with open(path, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["form_factors", "solver", "rays", "target_elements", "refine_threshold", "tolerance",
                        "elements", "seconds", "relative_rmse"])
            for r in front:
                w.writerow([r["form_factors"], r["solver"], r["rays"], r["target_elements"], r["refine_threshold"],
                            r["tolerance"], r["elements"], "%.4g" % r["seconds"], "%.4g" % r["relative_rmse"]])
    write_atomically(os.path.join(out_dir, "pareto_%s.csv" % name), write_front)
    print("%s: %d configurations, Pareto front: %s" % (name, len(rows), "; ".join(
        "%s %s %s el. %.3g s %.3g" % (kind(r), r["solver"], r["elements"], r["seconds"], r["relative_rmse"])
        for r in front)))


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out_dir = sys.argv[1]
    paths = sorted(glob.glob(os.path.join(out_dir, "time_vs_error_*.csv")))
    if not paths:
        sys.exit("plot_time_vs_error: no %s/time_vs_error_*.csv (run bench/time_vs_error first)" % out_dir)
    for path in paths:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
        if not rows:
            sys.exit("plot_time_vs_error: %s has no rows" % path)
        plot(rows[0]["scene"], rows, out_dir)


if __name__ == "__main__":
    main()
