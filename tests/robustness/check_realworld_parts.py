#!/usr/bin/env python3
"""Issue 32, item 3, where it holds today: with the default options, `fcvt remesh IN OUT.ply
--vertices N` keeps every part of the input (a component with at least 0.5 % of its area) whole:
every point of it within 2 of the output's edge lengths of the output (`part_gap` of `fcvt
metrics OUT --ref IN`, exact closest points from samples every half edge length) and no part in
more than one output piece (`part_pieces`). Smaller components that the output lacks (farther
than 2 edge lengths) must have been dropped with the repair's one warning giving their number and
area.

  check_realworld_parts.py FCVT REALWORLD_DIR WORKDIR NAME:N ...
"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cli"))
from fcvt_check import check, finish, metrics_json  # noqa: E402


def main():
    fcvt, directory, work, cases = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    os.makedirs(work, exist_ok=True)
    for case in cases:
        name, n = case.rsplit(":", 1)
        path = os.path.join(directory, name)
        out = os.path.join(work, f"{name}.{n}.ply")
        run = subprocess.run([fcvt, "remesh", path, out, "--vertices", n], capture_output=True, text=True, timeout=300)
        label = f"{name} at {n} vertices"
        if not check(run.returncode == 0, f"{label}: exit {run.returncode}: {run.stderr.strip()[-300:]}"):
            continue
        m = metrics_json(fcvt, out, ref=path)
        print(f"{label}: {m['parts']} parts, largest gap {m['part_gap']:.2f} edge lengths, at most "
              f"{m['part_pieces']} pieces; {m['small_parts']} small components ({m['small_parts_area_pct']:.2f} % of "
              f"the area), the farthest {m['small_parts_gap']:.1f} edge lengths away")
        check(m["parts"] >= 1, f"{label}: no part over 0.5 % of the area (the case tests nothing)")
        check(m["part_gap"] is not None and m["part_gap"] <= 2.0, f"{label}: a part is {m['part_gap']} edge lengths away")
        check(m["part_pieces"] <= 1, f"{label}: a part came back in {m['part_pieces']} pieces")
        if m["small_parts"] > 0 and m["small_parts_gap"] > 2.0:
            warned = [line for line in run.stderr.splitlines() if "connected components too small" in line and
                      "dropped" in line and "area" in line]
            check(len(warned) == 1, f"{label}: small components missing from the output without one warning")
    finish()


if __name__ == "__main__":
    main()
