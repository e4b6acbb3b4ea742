"""What the module's tests share: the CLI, the resources, a temporary folder, a small mesh."""
import os
import subprocess
import sys
import tempfile

import numpy as np

import fcvt

CLI = os.environ.get("FCVT_CLI", "fcvt")
RESOURCES = os.environ.get("FCVT_RESOURCES", os.path.join(os.path.dirname(__file__), "..", "..", "resources"))
BUNNY = os.path.join(RESOURCES, "bunny.ply")


def run_cli(*args):
    """Runs `fcvt ARGS`; returns the completed process (stdout, stderr as text), checked."""
    done = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"fcvt {' '.join(map(str, args))} failed ({done.returncode}): {done.stderr}")
    return done


def cli_error(*args):
    """The one line `fcvt ARGS` prints on failure, without its 'fcvt: error: ' prefix."""
    done = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    assert done.returncode != 0, args
    line = done.stderr.strip().splitlines()[-1]
    assert line.startswith("fcvt: error: "), line
    return line[len("fcvt: error: "):]


def temp_dir():
    return tempfile.TemporaryDirectory(prefix="fcvt-python-")


def octahedron():
    V = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=float)
    F = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
    return V, F


def check(condition, message):
    if not condition:
        raise AssertionError(message)


def main(tests):
    """Runs each test function, prints its name and the failures; exits 1 on any."""
    failed = 0
    for test in tests:
        try:
            test()
            print(f"ok   {test.__name__}", flush=True)
        except Exception as e:  # noqa: BLE001 (report and go on)
            failed += 1
            print(f"FAIL {test.__name__}: {type(e).__name__}: {e}", flush=True)
    print(f"{len(tests) - failed} of {len(tests)} passed (fcvt {fcvt.__version__}, {fcvt.__file__})")
    sys.exit(1 if failed else 0)
