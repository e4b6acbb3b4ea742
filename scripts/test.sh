#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds, runs every test (unit tests, CLI
# end-to-end and quality bars, meshlabserver end-to-end) through CTest.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bash "$here/scripts/setup.sh"
bash "$here/scripts/build.sh"
cd "${FCVT_BUILD_DIR:-$here/build}"
ctest --output-on-failure -j "$(nproc)"
