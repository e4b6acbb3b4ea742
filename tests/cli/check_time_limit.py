"""`fcvt remesh --time-limit SEC`: a run that would take far longer ends soon after SEC seconds,
exits 0 with a manifold output, and its report warns that the time limit was reached.
Usage: check_time_limit.py FCVT INPUT WORKDIR"""
import json
import os
import sys

from fcvt_check import check, finish, run_ok

fcvt, source, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
out, report = os.path.join(work, "out.ply"), os.path.join(work, "report.json")
run_ok([fcvt, "remesh", source, out, "--vertices", "2000", "--cvt-iterations", "100000", "--time-limit", "1",
        "--quiet", "--report", report])
with open(report) as f:
    r = json.load(f)
check(any("time limit of 1 s reached" in w for w in r["warnings"]), f"no time-limit warning in {r['warnings']}")
check(r["output"]["manifold"], "output not manifold")
check(r["evaluations"] < 100000, f"{r['evaluations']} evaluations")
optimisation = sum(r["time_s"].get(k, 0) for k in ("lloyd", "cvt", "fcvt"))
check(optimisation < 10, f"optimisation took {optimisation} s despite the 1 s limit")
finish()
