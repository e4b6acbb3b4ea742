#!/usr/bin/env bash
# A picture straight from MeshLab (issue 4's last bar, issue 7 item 4): runs "Remeshing:
# Field-Aligned CVT (FCVT)" with its defaults on IN through a staged meshlabserver (our plugin
# next to Debian's MeshLab 2020.09, scripts/stage-meshlab.sh), then "Remeshing Quality Report
# (FCVT)" on the result against the input with colorIrregular on (vertices blue below their
# target valence, pink above, white at it), saves the coloured PLY, opens it in the staged
# MeshLab GUI under Xvfb (flat shading plus wireframe, through a .mlp project's
# RenderingOption), takes a screenshot (xwd), crops it to the 3D view and writes OUT.png.
#
# Usage: render_meshlab.sh IN OUT.png [--plugin SO] [--ply OUT.ply] [--log OUT.txt] [--work DIR]
#                          [--screen WxH] [--zoom STEPS] [--info]
#   --plugin  libfilter_fcvt.so to stage (default: build/filter_fcvt/libfilter_fcvt.so)
#   --ply     also keep the remeshed, coloured PLY (what the picture shows)
#   --log     also keep meshlabserver's log (the quality report's figures)
#   --work    scratch directory (default: a temporary one, removed at the end)
#   --screen  virtual screen size, i.e. the GUI's window (default 900x760)
#   --zoom    mouse-wheel steps towards the mesh after MeshLab's own fit (default 1)
#   --info    keep MeshLab's info panel (FOV, FPS, vertex and face counts) over the view
# Needs: meshlab (meshlabserver and the GUI), xvfb (xvfb-run), x11-apps (xwd), x11-utils
# (xwininfo), xdotool, python3; optipng if installed.
# The filter's defaults: vertexCount = the input's vertex count capped at 5000, lambda 0.002,
# 65 + 65 iterations, extrinsic field, seed 1, valence optimisation on; meshlabserver 2020.09
# needs every parameter in the script, so the script is resources/fcvt-remesh.mlx with
# vertexCount and targetLength (1 % of the diagonal, used only in edge-length mode) set to the
# defaults the filter computes for IN.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
die() { echo "render_meshlab.sh: $*" >&2; exit 1; }

[ $# -ge 2 ] || { sed -n '2,25p' "$0" >&2; exit 2; }
in="$1"; out="$2"; shift 2
plugin="$here/build/filter_fcvt/libfilter_fcvt.so"; keep_ply=""; keep_log=""; work=""; screen="900x760"; zoom=1; info=0
while [ $# -gt 0 ]; do
  case "$1" in
    --plugin) plugin="$2"; shift 2 ;;
    --ply) keep_ply="$2"; shift 2 ;;
    --log) keep_log="$2"; shift 2 ;;
    --work) work="$2"; shift 2 ;;
    --screen) screen="$2"; shift 2 ;;
    --zoom) zoom="$2"; shift 2 ;;
    --info) info=1; shift ;;
    *) die "unknown option $1" ;;
  esac
done
[ -f "$in" ] || die "$in not found"
[ -f "$plugin" ] || die "plugin $plugin not found (build the filter_fcvt target)"
for tool in xvfb-run xwd xwininfo xdotool python3; do
  command -v "$tool" >/dev/null || die "$tool not installed"
done
[ -x /usr/bin/meshlab ] || die "/usr/bin/meshlab (the GUI) not installed"

if [ -z "$work" ]; then
  work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
fi
mkdir -p "$work/home" "$work/runtime"; chmod 700 "$work/runtime"
work="$(cd "$work" && pwd)"
"$here/scripts/stage-meshlab.sh" "$work/stage" "$plugin" >/dev/null

# MeshLab 2020.09's OBJ importer aborts on some files: hand it an OFF copy.
name="$(basename "${in%.*}")"
case "$in" in
  *.obj|*.OBJ) "$here/tests/meshlab/obj2off.sh" "$in" "$work/$name.off"; input="$work/$name.off" ;;
  *) cp "$in" "$work/$(basename "$in")"; input="$work/$(basename "$in")" ;;
esac

