"""What a run pays besides the optimisation (issue 54 item 2), per stage, for each preset and,
with --baseline, for another build in the same rounds.

For each row and each (build, preset): --repeat alternating rounds of
  fcvt remesh IN OUT.ply --vertices N --threads T --quiet            (the whole command, timed)
  fcvt remesh IN OUT.ply --vertices N --threads T --quiet --report R  (the stage times of R)
The report's run also measures d_RMS / d_H ("metrics" grows by that; the quiet command has no
report and skips them), so the whole-command line is the quiet run's. "start" is a process that
only prints its version (`fcvt --version`): what starting the program costs. Medians; the
optimisation is lloyd + cvt + features + fcvt, everything else is the fixed cost.

  python3 bench/fixed_costs.py BUILD/cli/fcvt [--baseline OLD/cli/fcvt] [--presets default,fast]
                               [--threads 2] [--repeat 5] [MESH:N ...]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from side_by_side import SHARED, timed  # noqa: E402

OPTIMISATION = ("lloyd", "cvt", "features", "fcvt")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("fcvt")
    ap.add_argument("rows", nargs="*", default=["torus.obj:1000", "bunny.obj:5000"])
    ap.add_argument("--baseline", help="another build's fcvt, run in the same rounds (its default schedule)")
    ap.add_argument("--presets", default="default,fast")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--repeat", type=int, default=5)
    a = ap.parse_intermixed_args()
    runs = [("baseline", a.baseline, None)] if a.baseline else []
    runs += [(p, a.fcvt, p) for p in a.presets.split(",")]
    print(f"# fixed costs: {a.threads} threads, medians of {a.repeat} alternating rounds, seconds")
    with tempfile.TemporaryDirectory() as work:
        for spec in a.rows:
            path, n = spec.rsplit(":", 1)
            if not os.path.exists(path):
                path = os.path.join(SHARED, "meshes", path)
            stages = {name: {} for name, _, _ in runs}
            whole = {name: [] for name, _, _ in runs}
            start = {name: [] for name, _, _ in runs}
            for _ in range(a.repeat):
                for name, exe, preset in runs:
                    base = [exe, "remesh", path, os.path.join(work, "out.ply"), "--vertices", n, "--threads",
                            str(a.threads), "--quiet"] + (["--preset", preset] if preset else [])
                    start[name].append(timed([exe, "--version"])[0])
                    whole[name].append(timed(base)[0])
                    report = os.path.join(work, "r.json")
                    timed(base + ["--report", report])
                    with open(report) as fh:
                        for stage, seconds in json.load(fh)["time_s"].items():
                            stages[name].setdefault(stage, []).append(seconds)
            names = [name for name, _, _ in runs]
            print(f"\n{os.path.basename(path)} {n}\n")
            print("| stage | " + " | ".join(names) + " |")
            print("|---|" + "---|" * len(names))
            order = [s for s in stages[names[-1]] if s != "total"]
            for s in order + [k for k in stages[names[0]] if k not in order and k != "total"]:
                cells = [f"{statistics.median(stages[nm][s]):.3f}" if s in stages[nm] else "-" for nm in names]
                print(f"| {s}{' (optimisation)' if s in OPTIMISATION else ''} | " + " | ".join(cells) + " |")
            fixed = []
            for nm in names:
                med = {s: statistics.median(v) for s, v in stages[nm].items()}
                fixed.append(sum(v for s, v in med.items() if s not in OPTIMISATION and s not in ("total", "metrics")))
            print("| fixed (all but optimisation and metrics) | " + " | ".join(f"{f:.3f}" for f in fixed) + " |")
            print("| start (`fcvt --version`) | " + " | ".join(f"{statistics.median(start[nm]):.3f}" for nm in names) + " |")
            print("| whole command (quiet, no report) | " + " | ".join(f"{statistics.median(whole[nm]):.3f}" for nm in names)
                  + " |", flush=True)


if __name__ == "__main__":
    main()
