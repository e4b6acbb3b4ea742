#!/usr/bin/env bash
# The remeshing filter's "Preset" (preset, the core's applyPreset, the CLI's --preset):
# resources/bunny.ply at 1000 vertices through meshlabserver with the shipped script and preset 0
# (fast), CVT and FCVT iterations left at 10 and 40 ("as the preset says"), has the vertex and
# face counts of `fcvt remesh --preset fast --vertices 1000`; and its log has no CVT phase (fast
# runs no CVT iterations), so the preset is read. A script with preset 3 fails with the message
# naming the parameter and its three values, without an abort or an output. A script without
# the parameter runs with the default where the MeshLab fills it in (2022.02's host);
# meshlabserver 2020.09 aborts on a script that lacks a parameter (reported, not failed on).
# Usage: preset.sh SOURCE_DIR PLUGIN_SO WORK_DIR FCVT_CLI
set -euo pipefail
FCVT_SOURCE_DIR="$1"; plugin="$2"; work="$3"; cli="$4"
source "$FCVT_SOURCE_DIR/tests/meshlab/common.sh"

rm -rf "$work/out"; mkdir -p "$work/out"
server="$(stage_meshlab "$work/stage" "$plugin")"
shipped="$FCVT_SOURCE_DIR/resources/fcvt-remesh.mlx"
grep -q 'name="preset" value="1"' "$shipped" || fail "no preset (default 1, default) in $shipped"
[ "$(mlx_param "$shipped" cvtIterations)" = 10 ] && [ "$(mlx_param "$shipped" fcvtIterations)" = 40 ] \
  || fail "the shipped script's CVT / FCVT iterations are not 10 / 40"
n=1000
input="$FCVT_SOURCE_DIR/resources/bunny.ply"

# filter NAME PRESET(0..|absent): the shipped script at N vertices -> $work/out/NAME.ply
filter() {
  local name="$1" mlx="$work/out/$1.mlx"
  mlx_with "$shipped" "$mlx" "$n" preset "$2"
  run_meshlabserver "$server" "$work/out/$name.txt" -i "$input" -o "$work/out/$name.ply" -s "$mlx"
}

filter fast 0
[ "$MLS_RC" -eq 0 ] || fail "preset fast: meshlabserver exited with $MLS_RC"
"$cli" remesh "$input" "$work/out/cli-fast.ply" --vertices "$n" --preset fast --quiet 2>/dev/null \
  || fail "fcvt remesh --preset fast failed"
filter_v="$(ply_count "$work/out/fast.ply" vertex)"; filter_f="$(ply_count "$work/out/fast.ply" face)"
cli_v="$(ply_count "$work/out/cli-fast.ply" vertex)"; cli_f="$(ply_count "$work/out/cli-fast.ply" face)"
echo "preset fast at $n: filter $filter_v vertices, $filter_f faces; CLI --preset fast $cli_v vertices, $cli_f faces"
[ -n "$filter_v" ] && [ -n "$filter_f" ] && [ -n "$cli_v" ] && [ -n "$cli_f" ] || fail "a count could not be read"
[ "$filter_v" = "$cli_v" ] && [ "$filter_f" = "$cli_f" ] \
  || fail "preset fast: $filter_v vertices, $filter_f faces; the CLI's --preset fast $cli_v, $cli_f"
energy="$(grep "FCVT energy at the end of each phase" "$work/out/fast.txt" || true)"
[ -n "$energy" ] || fail "preset fast: no energy line in the log"
! grep -Eq "(^|[:;] )cvt E_CVT" <<<"$energy" || fail "preset fast: a CVT phase ran (the preset was not read): $energy"

# An enum value out of range (MeshLab does not check it): the filter's message, no output.
filter range 3
[ "$MLS_RC" -ne 0 ] || fail "preset 3: meshlabserver succeeded"
if [ "$MLS_RC" -gt 128 ] && [ "$MLS_RC" -ne 255 ]; then fail "preset 3: died with status $MLS_RC"; fi
grep -qF "FCVT: 'Preset' (preset) must be 0 (fast), 1 (default) or 2 (quality), got 3" "$work/out/range.txt" \
  || fail "preset 3: the message is not in the log"
! grep -Eq "Assertion|Aborted|terminate called" "$work/out/range.txt.err" || fail "preset 3: abort in stderr"
[ ! -e "$work/out/range.ply" ] || fail "preset 3: an output was written despite the failure"

# A script without preset: the default preset.
filter absent absent
if [ "$MLS_RC" -eq 0 ]; then
  grep -Eq "(^|[:;] )cvt E_CVT" <<<"$(grep "FCVT energy at the end of each phase" "$work/out/absent.txt")" \
    || fail "a script without preset: no CVT phase (not the default preset)"
  echo "a script without preset ran with the default: $(ply_count "$work/out/absent.ply" vertex) vertices"
elif grep -q "Assertion .parameterSet.size() == required.size()' failed" "$work/out/absent.txt.err"; then
  echo "NOTE: meshlabserver 2020.09 aborts ($MLS_RC) on a script without preset: it asserts that a script lists every parameter"
else
  fail "a script without preset: exit $MLS_RC"
fi
echo "PASS"
