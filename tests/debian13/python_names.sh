#!/usr/bin/env bash
# The names pymeshlab gives the FCVT filters and their parameters, as MeshLab's own
# computePythonName makes them (the test host's -y, run against the release's plugin manager):
# what docs/meshlab.md tells pymeshlab users to call. Host runs only (FCVT_MESHLAB_HOST).
# Usage: python_names.sh SOURCE_DIR PLUGIN_SO WORK_DIR
set -euo pipefail
FCVT_SOURCE_DIR="$1"; plugin="$2"; work="$3"
source "$FCVT_SOURCE_DIR/tests/meshlab/common.sh"
[ -n "${FCVT_MESHLAB_HOST:-}" ] || { echo "SKIP: MeshLab 2020.09 has no pymeshlab names"; exit 77; }
rm -rf "$work/out"; mkdir -p "$work/out"
server="$(stage_meshlab "$work/stage" "$plugin")"
run_meshlabserver "$server" "$work/out/log.txt" -y "$work/out/names.txt"
[ "$MLS_RC" -eq 0 ] || fail "the host exited with $MLS_RC"
cat "$work/out/names.txt"
expect() {  # expect FILTER PARAM...: the filter's line has these parameters
  local line
  line="$(grep "^$1:" "$work/out/names.txt")" || fail "no filter named $1"
  shift
  for p in "$@"; do
    grep -qw -- "$p" <<<"$line" || fail "no parameter $p in: $line"
  done
}
expect remeshing_field_aligned_cvt_fcvt vertexcount lambda_ sizemode targetlength seed repair exactcount preset
expect compute_6_rosy_field fieldsource seed maxcrosses
expect remeshing_quality_report_fcvt referencelayer colorirregular
[ "$(wc -l < "$work/out/names.txt")" -eq 3 ] || fail "expected exactly three filters"
echo "PASS"
