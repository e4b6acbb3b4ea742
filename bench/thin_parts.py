"""Issue 32 item 2: how often the thin parts' passes bring a closed part's topology back.
For each case and seed, `fcvt remesh IN OUT.ply --vertices N --seed S --report R.json` (and the
same with --exact-count): the topology distance |Δgenus| + |Δboundary loops| + |Δcomponents|
from the input, the output's vertices and smallest angle; then the runs recovered and the sums.

  python3 bench/thin_parts.py BUILD/cli/fcvt [--seeds 1 2 3 4]

Cases: casting.off, tray_bottom.stl, adis16480.stl of ../shared/realworld at N = V/4 and V/8,
and a generated ring (tube radius 0.25) with a neck 0.06 across at 150 and 200 vertices.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

SHARED = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared")
CASES = [("casting.off", 1274), ("casting.off", 637), ("tray_bottom.stl", 554), ("tray_bottom.stl", 300),
         ("adis16480.stl", 918), ("adis16480.stl", 459), ("neck", 150), ("neck", 200)]


def write_necked_ring(path, n=240, m=16, thick=0.25, neck=0.03):
    with open(path, "w") as out:
        for i in range(n):
            for j in range(m):
                u, v = 2 * math.pi * i / n, 2 * math.pi * j / m
                d = abs(math.remainder(u, 2 * math.pi))
                r = thick if d > 0.6 else neck + (thick - neck) * (d / 0.6) ** 2
                out.write("v %.9f %.9f %.9f\n" % ((1 + r * math.cos(v)) * math.cos(u), (1 + r * math.cos(v)) * math.sin(u),
                                                  r * math.sin(v)))
        for i in range(n):
            for j in range(m):
                a, b = i * m + j, ((i + 1) % n) * m + j
                c, d = ((i + 1) % n) * m + (j + 1) % m, i * m + (j + 1) % m
                out.write("f %d %d %d\nf %d %d %d\n" % (a + 1, b + 1, c + 1, a + 1, c + 1, d + 1))


def run(fcvt, path, n, seed, work, extra):
    out, report = os.path.join(work, "out.ply"), os.path.join(work, "r.json")
    subprocess.run([fcvt, "remesh", path, out, "--vertices", str(n), "--seed", str(seed), "--quiet", "--report", report,
                    *extra], check=True, capture_output=True)
    r = json.load(open(report))
    i, o = r["input"], r["output"]
    distance = sum(abs(i[k] - o[k]) for k in ("genus", "boundary_loops", "components"))
    return distance, r["vertices"], r["metrics"]["theta_min"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("fcvt")
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3, 4])
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        ring = os.path.join(work, "neck.obj")
        write_necked_ring(ring)
        print("| input, N | default: distance / vertices / θ_min per seed | --exact-count: the same |")
        print("|---|---|---|")
        totals = {"": [0, 0, 0], "--exact-count": [0, 0, 0]}
        for name, n in CASES:
            path = ring if name == "neck" else os.path.join(SHARED, "realworld", name)
            cells = []
            for mode in ("", "--exact-count"):
                runs = [run(args.fcvt, path, n, s, work, [mode] if mode else []) for s in args.seeds]
                cells.append(", ".join("%d / %d / %.0f" % r for r in runs))
                t = totals[mode]
                t[0] += sum(r[0] == 0 for r in runs)
                t[1] += sum(r[0] for r in runs)
                t[2] += sum(r[1] for r in runs)
            print("| %s, %d | %s | %s |" % (name, n, cells[0], cells[1]))
            sys.stdout.flush()
        runs = len(CASES) * len(args.seeds)
        for mode, (recovered, distance, vertices) in totals.items():
            print("%s: %d of %d runs recovered, distances %d, vertices %d" % (mode or "default", recovered, runs, distance,
                                                                               vertices))


if __name__ == "__main__":
    main()
