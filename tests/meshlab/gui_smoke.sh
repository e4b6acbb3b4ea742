#!/usr/bin/env bash
# GUI smoke test (issue 7 item 4): the staged `meshlab` GUI starts under Xvfb with a mesh and our
# plugin, maps its window, has libfilter_fcvt.so loaded (seen in /proc/PID/maps), and a
# screenshot (xwd, converted to PNG) shows more than a blank screen; its log has no error.
# Exits 77 (CTest: skipped) when the GUI, xwd or the virtual display is not available.
# Usage: gui_smoke.sh SOURCE_DIR PLUGIN_SO WORK_DIR
set -euo pipefail
FCVT_SOURCE_DIR="$1"; plugin="$2"; work="$3"
source "$FCVT_SOURCE_DIR/tests/meshlab/common.sh"
skip() { echo "SKIP: $*"; exit 77; }

command -v xwd >/dev/null || skip "xwd not installed (Debian package x11-apps)"
command -v xwininfo >/dev/null || skip "xwininfo not installed (Debian package x11-utils)"
[ -x /usr/bin/meshlab ] || skip "/usr/bin/meshlab not installed"

rm -rf "$work/out"; mkdir -p "$work/out/home" "$work/out/runtime"
chmod 700 "$work/out/runtime"
stage_meshlab "$work/stage" "$plugin" >/dev/null
gui="$work/stage/bin/meshlab"
[ -x "$gui" ] || fail "stage-meshlab.sh did not stage the GUI"
# The shipped GUI example (issue 15 item 8): a PLY, which MeshLab 2020.09 opens (its OBJ importer
# aborts on torus.obj).
cp "$FCVT_SOURCE_DIR/resources/torus.ply" "$work/out/torus.ply"

# Runs inside the virtual display: start the GUI, wait for its window, look for our plugin in
# its address space, take the screenshot, close it.
cat > "$work/out/inside.sh" <<'INSIDE'
set -u
out="$1"; gui="$2"
touch "$out/display-started"
# A private HOME: no settings of the user read or written, no first-run state carried over.
HOME="$out/home" XDG_RUNTIME_DIR="$out/runtime" "$gui" "$out/torus.ply" >"$out/gui.log" 2>&1 &
pid=$!
for _ in $(seq 1 120); do
  xwininfo -root -tree 2>/dev/null | grep -q '"MeshLab' && break
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.5
done
xwininfo -root -tree >"$out/windows.txt" 2>&1
sleep 5   # let it render the mesh
if kill -0 "$pid" 2>/dev/null; then
  grep -c "libfilter_fcvt.so" "/proc/$pid/maps" >"$out/plugin-mapped.txt" || true
  xwd -root -silent >"$out/screen.xwd"
  kill "$pid"
  wait "$pid" 2>/dev/null
  echo "closed" >"$out/gui-status.txt"
else
  wait "$pid"; echo "exited early with status $?" >"$out/gui-status.txt"
fi
INSIDE
set +e
timeout 300 xvfb-run -a -s "-screen 0 1024x768x24" bash "$work/out/inside.sh" "$work/out" "$gui" \
  >"$work/out/xvfb.log" 2>&1
rc=$?
set -e
[ -e "$work/out/display-started" ] || { cat "$work/out/xvfb.log"; skip "the virtual display did not start (xvfb-run status $rc)"; }
echo "--- GUI log:"; cat "$work/out/gui.log"
status="$(cat "$work/out/gui-status.txt" 2>/dev/null || echo "unknown")"
[ "$status" = "closed" ] || fail "the GUI did not stay up: $status"
grep -q '"MeshLab' "$work/out/windows.txt" || fail "no MeshLab window mapped"
[ "$(cat "$work/out/plugin-mapped.txt")" -gt 0 ] || fail "libfilter_fcvt.so not loaded by the GUI"
grep -q "Current Plugins Dir is: $work/stage/" "$work/out/gui.log" || fail "the GUI did not use the staged plugins"
grep -q "Opened mesh .*torus.ply" "$work/out/gui.log" || fail "the mesh was not opened"
if grep -Eiv "^QStandardPaths:" "$work/out/gui.log" | grep -Eiq "error|assert|abort|segmentation|failed|cannot|can't"; then
  fail "errors in the GUI log"
fi
info="$(python3 "$FCVT_SOURCE_DIR/tests/meshlab/xwd2png.py" "$work/out/screen.xwd" "$work/out/screen.png")"
echo "screenshot $work/out/screen.png: $info"
colours="${info% colours}"; colours="${colours##* }"
[ "$colours" -gt 50 ] || fail "the screenshot is nearly blank ($info)"
echo "PASS"
