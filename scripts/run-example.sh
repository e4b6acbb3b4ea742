#!/usr/bin/env bash
# The main job on a bundled mesh: installs what is missing, builds, remeshes
# resources/bunny.obj to 5000 vertices and writes the result and its quality report to out/.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bash "$here/scripts/setup.sh"
bash "$here/scripts/build.sh"
mkdir -p "$here/out"
"$here/build/cli/fcvt" remesh "$here/resources/bunny.obj" "$here/out/bunny-fcvt.ply" --vertices 5000 \
  --report "$here/out/bunny-fcvt.json"
"$here/build/cli/fcvt" metrics "$here/out/bunny-fcvt.ply" --ref "$here/resources/bunny.obj"
echo "wrote $here/out/bunny-fcvt.ply and $here/out/bunny-fcvt.json"
