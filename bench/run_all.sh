#!/usr/bin/env bash
# The issue-8 benchmark in one command: ray throughput (form factors against raw Embree, same
# rays, 1…all threads: ratio and parallel scaling) and cost growth with scene size.
# Writes bench/results/{throughput.json,throughput.csv,growth.csv,growth_fit.json,growth.svg}.
#   bash bench/run_all.sh [BUILD_DIR]        (default: build; builds the needed targets first)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
OUT=bench/results
mkdir -p "$OUT"
cmake --build "$BUILD" --target radiosity throughput -j"$(nproc)"
"$BUILD/bin/throughput" --benchmark_format=json --benchmark_min_time=1 >"$OUT/throughput.json"
python3 - "$OUT" <<'PY'
import csv, json, sys
out = sys.argv[1]
runs = json.load(open(f"{out}/throughput.json"))["benchmarks"]
rate = {}
for r in runs:
    name, threads = r["name"].split("/")[0], int(r["name"].split("threads:")[1].split("/")[0])
    rate[(name, threads)] = r["rays_per_s"]
threads = sorted({t for _, t in rate})
with open(f"{out}/throughput.csv", "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["threads", "form_factor_rays_per_s", "raw_embree_rays_per_s", "ratio", "form_factor_speedup",
                "form_factor_efficiency"])
    for t in threads:
        ff, raw = rate[("formFactorRows", t)], rate[("rawEmbree", t)]
        speedup = ff / rate[("formFactorRows", 1)]
        w.writerow([t, f"{ff:.4g}", f"{raw:.4g}", f"{ff / raw:.3f}", f"{speedup:.3f}", f"{speedup / t:.3f}"])
        print(f"{t} threads: form factors {ff / 1e6:.2f} M rays/s, raw Embree {raw / 1e6:.2f} M rays/s, "
              f"ratio {ff / raw:.3f}, speed-up {speedup:.2f} (efficiency {speedup / t:.0%})")
PY
python3 bench/growth.py --build "$BUILD" --out "$OUT"
