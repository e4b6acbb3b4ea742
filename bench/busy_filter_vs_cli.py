"""The MeshLab filter against the CLI on a busy machine (issue 38 item 2): the same remeshing
(resources/bunny.ply, 5000 vertices, the filter's defaults) with 0, 1 and 2 busy loops beside it,
the filter in meshlabserver (the staged plugin, under xvfb-run) and the CLI's `fcvt remesh`, one
after the other, medians of --repeat runs. Times are the remeshing itself, the same sum for both:
the stages of the filter's log line ("FCVT times (N threads): prepare T s, ...") and the same
stages of the CLI's report (read and write left out), so that MeshLab's start-up and file I/O
are not counted.

  python3 bench/busy_filter_vs_cli.py BUILD_DIR [--repeat 3] [--busy 0 1 2]
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import time

here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(here, "bench"))
from filter_vs_cli import staged_meshlabserver  # noqa: E402
a = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
a.add_argument("build")
a.add_argument("--repeat", type=int, default=3)
a.add_argument("--busy", type=int, nargs="+", default=[0, 1, 2])
a.add_argument("--vertices", type=int, default=5000)
a.add_argument("--runs", action="store_true", help="also print every run's times")
args = a.parse_args()
fcvt, server, work = staged_meshlabserver(args.build, "fcvt-busy-")
source = os.path.join(here, "resources", "bunny.ply")
mlx = os.path.join(work, "remesh.mlx")
with open(os.path.join(here, "resources", "fcvt-remesh.mlx")) as fh:
    text = re.sub(r'(name="vertexCount"[^>]*value=")[^"]*"', r'\g<1>%d"' % args.vertices, fh.read())
with open(mlx, "w") as fh:
    fh.write(text)
env = {k: v for k, v in os.environ.items() if "OMP" not in k}


def cli_run():
    report = os.path.join(work, "cli.json")
    subprocess.run([fcvt, "remesh", source, os.path.join(work, "cli.ply"), "--vertices", str(args.vertices), "--quiet",
                    "--report", report], check=True, env=env, stderr=subprocess.DEVNULL)
    r = json.load(open(report))
    return sum(v for k, v in r["time_s"].items() if k not in ("read", "write", "total")), r["threads_used"]


def stage_sum(line):
    """The sum of the stage times of the filter's "FCVT times" line (its total left out)."""
    return sum(float(t) for name, t in re.findall(r"(\w+) ([0-9.e+-]+) s", line) if name != "total")


def filter_run():
    p = subprocess.run(["xvfb-run", "-a", server, "-i", source, "-o", os.path.join(work, "filter.ply"), "-s", mlx],
                       env=env, capture_output=True, text=True)
    m = re.search(r"FCVT times \((\d+) threads?\):(.*)$", p.stdout, re.M)
    if p.returncode != 0 or not m:
        sys.exit("meshlabserver failed:\n" + p.stderr[-2000:])
    time.sleep(0.5)  # xvfb-run stops its X server without waiting: not a task beside the next run
    return stage_sum(m.group(2)), int(m.group(1))


print(f"# bunny.ply -> {args.vertices} vertices, {len(os.sched_getaffinity(0))} cores, medians of {args.repeat}")
print("| busy loops | CLI s | filter s | filter / CLI | threads CLI / filter |")
print("|---|---|---|---|---|")
for k in args.busy:
    loops = [subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range(k)]
    try:
        time.sleep(0.3)
        cli, filt = [], []
        for _ in range(args.repeat):  # alternating
            cli.append(cli_run())
            filt.append(filter_run())
    finally:
        for p in loops:
            p.kill()
            p.wait()
    c, f = statistics.median(t for t, _ in cli), statistics.median(t for t, _ in filt)
    if args.runs:
        print(f"# {k} busy: CLI " + " ".join(f"{t:.2f}" for t, _ in cli) + ", filter " + " ".join(f"{t:.2f}" for t, _ in filt))
    threads = lambda runs: ",".join(sorted({str(n) for _, n in runs}))
    print(f"| {k} | {c:.2f} | {f:.2f} | {f / c:.2f} | {threads(cli)} / {threads(filt)} |")
