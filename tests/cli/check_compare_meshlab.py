"""`fcvt compare` with MeshLab's built-in isotropic remeshing: a "meshlab-isotropic" row when a
meshlabserver runs (its vertex count within 10 % of N, every metric measured), none with
--no-meshlab, a usage error for a --meshlabserver that is not executable, and a warning but no row
(exit 0) when meshlabserver fails. Usage: check_compare_meshlab.py FCVT MESHLABSERVER INPUT VERTICES"""
import json
import sys

from fcvt_check import METRIC_KEYS, check, finish, run, run_ok

fcvt, server, source, vertices = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
base = [fcvt, "compare", source, "--vertices", str(vertices), "--json", "--quiet"]

rows = json.loads(run_ok(base + ["--meshlabserver", server, "--meshlab-iterations", "5"]))
methods = [r.get("method") for r in rows]
check(methods == ["CVT", "FCVT", "meshlab-isotropic"], f"methods {methods}")
if len(rows) == 3:
    ml = rows[2]
    # (d_boundary and boundary_v4_pct are null on a closed mesh)
    for key in ["vertices", "faces", "seconds", "target_length"] + [k for k in METRIC_KEYS if "boundary" not in k]:
        check(isinstance(ml.get(key), (int, float)), f"meshlab-isotropic: {key} = {ml.get(key)!r}")
    check(abs(ml["vertices"] - vertices) <= 0.1 * vertices, f"meshlab-isotropic has {ml['vertices']} vertices for {vertices}")
    check(ml.get("iterations") == 5 and 1 <= ml.get("runs", 0) <= 3, f"meshlab-isotropic iterations/runs {ml}")
    print({k: ml[k] for k in ["vertices", "q_avg", "theta_min", "v6_pct", "d_h", "target_length", "runs", "seconds"]})

rows = json.loads(run_ok(base + ["--no-meshlab"]))
check([r.get("method") for r in rows] == ["CVT", "FCVT"], f"--no-meshlab rows {[r.get('method') for r in rows]}")

code, stdout, stderr = run(base + ["--meshlabserver", "/nonexistent/meshlabserver"])
check(code == 2 and stderr.startswith("fcvt: error: ") and "--meshlabserver" in stderr,
      f"missing meshlabserver: exit {code}, stderr {stderr!r}")
code, stdout, stderr = run(base + ["--no-meshlab", "--meshlabserver", server])
check(code == 2 and "--no-meshlab" in stderr, f"--no-meshlab with --meshlabserver: exit {code}, stderr {stderr!r}")

# A "meshlabserver" that fails: the CVT and FCVT rows stand, a warning says why there is no third.
code, stdout, stderr = run([fcvt, "compare", source, "--vertices", str(vertices), "--json", "--meshlabserver", "/bin/false"])
check(code == 0, f"failing meshlabserver: exit {code}")
if code == 0:
    check([r.get("method") for r in json.loads(stdout)] == ["CVT", "FCVT"], "failing meshlabserver: rows")
check("no meshlab-isotropic row" in stderr, f"failing meshlabserver: no warning in {stderr!r}")
finish()
