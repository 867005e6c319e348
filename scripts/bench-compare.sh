#!/usr/bin/env bash
# Compares the default query's time per benchmark set between two commits, side by side in one run on
# this machine: bench/bench_pipeline of each commit (built in temporary worktrees, as scripts/bench.sh builds
# it), run in turn ROUNDS times (old, new, old, new, ...), each set's median time per query taken over
# the rounds, and the ratio new/old. A change to the pipeline should leave every set within 10%.
# Usage: scripts/bench-compare.sh BASE [HEAD]     (HEAD defaults to the working tree's HEAD)
# Environment: ROUNDS (default 3), JOBS (build parallelism, default nproc), KEEP=1 keeps the worktrees.
set -euo pipefail
cd "$(dirname "$0")/.."
base=${1:?usage: scripts/bench-compare.sh BASE [HEAD]}
head=${2:-HEAD}
rounds=${ROUNDS:-3}
bash scripts/deps.sh libbenchmark-dev pkg-config
work=$(mktemp -d)
cleanup() {
    if [ "${KEEP:-0}" != 1 ]; then
        git worktree remove --force "$work/old" 2>/dev/null || true
        git worktree remove --force "$work/new" 2>/dev/null || true
        rm -rf "$work"
    fi
}
trap cleanup EXIT
for side in old new; do
    rev=$base
    [ "$side" = new ] && rev=$head
    git worktree add --detach -q "$work/$side" "$rev"
    # The benchmark as that commit names it (bench_sets at older commits).
    target=bench_pipeline
    [ -f "$work/$side/bench/bench_pipeline.cpp" ] || target=bench_sets
    echo "$target" > "$work/$side.target"
    echo "building $target at $(git -C "$work/$side" rev-parse --short HEAD) ($side)" >&2
    cmake -S "$work/$side" -B "$work/$side/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O2 -g -DNDEBUG" \
        -DBOXCYL_BUILD_BENCHMARKS=ON -DBOXCYL_BENCH_PEERS=OFF -DBOXCYL_BUILD_TESTS=OFF -DBOXCYL_BUILD_TOOLS=OFF \
        -DBOXCYL_BUILD_PYTHON=OFF -DBOXCYL_INSTALL=OFF >/dev/null
    cmake --build "$work/$side/build" -j "${JOBS:-$(nproc)}" --target "$target" >/dev/null
done
for ((r = 1; r <= rounds; ++r)); do
    for side in old new; do
        echo "round $r: $side" >&2
        "$work/$side/build/bench/$(cat "$work/$side.target")" --benchmark_filter='^[a-z_]+/default$' --benchmark_repetitions=1 \
            --benchmark_out="$work/$side.$r.json" --benchmark_out_format=json >/dev/null
    done
done
python3 - "$work" "$rounds" "$(git rev-parse --short "$base")" "$(git rev-parse --short "$head")" <<'PY'
import json, statistics, sys
work, rounds, old_rev, new_rev = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
def times(side):
    per = {}
    for r in range(1, rounds + 1):
        for b in json.load(open(f"{work}/{side}.{r}.json"))["benchmarks"]:
            if b.get("run_type") == "iteration" and b.get("items_per_second"):
                per.setdefault(b["run_name"], []).append(1e9 / b["items_per_second"])
    return {k: statistics.median(v) for k, v in per.items()}
old, new = times("old"), times("new")
print(f"| set | {old_rev} (ns per query) | {new_rev} (ns per query) | {new_rev} / {old_rev} |")
print("| --- | ---: | ---: | ---: |")
for name in old:
    if name in new:
        print(f"| {name.split('/')[0]} | {old[name]:.1f} | {new[name]:.1f} | {new[name] / old[name]:.3f} |")
PY
