"""Same seed, same output bytes: two runs with the same seed, and runs with 1 and 2 threads,
write identical files (PLY and OBJ), with or without --report (without it --quiet skips
the distances). Usage: check_determinism.py FCVT INPUT VERTICES WORK_DIR"""
import filecmp
import os
import sys

from fcvt_check import check, finish, run_ok

fcvt, source, vertices, work = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
os.makedirs(work, exist_ok=True)


def remesh(name, *extra, seed="7"):
    path = os.path.join(work, name)
    run_ok([fcvt, "remesh", source, path, "--vertices", vertices, "--seed", seed, "--quiet", *extra])
    return path


for ext in ["ply", "obj"]:
    first = remesh(f"a.{ext}", "--threads", "2")
    second = remesh(f"b.{ext}", "--threads", "2")
    one_thread = remesh(f"t1.{ext}", "--threads", "1")
    check(filecmp.cmp(first, second, shallow=False), f"two runs with the same seed differ ({ext})")
    check(filecmp.cmp(first, one_thread, shallow=False), f"--threads 1 and --threads 2 differ ({ext})")

# --quiet without --report skips the distances; the mesh written must not depend on it.
reported = remesh("reported.ply", "--threads", "2", "--report", os.path.join(work, "reported.json"))
check(filecmp.cmp(os.path.join(work, "a.ply"), reported, shallow=False), "--report changes the output mesh")

other_seed = remesh("seed8.ply", "--threads", "2", seed="8")
check(not filecmp.cmp(os.path.join(work, "a.ply"), other_seed, shallow=False), "another seed gives the same output")

finish()
