#!/usr/bin/env bash
# Issue 14 through meshlabserver's "Compute 6-RoSy Field" (resources/fcvt-field.mlx): the field
# is computed on the normalised surface (a UV sphere at 1e30 and 1e-30, the range MeshLab's float
# coordinates hold: the sphere's index sum 12 = 6 chi), and a cube of polygons with straight
# corners, which MeshLab's OFF importer fans into zero-area triangles, reaches the core as one
# closed surface (triangulated again from its file, or flipped; not torn: index sum 12 again).
# Usage: field_scaled.sh SOURCE_DIR PLUGIN_SO WORK_DIR
set -euo pipefail
FCVT_SOURCE_DIR="$1"; plugin="$2"; work="$3"
source "$FCVT_SOURCE_DIR/tests/meshlab/common.sh"

rm -rf "$work/out"; mkdir -p "$work/out"
server="$(stage_meshlab "$work/stage" "$plugin")"
mlx="$FCVT_SOURCE_DIR/resources/fcvt-field.mlx"
python3 - "$FCVT_SOURCE_DIR/tests/robustness" "$work/out" <<'PY'
import os, sys
sys.path.insert(0, sys.argv[1])
import meshgen as g
out = sys.argv[2]
for name, scale in (("uv-1e30", 1e30), ("uv-1e-30", 1e-30)):
    with open(os.path.join(out, name + ".ply"), "wb") as fh:
        fh.write(g.ply_bytes(g.transform(g.uv_sphere(), scale), True, "float"))
with open(os.path.join(out, "polygon-cube.off"), "wb") as fh:
    fh.write(g.off_bytes(g.polygon_cube(3)))
PY
for name in uv-1e30.ply uv-1e-30.ply polygon-cube.off; do
  log="$work/out/$name.log"
  run_meshlabserver "$server" "$log" -i "$work/out/$name" -o "$work/out/$name-field.ply" -s "$mlx"
  [ "$MLS_RC" -eq 0 ] || fail "$name: meshlabserver exited with $MLS_RC"
  grep -Eq "FCVT field: extrinsic 6-RoSy \(seed 1\) on layer '$name': [0-9]+ singularities, index sum 12 \(" "$log" \
    || fail "$name: no index sum 12 (6 chi of a sphere) in the log: $(grep 'FCVT field' "$log" | head -1)"
  ! grep -Eq "Assertion|Aborted|terminate called" "$log.err" || fail "$name: abort in stderr"
done
# The layer is the file as read: the readers' triangulation of its polygons (no zero-area
# triangle) replaces MeshLab's fans, and the log says so; an edited layer would get the flips.
grep -Eq "FCVT input: (the polygons of '[^']*polygon-cube.off' triangulated as the command line does|flipped [0-9]* zero-area triangles of 'polygon-cube.off')" \
  "$work/out/polygon-cube.off.log" || fail "polygon-cube.off: neither the readers' triangulation nor the flips in the log"
echo "PASS"
