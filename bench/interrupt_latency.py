#!/usr/bin/env python3
"""How soon an interrupted run stops: the seconds from Ctrl-C (SIGINT) or SIGTERM to the exit of
`radiosity solve` on the Cornell box, in the form-factor pass (Gauss-Seidel: all rows up front) and
in progressive shooting. The robustness tests check what an interrupt does (exit 128 + signal, the
message, nothing left behind); this measures how long it takes, which a test on a loaded machine
cannot assert.

    python3 bench/interrupt_latency.py [--binary build/bin/radiosity] [--repeats 5]

Prints one line per case with the median and the largest latency over the repeats, and the
exit codes seen.
"""
import argparse
import os
import signal
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CASES = [
    ("sigint_form_factors", signal.SIGINT, 0.5,
     ["--elements", "20000", "--solver", "gauss-seidel", "--quiet"]),
    ("sigterm_form_factors", signal.SIGTERM, 0.5,
     ["--elements", "20000", "--solver", "gauss-seidel", "--quiet"]),
    ("sigint_shooting", signal.SIGINT, 1.0,
     ["--elements", "20000", "--tolerance", "0", "--max-iterations", "2000000000", "--quiet"]),
]


def catches(pid, sig):
    """Whether the process has installed a handler for `sig` (SigCgt in /proc/PID/status)."""
    try:
        with open(f"/proc/{pid}/status") as status:
            for line in status:
                if line.startswith("SigCgt:"):
                    return (int(line.split()[1], 16) >> (sig - 1)) & 1 == 1
    except FileNotFoundError:
        return False
    return False


def one_run(binary, sig, after, args):
    with tempfile.TemporaryDirectory() as scratch:
        out = os.path.join(scratch, "out")
        scene = os.path.join(ROOT, "data/cornell_box/cornell_box.obj")
        child = subprocess.Popen([binary, "solve", scene, "--out", out] + args,
                                 stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        deadline = time.monotonic() + 30
        while not catches(child.pid, sig) and time.monotonic() < deadline:
            time.sleep(0.01)
        time.sleep(after)
        if child.poll() is not None:
            sys.exit("interrupt_latency: the run ended before the signal; make it longer")
        sent = time.monotonic()
        child.send_signal(sig)
        code = child.wait(timeout=60)
        return time.monotonic() - sent, code


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--binary", default=os.path.join(ROOT, "build/bin/radiosity"))
    parser.add_argument("--repeats", type=int, default=5)
    options = parser.parse_args()
    if options.repeats < 1:
        parser.error("--repeats must be at least 1")
    if not os.access(options.binary, os.X_OK):
        parser.error(f"{options.binary}: not an executable (build first: bash scripts/build.sh)")
    # Interleaved: each repeat runs every case once, so a change of load touches them alike.
    latencies = {name: [] for name, *_ in CASES}
    codes = {name: set() for name, *_ in CASES}
    for _ in range(options.repeats):
        for name, sig, after, args in CASES:
            seconds, code = one_run(options.binary, sig, after, args)
            latencies[name].append(seconds)
            codes[name].add(code)
    for name, *_ in CASES:
        values = latencies[name]
        print(f"{name}: median {statistics.median(values):.3f} s, max {max(values):.3f} s "
              f"over {len(values)} runs, exit codes {sorted(codes[name])}")


if __name__ == "__main__":
    main()
