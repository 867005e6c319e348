#!/usr/bin/env bash
# The main job on shipped data: builds the boxcyl CLI and answers the example queries in
# examples/queries.jsonl (one JSON line out per line in). Extra arguments go to `boxcyl intersect`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
build="${BUILD_DIR:-build-release}"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DBOXCYL_BUILD_TESTS=OFF -DBOXCYL_BUILD_TOOLS=ON >/dev/null
cmake --build "$build" -j "$(nproc)" --target boxcyl_cli >/dev/null
"$build/tools/cli/boxcyl" intersect "$@" examples/queries.jsonl
