#!/usr/bin/env bash
# scripts/render.py (f3d under xvfb-run): renders small generated meshes and checks each PNG:
# the signature, the requested size, and that it is not blank: pixels of the edge colour (the
# edges are unlit line cells, so their colour is exact), of the face colour's hue, of the
# background; and the orientation (the right angle of a triangle at the origin is at the bottom
# left: not mirrored, not upside down), the valence colours (an octahedron: every vertex has
# valence 4 < 6, so blue), the field crosses (red) and a PLY's own vertex colours.
# Exits 77 (CTest: skipped) when f3d or xvfb-run is not installed.
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
export PYTHONDONTWRITEBYTECODE=1  # no __pycache__ in scripts/
skip() { echo "SKIP: $*"; exit 77; }
fail() { echo "FAIL: $*" >&2; exit 1; }
command -v f3d >/dev/null || skip "f3d not installed (Debian package f3d)"
command -v xvfb-run >/dev/null || skip "xvfb-run not installed (Debian package xvfb)"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
render() { python3 "$here/scripts/render.py" "$@" --quiet || fail "render.py $*"; }
png() { python3 "$here/scripts/render_png.py" "$@"; }

# A 6 x 6 grid of squares, each cut in two, in the z = 0 plane; a right triangle; an octahedron
# with a field; the same octahedron with its own vertex colours (green).
python3 - "$tmp" <<'PY'
import sys
d = sys.argv[1]
n = 6
with open(d + "/grid.off", "w") as f:
    f.write("OFF\n%d %d 0\n" % ((n + 1) ** 2, 2 * n * n))
    for j in range(n + 1):
        for i in range(n + 1):
            f.write("%g %g 0\n" % (i / n, j / n))
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            f.write("3 %d %d %d\n3 %d %d %d\n" % (a, a + 1, a + n + 2, a, a + n + 2, a + n + 1))
with open(d + "/tri.off", "w") as f:
    f.write("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
pts = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
faces = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
def ply(path, extra_names, extra):
    with open(path, "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\nproperty float z\n")
        for name, kind in extra_names:
            f.write("property %s %s\n" % (kind, name))
        f.write("element face 8\nproperty list uchar int vertex_indices\nend_header\n")
        for p, e in zip(pts, extra):
            f.write(" ".join(str(v) for v in p + e) + "\n")
        for t in faces:
            f.write("3 %d %d %d\n" % t)
# rosy: any tangent direction (render.py projects it on the tangent plane)
ply(d + "/octa-field.ply", [("rosy_x", "float"), ("rosy_y", "float"), ("rosy_z", "float")],
    [(0, 0.3, 1), (0, 0.3, 1), (1, 0, 0.2), (1, 0, 0.2), (1, 0.5, 0), (1, 0.5, 0)])
ply(d + "/octa-green.ply", [("red", "uchar"), ("green", "uchar"), ("blue", "uchar")], [(40, 200, 40)] * 6)
PY

# Pixels whose colour is near RRGGBB (max channel difference TOL).
near() { png count "$1" "$2" "$3"; }
# Pixels where channel C (r, g or b) exceeds both others by more than 35 (f3d's own lights wash
# colours out: the red triangle below comes out about (135, 85, 85)).
dominant() {
  python3 - "$here/scripts" "$1" "$2" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
import render_png
_, _, rows = render_png.read_png(sys.argv[2])
k = "rgb".index(sys.argv[3])
n = 0
for r in rows:
    for x in range(0, len(r), 3):
        c = r[x:x + 3]
        if all(c[k] > c[j] + 35 for j in range(3) if j != k):
            n += 1
print(n)
PY
}
check_size() {
  local info; info="$(png info "$1")" || fail "$1: not a readable PNG"
  read -r w h colours <<<"$info"
  [ "$w" = "$2" ] && [ "$h" = "$3" ] || fail "$1 is ${w}x$h, not $2x$3"
  [ "$colours" -ge 3 ] || fail "$1 has $colours colours: blank"
  head -c 8 "$1" | od -An -tx1 | grep -q "89 50 4e 47 0d 0a 1a 0a" || fail "$1: bad PNG signature"
}

# 1. The grid, green faces, near-black edges, default sky light, 160 x 120.
render "$tmp/grid.off" --out "$tmp/grid.png" --size 160 120 --face-color 30c030 --edge-color 101010
check_size "$tmp/grid.png" 160 120
edge="$(near "$tmp/grid.png" 101010 12)"; face="$(dominant "$tmp/grid.png" g)"; bg="$(near "$tmp/grid.png" ffffff 0)"
echo "grid: $edge edge, $face face, $bg background pixels"
[ "$edge" -gt 300 ] || fail "grid: too few edge pixels ($edge)"
[ "$face" -gt 3000 ] || fail "grid: too few face pixels ($face)"
[ "$bg" -gt 1000 ] || fail "grid: too few background pixels ($bg)"

# 2. Orientation, with f3d's own lights and f3d's own (black) edges: the triangle covers the
#    bottom left, not the top right.
render "$tmp/tri.off" --out "$tmp/tri.png" --size 64 48 --light f3d --edges f3d --face-color c02020
check_size "$tmp/tri.png" 64 48
png crop "$tmp/tri.png" "$tmp/tri-bl.png" 8 28 12 12
png crop "$tmp/tri.png" "$tmp/tri-tr.png" 44 8 12 12
bl="$(dominant "$tmp/tri-bl.png" r)"; tr="$(near "$tmp/tri-tr.png" ffffff 0)"
echo "triangle: $bl red pixels at the bottom left, $tr background pixels at the top right"
[ "$bl" -gt 100 ] || fail "the bottom left should be covered (mirrored or upside down?)"
[ "$tr" -eq 144 ] || fail "the top right should be background"

# 3. Valence colours and the field: every octahedron vertex is blue (valence 4 < 6), the
#    crosses are red (220, 20, 20).
render "$tmp/octa-field.ply" --out "$tmp/octa.png" --size 120 120 --valence --dots 4 --field --view 30 20
check_size "$tmp/octa.png" 120 120
blue="$(dominant "$tmp/octa.png" b)"; red="$(near "$tmp/octa.png" dc1414 40)"
echo "octahedron: $blue blue, $red field pixels"
[ "$blue" -gt 1000 ] || fail "octahedron: not coloured by valence ($blue blue pixels)"
[ "$red" -gt 20 ] || fail "octahedron: no field crosses ($red red pixels)"

# 4. A PLY's own vertex colours are shown (green), without --valence.
render "$tmp/octa-green.ply" --out "$tmp/green.png" --size 120 120 --view 30 20
check_size "$tmp/green.png" 120 120
green="$(dominant "$tmp/green.png" g)"
echo "coloured PLY: $green green pixels"
[ "$green" -gt 1000 ] || fail "the PLY's vertex colours are not shown ($green green pixels)"

# 5. Errors: a missing file and --field without a field give one line and exit 1.
set +e
python3 "$here/scripts/render.py" "$tmp/none.off" --out "$tmp/x.png" 2>"$tmp/err1"; rc1=$?
python3 "$here/scripts/render.py" "$tmp/grid.off" --out "$tmp/x.png" --field 2>"$tmp/err2"; rc2=$?
set -e
[ "$rc1" -eq 1 ] && grep -q "render.py: error:" "$tmp/err1" || fail "missing file: exit $rc1, $(cat "$tmp/err1")"
[ "$rc2" -eq 1 ] && grep -q "rosy_x" "$tmp/err2" || fail "--field without a field: exit $rc2, $(cat "$tmp/err2")"
echo "PASS"
