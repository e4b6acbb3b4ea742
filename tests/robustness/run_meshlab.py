"""The robustness corpus through meshlabserver: the cases whose file MeshLab 2020.09's own
importers load (well-formed OFF/PLY with bad geometry, and the bad-parameter cases), run with
resources/fcvt-remesh.mlx (parameters set per case) on a staged MeshLab tree with our plugin,
under xvfb-run. A failing filter must end meshlabserver through its own exit(-1) (status 255),
never a signal or an abort (129-254), never a hang; no "Segmentation"/"Aborted" in stderr.
A case expected to succeed must exit 0 and write its output; one expected to fail must not.
Usage: run_meshlab.py SOURCE_DIR PLUGIN_SO WORK_DIR [--timeout S] [--jobs N] [--only NAME,...]"""
import argparse
import concurrent.futures
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import corpus  # noqa: E402

MLX_NAMES = {"--vertices": "vertexCount", "--lambda": "lambda", "--cvt-iterations": "cvtIterations",
             "--fcvt-iterations": "fcvtIterations", "--seed": "seed"}


def mlx_for(template, args):
    text = template
    if "--no-repair" in args:  # the one flag without a value: the checkbox off
        args = [x for x in args if x != "--no-repair"]
        text, n = re.subn(r'(name="repair"[^>]*value=")[^"]*"', r'\g<1>false"', text)
        assert n == 1, "no parameter repair in the .mlx template"
    for flag, value in zip(args[0::2], args[1::2]):
        name = MLX_NAMES.get(flag)
        if name:
            text, n = re.subn(r'(name="%s"[^>]*value=")[^"]*"' % name, r'\g<1>%s"' % value, text)
            assert n == 1, "no parameter %s in the .mlx template" % name
    return text


def run_case(server, work, template, c, timeout):
    inp = os.path.join(work, "in", c["file"])
    out = os.path.join(work, "out", c["name"] + ".ply")
    mlx = os.path.join(work, "out", c["name"] + ".mlx")
    with open(mlx, "w") as fh:
        fh.write(mlx_for(template, c["args"]))
    if os.path.exists(out):
        os.remove(out)
    cmd = ["timeout", "-k", "5", str(timeout), "xvfb-run", "-a", server, "-i", inp, "-o", out, "-s", mlx]
    p = subprocess.run(cmd, capture_output=True)
    rc = p.returncode
    stdout = p.stdout.decode("utf-8", "replace")
    stderr = p.stderr.decode("utf-8", "replace")
    problems = []
    if rc in (124, 137) or rc < 0:
        problems.append("hang: killed after %g s" % timeout)
    elif 129 <= rc <= 254:
        problems.append("meshlabserver died with status %d (signal %d)" % (rc, rc - 128))
    for word in ("Segmentation", "Aborted", "terminate called", "Assertion"):
        if word in stderr or word in stdout:
            problems.append("%r in meshlabserver's output" % word)
    if not problems:
        if c["expect"] == "ok" and (rc != 0 or not os.path.exists(out)):
            problems.append("exit %d, expected success with an output" % rc)
        if c["expect"] == "error" and (rc == 0 or os.path.exists(out)):
            problems.append("exit %d, expected the filter to fail (255) without an output" % rc)
        if c["expect"] == "error" and "FCVT" not in stdout:
            problems.append("no FCVT message in the log")
        # The CLI's option names aside, the filter reports the same message as the CLI.
        if c["expect"] == "error" and c["fragment"] and not c["fragment"].startswith("--") and c["fragment"] not in stdout:
            problems.append("the log does not mention %r" % c["fragment"])
        # What MeshLab's importer made of the file must reach the core as one closed surface
        # (its polygon fans' zero-area triangles flipped, not removed), and so must the output.
        closed = r"FCVT topology: input genus \d+, 0 boundary loops, 1 components; output genus \d+, 0 boundary loops, 1 components"
        if c["expect"] == "ok" and c["closed"] and not re.search(closed, stdout):
            problems.append("the log does not show a closed input and output (one component, no boundary loop)")
    # The filter's last own message (its progress lines run together without newlines).
    said = [line.strip() for line in stdout.splitlines() if re.search(r"FCVT( metrics)?: ", line) and len(line) < 400]
    print("%-32s exit %-4d %s" % (c["name"], rc, (said[-1] if said else "")[:140]), flush=True)
    if problems:
        problems += ["command: " + " ".join(cmd), "log: " + stdout[-1200:], "stderr: " + stderr[-800:]]
    return c, problems


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("source")
    ap.add_argument("plugin")
    ap.add_argument("work")
    ap.add_argument("--timeout", type=float, default=120)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--only", default="")
    a = ap.parse_args()
    os.makedirs(os.path.join(a.work, "in"), exist_ok=True)
    os.makedirs(os.path.join(a.work, "out"), exist_ok=True)
    stage = subprocess.run([os.path.join(a.source, "scripts", "stage-meshlab.sh"), os.path.join(a.work, "stage"), a.plugin],
                           capture_output=True, text=True)
    if stage.returncode != 0:
        print("FAIL: staging MeshLab: " + stage.stderr)
        sys.exit(1)
    server = stage.stdout.strip().splitlines()[-1]
    with open(os.path.join(a.source, "resources", "fcvt-remesh.mlx")) as fh:
        template = fh.read()
    cases = [c for c in corpus.cases() if c["meshlab"] and (not a.only or c["name"] in a.only.split(","))]
    for c in cases:
        with open(os.path.join(a.work, "in", c["file"]), "wb") as fh:
            fh.write(c["data"])
    failures = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        for c, problems in pool.map(lambda c: run_case(server, a.work, template, c, a.timeout), cases):
            if problems:
                failures[c["name"]] = problems
    for name, problems in failures.items():
        print("FAIL %s:\n  %s" % (name, "\n  ".join(problems)))
    print("%d cases through meshlabserver, %d failed" % (len(cases), len(failures)))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
