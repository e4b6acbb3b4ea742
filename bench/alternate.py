"""Whole `fcvt remesh` commands of several builds or environments, run alternately, medians.

  python3 bench/alternate.py ROUNDS MESH N NAME=FCVT[,VAR:VALUE...] [NAME=FCVT[,VAR:VALUE...] ...]

Each round runs every variant once, in the order given, as `FCVT remesh MESH OUT.ply --vertices N
--threads 2 --quiet` with the variant's extra environment variables; the first variant is the
baseline of the ratios. Prints one line: each variant's median time and its ratio, and whether
the outputs are the same bytes. E.g. the build before a change against the build after it, and
the build before without huge pages:

  python3 bench/alternate.py 15 ../shared/meshes/bunny.obj 5000 before=OLD/cli/fcvt \\
      after=build/cli/fcvt neither=OLD/cli/fcvt,GLIBC_TUNABLES:glibc.malloc.check=0
"""
import os
import statistics
import subprocess
import sys
import tempfile
import time

if len(sys.argv) < 5:
    sys.exit(__doc__)
rounds, mesh, count = int(sys.argv[1]), sys.argv[2], sys.argv[3]
variants = [arg.split("=", 1) for arg in sys.argv[4:]]
work = tempfile.mkdtemp(prefix="fcvt-alternate-")
times = {name: [] for name, _ in variants}
for _ in range(rounds):
    for name, spec in variants:
        binary, *settings = spec.split(",")
        env = dict(os.environ, **dict(s.split(":", 1) for s in settings))
        out = os.path.join(work, name + ".ply")
        start = time.perf_counter()
        subprocess.run([binary, "remesh", mesh, out, "--vertices", count, "--threads", "2", "--quiet"], env=env, check=True)
        times[name].append(time.perf_counter() - start)
base = statistics.median(times[variants[0][0]])
outputs = {open(os.path.join(work, name + ".ply"), "rb").read() for name, _ in variants}
print("%s %s, medians of %d: " % (os.path.basename(mesh), count, rounds) +
      "  ".join("%s %.3f s (%.3f)" % (name, statistics.median(t), statistics.median(t) / base) for name, t in times.items()) +
      ("  same bytes" if len(outputs) == 1 else "  outputs differ"))
