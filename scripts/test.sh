#!/usr/bin/env bash
# Builds boxcyl and runs the whole test suite (everything but the "long" label) — the README's test
# command and what CI runs. Exits non-zero on any failure. BUILD_DIR and JOBS may be overridden.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
build="${BUILD_DIR:-build-test}"
jobs="${JOBS:-$(nproc)}"
# RelWithDebInfo with assertions kept on (no -DNDEBUG): preconditions are checked while testing. No -g:
# debug information makes the compiles about 40% slower (tests/test_grid.cpp, GCC 12: 31 s of CPU
# without, 43 s with) and no test reads it (a failing case prints itself; the sanitizer stage below
# keeps -g for its stack traces).
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2" \
      -DBOXCYL_BUILD_TESTS=ON -DBOXCYL_BUILD_TOOLS=ON -DBOXCYL_BUILD_PYTHON=ON
cmake --build "$build" -j "$jobs"
ctest --test-dir "$build" --output-on-failure -j "$jobs" -LE long --timeout 1500
# Then ASan + UBSan on the input-facing tests and a 20 s libFuzzer run per target, in a separate clang
# build of those targets only (docs/reliability.md). BOXCYL_CI_SANITIZE=0 skips it.
if [[ ${BOXCYL_CI_SANITIZE:-1} != 0 ]]; then
    BUILD_DIR="$build-ci-sanitize" JOBS="$jobs" bash scripts/ci-sanitize.sh 20
fi
