#!/usr/bin/env python3
"""Issue 32, item 1, on the real-world meshes of resources/realworld: with the default options of
`fcvt remesh IN OUT.ply --vertices N`, at N = max(500, V/4) and N = max(300, V/8) (V: the input's
vertices as `fcvt metrics` reads them), no zero-area face on every run; no angle under 15 degrees and
at most 0.5 % of the triangles with an angle under 30 degrees (`fcvt metrics OUT --json`), borders
included, on every run whose shells the restricted Delaunay triangulation kept, and on at least
14 of the 18 runs (issue 52: a shell remeshed by local operations is counted, not held to
the two bars each).

  check_realworld_triangles.py FCVT REALWORLD_DIR WORKDIR NAME...
"""
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cli"))
from fcvt_check import check, finish, metrics_json, read_ply, run_ok  # noqa: E402


def zero_area_faces(vertices, faces):
    count = 0
    for a, b, c in faces:
        p, q, r = vertices[a], vertices[b], vertices[c]
        u = [q[i] - p[i] for i in range(3)]
        w = [r[i] - p[i] for i in range(3)]
        cross = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
        count += all(x == 0.0 for x in cross)
    return count


def main():
    fcvt, directory, work, names = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    os.makedirs(work, exist_ok=True)
    held = 0  # runs held to the bars
    for name in names:
        path = os.path.join(directory, name)
        table = dict(line.split(None, 1) for line in run_ok([fcvt, "metrics", path]).splitlines() if line.strip())
        v = int(table["vertices"])
        for divisor, floor in ((4, 500), (8, 300)):
            n = max(floor, v // divisor)
            out = os.path.join(work, f"{name}.{n}.ply")
            report = out + ".json"
            run_ok([fcvt, "remesh", path, out, "--vertices", str(n), "--quiet", "--report", report])
            local = json.load(open(report))["local_shells"]["shells"]
            m = metrics_json(fcvt, out)
            zero = zero_area_faces(*read_ply(out))
            label = f"{name} at {n} vertices"
            print(f"{label}: theta_min {m['theta_min']:.2f}, {m['pct_lt30']:.2f} % under 30, {zero} zero-area faces, "
                  f"{local} shells remeshed by local operations")
            check(zero == 0, f"{label}: {zero} zero-area faces")
            meets = m["theta_min"] >= 15 and m["pct_lt30"] <= 0.5
            if local:
                # Issue 52 item 4, not met everywhere yet: a shell remeshed by local operations
                # keeps the bars where the strip sizing resolves its creases (tray_bottom's rims,
                # greek_helmet, casting), on many_small_holes and, its border spikes cut, on
                # lato180; not yet on adis16480's steps under an eighth of the edge. Counted
                # here, tracked in docs/measurements.md; the bars hold wherever the
                # triangulation kept it.
                held += meets
                continue
            held += 1
            check(m["theta_min"] >= 15, f"{label}: smallest angle {m['theta_min']:.2f} < 15 degrees")
            check(m["pct_lt30"] <= 0.5, f"{label}: {m['pct_lt30']:.2f} % of the triangles under 30 degrees (> 0.5 %)")
    # 16 of the 18 runs meet the bars today (7 kept by the triangulation, 9 of the 11 with local
    # shells): fewer means a run lost them, which this test must not let pass unseen.
    check(held >= 16 * len(names) // 9, f"only {held} runs meet the bars (at least {16 * len(names) // 9})")
    finish()


if __name__ == "__main__":
    main()
