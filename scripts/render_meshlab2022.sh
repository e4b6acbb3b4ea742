#!/usr/bin/env bash
# The README's picture of the filter in MeshLab 2022.02 (Debian 13), or 2025.07 with
# FCVT_DEBIAN_RELEASE=forky: in the root that the debian13 (forky) tests leave in
# BUILD/debian13-root (BUILD/forky-root), with our package and fcvt-meshlab-host installed,
# runs "Remeshing: Field-Aligned CVT (FCVT)" (resources/fcvt-remesh.mlx with VERTICES vertices)
# and "Remeshing Quality Report (FCVT)" (colorIrregular on) on resources/bunny.ply through
# that MeshLab's own plugin manager, then opens the coloured result in the root's MeshLab
# GUI under Xvfb (tests/debian13/gui.sh) and writes its screenshot to OUT.png.
#
# Usage (as root): render_meshlab2022.sh OUT.png [VERTICES]   (default 5000; BUILD: $FCVT_BUILD_DIR or build/)
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
[ $# -ge 1 ] || { sed -n '2,9p' "$0" >&2; exit 2; }
out="$1"; vertices="${2:-5000}"
build="$(cd "${FCVT_BUILD_DIR:-$here/build}" && pwd)"
release="${FCVT_DEBIAN_RELEASE:-trixie}"
source "$here/scripts/debian-release.sh"
debian_release "$release" || { echo "render_meshlab2022: unknown FCVT_DEBIAN_RELEASE $release" >&2; exit 2; }
export FCVT_DEBIAN_RELEASE="$release"
root="$build/$tag-root"
[ "$(cat "$build/$tag-out/status" 2>/dev/null)" = ok ] \
  || { echo "render_meshlab2022: no $release root; run: cd build && ctest -L $tag" >&2; exit 1; }
work="$build/render-meshlab-$tag"
rm -rf "$work"; mkdir -p "$work"

body() { sed -n '/<filter /,/<\/filter>/p' "$1"; }
# FCVT_PICTURE_REGION=1: only a disk of faces (MeshLab's Conditional Face Selection, as the
# meshlab_remesh_selected test's centre, radius 0.063) is remeshed, with VERTICES vertices ("Remesh only selected faces").
region="${FCVT_PICTURE_REGION:-0}"
{
  echo '<!DOCTYPE FilterScript>'; echo '<FilterScript>'
  if [ "$region" = 1 ]; then
    echo ' <filter name="Conditional Face Selection">'
    echo '  <Param type="RichString" name="condSelect" value="(((x0+x1+x2)/3+0.025969)^2+((y0+y1+y2)/3-0.156664)^2+((z0+z1+z2)/3+0.002607)^2 &lt; 0.004)" description="boolean function" tooltip="a disk of faces"/>'
    echo ' </filter>'
  fi
  body "$here/resources/fcvt-remesh.mlx" | sed "s/\(name=\"vertexCount\"[^>]*value=\"\)[^\"]*\"/\1$vertices\"/" \
    | { if [ "$region" = 1 ]; then sed 's/\(name="selectedOnly"[^>]*value="\)[^"]*"/\1true"/'; else cat; fi; }
  body "$here/resources/fcvt-quality.mlx" | sed 's/\(name="colorIrregular"[^>]*value="\)[^"]*"/\1true"/'
  echo '</FilterScript>'
} > "$work/picture.mlx"

server="$(bash "$here/tests/debian13/stage-host.sh" "$root" "$here" "$work/stage")"
"$server" -i "$here/resources/bunny.ply" -o "$work/bunny-fcvt.ply" -m vc -s "$work/picture.mlx" \
  >"$work/host.log" 2>"$work/host.err" || { tail -n 20 "$work/host.log" >&2; exit 1; }
grep "FCVT quality: Q_min\|FCVT quality of" "$work/host.log" | tail -n 2

# MeshLab 2022.02 sizes its first window from the screen (no window manager here to resize
# it); the picture is cropped to that window (the screen around it is black).
FCVT_GUI_SCREEN="${FCVT_GUI_SCREEN:-1500x1000}" \
  FCVT_GUI_SETTLE="${FCVT_GUI_SETTLE:-8}" \
  bash "$here/tests/debian13/gui.sh" "$build" "$here" "$work/gui" "$work/bunny-fcvt.ply" | tail -n 2
PYTHONDONTWRITEBYTECODE=1 PYTHONPATH="$here/tests/meshlab" python3 - "$work/gui/screen.xwd" "$out" <<'PY'
import sys
import xwd2png
width, height, rows = xwd2png.read_xwd(sys.argv[1])
black = bytes(3)
cols = [x for x in range(width) if any(r[3 * x:3 * x + 3] != black for r in rows)]
lines = [y for y in range(height) if rows[y].strip(b"\0")]
x0, x1, y0, y1 = cols[0], cols[-1] + 1, lines[0], lines[-1] + 1
xwd2png.write_png(sys.argv[2], x1 - x0, y1 - y0, [r[3 * x0:3 * x1] for r in rows[y0:y1]])
print(f"window {x1 - x0}x{y1 - y0} of the {width}x{height} screen")
PY
command -v optipng >/dev/null && optipng -quiet -o2 "$out" || true
echo "render_meshlab2022: $out"