# The remeshing script with the filter's defaults for this input, then the quality report.
PYTHONDONTWRITEBYTECODE=1 PYTHONPATH="$here/scripts" python3 - "$here/resources/fcvt-remesh.mlx" "$here/resources/fcvt-quality.mlx" "$input" "$work/picture.mlx" <<'PY'
import math, re, sys
import render
remesh, quality, mesh, out = sys.argv[1:5]
verts, polys, _ = render.read_mesh(mesh)
diag = math.sqrt(sum((max(v[k] for v in verts) - min(v[k] for v in verts)) ** 2 for k in range(3)))
body = lambda s: s[s.index("<filter"):s.rindex("</filter>") + len("</filter>")]
r = body(open(remesh).read())
defaults = [("vertexCount", "value", str(max(4, min(len(verts), 5000)))),
            ("targetLength", "value", "%.6g" % (0.01 * diag)), ("targetLength", "max", "%.6g" % diag),
            ("lambda", "value", "0.002"), ("cvtIterations", "value", "65"), ("fcvtIterations", "value", "65"),
            ("fieldSource", "value", "0"), ("seed", "value", "1"), ("sizeMode", "value", "0"),
            ("valenceOptimization", "value", "true"), ("featureAngle", "value", "0"),
            ("featureSelection", "value", "false"), ("adaptive", "value", "0"), ("gradation", "value", "1"),
            ("colorIrregular", "value", "false")]
for name, attr, value in defaults:
    r, n = re.subn(r'(name="%s"[^>]*?%s=")[^"]*"' % (name, attr), r'\g<1>%s"' % value, r)
    assert n == 1, (name, attr)
q = body(open(quality).read())
q, n = re.subn(r'(name="colorIrregular"[^>]*value=")[^"]*"', r'\g<1>true"', q)
assert n == 1
open(out, "w").write("<!DOCTYPE FilterScript>\n<FilterScript>\n " + r + "\n " + q + "\n</FilterScript>\n")
PY

ply="$work/$name-fcvt.ply"
set +e
timeout 900 xvfb-run -a "$work/stage/bin/meshlabserver" -i "$input" -o "$ply" -m vc -s "$work/picture.mlx" \
  >"$work/server.log" 2>"$work/server.err"
rc=$?
set -e
[ $rc -eq 0 ] && [ -s "$ply" ] || { tail -n 30 "$work/server.log" "$work/server.err" >&2; die "meshlabserver failed ($rc)"; }
grep -q "FCVT quality of '${name}_FCVT'" "$work/server.log" || { cat "$work/server.log" >&2; die "the quality report did not run on the FCVT layer"; }
[ -n "$keep_log" ] && cp "$work/server.log" "$keep_log"
[ -n "$keep_ply" ] && cp "$ply" "$keep_ply"

# A project that opens the PLY with flat shading, vertex colours and the triangle wireframe.
# RenderingOption is MLRenderingData::serialize() of MeshLab 2020.09 (vcglib's PerViewData):
#   4 chars  primitive mask, highest first: solid, wireframe triangles, wireframe edges, points;
#   4 x 9    attributes per primitive (points, edges, triangles, solid), in the order: position,
#            vertex normal, face normal, vertex colour, face colour, vertex texcoord, wedge
#            texcoord, vertex indices, edge indices;
#   32 chars MLPerViewGLOptions in its serialize() order (visible ... point attenuation); the
#            defaults but _peredge_wire_enabled (the wireframe's colour is the attribute wireColor).
solid="101100000"    # position, face normal (flat), vertex colour
wire="100000000"     # position; drawn in wireColor
# visible, wire on (what the toolbar's wireframe button sets; without it the wireframe primitive
# is switched off again), single-side lighting, selection flags, fixed bbox/wire/solid
# colours, unshaded wire, point attenuation
opts="10000000010100011010110000001001"
cat >"$work/picture.mlp" <<MLP
<!DOCTYPE MeshLabDocument>
<MeshLabProject>
 <MeshGroup>
  <MLMesh label="${name}_FCVT" filename="$(basename "$ply")" visible="1">
   <MLMatrix44>
1 0 0 0 
0 1 0 0 
0 0 1 0 
0 0 0 1 
</MLMatrix44>
   <RenderingOption wireColor="40 40 48 255" wireWidth="1" solidColor="255 255 255 255" boxColor="234 234 234 255" pointColor="131 149 69 255" pointSize="3">1100000000000000000000$wire$solid$opts</RenderingOption>
  </MLMesh>
 </MeshGroup>
 <RasterGroup/>
