#!/usr/bin/env bash
# resources/compare-isotropic.mlx (issue 7 item 3): MeshLab's built-in isotropic remeshing and
# FCVT at the same target edge length into two layers, each measured by the quality report
# against the input. Checks that every step ran, that both layers were measured with distances,
# and that their vertex counts are within 25 % of each other (matched resolution).
# Usage: compare_isotropic.sh SOURCE_DIR PLUGIN_SO WORK_DIR
set -euo pipefail
FCVT_SOURCE_DIR="$1"; plugin="$2"; work="$3"
source "$FCVT_SOURCE_DIR/tests/meshlab/common.sh"

rm -rf "$work/out"; mkdir -p "$work/out"
server="$(stage_meshlab "$work/stage" "$plugin")"
"$FCVT_SOURCE_DIR/tests/meshlab/obj2off.sh" "$FCVT_SOURCE_DIR/resources/torus.obj" "$work/out/torus.off"
run_meshlabserver "$server" "$work/out/log.txt" -i "$work/out/torus.off" -o "$work/out/last.ply" \
  -s "$FCVT_SOURCE_DIR/resources/compare-isotropic.mlx"
log="$work/out/log.txt"
[ "$MLS_RC" -eq 0 ] || fail "meshlabserver exited with $MLS_RC"
! grep -q "Problem with filter" "$log" || fail "a filter failed"
for f in "Duplicate Current layer" "Remeshing: Isotropic Explicit Remeshing" "Change the current layer" \
         "Remeshing: Field-Aligned CVT (FCVT)" "Remeshing Quality Report (FCVT)"; do
  grep -q "filter: $f" "$log" || fail "'$f' not run"
done
# meshlabserver reprints the whole log after each filter: take the last report of each layer.
count() { grep "FCVT quality of '$1'" "$log" | tail -n 1 | sed -n 's/.*: \([0-9]*\) vertices.*/\1/p'; }
n_fcvt="$(count "torus_FCVT")"; n_iso="$(count "torus.off_copy")"
[ -n "$n_fcvt" ] && [ -n "$n_iso" ] || fail "both layers must be measured (FCVT '$n_fcvt', built-in '$n_iso')"
grep -q "FCVT quality: d_RMS .*diagonal of 'torus.off')" "$log" || fail "no distances against the input"
echo "FCVT layer $n_fcvt vertices, built-in layer $n_iso vertices"
awk -v a="$n_fcvt" -v b="$n_iso" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 0.25 * a) }' \
  || fail "vertex counts not matched: $n_fcvt vs $n_iso"
grep "FCVT quality: Q_min" "$log" | tail -n 2
echo "PASS"
