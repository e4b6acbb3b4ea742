#!/usr/bin/env bash
# The remeshing filter's "Exact vertex count" (exactCount, the core's RemeshParams::exactCount)
# gives the CLI's vertex count: resources/necked_ring.obj (as OFF: 2020.09's OBJ importer
# aborts) at 150 vertices, where the neck is thinner than the edge length, through meshlabserver
# with the shipped script and exactCount true has as many vertices as `fcvt remesh --exact-count`
# with the same options, and with exactCount false as many as `fcvt remesh` (vertices added, said
# in the log); the two differ, so the parameter is read. A script without the parameter keeps
# the default where the MeshLab runs it (2022.02's host); meshlabserver 2020.09 aborts on a
# script that lacks a parameter (reported, not failed on).
# Usage: exact_count.sh SOURCE_DIR PLUGIN_SO WORK_DIR FCVT_CLI
set -euo pipefail
FCVT_SOURCE_DIR="$1"; plugin="$2"; work="$3"; cli="$4"
source "$FCVT_SOURCE_DIR/tests/meshlab/common.sh"

rm -rf "$work/out"; mkdir -p "$work/out"
server="$(stage_meshlab "$work/stage" "$plugin")"
shipped="$FCVT_SOURCE_DIR/resources/fcvt-remesh.mlx"
grep -q 'name="exactCount" value="false"' "$shipped" || fail "no exactCount (default false) in $shipped"
n=150
input="$work/out/necked_ring.off"
"$FCVT_SOURCE_DIR/tests/meshlab/obj2off.sh" "$FCVT_SOURCE_DIR/resources/necked_ring.obj" "$input"

# filter NAME EXACT(true|false|absent): the shipped script at N vertices -> $work/out/NAME.ply
filter() {
  local name="$1" mlx="$work/out/$1.mlx"
  mlx_with "$shipped" "$mlx" "$n" exactCount "$2"
  run_meshlabserver "$server" "$work/out/$name.txt" -i "$input" -o "$work/out/$name.ply" -s "$mlx"
}

filter exact true
[ "$MLS_RC" -eq 0 ] || fail "exactCount true: meshlabserver exited with $MLS_RC"
filter default false
[ "$MLS_RC" -eq 0 ] || fail "exactCount false: meshlabserver exited with $MLS_RC"
"$cli" remesh "$input" "$work/out/cli-exact.ply" --vertices "$n" --exact-count --quiet 2>/dev/null \
  || fail "fcvt remesh --exact-count failed"
"$cli" remesh "$input" "$work/out/cli-default.ply" --vertices "$n" --quiet 2>/dev/null || fail "fcvt remesh failed"

filter_exact="$(ply_count "$work/out/exact.ply" vertex)"
filter_default="$(ply_count "$work/out/default.ply" vertex)"
cli_exact="$(ply_count "$work/out/cli-exact.ply" vertex)"
cli_default="$(ply_count "$work/out/cli-default.ply" vertex)"
echo "vertices at $n: exactCount true: filter $filter_exact, CLI --exact-count $cli_exact;" \
  "exactCount false: filter $filter_default, CLI $cli_default"
[ -n "$filter_exact" ] && [ -n "$filter_default" ] && [ -n "$cli_exact" ] && [ -n "$cli_default" ] \
  || fail "a vertex count could not be read"
[ "$filter_exact" = "$cli_exact" ] || fail "exactCount true: $filter_exact vertices, the CLI's --exact-count $cli_exact"
[ "$filter_default" = "$cli_default" ] || fail "exactCount false: $filter_default vertices, the CLI's default $cli_default"
[ "$filter_default" -gt "$filter_exact" ] \
  || fail "exactCount false added no vertices ($filter_default, true $filter_exact): the ring no longer tears at $n"
grep -Eq "FCVT warning: [0-9]+ vertices added where the surface is thinner than the edge length" "$work/out/default.txt" \
  || fail "exactCount false: the added vertices are not in the log"
! grep -Eq "vertices added where the surface is thinner" "$work/out/exact.txt" \
  || fail "exactCount true: vertices were added"

# A script without exactCount.
filter absent absent
if [ "$MLS_RC" -eq 0 ]; then
  absent="$(ply_count "$work/out/absent.ply" vertex)"
  [ "$absent" = "$filter_default" ] || fail "a script without exactCount: $absent vertices, the default $filter_default"
  echo "a script without exactCount ran with the default: $absent vertices"
elif grep -q "Assertion .parameterSet.size() == required.size()' failed" "$work/out/absent.txt.err"; then
  echo "NOTE: meshlabserver 2020.09 aborts ($MLS_RC) on a script without exactCount: it asserts that a script lists every parameter"
else
  fail "a script without exactCount: exit $MLS_RC"
fi
echo "PASS"
