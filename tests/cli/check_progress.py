"""Progress output of `fcvt remesh` (issue 7 item 6): on a terminal one line rewritten in place
with a bar, the percent and the stage; plain lines ("fcvt: STAGE N %") when stderr is a pipe;
nothing with --quiet. Usage: check_progress.py FCVT RESOURCES_DIR WORK_DIR"""
import os
import pty
import re
import subprocess
import sys

from fcvt_check import check, finish, run

fcvt, resources, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
args = [fcvt, "remesh", os.path.join(resources, "torus.obj"), os.path.join(work, "out.ply"),
        "--vertices", "200", "--cvt-iterations", "5", "--fcvt-iterations", "5"]

# Pipe: plain lines, each "fcvt: STAGE [STEP/BUDGET] N %", the stages in pipeline order, ending
# at done 100 %.
code, _, stderr = run(args, timeout=300)
check(code == 0, f"piped run failed: {stderr}")
lines = [l for l in stderr.splitlines() if not l.startswith("fcvt: warning")]
check("\r" not in stderr and "\33[" not in stderr, "terminal control characters on a pipe")
bad = [l for l in lines if not re.fullmatch(r"fcvt: \S+ (\d+/\d+ )?\d{1,3} %", l)]
check(not bad, f"lines not of the form 'fcvt: STAGE [I/N] N %': {bad[:3]}")
steps = [l for l in lines if re.fullmatch(r"fcvt: (lloyd|cvt|fcvt) \d+/\d+ \d{1,3} %", l)]
check(steps, "no iteration steps (e.g. 'cvt 3/5') reported")
stages = [l.split()[1] for l in lines]
for stage in ["prepare", "cvt", "fcvt", "rdt", "done"]:
    check(stage in stages, f"stage {stage} not reported: {stages}")
check(lines[-1:] == ["fcvt: done 100 %"], f"last progress line {lines[-1:]}")
check(len(lines) < 60, f"{len(lines)} progress lines for a short run: too chatty for a log")

# --quiet: no progress at all.
code, stdout, stderr = run(args + ["--quiet"], timeout=300)
check(code == 0 and stderr == "" and stdout == "", f"--quiet printed stdout {stdout!r} stderr {stderr!r}")

# Terminal: stderr on a pseudo-terminal gets the bar, rewritten in place with \r.
master, slave = pty.openpty()
p = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=slave)
os.close(slave)
chunks = []
while True:
    try:
        data = os.read(master, 4096)
    except OSError:
        break
    if not data:
        break
    chunks.append(data)
p.wait(timeout=300)
os.close(master)
tty = b"".join(chunks).decode("utf-8", "replace")
check(p.returncode == 0, f"terminal run failed: {tty[-300:]!r}")
check(re.search(r"\rfcvt: \[[#-]{30}\] +\d+\.\d %", tty) is not None, f"no progress bar on a terminal: {tty[:200]!r}")
check("\rfcvt: [" + "#" * 30 + "] 100.0 % done" in tty, "the bar does not end full at 'done'")
check(tty.count("\n") <= 2, f"the bar is not rewritten in place ({tty.count(chr(10))} line ends)")
finish()
