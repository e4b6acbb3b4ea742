#!/usr/bin/env bash
# Runs one pymeshlab test (tests/pymeshlab/TEST.py) with the plugin pymeshlab_plugin_build built:
# /usr/bin/python3 (the Python pymeshlab was built for) with ../shared/pymeshlab on PYTHONPATH.
# Skipped (77) with the build's reason when it was skipped (no pymeshlab, no MeshLab source).
# Usage: run.sh SOURCE_DIR WORK_DIR TEST [FCVT_CLI]
set -euo pipefail
source="$(cd "$1" && pwd)"; work="$2"; test="$3"; cli="${4:-}"
status="$(cat "$work/status" 2>/dev/null || echo "pymeshlab_plugin_build has not run")"
case "$status" in
  ok) ;;
  skipped:*) echo "$status"; exit 77 ;;
  *) echo "FAIL: no plugin: $status" >&2; exit 1 ;;
esac
pymeshlab_dir="$(cd "${FCVT_PYMESHLAB_DIR:-$source/../shared/pymeshlab}" && pwd)"
plugin="$work/upstream/fcvt/filter_fcvt/libfilter_fcvt.so"
out="$work/$test"
rm -rf "$out"; mkdir -p "$out"
# Bytecode stays out of the shared folder; no display needed (offscreen for Qt all the same).
PYTHONPATH="$pymeshlab_dir:$source/tests/pymeshlab" PYTHONDONTWRITEBYTECODE=1 QT_QPA_PLATFORM=offscreen \
  exec /usr/bin/python3 "$source/tests/pymeshlab/$test.py" "$plugin" "$source" "$out" "$cli"
