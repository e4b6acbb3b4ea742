#!/usr/bin/env bash
# Configures and builds everything (core, fcvt CLI, MeshLab plugin, tests, benchmark) in build/.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${FCVT_BUILD_DIR:-$here/build}"
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)"
