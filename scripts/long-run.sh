#!/usr/bin/env bash
# The long randomized runs kept out of CI (ctest label "long"), recorded in docs/long-run.md.
# exact: >= 1,000,000 exact cases per algorithm against the oracle (hours on 2 cores).
# Usage: scripts/long-run.sh [ctest -R regex, default 'exact_']
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
build="${BUILD_DIR:-build-test}"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g" -DBOXCYL_BUILD_TESTS=ON >/dev/null
cmake --build "$build" -j "$(nproc)" >/dev/null
regex="${1:-exact_}"
log=$(mktemp)
start=$(date -u +%s)
status=0
ctest --test-dir "$build" -L long -R "$regex" -j "$(nproc)" -V > "$log" 2>&1 || status=$?
end=$(date -u +%s)
{
  echo "# Long runs"
  echo
  echo "Recorded by \`scripts/long-run.sh $regex\` on $(date -u +%Y-%m-%d), $(uname -m), $(nproc) cores,"
  echo "commit $(git rev-parse --short HEAD), $(( (end - start) / 60 )) minutes. ctest exit status: $status."
  echo
  echo '```'
  grep -E "^[0-9]+: (exact|random|boundary|  \()" "$log" | sed -E 's/^[0-9]+: //'
  grep -E "tests passed|tests failed" "$log"
  echo '```'
} > docs/long-run.md
echo "wrote docs/long-run.md (ctest status $status)"
exit $status
