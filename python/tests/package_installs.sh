#!/usr/bin/env bash
# The python3-fcvt Debian package (python/packaging.cmake): built with cpack, unpacked into a
# throw-away root, its module imported from there (not from the build tree) and run once.
# Usage: package_installs.sh BUILD_DIR WORK_DIR
set -euo pipefail
build="$1"
work="$2"
rm -rf "$work"
mkdir -p "$work"
cmake --build "$build" --target python3-fcvt-deb >"$work/cpack.log" 2>&1 || { cat "$work/cpack.log"; exit 1; }
deb="$(ls "$build"/python/package/python3-fcvt_*_amd64.deb)"
echo "package: $deb"
dpkg-deb -f "$deb" Package Version Depends
dpkg-deb -x "$deb" "$work/root"
module="$(ls "$work"/root/usr/lib/python3/dist-packages/fcvt.cpython-*.so)"
[ -f "$work/root/usr/share/doc/python3-fcvt/copyright" ] || { echo "FAIL: no copyright file"; exit 1; }
dpkg-deb -f "$deb" Depends | grep -q "python3-numpy" || { echo "FAIL: no python3-numpy dependency"; exit 1; }
cd "$work"
env -u PYTHONPATH PYTHONPATH="$work/root/usr/lib/python3/dist-packages" /usr/bin/python3 - "$module" <<'PY'
import sys
import numpy as np
import fcvt
assert fcvt.__file__ == sys.argv[1], (fcvt.__file__, sys.argv[1])
V = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=float)
F = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
r = fcvt.remesh(V, F, vertices=200)
assert r.vertices.shape[1] == 3 and len(r.faces) > 300, r
print(f"ok: {fcvt.__file__}: {len(r.vertices)} vertices, Q_avg {r.report['metrics']['q_avg']:.3f}")
PY
