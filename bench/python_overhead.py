#!/usr/bin/env python3
"""What `import fcvt` adds over the core (issue 53 item 4): bunny at 5000 vertices, medians of 5.

The module's time is the wall time of fcvt.remesh(V, F, vertices=N) (arrays in, the core, the
report, arrays out); the core's is the sum of the stage times of `fcvt remesh IN OUT --vertices N
--report R` (time_s without read, write and total), the same run in the CLI. Prints one line:
module / core - 1 in per cent (the goal: at most 5 %).

Usage: PYTHONPATH=BUILD/python python3 bench/python_overhead.py BUILD/cli/fcvt [MESH] [--vertices N] [--runs K]
"""
import argparse
import json
import os
import statistics
import subprocess
import tempfile
import time
import warnings

import fcvt


def core_seconds(cli, mesh, vertices, tmp):
    report = os.path.join(tmp, "r.json")
    subprocess.run([cli, "remesh", mesh, os.path.join(tmp, "o.ply"), "--vertices", str(vertices), "--report", report,
                    "--quiet"], check=True, capture_output=True)
    with open(report) as f:
        times = json.load(f)["time_s"]
    return sum(v for k, v in times.items() if k not in ("read", "write", "total"))


def module_seconds(V, F, vertices):
    start = time.perf_counter()
    fcvt.remesh(V, F, vertices=vertices)
    return time.perf_counter() - start


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("cli")
    parser.add_argument("mesh", nargs="?", default=os.path.join(here, "..", "resources", "bunny.ply"))
    parser.add_argument("--vertices", type=int, default=5000)
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args()
    warnings.simplefilter("ignore", UserWarning)
    V, F = fcvt.read(args.mesh)
    module, core = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(args.runs):  # interleaved, so that a slow spell of the machine hits both
            core.append(core_seconds(args.cli, args.mesh, args.vertices, tmp))
            module.append(module_seconds(V, F, args.vertices))
    m, c = statistics.median(module), statistics.median(core)
    print(f"{os.path.basename(args.mesh)} at {args.vertices} vertices, medians of {args.runs}: module {m:.3f} s, "
          f"core (CLI stages) {c:.3f} s: module / core = {m / c:.3f} ({100 * (m / c - 1):+.1f} %)")


if __name__ == "__main__":
    main()
