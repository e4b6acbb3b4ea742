"""Idle OpenMP threads of `fcvt` sleep at once (OMP_WAIT_POLICY=PASSIVE, libgomp's spin count 0)
when another task is runnable as the command starts: here a busy process beside it. (On an idle
machine they keep libgomp's default brief spin; tests/test_wait_policy.cpp pins that choice.)
Usage: check_wait_policy.py FCVT"""
import os
import subprocess
import sys
import time

fcvt = sys.argv[1]
env = {k: v for k, v in os.environ.items() if k not in ("OMP_WAIT_POLICY", "GOMP_SPINCOUNT")}
env["OMP_DISPLAY_ENV"] = "verbose"
cores = len(os.sched_getaffinity(0))
# One busy process per core: whatever else runs, the command's threads do not fit beside them.
busy = [subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range(cores)]
try:
    time.sleep(0.3)
    done = subprocess.run([fcvt, "--version"], env=env, capture_output=True, text=True, timeout=60)
finally:
    for p in busy:
        p.kill()
        p.wait()
shown = done.stderr + done.stdout
if done.returncode != 0 or "GOMP_SPINCOUNT = '0'" not in shown:
    print(f"FAIL: expected libgomp's spin count 0 beside {cores} busy process(es); got exit {done.returncode}:\n{shown}")
    sys.exit(1)
print(f"ok: threads sleep beside {cores} busy process(es)")
