"""The settings `fcvt` runs with (cli/main.cpp, core/thread_budget.h):
- beside busy processes, one per core, a run with the default thread count takes one thread (the
  core's in-process choice, which the MeshLab filter makes too: no OMP_WAIT_POLICY or
  GOMP_SPINCOUNT is set and the program does not run itself again for them);
- the heap asks for transparent huge pages (GLIBC_TUNABLES=glibc.malloc.hugetlb=1), seen in the
  environment of the running command; a GLIBC_TUNABLES of the user's own is kept.
Usage: check_runtime_settings.py FCVT RESOURCES_DIR WORK_DIR"""
import json
import os
import subprocess
import sys
import time

fcvt, resources, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
failures = []
base = {k: v for k, v in os.environ.items() if k not in ("OMP_WAIT_POLICY", "GOMP_SPINCOUNT", "GLIBC_TUNABLES", "OMP_NUM_THREADS")}

# 1. Beside one busy process per core: whatever else runs, one thread.
cores = len(os.sched_getaffinity(0))
report = os.path.join(work, "busy.json")
busy = [subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range(cores)]
try:
    time.sleep(0.3)
    done = subprocess.run([fcvt, "remesh", os.path.join(resources, "torus.obj"), os.path.join(work, "busy.ply"),
                           "--vertices", "300", "--quiet", "--report", report], env=base, capture_output=True, text=True,
                          timeout=120)
finally:
    for p in busy:
        p.kill()
        p.wait()
if done.returncode != 0:
    failures.append(f"fcvt remesh beside {cores} busy process(es) exited with {done.returncode}: {done.stderr}")
else:
    used = json.load(open(report)).get("threads_used")
    if used != 1:
        failures.append(f"expected 1 thread beside {cores} busy process(es), the report says {used!r}")


# 2. The environment the remeshing runs with (read from /proc while it runs).
def running_environment(env):
    out = os.path.join(work, "out.ply")
    p = subprocess.Popen([fcvt, "remesh", os.path.join(resources, "fertility.off"), out, "--vertices", "3000", "--quiet"],
                         env=env)
    seen = {}
    try:
        deadline = time.time() + 30
        while p.poll() is None and time.time() < deadline:
            try:
                with open(f"/proc/{p.pid}/environ", "rb") as f:
                    entries = [e.decode(errors="replace") for e in f.read().split(b"\0") if b"=" in e]
                seen = dict(e.split("=", 1) for e in entries)
            except OSError:
                break
            if "GLIBC_TUNABLES" in seen:
                break  # the command runs again with its settings
            time.sleep(0.005)
    finally:
        code = p.wait()
    if code != 0:
        failures.append(f"fcvt remesh exited with {code}")
    return seen


seen = running_environment(base)
if "OMP_WAIT_POLICY" in seen or "GOMP_SPINCOUNT" in seen:
    failures.append("the command set a libgomp variable for itself: " + repr({k: seen[k] for k in seen if "OMP" in k}))
if seen.get("GLIBC_TUNABLES") != "glibc.malloc.hugetlb=1":
    failures.append(f"expected GLIBC_TUNABLES=glibc.malloc.hugetlb=1 in the running command, got {seen.get('GLIBC_TUNABLES')!r}")
seen = running_environment(dict(base, GLIBC_TUNABLES="glibc.malloc.check=0"))
if seen.get("GLIBC_TUNABLES") != "glibc.malloc.check=0":
    failures.append(f"the user's GLIBC_TUNABLES was not kept: {seen.get('GLIBC_TUNABLES')!r}")

if failures:
    print("FAIL:\n" + "\n".join(failures))
    sys.exit(1)
print(f"ok: one thread beside {cores} busy process(es); the heap asks for huge pages; the user's tunables kept")
