#!/usr/bin/env bash
# The staged meshlabserver loads libfilter_fcvt.so, and resources/fcvt-remesh.mlx lists as many
# parameters as the filter declares (meshlabserver 2020.09 asserts on a script missing one).
# Usage: plugin_loads.sh SOURCE_DIR PLUGIN_SO WORK_DIR
set -euo pipefail
FCVT_SOURCE_DIR="$1"; plugin="$2"; work="$3"
source "$FCVT_SOURCE_DIR/tests/meshlab/common.sh"

rm -rf "$work/out"; mkdir -p "$work/out"
server="$(stage_meshlab "$work/stage" "$plugin")"
run_meshlabserver "$server" "$work/out/log.txt" -d "$work/out/filters.txt"
[ "$MLS_RC" -eq 0 ] || fail "meshlabserver -d exited with $MLS_RC"
grep -q "Current Plugins Dir is: $work/stage/lib/x86_64-linux-gnu/meshlab/plugins" "$work/out/log.txt.err" \
  || fail "meshlabserver did not search the staged plugin directory"

# The dump has one "\section" per filter followed by one <TR> row per parameter.
declared="$(awk '/\\section /{ours = index($0, "Remeshing: Field-Aligned CVT (FCVT)") > 0; found += ours}
                 ours && /<TR>/ {n++}
                 END {if (!found) print "missing"; else print n + 0}' "$work/out/filters.txt")"
[ "$declared" != missing ] || fail "filter 'Remeshing: Field-Aligned CVT (FCVT)' not loaded"
listed="$(grep -c '<Param ' "$FCVT_SOURCE_DIR/resources/fcvt-remesh.mlx")"
echo "filter declares $declared parameters, fcvt-remesh.mlx lists $listed"
[ "$declared" -eq "$listed" ] || fail "fcvt-remesh.mlx must list every parameter of the filter"
for p in vertexCount lambda cvtIterations fcvtIterations seed; do
  grep -q "name=\"$p\"" "$FCVT_SOURCE_DIR/resources/fcvt-remesh.mlx" || fail "parameter $p missing from the .mlx"
done
echo "PASS"
