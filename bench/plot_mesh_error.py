#!/usr/bin/python3
"""PNG plot of bench/mesh_results/mesh_error.csv (written by build/bin/mesh_error): elements
against the relative RMS error of the displayed radiance, uniform and adaptive, log-log, with the
reference check's difference as a floor line.

    /usr/bin/python3 bench/plot_mesh_error.py [DIR]     (default bench/mesh_results)
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else "bench/mesh_results"
rows = list(csv.DictReader(open(f"{out}/mesh_error.csv")))
fig, ax = plt.subplots(figsize=(7, 4.6), dpi=110)
for kind, style in (("uniform", "o-"), ("adaptive", "s-")):
    pts = [(int(r["elements"]), float(r["relative_rms_error"])) for r in rows if r["kind"] == kind]
    if pts:
        ax.plot(*zip(*pts), style, label=kind)
    if kind == "adaptive":
        for r in rows:
            if r["kind"] == kind and r["uniform_elements_same_error"]:
                ax.annotate(f'{float(r["element_ratio"]):.1f}×', (int(r["elements"]), float(r["relative_rms_error"])),
                            textcoords="offset points", xytext=(6, -12), fontsize=8)
reference = [r for r in rows if r["kind"] == "reference"]
if reference:
    r = reference[0]
    ax.axhline(float(r["relative_rms_error"]), color="grey", ls=":",
               label=f'reference check difference ({r["elements"]} elements)')
ax.set_xscale("log")
ax.set_yscale("log")
ax.set_xlabel("elements")
ax.set_ylabel("relative RMS error of displayed radiance")
ax.set_title("Cornell box: uniform against adaptive meshing\n(labels: uniform elements needed for the same error ÷ adaptive elements)",
             fontsize=9)
ax.grid(True, which="both", alpha=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(f"{out}/mesh_error.png")
print(f"wrote {out}/mesh_error.png")