</MeshLabProject>
MLP
[ "${#solid}${#wire}${#opts}" = "9932" ] || die "bad RenderingOption lengths"

cat >"$work/inside.sh" <<'INSIDE'
set -u
work="$1"; width="$2"; height="$3"; zoom="$4"; info="$5"
HOME="$work/home" XDG_RUNTIME_DIR="$work/runtime" "$work/stage/bin/meshlab" "$work/picture.mlp" >"$work/gui.log" 2>&1 &
pid=$!
source "$FCVT_WINDOW_HELPER"
wid="$(wait_meshlab_window "$pid")"
sleep 3   # let it load the mesh
if [ -n "$wid" ] && kill -0 "$pid" 2>/dev/null; then
  # No window manager: showMaximized() does nothing, so size the window by hand; then hide
  # the layer dialog (Ctrl+L), the trackball (Shift+H) and the info panel (View menu), so that
  # the 3D view fills the window and shows only the mesh.
  xdotool windowmove "$wid" 0 0 windowsize "$wid" "$width" "$height"
  xdotool windowfocus --sync "$wid" 2>/dev/null || xdotool windowfocus "$wid"
  sleep 1
  xdotool key --clearmodifiers ctrl+l
  sleep 0.5
  xdotool key --clearmodifiers shift+h
  sleep 0.5
  [ "$info" = 1 ] || { xdotool key --clearmodifiers alt+v; sleep 0.5; xdotool key p; sleep 0.5; }  # View > Show Info Panel
  # come closer: mouse-wheel steps over the middle of the view
  xdotool mousemove $((width / 2)) $((height / 2))
  for _ in $(seq 1 "$zoom"); do xdotool click 5; sleep 0.3; done
  xdotool mousemove "$width" "$height"
  sleep 3
  xwininfo -root -tree >"$work/windows.txt" 2>&1
  xwd -root -silent >"$work/screen.xwd"
  kill "$pid"; wait "$pid" 2>/dev/null
  echo closed >"$work/gui-status.txt"
else
  wait "$pid"; echo "exited early with status $?" >"$work/gui-status.txt"
fi
INSIDE
set +e
FCVT_WINDOW_HELPER="$here/scripts/meshlab_window.sh" timeout 300 xvfb-run -a -s "-screen 0 ${screen}x24" bash "$work/inside.sh" "$work" "${screen%x*}" "${screen#*x}" "$zoom" "$info" \
  >"$work/xvfb.log" 2>&1
set -e
[ "$(cat "$work/gui-status.txt" 2>/dev/null)" = closed ] || { cat "$work/xvfb.log" "$work/gui.log" >&2 || true; die "the GUI did not stay up"; }
python3 "$here/tests/meshlab/xwd2png.py" "$work/screen.xwd" "$work/screen.png" >/dev/null

# The 3D view: with the layer dialog hidden, the largest window in the tree below the main
# window (Qt gives the QGLWidget its own native window). Its absolute position comes from xwininfo's "+X+Y".
read -r x y w h <<<"$(python3 - "$work/windows.txt" <<'PY'
import re, sys
best = None
for line in open(sys.argv[1]):
    m = re.search(r'(\d+)x(\d+)\+-?\d+\+-?\d+\s+\+(-?\d+)\+(-?\d+)\s*$', line)
    if not m or '"MeshLab 20' in line:
        continue
    w, h, x, y = map(int, m.groups())
    if w >= 100 and h >= 100 and (best is None or w * h > best[2] * best[3]) and w * h < 0.9 * 1e7:
        best = (x, y, w, h)
print(*best if best else (0, 0, 0, 0))
PY
)"
[ "${w:-0}" -gt 0 ] || die "no 3D view found in the window tree ($work/windows.txt)"
python3 "$here/scripts/render_png.py" crop "$work/screen.png" "$out" "$x" "$y" "$w" "$h"
command -v optipng >/dev/null && optipng -quiet -o2 "$out"
read -r _ _ colours <<<"$(python3 "$here/scripts/render_png.py" info "$out")"
[ "$colours" -gt 50 ] || die "the screenshot $out is nearly blank ($colours colours)"
echo "$out: the 3D view ${w}x${h} at +$x+$y of the MeshLab window; $(grep -m1 "FCVT quality: Q_min" "$work/server.log" | sed 's/^.*FCVT quality: //')"
