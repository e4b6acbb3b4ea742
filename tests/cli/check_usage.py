"""fcvt usage and runtime errors: exit code 2 for usage errors, 1 for runtime failures, and
exactly one line "fcvt: error: ..." on stderr, nothing on stdout; help and version succeed.
Usage: check_usage.py FCVT RESOURCES_DIR WORK_DIR"""
import os
import sys

import fcvt_check
from fcvt_check import bad_mesh_files, check, finish, run, write_file

fcvt, resources, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
torus = os.path.join(resources, "torus.obj")
out = os.path.join(work, "out.ply")


def expect_error(args, code, fragment=""):
    fcvt_check.expect_error(fcvt, args, code, fragment)


# Usage errors: exit code 2.
for args, fragment in [
    ([], "no command"),
    (["frobnicate"], "unknown command"),
    (["remesh", torus, out], "--vertices"),
    (["remesh", torus, "--vertices", "100"], "input and an output"),
    (["remesh", torus, out, "--vertices", "2"], "--vertices"),
    (["remesh", torus, out, "--vertices", "-100"], "--vertices"),
    (["remesh", torus, out, "--vertices", "12abc"], "12abc"),
    (["remesh", torus, out, "--vertices", "1e3"], "1e3"),
    (["remesh", torus, out, "--vertices", ""], "--vertices"),
    (["remesh", torus, out, "--vertices", "99999999999999999999"], "--vertices"),
    (["remesh", torus, out, "--vertices"], "needs a value"),
    (["remesh", torus, out, "--vertices", "100", "--lambda", "-1"], "--lambda"),
    (["remesh", torus, out, "--vertices", "100", "--lambda", "nan"], "--lambda"),
    (["remesh", torus, out, "--vertices", "100", "--lambda", "inf"], "--lambda"),
    (["remesh", torus, out, "--vertices", "100", "--lambda", "0.5x"], "--lambda"),
    (["remesh", torus, out, "--vertices", "100", "--cvt-iterations", "-1"], "--cvt-iterations"),
    (["remesh", torus, out, "--vertices", "100", "--fcvt-iterations", "-3"], "--fcvt-iterations"),
    (["remesh", torus, out, "--vertices", "100", "--seed", "-1"], "--seed"),
    (["remesh", torus, out, "--vertices", "100", "--threads", "-2"], "--threads"),
    (["remesh", torus, out, "--vertices", "100", "--bogus"], "--bogus"),
    (["remesh", torus, out, "--vertices", "100", "--vertices", "200"], "twice"),
    (["remesh", torus, out, "--vertices", "100", "--quiet=yes"], "--quiet"),
    (["remesh", torus, out, "--vertices", "100", "--field", "smooth"], "--field"),
    (["remesh", torus, out, "--vertices", "100", "--field"], "needs a value"),
    (["remesh", torus, out, "--vertices", "100", "--field", "user"], "rosy_x"),
    (["field", torus], "input and an output"),
    (["field", torus, os.path.join(work, "field.obj")], ".ply"),
    (["field", torus, os.path.join(work, "field.ply"), "--field", "curvature"], "--field"),
    (["field", torus, os.path.join(work, "field.ply"), "--seed", "x"], "--seed"),
    (["field", torus, os.path.join(work, "field.ply"), "--vertices", "10"], "--vertices"),
    (["compare", torus], "--vertices"),
    (["compare", "--vertices", "100"], "exactly one"),
    (["compare", torus, "--vertices", "100", "--field", "none"], "--field"),
    (["compare", torus, "--vertices", "100", "--lambda", "-0.1"], "--lambda"),
    (["metrics"], "exactly one"),
    (["metrics", torus, "--ref"], "needs a value"),
    (["metrics", torus, "-x"], "-x"),
]:
    expect_error(args, 2, fragment)

# Runtime failures: exit code 1, the message names the file.
bad = bad_mesh_files(work)
garbage, truncated, truncated_ply, empty, cloud, nan_mesh = (
    bad[k] for k in ["garbage", "truncated", "truncated_ply", "empty", "cloud", "nan"])
missing = os.path.join(work, "missing.ply")
plain_ply = write_file(work, "plain.ply", b"ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                  b"property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n"
                  b"0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
for args, fragment in [
    (["remesh", missing, out, "--vertices", "100"], missing),
    (["remesh", garbage, out, "--vertices", "100"], garbage),
    (["remesh", truncated, out, "--vertices", "100"], truncated),
    (["remesh", truncated_ply, out, "--vertices", "100"], truncated_ply),
    (["remesh", empty, out, "--vertices", "100"], empty),
    (["remesh", cloud, out, "--vertices", "100"], cloud),
    (["remesh", torus, os.path.join(work, "out.xyz"), "--vertices", "100"], "out.xyz"),
    (["remesh", nan_mesh, out, "--vertices", "100", "--quiet"], ""),
    (["remesh", torus, os.path.join(work, "no", "such", "dir", "out.ply"), "--vertices", "100", "--quiet"], "out.ply"),
    (["remesh", plain_ply, out, "--vertices", "100", "--field", "user"], "rosy_x rosy_y rosy_z"),
    (["field", plain_ply, os.path.join(work, "field.ply"), "--field", "user"], "rosy_x rosy_y rosy_z"),
    (["field", missing, os.path.join(work, "field.ply")], missing),
    (["field", torus, os.path.join(work, "no", "dir", "field.ply")], "field.ply"),
    (["compare", missing, "--vertices", "100"], missing),
    (["metrics", missing], missing),
    (["metrics", torus, "--ref", truncated], truncated),
    (["metrics", work], work),
]:
    expect_error(args, 1, fragment)

# Help and version.
for args, text in [(["--help"], "Usage: fcvt <command>"), (["-h"], "Usage: fcvt <command>"),
                   (["remesh", "--help"], "--cvt-iterations"), (["remesh", "--help"], "--field"),
                   (["field", "--help"], "rosy_x"), (["compare", "--help"], "V6%"), (["--help"], "compare"),
                   (["metrics", "--help"], "--ref"),
                   (["--version"], "fcvt ")]:
    code, stdout, stderr = run([fcvt] + args)
    check(code == 0 and text in stdout and stderr == "", f"'{' '.join(args)}': exit {code}, stdout {stdout[:60]!r}")

finish()
