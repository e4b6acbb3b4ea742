#!/usr/bin/env bash
# debian13_gui_dialog / forky_gui_dialog (issue 38): the remeshing dialog of MeshLab 2022.02
# or 2025.07, opened with the filter search (Ctrl+F) in the GUI under Xvfb inside the release's
# root, fits a 1280 x 1024 and a 1366 x 768 screen: at 1280 x 1024 it is below 2/3 of the
# screen (682 pixels; above that Qt stops a window growing by itself and MeshLab clips its last
# row), at 1366 x 768 it is as tall as there (nothing squeezed) and entirely on the screen. The
# parameters few users change are behind MeshLab's "advanced" button (ParamDef::advanced).
# A screenshot of each dialog is left in WORK_DIR for a look.
# Usage: gui_dialog.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
BUILD="$1"; SOURCE="$2"; work="$3"
source "$SOURCE/tests/debian13/common.sh"
require_installed
[ -x "$root/usr/bin/xdotool" ] || fail "xdotool is not installed in the root (scripts/package-debian.sh)"
rm -rf "$work"; mkdir -p "$work"
work="$(cd "$work" && pwd)"
bash "$SOURCE/tests/meshlab/obj2off.sh" "$SOURCE/resources/torus.obj" "$work/torus.off"

cat > "$work/inside.sh" <<'INSIDE'
set -u
out="$1"; tag="$2"; mesh="$3"; source "$4/scripts/meshlab_window.sh"
mkdir -p "$out/home-$tag" "$out/runtime-$tag"; chmod 700 "$out/runtime-$tag"
touch "$out/display-started"
HOME="$out/home-$tag" XDG_RUNTIME_DIR="$out/runtime-$tag" meshlab "$mesh" >"$out/gui-$tag.log" 2>&1 &
pid=$!
wid="$(wait_meshlab_window "$pid")"
[ -n "$wid" ] || { echo "no window" >"$out/status-$tag.txt"; exit 0; }
sleep 4
xdotool windowfocus "$wid" 2>/dev/null; sleep 1
xdotool key --clearmodifiers ctrl+f; sleep 1
xdotool type --delay 50 "Field-Aligned CVT"; sleep 2
xdotool key Down; sleep 0.5
xdotool key Return; sleep 4
did="$(xdotool search --name "Field-Aligned CVT" 2>/dev/null | grep -v "^$wid\$" | head -n 1)"
[ -n "$did" ] || { echo "no dialog" >"$out/status-$tag.txt"; kill "$pid"; exit 0; }
eval "$(xdotool getwindowgeometry --shell "$did")"
echo "$WIDTH $HEIGHT $Y" >"$out/dialog-$tag.txt"
xdotool mousemove 1 1; sleep 3
xwd -id "$did" -silent >"$out/dialog-$tag.xwd"
kill "$pid"; wait "$pid" 2>/dev/null
echo closed >"$out/status-$tag.txt"
INSIDE

check_screen() {  # WIDTH HEIGHT TAG
  # `xvfb-run -a` inside the root picks a display number by the root's lock files; a server of
  # the test just before (or of this machine) can still hold it, and then MeshLab "could not
  # connect to display" (a clean-clone CI run, forky, :100). That is the harness, not the
  # dialog: up to three tries, as tests/meshlab/gui_field_dialog.sh does.
  for attempt in 1 2 3; do
    rm -f "$work/status-$3.txt"
    set +e
    timeout 300 bash "$SOURCE/scripts/debian13-chroot.sh" "$root" --bind "$SOURCE" --bind "$work" -- \
      xvfb-run -a -s "-screen 0 ${1}x${2}x24" bash "$work/inside.sh" "$work" "$3" "$work/torus.off" "$SOURCE" \
      >"$work/xvfb-$3.log" 2>&1
    set -e
    grep -aqs "could not connect to display" "$work/xvfb-$3.log" "$work/gui-$3.log" || break
    echo "$3: the virtual display was taken (try $attempt), again"
    sleep 2
  done
  [ -e "$work/display-started" ] || { cat "$work/xvfb-$3.log"; skip "the virtual display did not start in the root"; }
  [ "$(cat "$work/status-$3.txt" 2>/dev/null)" = closed ] \
    || { tail -n 20 "$work/gui-$3.log"; fail "$3: $(cat "$work/status-$3.txt" 2>/dev/null || echo "the GUI did not run")"; }
  local w h y
  read -r w h y <"$work/dialog-$3.txt"
  python3 "$SOURCE/tests/meshlab/xwd2png.py" "$work/dialog-$3.xwd" "$work/dialog-$3.png" >/dev/null || true
  echo "remeshing dialog at ${1}x$2: ${w}x$h, top at $y"
  [ $((y + h)) -le "$2" ] || fail "at ${1}x$2 the dialog's bottom ($((y + h))) is below the screen"
}
check_screen 1280 1024 sxga
check_screen 1366 768 wxga
read -r _ sxga_h _ <"$work/dialog-sxga.txt"
read -r _ wxga_h _ <"$work/dialog-wxga.txt"
[ "$sxga_h" -le 682 ] || fail "at 1280x1024 the dialog is $sxga_h pixels tall, above 2/3 of the screen: its last row is clipped"
[ "$wxga_h" = "$sxga_h" ] || fail "at 1366x768 the dialog is squeezed ($wxga_h pixels, needs $sxga_h)"
echo "PASS"
