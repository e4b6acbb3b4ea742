#!/usr/bin/env bash
# debian13_meshlab_*: one of the meshlabserver tests of tests/meshlab/ run unchanged against
# MeshLab 2022.02 in the Debian 13 root (FCVT_MESHLAB_HOST, see tests/meshlab/common.sh): the
# installed package's plugin, MeshLab 2022.02's plugin manager and IO plugins, our test host in
# place of meshlabserver. Skipped (77) without the root.
# Usage: meshlab_test.sh BUILD_DIR SOURCE_DIR TEST.sh WORK_DIR [ARGS...]
set -euo pipefail
BUILD="$1"; SOURCE="$2"; test="$3"; work="$4"; shift 4
source "$SOURCE/tests/debian13/common.sh"
if [ -n "${FCVT_UPSTREAM_DOUBLE:-}" ]; then
  # forky_upstream_double_meshlab_*: the double-precision plugin, io_base and host that
  # upstream_build.sh built against MeshLab 2025.07's source (stage-host.sh, FCVT_HOST_BUILD).
  require_root
  export FCVT_HOST_BUILD="$BUILD/$tag-upstream-double"
  [ "$(cat "$FCVT_HOST_BUILD/status" 2>/dev/null)" = ok ] || fail "no upstream build (${tag}_upstream_double_build)"
else
  require_installed
fi
mkdir -p "$work"
FCVT_MESHLAB_HOST="$root" exec bash "$test" "$SOURCE" "$root$plugin_in_root" "$work" "$@"
