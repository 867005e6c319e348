#!/usr/bin/env bash
# clang-tidy (bugprone-*, performance-*; see .clang-tidy) over every translation unit of a build.
# Usage: scripts/tidy.sh [build-dir]   — prints the warnings; exits 1 if there are any.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh clang-tidy libfcl-dev libbullet-dev libode-dev libmujoco-dev pkg-config
build="${1:-build-tidy}"
cmake -S . -B "$build" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -DCMAKE_BUILD_TYPE=Debug -DBOXCYL_BUILD_TESTS=ON -DBOXCYL_BUILD_TOOLS=ON \
      -DBOXCYL_BUILD_PYTHON=ON -DBOXCYL_BUILD_BENCHMARKS=ON -DBOXCYL_BENCH_PEERS=ON >/dev/null
files=$(git ls-files '*.cpp')
out=$(for f in $files; do clang-tidy -p "$build" --quiet "$f" 2>/dev/null; done | grep -E "warning:|error:" | sort -u || true)
if [ -n "$out" ]; then echo "$out"; echo "clang-tidy: $(echo "$out" | wc -l) warnings"; exit 1; fi
echo "clang-tidy: clean ($(echo "$files" | wc -w) files)"
