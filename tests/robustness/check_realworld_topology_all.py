#!/usr/bin/env python3
"""Issue 52 ("topology first"), items 1-2, on the real-world meshes of resources/realworld: with
the default options, `fcvt remesh IN OUT.ply --vertices N` at N = max(500, V/4) and
N = max(300, V/8) (V: the input's vertices, as `fcvt metrics IN` counts them) brings back every
part of the input (a connected component with 0.5 % of its area or more, its non-manifold
vertices split one per fan as the repair does) as exactly one output shell, with the part's genus
(where the part is manifold and oriented) and its boundary loops, and merges no two parts
(topology_classes.compare). The input's cracks that the repair welds (its report's
welded_vertices, within its weld_distance) are welded first: they are no holes. Holes FCVT closes by design (under 2 edge lengths across; the report
or its warning counts them) may be missing from the loops, no more. The output is manifold.
Companion of check_realworld_topology.py (issue 32's thin parts, where they hold already).
`--options "..."` first adds those options to every run: `--feature-angle 45` (item 5, what a
CAD user turns on). `--triangles K` also asks issue 32's triangle bars (item 4: no angle under 15
degrees, at most 0.5 % of the triangles with an angle under 30, `fcvt metrics OUT --json`) on at
least K of the runs, and prints each run's figures.

  check_realworld_topology_all.py FCVT REALWORLD_DIR WORKDIR [--options "OPT ..."] [--triangles K]
                                  NAME[:N[,N...]] ...
"""
import json
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "cli"))
import topology_classes as tc  # noqa: E402
from fcvt_check import check, finish, read_ply  # noqa: E402


def budgets(fcvt, path):
    """N = max(500, V/4) and max(300, V/8), V the input's vertices as fcvt metrics counts them."""
    text = subprocess.run([fcvt, "metrics", path], capture_output=True, text=True, check=True).stdout
    v = next(int(line.split()[1]) for line in text.splitlines() if line.split()[:1] == ["vertices"])
    return v, [max(500, v // 4), max(300, v // 8)]


def main():
    fcvt, directory, work, cases = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    options = []
    if cases[:1] == ["--options"]:
        options, cases = cases[1].split(), cases[2:]
    triangles = None  # runs that must meet the triangle bars
    if cases[:1] == ["--triangles"]:
        triangles, cases = int(cases[1]), cases[2:]
    runs = held = 0
    os.makedirs(work, exist_ok=True)
    for case in cases:
        name, _, given = case.partition(":")
        path = os.path.join(directory, name)
        v, ns = budgets(fcvt, path)
        if given:
            ns = [int(x) for x in given.split(",")]
        inp = tc.read_mesh(path)
        for n in ns:
            label = f"{name} at {n} vertices (V = {v})" + "".join(" " + o for o in options)
            out = os.path.join(work, f"{name}.{n}.ply")
            report = out + ".json"
            start = time.perf_counter()
            run = subprocess.run([fcvt, "remesh", path, out, "--vertices", str(n), "--report", report] + options,
                                 capture_output=True, text=True, timeout=600)
            seconds = time.perf_counter() - start
            if not check(run.returncode == 0, f"{label}: exit {run.returncode}: {run.stderr.strip()[-300:]}"):
                continue
            r = json.load(open(report))
            closed = tc.holes_closed(r, run.stderr)
            repair = r.get("repair") or {}
            weld = repair.get("weld_distance", 0.0) if repair.get("welded_vertices", 0) > 0 else 0.0
            result = tc.compare(inp, read_ply(out), closed, weld_distance=weld)
            i_loops, i_pieces, i_genus = tc.summary([result["in_shells"][k] for k in result["parts"]])
            o_loops, o_pieces, o_genus = tc.summary(result["out_shells"])
            print(f"{label}: {r['vertices']} vertices; parts {len(result['parts'])} of {len(result['in_shells'])} "
                  f"shells (loops {i_loops}, genus {i_genus}); output {o_pieces} shells, loops {o_loops}, genus "
                  f"{o_genus}; {closed} holes closed by design; {len(result['problems'])} problems; {seconds:.1f} s",
                  flush=True)
            for problem in result["problems"][:6]:
                check(False, f"{label}: {problem}")
            if len(result["problems"]) > 6:
                check(False, f"{label}: ... and {len(result['problems']) - 6} more topology problems")
            check(r["output"]["manifold"], f"{label}: the output is not manifold")
            if triangles is not None:
                m = json.loads(subprocess.run([fcvt, "metrics", out, "--json"], capture_output=True, text=True,
                                              check=True).stdout)
                meets = m["theta_min"] >= 15 and m["pct_lt30"] <= 0.5
                runs, held = runs + 1, held + meets
                print(f"{label}: theta_min {m['theta_min']:.1f}, {m['pct_lt30']:.2f} % under 30: "
                      f"{'meets' if meets else 'misses'} the triangle bars", flush=True)
    if triangles is not None:
        print(f"triangle bars met on {held} of {runs} runs (asked: {triangles})")
        check(held >= triangles, f"the triangle bars hold on {held} of {runs} runs, fewer than {triangles}")
    finish()


if __name__ == "__main__":
    main()
