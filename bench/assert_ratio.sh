#!/usr/bin/env bash
# The default query with its precondition asserts on (built without NDEBUG) against the same query
# with them off, and validate()/is_valid() per pair: runs bench_validate and bench_validate_asserts
# (bench/bench_validate.cpp, both built by -DBOXCYL_BUILD_BENCHMARKS=ON) and prints the medians and
# the ratio per data set.
# Usage: bash bench/assert_ratio.sh BUILD_DIR [repetitions (default 5)]
set -euo pipefail
build=${1:?usage: bash bench/assert_ratio.sh BUILD_DIR [repetitions]}
reps=${2:-5}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for b in bench_validate bench_validate_asserts; do
    exe="$build/bench/$b"
    [[ -x $exe ]] || { echo "assert_ratio.sh: $exe not found (configure with -DBOXCYL_BUILD_BENCHMARKS=ON and build $b)" >&2; exit 2; }
    echo "running $b ($reps repetitions)..." >&2
    "$exe" --benchmark_repetitions="$reps" --benchmark_report_aggregates_only=true \
           --benchmark_out="$tmp/$b.json" --benchmark_out_format=json >/dev/null 2>"$tmp/$b.log" ||
        { cat "$tmp/$b.log" >&2; exit 1; }
done
/usr/bin/python3 - "$tmp/bench_validate.json" "$tmp/bench_validate_asserts.json" <<'PY'
import json, sys

def medians(path):
    with open(path) as f:
        runs = json.load(f)["benchmarks"]
    return {r["run_name"]: r["cpu_time"] for r in runs if r.get("aggregate_name") == "median"}

off, on = medians(sys.argv[1]), medians(sys.argv[2])
print(f"{'benchmark (CPU time, median)':32} {'NDEBUG':>10} {'no NDEBUG':>10} {'ratio':>6}")
for name in off:
    print(f"{name:32} {off[name]:8.1f}ns {on[name]:8.1f}ns {on[name] / off[name]:6.2f}")
PY
