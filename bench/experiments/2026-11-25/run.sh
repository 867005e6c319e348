#!/usr/bin/env bash
# The ninth session's measured-and-not-kept experiments (docs/performance.md, ninth-session section),
# reproducible: each patch here is applied to the commit it was measured against, and harness.cpp (or,
# for the batch patches, bench_batch) is built from that commit with and without it and run
# alternately ROUNDS times (default 3); the best of each is printed. Times are of the machine at hand.
# Usage: bench/experiments/2026-11-25/run.sh [ROUNDS] [PATCH-NAME...]   (needs the benchmark's deps:
# scripts/deps.sh libbenchmark-dev; about a minute per patch and round on 2 cores)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../../.." && pwd)"
rounds="${1:-3}"; shift || true
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
flags=(-std=c++20 -O2 -g -DNDEBUG -ffp-contract=off -Wno-maybe-uninitialized -DBOXCYL_HAS_EXACT=1)

# patch → the commit it was measured against (7846930: the eighth session's last; 150eaa9: the unit
# axis's masks; 38d0555: the batch's gather). unit_axis_masks and batch_gather_intrinsics are the two
# changes kept (7846930 → 150eaa9 and 150eaa9 → 9edba9f, headers only); all others were not kept.
declare -A base=(
  [unit_axis_masks]=7846930 [batch_gather_intrinsics]=150eaa9
  [unnormalised]=7846930 [branchfree]=7846930 [onediv]=7846930 [newton4]=7846930 [newton2]=7846930
  [no_unit_division]=7846930 [sqrt_intrinsic]=150eaa9 [inline_overloads]=150eaa9 [max_pairs]=150eaa9
  [inside_branch_free]=150eaa9 [lambda_box_pair_inlined]=150eaa9 [lambdas_all_inlined]=150eaa9
  [count_stage0_tests]=150eaa9 [count_stage0b_steps]=150eaa9
  [batch_prefetch_256]=38d0555 [batch_prefetch_1024]=38d0555)
declare -A defines=([no_unit_division]=-DNORMALISE_AXES [count_stage0_tests]=-DCLASSES_STAGE0
                    [count_stage0b_steps]=-DCLASSES_STAGE0B)
names=("$@")
[ ${#names[@]} -gt 0 ] || names=(unit_axis_masks batch_gather_intrinsics unnormalised branchfree onediv no_unit_division newton4 newton2 sqrt_intrinsic
  inline_overloads max_pairs inside_branch_free lambda_box_pair_inlined lambdas_all_inlined
  count_stage0_tests count_stage0b_steps batch_prefetch_256 batch_prefetch_1024)

tree() {  # tree DIR COMMIT [PATCH]
    mkdir -p "$1"
    git -C "$repo" archive "$2" include src bench tests | tar -x -C "$1"
    if [ -n "${3:-}" ]; then (cd "$1" && patch -s -p1 < "$here/$3.diff"); fi
}
build() {  # build DIR NAME
    local d="$1" name="$2"
    if [[ $name == batch_* ]]; then
        (cd "$d" && g++ "${flags[@]}" -DBOXCYL_BATCH_DISPATCH=1 -DBOXCYL_BATCH_HAVE_AVX2=1 -DBOXCYL_BATCH_HAVE_AVX512=1 \
            -Iinclude -Itests bench/bench_batch.cpp src/batch/*.cpp -o run -lbenchmark -lgmpxx -lgmp -pthread)
    else
        (cd "$d" && g++ "${flags[@]}" ${defines[$name]:-} -Iinclude -Itests "$here/harness.cpp" -o run -lgmpxx -lgmp)
    fi
}
measure() {  # measure DIR NAME: one line of numbers
    if [[ $2 == batch_* ]]; then
        "$1/run" --benchmark_filter='large_batch/(voxels|random)/threads_1/(automatic|compiled)|batched/mixed/(aligned|oriented)/automatic' \
            --benchmark_min_time=0.2 2>/dev/null | grep -oE '^[a-z_]+/[a-z_/0-9]+ .*ns_per_box=[0-9.]+' |
            sed -E 's/ +[0-9].*ns_per_box=/ /; s/^(batched|large_batch)\///; s/\/automatic//; s/\/real_time//' | paste -sd' '
    else
        "$1/run" | paste -sd' '
    fi
}

for name in "${names[@]}"; do
    commit="${base[$name]}"
    echo "== $name.diff against $commit"
    tree "$work/$name/variant" "$commit" "$name"; build "$work/$name/variant" "$name"
    if [[ $name != count_* ]]; then tree "$work/$name/base" "$commit"; build "$work/$name/base" "$name"; fi
    for ((r = 1; r <= rounds; ++r)); do
        if [[ $name == count_* ]]; then "$work/$name/variant/run"; continue; fi  # classes, one line each
        echo "base:    $(measure "$work/$name/base" "$name")"
        echo "variant: $(measure "$work/$name/variant" "$name")"
    done
done
