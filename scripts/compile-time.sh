#!/usr/bin/env bash
# What one consumer source file costs to compile at -O2: tests/consumer/compiled.cpp, which calls the
# double and float queries (scalar for the three box kinds, batch, grid), compiled
#   1. against the compiled library's light header (<boxcyl/boxcyl.hpp>, linking boxcyl::boxcyl), and
#   2. against the header-only templates with the exact backend (boxcyl::exact: -DBOXCYL_HEADER_ONLY
#      -DBOXCYL_HAS_EXACT, plus <boxcyl/batch.hpp> and <boxcyl/grid.hpp>).
# Compile only (-c), best of RUNS (default 3) by CPU time; prints CPU seconds, wall seconds and peak memory
# of the compiler. CXX (default c++) may be overridden. Idle machines give the figures to quote: CPU time
# is less sensitive to load than wall time, not immune.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh build time
runs="${RUNS:-3}"
cxx="${CXX:-c++}"
src=tests/consumer/compiled.cpp
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

measure() {  # measure LABEL FLAGS...: best of $runs
    local label="$1"; shift
    local best="" line
    for ((r = 0; r < runs; ++r)); do
        /usr/bin/time -f "%U %S %e %M" -o "$out/time" "$cxx" -std=c++20 -O2 -Iinclude "$@" -c "$src" -o "$out/a.o"
        line="$(awk '{printf "%.2f %.2f %.0f\n", $1 + $2, $3, $4 / 1024}' "$out/time")"
        if [[ -z $best ]] || awk -v a="${line%% *}" -v b="${best%% *}" 'BEGIN { exit !(a < b) }'; then best="$line"; fi
    done
    read -r cpu wall mb <<<"$best"
    printf '%-58s %6s s CPU  %6s s wall  %5s MB\n' "$label" "$cpu" "$wall" "$mb"
}

echo "compile time of $src at -O2 ($("$cxx" --version | head -1); best of $runs):"
measure "compiled library (boxcyl::boxcyl, light header)"
measure "header-only templates (boxcyl::exact)" -DBOXCYL_HEADER_ONLY=1 -DBOXCYL_HAS_EXACT=1
