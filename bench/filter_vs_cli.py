"""The MeshLab filter against the CLI (issue 35 item 2): the filter's wall time inside MeshLab at
most 1.1 times the CLI's remeshing stages, on the rows of bench/side_by_side.py (../shared/meshes).

Both remesh the same mesh (a PLY copy made by `fcvt convert`) with the same parameters (the filter's defaults; resources/fcvt-remesh.mlx
with the row's vertex count, and `fcvt remesh IN OUT --vertices N` at the filter's thread count).
The filter's time is its own log line, "FCVT filter time: T s from the layer to the new layer":
everything it does inside MeshLab (the layer to the core's mesh, the core, the new layer, the
data carried over, the log), MeshLab's start-up and file I/O left out. The CLI's time is the sum of
its report's stages without `read` and `write`. Medians of --repeat alternating rounds; the
filter runs in meshlabserver with the staged plugin, under xvfb-run.

  python3 bench/filter_vs_cli.py BUILD_DIR [--repeat 5] [MESH:N ...]
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from side_by_side import DEFAULT_ROWS, SHARED  # noqa: E402


def staged_meshlabserver(build, prefix):
    """The build's fcvt, a meshlabserver staged with the build's plugin, and the work folder."""
    fcvt = os.path.join(build, "cli", "fcvt")
    plugin = os.path.join(build, "filter_fcvt", "libfilter_fcvt.so")
    work = tempfile.mkdtemp(prefix=prefix)
    subprocess.run(["bash", os.path.join(ROOT, "scripts", "stage-meshlab.sh"), os.path.join(work, "stage"), plugin],
                   check=True, stdout=subprocess.DEVNULL)
    return fcvt, os.path.join(work, "stage", "bin", "meshlabserver"), work


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("build")
    ap.add_argument("rows", nargs="*", help="MESH:N (a bare name is looked up in ../shared/meshes)")
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--runs", action="store_true", help="also print every run's times")
    a = ap.parse_args()
    fcvt, server, work = staged_meshlabserver(a.build, "fcvt-filter-cli-")
    with open(os.path.join(ROOT, "resources", "fcvt-remesh.mlx")) as fh:
        script = fh.read()
    env = {k: v for k, v in os.environ.items() if "OMP" not in k}

    def filter_run(source, n):
        mlx = os.path.join(work, f"remesh{n}.mlx")
        with open(mlx, "w") as fh:
            fh.write(re.sub(r'(name="vertexCount"[^>]*value=")[^"]*"', r'\g<1>%d"' % n, script))
        p = subprocess.run(["xvfb-run", "-a", server, "-i", source, "-o", os.path.join(work, "filter.ply"), "-s", mlx],
                           env=env, capture_output=True, text=True)
        wall = re.search(r"FCVT filter time: ([0-9.e+-]+) s", p.stdout)
        threads = re.search(r"FCVT times \((\d+) threads?\)", p.stdout)
        if p.returncode != 0 or not wall or not threads:
            sys.exit(f"meshlabserver failed on {source}:\n" + p.stdout[-1500:] + p.stderr[-1500:])
        time.sleep(0.5)  # xvfb-run stops its X server without waiting: not a task beside the next run
        return float(wall.group(1)), int(threads.group(1))

    def cli_run(source, n, threads):
        report = os.path.join(work, "cli.json")
        subprocess.run([fcvt, "remesh", source, os.path.join(work, "cli.ply"), "--vertices", str(n), "--quiet",
                        "--threads", str(threads), "--report", report], check=True, env=env, stderr=subprocess.DEVNULL)
        r = json.load(open(report))
        return sum(v for k, v in r["time_s"].items() if k not in ("read", "write", "total"))

    print(f"# filter (meshlabserver, staged plugin) against `fcvt remesh`, {len(os.sched_getaffinity(0))} cores, "
          f"medians of {a.repeat} alternating rounds")
    print("| mesh, N | threads | CLI stages s | filter s | filter / CLI |")
    print("|---|---|---|---|---|")
    ratios = []
    for row in a.rows or DEFAULT_ROWS:
        name, n = row.rsplit(":", 1)
        original = name if os.path.sep in name else os.path.join(SHARED, "meshes", name)
        # One PLY copy for both (MeshLab 2020.09's OBJ reader asserts on some of the shared OBJs).
        source = os.path.join(work, os.path.splitext(os.path.basename(name))[0] + ".ply")
        subprocess.run([fcvt, "convert", original, source], check=True, stdout=subprocess.DEVNULL)
        filt, cli = [], []
        for _ in range(a.repeat):
            wall, threads = filter_run(source, int(n))
            filt.append(wall)
            cli.append(cli_run(source, int(n), threads))
        f, c = statistics.median(filt), statistics.median(cli)
        ratios.append(f / c)
        if a.runs:
            print(f"# {row}: filter " + " ".join(f"{t:.3f}" for t in filt) + ", CLI " + " ".join(f"{t:.3f}" for t in cli))
        print(f"| {os.path.basename(name)} {n} | {threads} | {c:.3f} | {f:.3f} | {f / c:.2f} |")
    print(f"\nfilter / CLI: max {max(ratios):.2f}, geometric mean "
          f"{statistics.geometric_mean(ratios):.2f} over {len(ratios)} rows")


if __name__ == "__main__":
    main()
