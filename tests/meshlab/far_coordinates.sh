#!/usr/bin/env bash
# Issue 30 item 6 through the filter: MeshLab keeps single-precision coordinates, which are
# 0.0625 apart at 1e6. A unit cube there remeshed to 300 vertices (edges of ~0.15) cannot be
# held: the log must say so (naming floats, the offset and the spacing) rather than return a
# silently degenerate layer. Usage: far_coordinates.sh SOURCE_DIR PLUGIN_SO WORK_DIR
set -euo pipefail
FCVT_SOURCE_DIR="$1"; plugin="$2"; work="$3"
source "$FCVT_SOURCE_DIR/tests/meshlab/common.sh"

rm -rf "$work/out"; mkdir -p "$work/out"
server="$(stage_meshlab "$work/stage" "$plugin")"
mlx="$work/out/remesh-300.mlx"
sed 's/\(name="vertexCount"[^>]*value="\)[^"]*"/\1300"/' "$FCVT_SOURCE_DIR/resources/fcvt-remesh.mlx" > "$mlx"
[ "$(mlx_param "$mlx" vertexCount)" = 300 ] || fail "could not set vertexCount in $mlx"

python3 - "$work/out/far_cube.off" <<'PY'
import sys
o = 1e6
v = [(o + x, o + y, o + z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
tris = [t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))]
with open(sys.argv[1], "w") as fh:
    fh.write("OFF\n%d %d 0\n" % (len(v), len(tris)))
    fh.writelines("%.17g %.17g %.17g\n" % p for p in v)
    fh.writelines("3 %d %d %d\n" % t for t in tris)
PY
run_meshlabserver "$server" "$work/out/log.txt" -i "$work/out/far_cube.off" -o "$work/out/out.ply" -s "$mlx"
[ "$MLS_RC" -eq 0 ] || fail "meshlabserver failed (status $MLS_RC)"
grep -q "coordinates are too coarse for this edge length: floats 1e+06 from the origin are 0.0625 apart" \
  "$work/out/log.txt" || fail "no precision warning naming floats, the offset and the spacing in the log"
echo "PASS"
