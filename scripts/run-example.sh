#!/usr/bin/env bash
# The main job on shipped data: builds the boxcyl CLI and answers the example queries in
# examples/queries.jsonl (one JSON line out per line in), then a one-line summary of the answers with
# their ids ("line N" for a query without one). Installs only what the CLI needs (scripts/deps.sh build);
# progress goes to stderr, answers and summary to stdout. Extra arguments go to `boxcyl intersect`.
# BUILD_DIR (default build-release) and JOBS may be overridden. Exits as the CLI does (1 if a line
# had an error).
set -euo pipefail
cd "$(dirname "$0")/.."
say() { echo "run-example: $*" >&2; }
say "checking the build dependencies (scripts/deps.sh build)"
bash scripts/deps.sh build
build="${BUILD_DIR:-build-release}"
jobs="${JOBS:-$(nproc)}"
log="$(mktemp)"
answers="$(mktemp)"
trap 'rm -f "$log" "$answers"' EXIT
say "configuring $build (Release, the command-line tool only)"
if ! cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DBOXCYL_BUILD_TOOLS=ON -DBOXCYL_BUILD_TESTS=OFF \
           -DBOXCYL_BUILD_PYTHON=OFF -DBOXCYL_BUILD_BENCHMARKS=OFF >"$log" 2>&1; then
    cat "$log" >&2
    exit 1
fi
say "building the boxcyl CLI ($jobs jobs; a few minutes on 2 cores the first time, seconds after)"
cmake --build "$build" -j "$jobs" --target boxcyl_cli >&2
say "answering examples/queries.jsonl: $build/tools/cli/boxcyl intersect ${*:+$* }examples/queries.jsonl"
rc=0
"$build/tools/cli/boxcyl" intersect "$@" examples/queries.jsonl | tee "$answers" || rc=$?
# A summary: how many answers of each kind, then which (by id, or by line number where a query has
# none), wrapped to short lines.
awk '
    function who(   id) {
        if (match($0, /^\{"id": [^,]+,/)) { id = substr($0, 8, RLENGTH - 8); return id }
        return "line " NR
    }
    function add(kind, w) { n[kind]++; ids[kind] = ids[kind] (n[kind] > 1 ? ", " : "") w }
    /"intersect": true/  { add("intersect", who()); next }
    /"intersect": false/ { add("apart", who()); next }
    /"error":/           { add("error", who()); next }
    { add("other", who()) }
    function list(kind, label,   line, count, i, word, words) {
        if (!n[kind]) return
        count = split(ids[kind], words, ", ")
        line = "  " label ":"
        for (i = 1; i <= count; ++i) {
            word = words[i] (i < count ? "," : "")
            if (length(line) + 1 + length(word) > 100) { print line; line = "   " }
            line = line " " word
        }
        print line
    }
    END {
        s = "answered " NR " queries: " n["intersect"] + 0 " intersect, " n["apart"] + 0 " apart, " \
            n["error"] + 0 (n["error"] == 1 ? " error" : " errors")
        if (n["other"]) s = s ", " n["other"] " unrecognised"
        print s
        list("intersect", "intersect"); list("apart", "apart"); list("error", "errors"); list("other", "unrecognised")
    }' "$answers"
exit "$rc"
