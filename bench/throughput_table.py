#!/usr/bin/python3
"""Turns bench/throughput's Google Benchmark JSON into a table per thread count: form-factor rays/s,
raw Embree rays/s on the same rays, their ratio, and the form factors' speed-up and parallel
efficiency against one thread. With repetitions (--benchmark_repetitions=N), the medians.
ratio_in_turn is the ratio from the ratioInTurn benchmark, which times the two in turn inside each
iteration: less sensitive to other work on a shared machine than the ratio of two separate runs.

    /usr/bin/python3 bench/throughput_table.py THROUGHPUT.json OUT.csv
"""
import csv
import json
import os
import sys


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    runs = json.load(open(sys.argv[1]))["benchmarks"]
    rate = {}
    repeated = any(r.get("run_type") == "aggregate" for r in runs)
    for r in runs:
        if repeated and r.get("aggregate_name") != "median":
            continue
        name, threads = r["name"].split("/")[0], int(r["name"].split("threads:")[1].split("/")[0])
        if name == "ratioInTurn":
            rate[(name, threads)] = r["ratio"]
            continue
        rate[(name, threads)] = r["rays_per_s"]
    threads = sorted({t for n, t in rate if n == "formFactorRows"})
    names = sorted({n for n, _ in rate})
    if "formFactorRows" not in names or "rawEmbree" not in names or 1 not in threads:
        sys.exit("throughput_table: %s lacks formFactorRows/rawEmbree at 1 thread" % sys.argv[1])
    tmp = sys.argv[2] + ".tmp"
    with open(tmp, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["threads", "form_factor_rays_per_s", "raw_embree_rays_per_s", "ratio", "form_factor_speedup",
                    "form_factor_efficiency", "raw_embree_speedup", "raw_embree_efficiency", "ratio_in_turn"])
        for t in threads:
            ff, raw = rate[("formFactorRows", t)], rate[("rawEmbree", t)]
            speedup = ff / rate[("formFactorRows", 1)]
            in_turn = "%.3f" % rate[("ratioInTurn", t)] if ("ratioInTurn", t) in rate else ""
            raw_speedup = raw / rate[("rawEmbree", 1)]
            w.writerow([t, "%.4g" % ff, "%.4g" % raw, "%.3f" % (ff / raw), "%.3f" % speedup, "%.3f" % (speedup / t),
                        "%.3f" % raw_speedup, "%.3f" % (raw_speedup / t), in_turn])
            print("%2d threads: form factors %6.2f M rays/s, raw Embree %6.2f M rays/s, ratio %.3f, "
                  "speed-up %.2f (efficiency %.0f%%; raw Embree %.0f%%)"
                  % (t, ff / 1e6, raw / 1e6, ff / raw, speedup, 100 * speedup / t, 100 * raw_speedup / t)
                  + (", ratio in turn %s" % in_turn if in_turn else ""))
    os.replace(tmp, sys.argv[2])


if __name__ == "__main__":
    main()
