"""Remeshes a bundled mesh with fcvt and checks quality bars three ways: the run's JSON report,
`fcvt metrics --ref` on the written file, and a pure-Python measurement of that file.
By default the run is a pure CVT (lambda = 0, 130 CVT iterations, 0 FCVT iterations, no valence
optimisation, all explicit: the defaults are FCVT's; issue 2's bars); with the word `defaults`
among the bars it is the default pipeline (FCVT + valence optimisation). Arguments starting
with -- are passed on to `fcvt remesh`.
Usage: check_quality.py FCVT INPUT VERTICES WORK_DIR [BAR ...]
Bars: KEY>=X or KEY<=X on the metrics (q_avg, theta_min, pct_lt30, v6_pct, d_h, d_boundary,
boundary_v4_pct, ...), keep_genus, manifold, boundary_loops=N, vertex_tolerance=FRACTION."""
import json
import os
import sys

from fcvt_check import check, finish, measure, metrics_json, read_ply, run_ok

fcvt, source, vertices, work = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
bars = [b for b in sys.argv[5:] if not b.startswith("--") and b != "defaults"]
extra = [b for b in sys.argv[5:] if b.startswith("--")]
pure_cvt = "defaults" not in sys.argv[5:]
os.makedirs(work, exist_ok=True)
name = os.path.splitext(os.path.basename(source))[0]
out = os.path.join(work, f"{name}_{vertices}.ply")
report_path = os.path.join(work, f"{name}_{vertices}.json")

cvt = ["--lambda", "0", "--lloyd-iterations", "30", "--cvt-iterations", "130", "--fcvt-iterations", "0",
       "--no-valence"] if pure_cvt else []
print(run_ok([fcvt, "remesh", source, out, "--vertices", str(vertices), "--report", report_path] + cvt + extra))
with open(report_path) as f:
    report = json.load(f)
measured = metrics_json(fcvt, out, ref=source)
mesh_vertices, mesh_faces = read_ply(out)
python = measure(mesh_vertices, mesh_faces)
print("report metrics:", json.dumps(report["metrics"]))
print("fcvt metrics --ref:", json.dumps(measured))
print("python:", json.dumps(python))
print("topology in/out:", json.dumps(report["input"]), json.dumps(report["output"]))

# The three measurements agree (the report's distances use other random samples: looser).
check(report["vertices"] == len(mesh_vertices) and report["faces"] == len(mesh_faces), "report counts vs file")
for key in ["q_avg", "theta_min", "pct_lt30", "v6_pct"]:
    check(abs(report["metrics"][key] - measured[key]) < 1e-6, f"{key}: report {report['metrics'][key]} vs metrics {measured[key]}")
    check(abs(python[key] - measured[key]) < 1e-6 * max(1.0, abs(python[key])), f"{key}: python {python[key]} vs metrics {measured[key]}")

for bar in bars:
    if ">=" in bar or "<=" in bar:
        op = ">=" if ">=" in bar else "<="
        key, bound = bar.split(op)
        value = measured[key]
        ok = value is not None and (value >= float(bound) if op == ">=" else value <= float(bound))
        check(ok, f"{name}: {key} = {value}, bar {op} {bound}")
    elif bar == "keep_genus":
        check(report["output"]["genus"] == report["input"]["genus"],
              f"{name}: genus {report['output']['genus']}, input has {report['input']['genus']}")
        check(python["genus_if_connected"] == report["input"]["genus"] or report["output"]["components"] != 1,
              f"{name}: python genus {python['genus_if_connected']}")
    elif bar == "manifold":
        check(report["output"]["manifold"] and python["edges_manifold"], f"{name}: output not manifold")
    elif bar.startswith("boundary_loops="):
        loops = int(bar.split("=")[1])
        check(report["output"]["boundary_loops"] == loops and python["boundary_loops"] == loops,
              f"{name}: {report['output']['boundary_loops']} boundary loops (python {python['boundary_loops']}), expected {loops}")
    elif bar.startswith("vertex_tolerance="):
        tolerance = float(bar.split("=")[1])
        check(abs(len(mesh_vertices) - vertices) <= tolerance * vertices,
              f"{name}: {len(mesh_vertices)} vertices, target {vertices} +- {tolerance * 100} %")
    else:
        raise SystemExit(f"unknown bar {bar}")

finish()
