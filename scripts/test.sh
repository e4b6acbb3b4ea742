#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds, runs the sanitizer and fuzzing step
# (scripts/test-sanitizers.sh), then every CTest test (unit tests, CLI end-to-end and quality
# bars, robustness corpus, meshlabserver end-to-end, the Debian package, and label pymeshlab: the
# plugin built for MeshLab 2025.07 and run in ../shared/pymeshlab, skipped without it). Exits
# non-zero if either part fails.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bash "$here/scripts/setup.sh"
bash "$here/scripts/build.sh"

# The step's output is kept so that its findings can be printed again at the very end, where a
# CI log's tail shows them (the CTest output comes in between).
sanitizer_log="$(mktemp -t fcvt-sanitizers.XXXXXX)"
sanitizers=0
FCVT_FUZZ_SECONDS="${FCVT_FUZZ_SECONDS:-30}" bash "$here/scripts/test-sanitizers.sh" > >(tee "$sanitizer_log") 2>&1 || sanitizers=$?

cd "${FCVT_BUILD_DIR:-$here/build}"
tests=0
ctest --output-on-failure -j "$(nproc)" || tests=$?
# Label python (the module `import fcvt`, python/tests/) runs with the rest; setup.sh installs
# pybind11 and Python's headers, so no test of that label means the module was not built.
if ! ctest -N -L python | grep -q "Total Tests: [1-9]"; then
  echo "test.sh: no test of label python: the Python module was not built (pybind11-dev, python3-dev?)" >&2
  tests=1
fi
if [ "$sanitizers" -ne 0 ]; then
  echo "test.sh: the sanitizer/fuzzing step failed (exit $sanitizers); what it found:" >&2
  grep -E "FINDING|\(Failed\)|\(Subprocess aborted\)|\(Timeout\)|SUMMARY:|runtime error|ERROR:|\*\*\* \[|fatal error|Failure$|FAIL" \
    "$sanitizer_log" | head -n 40 >&2 || true
  tail -n 15 "$sanitizer_log" >&2
fi
rm -f "$sanitizer_log"
[ "$sanitizers" -eq 0 ] && [ "$tests" -eq 0 ]
