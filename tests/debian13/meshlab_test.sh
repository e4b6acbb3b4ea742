#!/usr/bin/env bash
# debian13_meshlab_*: one of the meshlabserver tests of tests/meshlab/ run unchanged against
# MeshLab 2022.02 in the Debian 13 root (FCVT_MESHLAB_HOST, see tests/meshlab/common.sh): the
# installed package's plugin, MeshLab 2022.02's plugin manager and IO plugins, our test host in
# place of meshlabserver. Skipped (77) without the root.
# Usage: meshlab_test.sh BUILD_DIR SOURCE_DIR TEST.sh WORK_DIR [ARGS...]
set -euo pipefail
BUILD="$1"; SOURCE="$2"; test="$3"; work="$4"; shift 4
source "$SOURCE/tests/debian13/common.sh"
require_installed
mkdir -p "$work"
FCVT_MESHLAB_HOST="$root" exec bash "$test" "$SOURCE" "$root$plugin_in_root" "$work" "$@"
