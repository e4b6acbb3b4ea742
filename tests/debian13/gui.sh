#!/usr/bin/env bash
# debian13_gui: MeshLab 2022.02's GUI starts under Xvfb inside the Debian 13 root with our
# package installed: its window maps, libfilter_fcvt.so is mapped into the process (MeshLab
# loaded it from its plugin directory), its log names no plugin error, and a screenshot (xwd,
# converted on the host by tests/meshlab/xwd2png.py) is not blank. With a MESH argument the GUI
# opens that mesh instead of the torus (scripts/render_meshlab2022.sh uses this for the README).
# Usage: gui.sh BUILD_DIR SOURCE_DIR WORK_DIR [MESH]
set -euo pipefail
BUILD="$1"; SOURCE="$2"; work="$3"; mesh="${4:-}"
source "$SOURCE/tests/debian13/common.sh"
require_installed
rm -rf "$work"; mkdir -p "$work/home" "$work/runtime"; chmod 700 "$work/runtime"
work="$(cd "$work" && pwd)"
if [ -z "$mesh" ]; then
  bash "$SOURCE/tests/meshlab/obj2off.sh" "$SOURCE/resources/torus.obj" "$work/torus.off"
  mesh="$work/torus.off"
else
  cp "$mesh" "$work/"; mesh="$work/$(basename "$mesh")"
fi
screen="${FCVT_GUI_SCREEN:-1024x768}"

cat > "$work/inside.sh" <<'INSIDE'
set -u
out="$1"; mesh="$2"
touch "$out/display-started"
HOME="$out/home" XDG_RUNTIME_DIR="$out/runtime" meshlab "$mesh" >"$out/gui.log" 2>&1 &
pid=$!
for _ in $(seq 1 160); do
  xwininfo -root -tree 2>/dev/null | grep -q '"MeshLab' && break
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.5
done
xwininfo -root -tree >"$out/windows.txt" 2>&1
sleep "${FCVT_GUI_SETTLE:-6}"   # let it render the mesh
if kill -0 "$pid" 2>/dev/null; then
  grep -c "libfilter_fcvt.so" "/proc/$pid/maps" >"$out/plugin-mapped.txt" || true
  xwd -root -silent >"$out/screen.xwd"
  kill "$pid"; wait "$pid" 2>/dev/null
  echo closed >"$out/gui-status.txt"
else
  wait "$pid"; echo "exited early with status $?" >"$out/gui-status.txt"
fi
INSIDE
set +e
timeout 300 bash "$SOURCE/scripts/debian13-chroot.sh" "$root" --bind "$SOURCE" --bind "$work" -- \
  env FCVT_GUI_SETTLE="${FCVT_GUI_SETTLE:-6}" xvfb-run -a -s "-screen 0 ${screen}x24" bash "$work/inside.sh" "$work" "$mesh" \
  >"$work/xvfb.log" 2>&1
rc=$?
set -e
[ -e "$work/display-started" ] || { cat "$work/xvfb.log"; skip "the virtual display did not start in the root (status $rc)"; }
echo "--- GUI log (last lines):"; tail -n 25 "$work/gui.log"
status="$(cat "$work/gui-status.txt" 2>/dev/null || echo unknown)"
[ "$status" = closed ] || fail "the GUI did not stay up: $status"
grep -q '"MeshLab' "$work/windows.txt" || fail "no MeshLab window mapped"
[ "$(cat "$work/plugin-mapped.txt")" -gt 0 ] || fail "libfilter_fcvt.so not loaded by the GUI"
if grep -i "fcvt" "$work/gui.log" | grep -Eiq "error|fail|cannot|invalid|undefined"; then
  fail "the GUI log reports a problem with our plugin"
fi
info="$(python3 "$SOURCE/tests/meshlab/xwd2png.py" "$work/screen.xwd" "$work/screen.png")"
echo "screenshot $work/screen.png: $info"
colours="${info% colours}"; colours="${colours##* }"
[ "$colours" -gt 50 ] || fail "the screenshot is nearly blank ($info)"
echo "PASS"
