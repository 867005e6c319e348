#!/usr/bin/env bash
# Runs the batch tests on emulated older CPUs (qemu-user), to show that a binary linked with
# boxcyl::batch_dispatch runs on any x86-64 and picks the widest kernel the CPU has:
#   Conroe   — x86-64 with SSSE3: no POPCNT, no AVX: only the header's kernel may run;
#   Haswell  — AVX2 + FMA, no AVX-512: the AVX2 kernel.
# A leaked AVX instruction outside the kernels (see scripts/check_isa_leaks.py) would stop the first
# with SIGILL. Not part of CI (qemu-user is a large package; the leak check runs in every test run).
# Usage: scripts/check-portable.sh [BUILD_DIR]   (default build-test, built by scripts/test.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build-test}"
bash scripts/deps.sh qemu-user
for cpu in Conroe Haswell; do
    echo "== test_batch on an emulated $cpu"
    BOXCYL_TEST_SCALE="${BOXCYL_TEST_SCALE:-0.2}" qemu-x86_64 -cpu "$cpu" "$build/tests/test_batch" \
        --gtest_brief=1 2> >(grep -v "TCG doesn't support" >&2) | grep -E "kernels run here|PASSED|FAILED|tests ran"
done
