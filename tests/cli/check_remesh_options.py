"""The issue-5 options of `fcvt remesh` are wired: --no-valence, --feature-angle DEG, --adaptive
curvature|none and --gradation G reach the report's "params", out-of-range values are usage errors
(exit 2, one error line), and the report has the "valence" block. Tests the wiring, not the
geometry (a short run on the torus). Usage: check_remesh_options.py FCVT RESOURCES_DIR WORK_DIR"""
import json
import os
import sys

from fcvt_check import check, finish, run, run_ok

fcvt, resources, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
torus = os.path.join(resources, "torus.obj")
out = os.path.join(work, "out.ply")
short = ["--vertices", "300", "--cvt-iterations", "5", "--fcvt-iterations", "5", "--quiet"]

for extra, fragment in [
    (["--feature-angle", "-1"], "--feature-angle"),
    (["--feature-angle", "180.5"], "--feature-angle"),
    (["--feature-angle", "nan"], "--feature-angle"),
    (["--feature-angle"], "needs a value"),
    (["--adaptive", "quality"], "--adaptive"),
    (["--adaptive", "curvature", "--gradation", "-0.5"], "--gradation"),
    (["--adaptive", "curvature", "--gradation", "inf"], "--gradation"),
    (["--gradation", "2"], "--adaptive curvature"),
    (["--adaptive", "none", "--gradation", "2"], "--adaptive curvature"),
    (["--no-valence=1"], "--no-valence"),
]:
    code, stdout, stderr = run([fcvt, "remesh", torus, out] + short + extra, timeout=300)
    label = " ".join(extra)
    check(code == 2, f"'{label}': exit code {code}, expected 2")
    lines = stderr.splitlines()
    check(len(lines) == 1 and lines[0].startswith("fcvt: error: ") and fragment in lines[0],
          f"'{label}': stderr {stderr!r} is not one error line mentioning {fragment!r}")

VALENCE_KEYS = ["enabled", "v6_before", "v6_after", "flips", "collapses", "splits"]
for extra, expect in [
    ([], {"valence_optimization": True, "feature_angle": 0, "adaptive": "none"}),
    (["--no-valence", "--feature-angle", "60"], {"valence_optimization": False, "feature_angle": 60}),
    (["--adaptive", "curvature", "--gradation", "0.5", "--feature-angle", "180"],
     {"adaptive": "curvature", "gradation": 0.5, "feature_angle": 180}),
]:
    report = os.path.join(work, "report.json")
    if os.path.exists(report):
        os.remove(report)
    run_ok([fcvt, "remesh", torus, out] + short + extra + ["--report", report], timeout=600)
    r = json.load(open(report))
    label = " ".join(extra) or "defaults"
    params = r.get("params", {})
    for key, value in expect.items():
        check(params.get(key) == value, f"{label}: params.{key} = {params.get(key)!r}, expected {value!r}")
    for key in ["valence_optimization", "feature_angle", "adaptive", "gradation"]:
        check(key in params, f"{label}: params lacks {key}")
    valence = r.get("valence", {})
    for key in VALENCE_KEYS:
        check(key in valence, f"{label}: valence lacks {key}: {valence}")
    check(valence.get("enabled") == params.get("valence_optimization"), f"{label}: valence.enabled {valence}")
    for key in ["flips", "collapses", "splits"]:
        check(isinstance(valence.get(key), int) and valence[key] >= 0, f"{label}: valence.{key} = {valence.get(key)!r}")
    if params.get("valence_optimization") is False:
        check(valence.get("flips") == valence.get("collapses") == valence.get("splits") == 0,
              f"{label}: operations counted without valence optimisation: {valence}")
    print(label, "->", {k: valence.get(k) for k in VALENCE_KEYS})

# --fcvt-iterations is used at any size: it sets the large runs' budget too (their default is
# smaller, RemeshParams::largeRunFcvtIterations); the report says the budget the run had.
report = os.path.join(work, "budget.json")
for extra, large, used in [([], 20, 40), (["--fcvt-iterations", "5"], 5, 5)]:
    run_ok([fcvt, "remesh", torus, out, "--vertices", "300", "--cvt-iterations", "5", "--no-valence", "--quiet",
            "--report", report] + extra, timeout=600)
    r = json.load(open(report))
    label = " ".join(extra) or "defaults"
    check(r["params"].get("large_run_fcvt_iterations") == large,
          f"{label}: params.large_run_fcvt_iterations = {r['params'].get('large_run_fcvt_iterations')!r}, expected {large}")
    check(r.get("fcvt_iterations") == used, f"{label}: fcvt_iterations = {r.get('fcvt_iterations')!r}, expected {used}")

code, stdout, _ = run([fcvt, "remesh", "--help"])
for option in ["--no-valence", "--feature-angle", "--adaptive", "--gradation"]:
    check(option in stdout, f"remesh --help does not mention {option}")
finish()
