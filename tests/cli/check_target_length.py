"""`fcvt remesh --target-length L`: the vertex count comes from the surface area, and the output's
mean edge length (reported as mean_edge_length, and measured here from the PLY) is within 15 % of
L; --vertices and --target-length together, or neither, is a usage error.
Usage: check_target_length.py FCVT INPUT LENGTH WORKDIR"""
import json
import math
import os
import sys

from fcvt_check import check, finish, read_ply, run, run_ok

fcvt, source, length, work = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4]
os.makedirs(work, exist_ok=True)
out, report = os.path.join(work, "out.ply"), os.path.join(work, "report.json")
run_ok([fcvt, "remesh", source, out, "--target-length", str(length), "--quiet", "--report", report])
with open(report) as f:
    r = json.load(f)
reported = r.get("mean_edge_length")
check(reported is not None and abs(reported - length) <= 0.15 * length,
      f"reported mean_edge_length {reported}, target {length}")

vertices, faces = read_ply(out)[:2]
edges = {tuple(sorted((f[k], f[(k + 1) % 3]))) for f in faces for k in range(3)}
measured = sum(math.dist(vertices[a], vertices[b]) for a, b in edges) / len(edges)
print(f"{len(vertices)} vertices, mean edge {measured:.5g} (reported {reported}, target {length})")
check(abs(measured - length) <= 0.15 * length, f"measured mean edge length {measured}, target {length}")
check(reported is not None and abs(measured - reported) <= 1e-6 * length,
      f"measured {measured} != reported {reported}")

for args in (["--vertices", "100", "--target-length", str(length)], []):
    code, _, err = run([fcvt, "remesh", source, os.path.join(work, "bad.ply")] + args)
    check(code == 2 and "exactly one of --vertices" in err, f"{args}: exit {code}, stderr {err!r}")
code, _, err = run([fcvt, "remesh", source, os.path.join(work, "bad.ply"), "--target-length", "-1"])
check(code == 2 and "--target-length" in err, f"negative length: exit {code}, stderr {err!r}")
finish()
