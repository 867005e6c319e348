#!/usr/bin/env bash
# Builds the unit tests and the CLI with AddressSanitizer + UndefinedBehaviorSanitizer (any report is
# fatal) and runs them all at reduced size (randomized tests at BOXCYL_TEST_SCALE, default 0.1): about
# 10 minutes of tests on one core, plus the build (docs/reliability.md). CI runs a subset of this
# (scripts/ci-sanitize.sh). Exits non-zero on any failure or sanitizer report.
# BUILD_DIR, JOBS, BOXCYL_TEST_SCALE and CXX may be overridden.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
build="${BUILD_DIR:-build-sanitize}"
jobs="${JOBS:-$(nproc)}"
san="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
# -O1 keeps the instrumented tests fast enough; assertions stay on (no -DNDEBUG), so the query's
# debug-build preconditions are checked too.
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Sanitize -DCMAKE_CXX_FLAGS_SANITIZE="-O1 -g $san" \
      -DCMAKE_EXE_LINKER_FLAGS_SANITIZE="$san" \
      -DBOXCYL_BUILD_TESTS=ON -DBOXCYL_BUILD_TOOLS=ON -DBOXCYL_BUILD_BENCHMARKS=OFF -DBOXCYL_BUILD_PYTHON=OFF \
      -DBOXCYL_INSTALL=OFF
# Every test executable (tests/test_*.cpp, the CLI's), but not the BOXCYL_CHECK_FILTER/BOXCYL_FORCE_EXACT
# copies of test_filtered (the same code paths again).
targets=(boxcyl_cli test_jsonl)
for f in tests/test_*.cpp; do targets+=("$(basename "$f" .cpp)"); done
[[ -f tools/cli/tests/test_explain.cpp ]] && targets+=(test_explain)
[[ -f fuzz/CMakeLists.txt ]] && targets+=(fuzz_replay_jsonl fuzz_replay_query)
cmake --build "$build" -j "$jobs" --target "${targets[@]}"

export ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
export BOXCYL_TEST_SCALE="${BOXCYL_TEST_SCALE:-0.1}"
# Left out: the copies not built above (and their placeholder tests).
exclude='^(checked|forced)\.|^test_filtered_(checked|forced)_NOT_BUILT$'
ctest --test-dir "$build" --output-on-failure -j "$jobs" -LE long -E "$exclude" --timeout 900
