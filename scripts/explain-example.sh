#!/usr/bin/env bash
# Regenerates the README's picture, docs/images/explain-example.svg (and .png): `boxcyl explain` on the
# example query "oriented-miss-inside-aabb" of examples/queries.jsonl. Builds the CLI into
# build-release (or $BUILD_DIR); the PNG is rendered with rsvg-convert (Debian: librsvg2-bin).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh librsvg2-bin
build="${BUILD_DIR:-build-release}"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DBOXCYL_BUILD_TESTS=OFF -DBOXCYL_BUILD_TOOLS=ON >/dev/null
cmake --build "$build" -j "${JOBS:-$(nproc)}" --target boxcyl_cli >/dev/null
id=oriented-miss-inside-aabb
line=$(grep -n "\"id\": \"$id\"" examples/queries.jsonl | cut -d: -f1)
mkdir -p docs/images
"$build/tools/cli/boxcyl" explain --line "$line" examples/queries.jsonl -o docs/images/explain-example.svg
rsvg-convert docs/images/explain-example.svg -o docs/images/explain-example.png
echo "wrote docs/images/explain-example.svg and .png (query $id, line $line of examples/queries.jsonl)"
