#!/usr/bin/env bash
# CI's sanitizer configuration (scripts/test.sh runs it after the plain suite). One clang build
# with AddressSanitizer + UndefinedBehaviorSanitizer (plus libFuzzer's coverage instrumentation, so the
# same objects serve the fuzzers) of the input-facing targets only, to stay within CI's time budget:
#   1. tests under the sanitizers: the input policy (test_validate), the CLI's JSON Lines layer and
#      its end-to-end cases (label cli, including --threads), the fuzz corpora and kept findings
#      replayed (label fuzz); randomized tests at BOXCYL_TEST_SCALE (default 0.1);
#   2. a SECONDS-long (default 20) libFuzzer run per target (scripts/fuzz.sh, same build directory).
# Every unit test under the sanitizers: scripts/test-sanitize.sh. Exits non-zero on any failure or report.
# Usage: scripts/ci-sanitize.sh [SECONDS]. BUILD_DIR (default build-ci-sanitize), JOBS may be overridden.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-20}"
export BUILD_DIR="${BUILD_DIR:-build-ci-sanitize}"
export JOBS="${JOBS:-$(nproc)}"
export FUZZ_ALSO_BUILD="test_validate test_jsonl fuzz_replay_jsonl fuzz_replay_query fuzz_replay_batch fuzz_replay_symmetry boxcyl_cli"
bash scripts/fuzz.sh 0  # configure and build only

# Left out: test_explain's placeholder (also labelled cli; not built here) and large_line_count (200,000
# lines: a minute under the sanitizers; line_count and threads run the same code under them).
ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1}" \
UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}" BOXCYL_TEST_SCALE="${BOXCYL_TEST_SCALE:-0.1}" \
    ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$JOBS" -LE long \
          -R '^(Validate\.|InputPolicy|cli\.|fuzz\.replay\.)' -E '_NOT_BUILT|large_line_count' --timeout 900

bash scripts/fuzz.sh "$seconds"
