#!/usr/bin/env bash
# Sanitizers and fuzzing (issue 6), bounded to ~12 minutes on 2 cores:
#  1. build-sanitize/: core, io, cli and tests with AddressSanitizer + UndefinedBehaviorSanitizer
#     (FCVT_SANITIZE=ON); runs the unit tests, the CLI robustness corpus and the CLI fuzzing
#     loop under them (not the slow quality bars);
#  2. if clang++ with libFuzzer is available, build-fuzz/: fuzz/fuzz_read_mesh and
#     fuzz/fuzz_remesh, each run for FCVT_FUZZ_SECONDS (default 60) from a generated seed corpus.
# Exits non-zero on any finding (test failure, sanitizer report, fuzzer crash/leak/timeout/OOM).
# Needs (Debian): clang, libclang-rt-14-dev (libFuzzer and the sanitizer runtimes), libomp-dev.
set -uo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
jobs="$(nproc)"
fuzz_seconds="${FCVT_FUZZ_SECONDS:-60}"
status=0
finding() { echo "FINDING: $*" >&2; status=1; }

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:exitcode=86:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:exitcode=87"

# --- 1. ASan + UBSan build: unit tests and the CLI robustness corpus ------------------------
san="${FCVT_SANITIZE_BUILD_DIR:-$here/build-sanitize}"
echo "== configuring $san (FCVT_SANITIZE=ON)"
cmake -S "$here" -B "$san" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFCVT_SANITIZE=ON \
      -DFCVT_BUILD_PLUGIN=OFF -DFCVT_BUILD_BENCH=OFF -DFCVT_BUILD_TESTS=ON >/dev/null || exit 1
cmake --build "$san" -j "$jobs" --target fcvt fcvt_tests || exit 1

echo "== unit tests under ASan/UBSan"
# Through CTest, one process per GoogleTest case (gtest_discover_tests): a sanitizer report
# aborts only its own test. Unit tests are the "Suite.Name" ones (the end-to-end tests differ).
ctest --test-dir "$san" -R '^[A-Za-z0-9_]+\.[A-Za-z0-9_/]+$' -j "$jobs" --output-on-failure \
      >"$san/unit-tests.log" 2>&1 || {
  finding "unit tests failed under sanitizers (log: $san/unit-tests.log)"
  grep -B2 -A12 -E "Failure$|\[  FAILED  \]|ERROR: |runtime error:" "$san/unit-tests.log" | head -n 80 >&2
}
grep -E "tests passed|tests failed|\(Failed\)|\(Subprocess aborted\)|\(Timeout\)" "$san/unit-tests.log" | tail -n 25
grep -qE "ERROR: (Address|Leak)Sanitizer|runtime error:" "$san/unit-tests.log" \
  && finding "sanitizer report in the unit tests: $(grep -m1 -E "SUMMARY: |runtime error:" "$san/unit-tests.log")"

echo "== CLI robustness corpus under ASan/UBSan"
python3 "$here/tests/robustness/run_cli.py" "$san/cli/fcvt" "$san/robustness/cli_corpus" --timeout 120 --jobs "$jobs" \
  || finding "CLI robustness corpus under sanitizers"
echo "== CLI fuzzing loop under ASan/UBSan"
python3 "$here/tests/robustness/fuzz_cli.py" "$san/cli/fcvt" "$san/robustness/cli_fuzz" --count "${FCVT_SANITIZE_FUZZ_COUNT:-100}" --timeout 60 --jobs "$jobs" \
  || finding "CLI fuzzing loop under sanitizers"

# --- 2. libFuzzer ----------------------------------------------------------------------------
cxx="${FCVT_FUZZ_CXX:-$(command -v clang++ || true)}"
probe="$(mktemp -d)"
echo 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }' > "$probe/p.cpp"
if [ -z "$cxx" ] || ! "$cxx" -fsanitize=fuzzer,address,undefined "$probe/p.cpp" -o "$probe/p" 2>/dev/null; then
  rm -rf "$probe"
  echo "== libFuzzer not available (apt-get install clang libclang-rt-14-dev libomp-dev): fuzzing skipped"
  exit $status
fi
rm -rf "$probe"

fz="${FCVT_FUZZ_BUILD_DIR:-$here/build-fuzz}"
echo "== configuring $fz (clang, FCVT_BUILD_FUZZ=ON)"
cmake -S "$here" -B "$fz" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFCVT_BUILD_FUZZ=ON \
      -DFCVT_BUILD_PLUGIN=OFF -DFCVT_BUILD_BENCH=OFF -DFCVT_BUILD_TESTS=OFF >/dev/null || exit 1
cmake --build "$fz" -j "$jobs" --target fuzz_read_mesh fuzz_remesh || exit 1
python3 "$here/fuzz/make_seeds.py" "$fz/seeds" || exit 1

run_fuzzer() {  # NAME SEED_DIR MAX_LEN
  local name="$1" seeds="$2" max_len="$3"
  local corpus="$fz/corpus/$name" artifacts="$fz/artifacts/$name/"
  # Artifacts of an earlier run in the same build folder are not this run's findings.
  rm -rf "$artifacts"
  mkdir -p "$corpus" "$artifacts"
  echo "== $name for ${fuzz_seconds}s"
  # Corpus dir first (new inputs go there), then the seeds; fixed seed for the mutations.
  ASAN_OPTIONS="$ASAN_OPTIONS:exitcode=1" "$fz/fuzz/$name" "$corpus" "$seeds" \
      -seed=6 -max_total_time="$fuzz_seconds" -max_len="$max_len" -timeout=20 -rss_limit_mb=2048 \
      -artifact_prefix="$artifacts" -print_final_stats=1 >"$fz/$name.log" 2>&1
  local rc=$?
  grep -E "^#[0-9]+ *DONE|stat::number_of_executed_units|stat::peak_rss_mb" "$fz/$name.log" | tail -n 3
  if [ $rc -ne 0 ] || ls "$artifacts" | grep -q .; then
    finding "$name: exit $rc, artifacts in $artifacts (log: $fz/$name.log; reproduce: $fz/fuzz/$name ARTIFACT)"
    grep -E "ERROR|runtime error|SUMMARY|==[0-9]+==" "$fz/$name.log" | head -n 15 >&2
  fi
}
run_fuzzer fuzz_read_mesh "$fz/seeds/read_mesh" 4096
run_fuzzer fuzz_remesh "$fz/seeds/remesh" 512

if [ $status -eq 0 ]; then echo "sanitizers and fuzzing: no findings"; else echo "sanitizers and fuzzing: FINDINGS (see above)"; fi
exit $status
