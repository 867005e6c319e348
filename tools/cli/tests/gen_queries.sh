#!/usr/bin/env bash
# Writes N generated query lines (JSON Lines for `boxcyl intersect`) to standard output: random aligned
# and oriented boxes (random rotations) and cylinders at unit scale, about half of them intersecting.
# Usage: gen_queries.sh N [SEED] [BAD_EVERY]
#   SEED       awk's random seed (default 1): the same awk and seed give the same file.
#   BAD_EVERY  when > 0, every BAD_EVERY-th line is bad instead (cycling through an empty line, a
#              truncated object, a negative radius and invalid UTF-8), to exercise the error path.
# For the line-count tests (cli.e2e.large_line_count, cli.e2e.threads) and scripts/stream-check.sh
# (the streaming measurement in docs/reliability.md).
set -euo pipefail
n=${1:?usage: gen_queries.sh N [SEED] [BAD_EVERY]}
seed=${2:-1}
bad_every=${3:-0}
LC_ALL=C awk -v n="$n" -v seed="$seed" -v bad_every="$bad_every" '
function r(lo, hi) { return lo + (hi - lo) * rand() }
function v3(a, b, c) { return sprintf("[%.17g, %.17g, %.17g]", a, b, c) }
BEGIN {
    srand(seed)
    for (i = 1; i <= n; ++i) {
        if (bad_every > 0 && i % bad_every == 0) {
            k = (i / bad_every) % 4
            if (k == 0) print ""
            else if (k == 1) print "{\"id\": " i ", \"box\": {\"min\": [0, 0"
            else if (k == 2) print "{\"id\": " i ", \"box\": {\"min\": [0, 0, 0], \"max\": [1, 1, 1]}, \"cylinder\": {\"center\": [0, 0, 0], \"axis\": [0, 0, 1], \"radius\": -1, \"height\": 1}}"
            else printf "{\"id\": %d, \"note\": \"\377\"}\n", i
            continue
        }
        cyl = sprintf("\"cylinder\": {\"center\": %s, \"axis\": %s, \"radius\": %.17g, \"height\": %.17g}",
                      v3(r(-2, 2), r(-2, 2), r(-2, 2)), v3(r(-1, 1), r(-1, 1), r(-1, 1)), r(0, 0.7), r(0, 2))
        if (rand() < 0.5) {
            x = r(-1, 0); y = r(-1, 0); z = r(-1, 0)
            box = sprintf("\"box\": {\"min\": %s, \"max\": %s}", v3(x, y, z), v3(x + r(0, 1), y + r(0, 1), z + r(0, 1)))
        } else {
            w = r(-1, 1); a = r(-1, 1); b = r(-1, 1); c = r(-1, 1)
            s = sqrt(w * w + a * a + b * b + c * c); w /= s; a /= s; b /= s; c /= s
            axes = sprintf("[%s, %s, %s]",
                           v3(1 - 2 * (b * b + c * c), 2 * (a * b + w * c), 2 * (a * c - w * b)),
                           v3(2 * (a * b - w * c), 1 - 2 * (a * a + c * c), 2 * (b * c + w * a)),
                           v3(2 * (a * c + w * b), 2 * (b * c - w * a), 1 - 2 * (a * a + b * b)))
            box = sprintf("\"box\": {\"center\": %s, \"axes\": %s, \"extents\": %s}",
                          v3(r(-0.5, 0.5), r(-0.5, 0.5), r(-0.5, 0.5)), axes, v3(r(0, 0.5), r(0, 0.5), r(0, 0.5)))
        }
        printf "{\"id\": %d, %s, %s}\n", i, box, cyl
    }
}'
