#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds, runs the sanitizer and fuzzing step
# (scripts/test-sanitizers.sh), then every CTest test (unit tests, CLI end-to-end and quality
# bars, robustness corpus, meshlabserver end-to-end, the Debian package). Exits non-zero if
# either part fails.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bash "$here/scripts/setup.sh"
bash "$here/scripts/build.sh"

sanitizers=0
FCVT_FUZZ_SECONDS="${FCVT_FUZZ_SECONDS:-30}" bash "$here/scripts/test-sanitizers.sh" || sanitizers=$?

cd "${FCVT_BUILD_DIR:-$here/build}"
tests=0
ctest --output-on-failure -j "$(nproc)" || tests=$?
if [ "$sanitizers" -ne 0 ]; then echo "test.sh: the sanitizer/fuzzing step failed (exit $sanitizers)" >&2; fi
[ "$sanitizers" -eq 0 ] && [ "$tests" -eq 0 ]
