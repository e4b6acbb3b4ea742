#!/usr/bin/env python3
"""Issue 32, item 2, where it holds today: with the default options, `fcvt remesh IN OUT.ply
--vertices N` on a closed CAD part whose thin walls and narrow holes tear its RDT at N brings the
shell back closed with its genus, with vertices added there (at most 2 N in all), a warning and the
report's thin_parts saying how many; --exact-count keeps N and the torn shell.

  check_realworld_topology.py FCVT REALWORLD_DIR WORKDIR NAME:N ...
"""
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cli"))
from fcvt_check import check, finish  # noqa: E402


def remesh(fcvt, path, out, n, *extra):
    report = out + ".json"
    run = subprocess.run([fcvt, "remesh", path, out, "--vertices", str(n), "--report", report, *extra],
                         capture_output=True, text=True, timeout=300)
    check(run.returncode == 0, f"{path} at {n}: exit {run.returncode}: {run.stderr.strip()[-300:]}")
    return json.load(open(report)), run.stderr


def main():
    fcvt, directory, work, cases = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    os.makedirs(work, exist_ok=True)
    for case in cases:
        name, n = case.rsplit(":", 1)
        n = int(n)
        path = os.path.join(directory, name)
        r, stderr = remesh(fcvt, path, os.path.join(work, f"{name}.{n}.ply"), n)
        i, o, thin = r["input"], r["output"], r["thin_parts"]
        label = f"{name} at {n} vertices"
        print(f"{label}: {r['vertices']} vertices ({thin['added_vertices']} added), genus {o['genus']}/{i['genus']}, "
              f"{o['boundary_loops']} loops, {o['components']} components")
        check(i["boundary_loops"] == 0 and i["components"] == 1, f"{label}: the input is not one closed shell")
        check((o["genus"], o["boundary_loops"], o["components"]) == (i["genus"], 0, 1) and o["manifold"],
              f"{label}: output genus {o['genus']}, {o['boundary_loops']} loops, {o['components']} components")
        check(r["vertices"] <= 2 * n, f"{label}: {r['vertices']} vertices > 2 N")
        check(thin["added_vertices"] > 0 and "vertices added where the surface is thinner" in stderr,
              f"{label}: no vertices added, or no warning")
        check("topology not recovered" not in stderr, f"{label}: still warns that the topology was not recovered")
        exact, _ = remesh(fcvt, path, os.path.join(work, f"{name}.{n}.exact.ply"), n, "--exact-count")
        check(exact["thin_parts"]["added_vertices"] == 0, f"{label}, --exact-count: vertices added")
        check(exact["output"]["boundary_loops"] > 0 or exact["output"]["genus"] != i["genus"],
              f"{label}, --exact-count: the shell is whole at N already (the case tests nothing)")
    finish()


if __name__ == "__main__":
    main()
