"""The settings `fcvt` gives the C library and libgomp by running itself again (cli/main.cpp):
- idle OpenMP threads sleep at once (OMP_WAIT_POLICY=PASSIVE, libgomp's spin count 0) when another
  task is runnable as the command starts, here busy processes beside it (on an idle machine they
  keep libgomp's brief spin: tests/test_wait_policy.cpp pins that choice);
- the heap asks for transparent huge pages (GLIBC_TUNABLES=glibc.malloc.hugetlb=1), seen in the
  environment of the running command; a GLIBC_TUNABLES of the user's own is kept.
Usage: check_runtime_settings.py FCVT RESOURCES_DIR WORK_DIR"""
import os
import subprocess
import sys
import time

fcvt, resources, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
failures = []
base = {k: v for k, v in os.environ.items() if k not in ("OMP_WAIT_POLICY", "GOMP_SPINCOUNT", "GLIBC_TUNABLES")}

# 1. Beside one busy process per core: whatever else runs, the command's threads do not fit.
cores = len(os.sched_getaffinity(0))
busy = [subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range(cores)]
try:
    time.sleep(0.3)
    done = subprocess.run([fcvt, "--version"], env=dict(base, OMP_DISPLAY_ENV="verbose"), capture_output=True, text=True,
                          timeout=60)
finally:
    for p in busy:
        p.kill()
        p.wait()
shown = done.stderr + done.stdout
if done.returncode != 0 or "GOMP_SPINCOUNT = '0'" not in shown:
    failures.append(f"expected libgomp's spin count 0 beside {cores} busy process(es); got exit {done.returncode}:\n{shown}")


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
            if "GOMP_SPINCOUNT" in seen or "OMP_WAIT_POLICY" in seen:
                break  # the command runs again with its settings
            time.sleep(0.005)
    finally:
        code = p.wait()
    if code != 0:
        failures.append(f"fcvt remesh exited with {code}")
    return seen


seen = running_environment(base)
if seen.get("GLIBC_TUNABLES") != "glibc.malloc.hugetlb=1":
    failures.append(f"expected GLIBC_TUNABLES=glibc.malloc.hugetlb=1 in the running command, got {seen.get('GLIBC_TUNABLES')!r}")
seen = running_environment(dict(base, GLIBC_TUNABLES="glibc.malloc.check=0"))
if seen.get("GLIBC_TUNABLES") != "glibc.malloc.check=0":
    failures.append(f"the user's GLIBC_TUNABLES was not kept: {seen.get('GLIBC_TUNABLES')!r}")

if failures:
    print("FAIL:\n" + "\n".join(failures))
    sys.exit(1)
print(f"ok: threads sleep beside {cores} busy process(es); the heap asks for huge pages; the user's tunables kept")
