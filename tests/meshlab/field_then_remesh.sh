#!/usr/bin/env bash
# The two filters chained in one script: "Compute 6-RoSy Field" stores `rosy` on the torus (and
# leaves it the current layer), then the remeshing filter with fieldSource = "per-vertex
# attribute rosy" aligns to that stored field. Scripts built from the shipped ones, so every
# parameter stays listed. Usage: field_then_remesh.sh SOURCE_DIR PLUGIN_SO WORK_DIR
set -euo pipefail
FCVT_SOURCE_DIR="$1"; plugin="$2"; work="$3"
source "$FCVT_SOURCE_DIR/tests/meshlab/common.sh"

rm -rf "$work/out"; mkdir -p "$work/out"
server="$(stage_meshlab "$work/stage" "$plugin")"
mlx="$work/out/chain.mlx"
{
  sed -n '1,2p' "$FCVT_SOURCE_DIR/resources/fcvt-field.mlx"
  sed -n '/<filter /,/<\/filter>/p' "$FCVT_SOURCE_DIR/resources/fcvt-field.mlx"
  sed -n '/<filter /,/<\/filter>/p' "$FCVT_SOURCE_DIR/resources/fcvt-remesh.mlx" \
    | sed 's/\(name="fieldSource"[^>]*value="\)[^"]*"/\13"/'
  echo '</FilterScript>'
} > "$mlx"
[ "$(grep -c '<filter ' "$mlx")" -eq 2 ] || fail "could not build $mlx"
target="$(mlx_param "$FCVT_SOURCE_DIR/resources/fcvt-remesh.mlx" vertexCount)"

"$FCVT_SOURCE_DIR/tests/meshlab/obj2off.sh" "$FCVT_SOURCE_DIR/resources/torus.obj" "$work/out/torus.off"
out="$work/out/torus-user-field.ply"
run_meshlabserver "$server" "$work/out/log.txt" -i "$work/out/torus.off" -o "$out" -s "$mlx"

[ "$MLS_RC" -eq 0 ] || fail "meshlabserver exited with $MLS_RC"
grep -q "FCVT field: new layer '6-RoSy field'" "$work/out/log.txt" || fail "field filter did not run"
grep -q "FCVT: new layer 'torus_FCVT'" "$work/out/log.txt" \
  || fail "the remeshing did not run on the torus layer"
grep -Eq "FCVT field: per-vertex attribute rosy; on (the input|the optimisation surface, a simplified copy of the input) \([0-9]+ faces\): [0-9]+ singularities" "$work/out/log.txt" \
  || fail "the remeshing did not use the stored field"
qavg="$(sed -n 's/^.*FCVT metrics: .*Q_avg \([0-9.eE+-]*\),.*/\1/p' "$work/out/log.txt" | head -n 1)"
awk -v q="$qavg" 'BEGIN { exit !(q + 0 >= 0.9) }' || fail "logged Q_avg '$qavg' < 0.9"
vn="$(sed -n 's/^element vertex \([0-9]*\).*/\1/p' "$out" | head -n 1 | tr -d '\r')"
awk -v n="$vn" -v t="$target" 'BEGIN { d = n - t; if (d < 0) d = -d; exit !(d <= 0.05 * t) }' \
  || fail "output has '$vn' vertices, script asked for $target (more than 5 % off)"
echo "PASS"
