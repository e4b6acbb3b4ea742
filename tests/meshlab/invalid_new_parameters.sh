#!/usr/bin/env bash
# The issue-5 parameters of the remeshing filter fail cleanly (errorMessage in the log, no
# output, no abort): featureAngle out of 0..180; adaptive on a layer without per-vertex quality;
# adaptive with a quality that is not > 0 everywhere. And featureSelection on a mesh without a
# selection only warns, while after "Conditional Face Selection" it logs the selection's border
# edges and runs. Usage: invalid_new_parameters.sh SOURCE_DIR PLUGIN_SO WORK_DIR
set -euo pipefail
FCVT_SOURCE_DIR="$1"; plugin="$2"; work="$3"
source "$FCVT_SOURCE_DIR/tests/meshlab/common.sh"

rm -rf "$work/out"; mkdir -p "$work/out"
server="$(stage_meshlab "$work/stage" "$plugin")"
"$FCVT_SOURCE_DIR/tests/meshlab/obj2off.sh" "$FCVT_SOURCE_DIR/resources/torus.obj" "$work/out/torus.off"
# The torus with per-vertex quality = z (negative on half of it).
python3 - "$work/out/torus.off" "$work/out/torus-q.ply" <<'PY'
import sys
tok = open(sys.argv[1]).read().split()
nv, nf = int(tok[1]), int(tok[2])
v = [tok[4 + 3 * i:7 + 3 * i] for i in range(nv)]
pos, faces = 4 + 3 * nv, []
for _ in range(nf):
    n = int(tok[pos]); faces.append(tok[pos + 1:pos + 1 + n]); pos += 1 + n
with open(sys.argv[2], "w") as f:
    f.write(f"ply\nformat ascii 1.0\nelement vertex {nv}\nproperty float x\nproperty float y\nproperty float z\n"
            f"property float quality\nelement face {nf}\nproperty list uchar int vertex_indices\nend_header\n")
    for p in v: f.write(f"{p[0]} {p[1]} {p[2]} {p[2]}\n")
    for fc in faces: f.write(f"{len(fc)} {' '.join(fc)}\n")
PY

# script NAME=VALUE... -> a copy of the shipped script with those values, short runs.
script() {
  local out="$work/out/$1.mlx"; shift
  local args=(-e 's/\(name="vertexCount"[^>]*value="\)[^"]*"/\1200"/'
              -e 's/\(name="cvtIterations"[^>]*value="\)[^"]*"/\15"/'
              -e 's/\(name="fcvtIterations"[^>]*value="\)[^"]*"/\15"/')
  for kv in "$@"; do args+=(-e "s/\\(name=\"${kv%%=*}\"[^>]*value=\"\\)[^\"]*\"/\\1${kv#*=}\"/"); done
  sed "${args[@]}" "$FCVT_SOURCE_DIR/resources/fcvt-remesh.mlx" > "$out"
  echo "$out"
}

# expect_failure NAME INPUT MESSAGE NAME=VALUE...
expect_failure() {
  local name="$1" input="$2" message="$3"; shift 3
  local mlx; mlx="$(script "$name" "$@")"
  run_meshlabserver "$server" "$work/out/$name.txt" -i "$input" -o "$work/out/$name.ply" -s "$mlx"
  [ "$MLS_RC" -ne 0 ] || fail "$name: meshlabserver succeeded"
  if [ "$MLS_RC" -gt 128 ] && [ "$MLS_RC" -ne 255 ]; then fail "$name: died with status $MLS_RC"; fi
  grep -qF "$message" "$work/out/$name.txt" || fail "$name: '$message' not in the log"
  ! grep -Eq "Assertion|Aborted|terminate called" "$work/out/$name.txt.err" || fail "$name: abort in stderr"
  [ ! -e "$work/out/$name.ply" ] || fail "$name: an output was written despite the failure"
}

expect_failure angle "$work/out/torus.off" "FCVT: 'Feature angle (deg)' (featureAngle) must be 0..180 degrees (0 = off), got 200" featureAngle=200
expect_failure noquality "$work/out/torus.off" "FCVT: 'Vertex density' (adaptive) 'vertex quality' needs per-vertex quality on layer 'torus.off'" adaptive=2
expect_failure badquality "$work/out/torus-q.ply" "must be finite and above 0 at every vertex" adaptive=2

mlx="$(script selection featureSelection=true)"
run_meshlabserver "$server" "$work/out/selection.txt" -i "$work/out/torus.off" -o "$work/out/selection.ply" -s "$mlx"
[ "$MLS_RC" -eq 0 ] || fail "featureSelection without a selection: meshlabserver exited with $MLS_RC"
grep -q "'Features from selection' (featureSelection) is on but the selection of 'torus.off' (0 of" "$work/out/selection.txt" \
  || fail "featureSelection without a selection: no warning"
# A selection (faces with all corners at x > 0): its border becomes feature edges.
sel="$work/out/selected.mlx"
{
  echo '<!DOCTYPE FilterScript>'; echo '<FilterScript>'
  echo ' <filter name="Conditional Face Selection">'
  echo '  <Param type="RichString" name="condSelect" value="(x0 &gt; 0) &amp;&amp; (x1 &gt; 0) &amp;&amp; (x2 &gt; 0)" description="boolean function" tooltip="type a boolean function that will be evaluated in order to select a subset of faces&lt;br&gt;"/>'
  echo ' </filter>'
  sed -n '/<filter /,/<\/filter>/p' "$mlx"
  echo '</FilterScript>'
} > "$sel"
run_meshlabserver "$server" "$work/out/selected.txt" -i "$work/out/torus.off" -o "$work/out/selected.ply" -s "$sel"
[ "$MLS_RC" -eq 0 ] || fail "featureSelection with a selection: meshlabserver exited with $MLS_RC"
grep -Eq "FCVT features: [1-9][0-9]* edges on the border of the [1-9][0-9]* selected faces" "$work/out/selected.txt" \
  || fail "featureSelection with a selection: no feature edges logged"
echo "PASS"
