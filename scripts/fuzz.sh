#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/) with clang and ASan + UBSan and runs each for SECONDS (default 30).
# Usage: scripts/fuzz.sh [SECONDS] [TARGET...]   targets: jsonl query batch symmetry (default all);
# SECONDS 0: build only
# The seed corpora (fuzz/corpus/<t>) and kept findings (fuzz/regressions/<t>) are read, never written;
# inputs libFuzzer finds new coverage with go to $BUILD_DIR/corpus/<t>, crashes to $BUILD_DIR/findings/<t>.
# Exits non-zero on any finding (crash, sanitizer report, wrong answer, timeout, out of memory):
# keep the input in fuzz/regressions/<t>/ once fixed, where CTest replays it (test fuzz.replay.<t>).
# BUILD_DIR (default build-fuzz; see FUZZ_SANITIZE), JOBS and FUZZ_CXX (default clang++-14) may be overridden. FUZZ_ALSO_BUILD:
# more targets to build with the same instrumentation (then the tests are configured too), e.g. tests
# to run under the sanitizers from the same objects (scripts/ci-sanitize.sh). FUZZ_ARGS: more libFuzzer
# flags for every target, e.g. FUZZ_ARGS="-runs=100000000 -seed=1" (a run stops at whichever limit
# comes first). FUZZ_SANITIZE=0: no ASan/UBSan, -O2 (default BUILD_DIR build-fuzz-fast), for long runs of
# the fast targets (symmetry: several times the inputs per second); it finds wrong answers and
# crashes, not what only the sanitizers report. FUZZ_COVERAGE=target (implies FUZZ_SANITIZE=0; default
# BUILD_DIR build-fuzz-target): coverage only on the targets' own code (fuzz/target-coverage.txt), the
# library uninstrumented: libFuzzer explores the decoding and the metamorphic steps while the queries run
# at full speed (symmetry: four to seven times the inputs per second of the whole-library instrumentation).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-30}"
shift || true
targets=("$@")
((${#targets[@]})) || targets=(jsonl query batch symmetry)
bash scripts/deps.sh clang-14 libclang-rt-14-dev
jobs="${JOBS:-$(nproc)}"
cxx="${FUZZ_CXX:-clang++-14}"
coverage="-fsanitize=fuzzer-no-link"
if [[ ${FUZZ_COVERAGE:-all} == target ]]; then
    build="${BUILD_DIR:-build-fuzz-target}"
    san=""
    opt="-O2"
    # BOXCYL_BUILD_FUZZERS instruments the targets' objects; the allowlist keeps the library's code
    # they instantiate out of it.
    coverage="-fsanitize-coverage-allowlist=$PWD/fuzz/target-coverage.txt"
elif [[ ${FUZZ_SANITIZE:-1} == 0 ]]; then
    build="${BUILD_DIR:-build-fuzz-fast}"
    san=""
    opt="-O2"
else
    build="${BUILD_DIR:-build-fuzz}"
    san="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
    opt="-O1"
fi
# Everything is instrumented for coverage (fuzzer-no-link) unless FUZZ_COVERAGE=target; only the fuzz
# executables link libFuzzer.
cmake -S . -B "$build" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Fuzz \
      -DCMAKE_CXX_FLAGS_FUZZ="$opt -g $coverage $san" -DCMAKE_EXE_LINKER_FLAGS_FUZZ="$san" \
      -DBOXCYL_BUILD_TESTS="$([[ -n ${FUZZ_ALSO_BUILD:-} ]] && echo ON || echo OFF)" -DBOXCYL_BUILD_TOOLS=ON -DBOXCYL_BUILD_FUZZERS=ON -DBOXCYL_INSTALL=OFF \
      -DBOXCYL_BUILD_PYTHON=OFF >/dev/null
# shellcheck disable=SC2086 # FUZZ_ALSO_BUILD is a list of target names
cmake --build "$build" -j "$jobs" --target "${targets[@]/#/fuzz_}" ${FUZZ_ALSO_BUILD:-}
((seconds > 0)) || exit 0

export ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
status=0
for t in "${targets[@]}"; do
    corpus="$build/corpus/$t"
    findings="$build/findings/$t"
    mkdir -p "$corpus" "$findings"
    max_len=8192  # several JSON lines
    [[ $t == query ]] && max_len=256  # a whole query is < 150 bytes in the decoder's format
    [[ $t == batch ]] && max_len=2048  # a cylinder and up to 40 boxes
    schedule=()
    if [[ $t == symmetry ]]; then
        max_len=256  # a query and its steps
        # Its executions are cheap and each covers a deep path (tens of thousands of features in all):
        # the entropic scheduler's bookkeeping then took ~90% of the time (18 times fewer executions).
        schedule=(-entropic=0 -reload=0)
    fi
    echo "== fuzz_$t for ${seconds}s" >&2
    # shellcheck disable=SC2086 # FUZZ_ARGS is a list of flags
    if ! "$build/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 -max_len="$max_len" \
            -print_final_stats=1 -artifact_prefix="$findings/" "${schedule[@]}" ${FUZZ_ARGS:-} \
            "$corpus" "fuzz/corpus/$t" "fuzz/regressions/$t"; then
        echo "FUZZ FINDING in fuzz_$t: see $findings/ (reproduce: $build/fuzz/fuzz_$t FILE)" >&2
        status=1
    fi
done
exit $status
