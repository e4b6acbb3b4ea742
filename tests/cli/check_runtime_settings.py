"""The settings `fcvt` runs with (cli/main.cpp, core/thread_budget.h):
- beside busy processes, one per core, a run with the default thread count takes one thread (the
  core's in-process choice, which the MeshLab filter makes too: no OMP_WAIT_POLICY or
  GOMP_SPINCOUNT is set and the program does not run itself again for them);
- the heap asks for transparent huge pages in-process (core/huge_pages.h, as the MeshLab filter
  does): while the remeshing runs, its anonymous memory is marked for them (the "hg" flag of
  /proc/PID/smaps), where the kernel offers huge pages on request; the program sets no
  GLIBC_TUNABLES and does not run itself again for them.
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


# 2. What the running remeshing holds (read from /proc while it runs): its own environment, and
# how much of its memory is marked for huge pages.
def thp_on_request():
    try:
        with open("/sys/kernel/mm/transparent_hugepage/enabled") as f:
            return "[never]" not in f.read()
    except OSError:
        return False


def running_state(env):
    out = os.path.join(work, "out.ply")
    p = subprocess.Popen([fcvt, "remesh", os.path.join(resources, "fertility.off"), out, "--vertices", "3000", "--quiet"],
                         env=env)
    seen, marked_kb = {}, 0
    try:
        deadline = time.time() + 30
        while p.poll() is None and time.time() < deadline:
            try:
                with open(f"/proc/{p.pid}/environ", "rb") as f:
                    entries = [e.decode(errors="replace") for e in f.read().split(b"\0") if b"=" in e]
                seen = dict(e.split("=", 1) for e in entries)
                size_kb, total_kb = 0, 0
                with open(f"/proc/{p.pid}/smaps") as f:
                    for line in f:
                        if line.startswith("Size:"):
                            size_kb = int(line.split()[1])
                        elif line.startswith("VmFlags:") and " hg" in line:
                            total_kb += size_kb
                marked_kb = total_kb
            except OSError:
                break
            if marked_kb > 0:
                break
            time.sleep(0.01)
    finally:
        code = p.wait()
    if code != 0:
        failures.append(f"fcvt remesh exited with {code}")
    return seen, marked_kb


seen, marked_kb = running_state(base)
for name in ("OMP_WAIT_POLICY", "GOMP_SPINCOUNT", "GLIBC_TUNABLES"):
    if name in seen:
        failures.append(f"the command set {name}={seen[name]!r} for itself")
if thp_on_request() and marked_kb < 2048:
    failures.append(f"no memory of the running remeshing is marked for huge pages ({marked_kb} kB with the hg flag)")

if failures:
    print("FAIL:\n" + "\n".join(failures))
    sys.exit(1)
print(f"ok: one thread beside {cores} busy process(es); {marked_kb} kB marked for huge pages in-process, no variable set")
