#!/usr/bin/env bash
# An invalid parameter (vertexCount 2) must fail the filter cleanly: meshlabserver reports the
# failure and exits on its own (its exit(-1), status 255), never through a signal or abort, and
# the log carries our message. Usage: invalid_parameter.sh SOURCE_DIR PLUGIN_SO WORK_DIR
set -euo pipefail
FCVT_SOURCE_DIR="$1"; plugin="$2"; work="$3"
source "$FCVT_SOURCE_DIR/tests/meshlab/common.sh"

rm -rf "$work/out"; mkdir -p "$work/out"
server="$(stage_meshlab "$work/stage" "$plugin")"
# Derived from the shipped script so every parameter stays listed (2020.09 asserts otherwise).
mlx="$work/out/invalid.mlx"
sed 's/\(name="vertexCount"[^>]*value="\)[^"]*"/\12"/' "$FCVT_SOURCE_DIR/resources/fcvt-remesh.mlx" > "$mlx"
[ "$(mlx_param "$mlx" vertexCount)" = 2 ] || fail "could not set vertexCount in $mlx"

"$FCVT_SOURCE_DIR/tests/meshlab/obj2off.sh" "$FCVT_SOURCE_DIR/resources/torus.obj" "$work/out/torus.off"
run_meshlabserver "$server" "$work/out/log.txt" -i "$work/out/torus.off" -o "$work/out/never.ply" -s "$mlx"

[ "$MLS_RC" -ne 0 ] || fail "meshlabserver succeeded with vertexCount 2"
# 128 + N is death by signal N (134 = SIGABRT); 255 is meshlabserver's own exit(-1).
if [ "$MLS_RC" -gt 128 ] && [ "$MLS_RC" -ne 255 ]; then
  fail "meshlabserver died with status $MLS_RC (signal $((MLS_RC - 128)))"
fi
grep -q "FCVT: 'Target vertices' (vertexCount) must be between 4 and 5000000, got 2" "$work/out/log.txt" \
  || fail "our error message is not in the log"
grep -q "Problem with filter: Remeshing: Field-Aligned CVT (FCVT)" "$work/out/log.txt" \
  || fail "meshlabserver did not report the filter failure"
! grep -Eq "Assertion|Aborted|terminate called" "$work/out/log.txt.err" || fail "abort in stderr"
[ ! -e "$work/out/never.ply" ] || fail "an output mesh was written despite the failure"
echo "PASS"
