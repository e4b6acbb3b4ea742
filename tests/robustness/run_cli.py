"""Runs the robustness corpus (corpus.py) through `fcvt remesh` and checks each documented
outcome: exit 0 with a manifold output, or exit 1/2 with exactly one stderr line starting
"fcvt: error:" (the last one; progress lines may come before it) -- never a signal, never a hang.
Usage: run_cli.py FCVT WORK_DIR [--timeout S] [--jobs N] [--only NAME,...]"""
import argparse
import concurrent.futures
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import corpus  # noqa: E402
import meshgen  # noqa: E402


def signal_name(code):
    try:
        import signal
        return signal.Signals(-code).name
    except (ValueError, ImportError):
        return "signal %d" % -code


def run_case(fcvt, work, c, timeout):
    """Returns (case, list of problems, output path)."""
    inp = os.path.join(work, "in", c["file"])
    if c["out_ext"] == "@input":
        out = inp
    elif c["out_ext"] == "@link":
        out = os.path.join(work, "out", c["file"])
        if os.path.lexists(out):
            os.remove(out)
        os.symlink(inp, out)
    elif c["out_ext"].startswith("/"):
        out = c["out_ext"]
    else:
        out = os.path.join(work, "out", c["name"] + "." + c["out_ext"])
        if os.path.exists(out):
            os.remove(out)
    cmd = [fcvt, "remesh", inp, out] + c["args"] + ["--threads", "1"]
    try:
        p = subprocess.run(cmd, capture_output=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return c, ["hang: no exit within %g s: %s" % (timeout, " ".join(cmd))], out
    stderr = p.stderr.decode("utf-8", "replace")
    lines = stderr.splitlines()
    problems = []
    rc = p.returncode
    if "Sanitizer" in stderr or "runtime error:" in stderr:
        problems.append("sanitizer report")
    if rc < 0:
        problems.append("killed by %s" % signal_name(rc))
    elif rc == 0:
        if c["expect"] == "error":
            problems.append("exit 0, expected an error (exit %s)" % c["codes"])
        elif c["out_ext"] == "obj":
            mesh = meshgen.read_obj(out)
            problems += ["output: " + x for x in meshgen.manifold_problems(mesh)]
            if c["closed"]:
                loops, components = meshgen.boundary_loops_and_components(mesh)
                if (loops, components) != (0, 1):
                    problems.append("output has %d boundary loops and %d components, expected one closed surface"
                                    % (loops, components))
            if c["measures"]:
                area, volume, tolerance = c["measures"]
                got_area, got_volume = meshgen.area_and_volume(mesh)
                if abs(got_area - area) > tolerance * area or abs(got_volume - volume) > tolerance * abs(volume):
                    problems.append("output area %.5g and volume %.5g, expected %.5g and %.5g (within %g %%)"
                                    % (got_area, got_volume, area, volume, 100 * tolerance))
        elif not os.path.getsize(out):
            problems.append("empty output file")
        if any(line.startswith("fcvt: error:") for line in lines):
            problems.append("exit 0 but an error line on stderr")
        if c["warning"] and not any(line.startswith("fcvt: warning:") and c["warning"] in line for line in lines):
            problems.append("no warning mentioning %r" % c["warning"])
    elif rc in (1, 2):
        errors = [line for line in lines if line.startswith("fcvt: error:")]
        if c["expect"] == "ok":
            problems.append("exit %d, expected success" % rc)
        if c["expect"] == "error" and rc not in c["codes"]:
            problems.append("exit %d, expected %s" % (rc, c["codes"]))
        if len(errors) != 1 or not lines or lines[-1] != errors[0]:
            problems.append("stderr does not end with exactly one 'fcvt: error:' line")
        if c["fragment"] and c["fragment"] not in stderr:
            problems.append("error does not mention %r" % c["fragment"])
        if c["out_ext"] != "" and not c["out_ext"].startswith(("/", "@")) and os.path.exists(out):
            problems.append("an output file was written despite the error")
        if c["early"] and len(lines) != 1:
            problems.append("the error did not come before the work (%d stderr lines)" % len(lines))
    else:
        problems.append("unexpected exit code %d" % rc)
    if c["out_ext"].startswith("@"):
        with open(inp, "rb") as fh:
            if fh.read() != c["data"]:
                problems.append("the input file was changed")
    if problems:
        problems.append("command: " + " ".join(cmd))
        problems.append("stderr: " + stderr[-800:])
    status = "exit %d" % rc if rc >= 0 else signal_name(rc)
    last = lines[-1] if lines else ""
    print("%-40s %-8s %s" % (c["name"], status, last[:140]), flush=True)
    return c, problems, out


def compare_transformed(ref_out, out, scale, offset):
    a = meshgen.read_obj(ref_out)
    b = meshgen.read_obj(out)
    if a[1] != b[1]:
        return ["faces differ from the unit-scale result (%d vs %d faces)" % (len(b[1]), len(a[1]))]
    lo = [min(p[k] for p in a[0]) for k in range(3)]
    hi = [max(p[k] for p in a[0]) for k in range(3)]
    diag = math.sqrt(sum((hi[k] - lo[k]) ** 2 for k in range(3)))
    worst = 0.0
    for p, q in zip(a[0], b[0]):
        back = [(q[k] - offset[k]) / scale for k in range(3)]
        worst = max(worst, math.sqrt(sum((back[k] - p[k]) ** 2 for k in range(3))))
    print("  %s: worst vertex deviation %.3g of the diagonal" % (os.path.basename(out), worst / diag))
    # fcvt writes OBJ coordinates with enough digits for 1e-6 of the diagonal at any scale.
    return [] if worst <= 1e-6 * diag else ["vertices differ from the unit-scale result by %.3g of the diagonal" % (worst / diag)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("fcvt")
    ap.add_argument("work")
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--only", default="")
    a = ap.parse_args()
    os.makedirs(os.path.join(a.work, "in"), exist_ok=True)
    os.makedirs(os.path.join(a.work, "out"), exist_ok=True)
    cases = corpus.cases()
    if a.only:
        keep = set(a.only.split(","))
        cases = [c for c in cases if c["name"] in keep or (c["same_as"] and c["name"] in keep)]
    for c in cases:
        if c["data"] is not None:
            with open(os.path.join(a.work, "in", c["file"]), "wb") as f:
                f.write(c["data"])
        elif os.path.exists(os.path.join(a.work, "in", c["file"])):
            os.remove(os.path.join(a.work, "in", c["file"]))
    failures = {}
    outputs = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        for c, problems, out in pool.map(lambda c: run_case(a.fcvt, a.work, c, a.timeout), cases):
            outputs[c["name"]] = out
            if problems:
                failures[c["name"]] = problems
    for c in cases:
        if c["same_as"] and c["name"] not in failures:
            ref, scale, offset = c["same_as"]
            if ref in failures or ref not in outputs:
                continue
            problems = compare_transformed(outputs[ref], outputs[c["name"]], scale, offset)
            if problems:
                failures[c["name"]] = problems
    for name, problems in failures.items():
        print("FAIL %s:\n  %s" % (name, "\n  ".join(problems)))
    print("%d cases, %d failed" % (len(cases), len(failures)))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
