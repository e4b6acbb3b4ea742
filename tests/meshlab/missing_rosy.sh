#!/usr/bin/env bash
# fieldSource = "per-vertex attribute rosy" on a mesh without that attribute must fail the
# remeshing filter cleanly: meshlabserver exits on its own (status 255), not through a signal,
# and the log carries our message. Usage: missing_rosy.sh SOURCE_DIR PLUGIN_SO WORK_DIR
set -euo pipefail
FCVT_SOURCE_DIR="$1"; plugin="$2"; work="$3"
source "$FCVT_SOURCE_DIR/tests/meshlab/common.sh"

rm -rf "$work/out"; mkdir -p "$work/out"
server="$(stage_meshlab "$work/stage" "$plugin")"
# Derived from the shipped script so every parameter stays listed; enum value 3 = the attribute.
mlx="$work/out/user-field.mlx"
sed 's/\(name="fieldSource"[^>]*value="\)[^"]*"/\13"/' "$FCVT_SOURCE_DIR/resources/fcvt-remesh.mlx" > "$mlx"
[ "$(mlx_param "$mlx" fieldSource)" = 3 ] || fail "could not set fieldSource in $mlx"

"$FCVT_SOURCE_DIR/tests/meshlab/obj2off.sh" "$FCVT_SOURCE_DIR/resources/torus.obj" "$work/out/torus.off"
run_meshlabserver "$server" "$work/out/log.txt" -i "$work/out/torus.off" -o "$work/out/never.ply" -s "$mlx"

[ "$MLS_RC" -ne 0 ] || fail "meshlabserver succeeded without a rosy attribute"
# 128 + N is death by signal N (134 = SIGABRT); 255 is meshlabserver's own exit(-1).
if [ "$MLS_RC" -gt 128 ] && [ "$MLS_RC" -ne 255 ]; then
  fail "meshlabserver died with status $MLS_RC (signal $((MLS_RC - 128)))"
fi
grep -q "FCVT: 'Field source' (fieldSource) 'per-vertex attribute rosy' needs the per-vertex Point3 attribute 'rosy' on layer 'torus.off'" \
  "$work/out/log.txt" || fail "our error message is not in the log"
grep -q "Problem with filter: Remeshing: Field-Aligned CVT (FCVT)" "$work/out/log.txt" \
  || fail "meshlabserver did not report the filter failure"
! grep -Eq "Assertion|Aborted|terminate called" "$work/out/log.txt.err" || fail "abort in stderr"
[ ! -e "$work/out/never.ply" ] || fail "an output mesh was written despite the failure"
echo "PASS"
