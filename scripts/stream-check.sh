#!/usr/bin/env bash
# Streaming check of `boxcyl intersect` (recorded in docs/reliability.md): generates LINES query
# lines (default 10,000,000; every 1000th bad: empty, truncated, invalid value, invalid UTF-8) with
# tools/cli/tests/gen_queries.sh, runs the Release CLI on them once per THREADS value (default 1 2)
# under /usr/bin/time -v, and prints for each run: wall time, lines/s, input MB/s, CPU time (user + sys,
# all threads) and the same rates per CPU-second (steadier than wall time on a busy machine), peak RSS.
# Checks (any failure exits non-zero): exit status 1 (the bad lines), exactly LINES output lines, in
# input order (output line i carries "id": i or starts with "line i:"), byte-identical across THREADS.
# Usage: scripts/stream-check.sh [LINES] [THREADS...]
# BUILD_DIR (default build-stream) and JOBS may be overridden. The input file (~5 GB for 10M lines) is
# kept in $BUILD_DIR/stream/ for reruns; outputs are deleted once checked.
set -euo pipefail
cd "$(dirname "$0")/.."
lines="${1:-10000000}"
shift || true
threads=("$@")
((${#threads[@]})) || threads=(1 2)
bash scripts/deps.sh time
build="${BUILD_DIR:-build-stream}"
jobs="${JOBS:-$(nproc)}"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DBOXCYL_BUILD_TOOLS=ON \
      -DBOXCYL_BUILD_PYTHON=OFF -DBOXCYL_INSTALL=OFF >/dev/null
cmake --build "$build" -j "$jobs" --target boxcyl_cli
exe="$build/tools/cli/boxcyl"

work="$build/stream"
mkdir -p "$work"
in="$work/queries-$lines.jsonl"
if [[ ! -s $in ]]; then
    echo "== generating $lines lines into $in" >&2
    bash tools/cli/tests/gen_queries.sh "$lines" 1 1000 >"$in.tmp"
    mv "$in.tmp" "$in"
fi
bytes=$(stat -c %s "$in")
echo "input: $lines lines, $bytes bytes; $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'))"

status=0
fail() {
    echo "FAIL (--threads $t): $*" >&2
    status=1
}
reference=""
for t in "${threads[@]}"; do
    out="$work/out.jsonl"
    rc=0
    start=$EPOCHREALTIME
    /usr/bin/time -v -o "$work/time.txt" "$exe" intersect --threads "$t" "$in" >"$out" || rc=$?
    end=$EPOCHREALTIME
    [[ $rc == 1 ]] || fail "exit status $rc, expected 1 (the input's bad lines)"
    got=$(wc -l <"$out")
    [[ $got == "$lines" ]] || fail "$got output lines for $lines input lines"
    LC_ALL=C awk '
        index($0, "{\"id\": " NR ", ") != 1 && index($0, "{\"error\": \"line " NR ": ") != 1 {
            print "output line " NR " out of order: " substr($0, 1, 200); bad = 1; exit
        }
        END { exit bad }' "$out" >&2 || fail "output not in input order"
    sum=$(sha256sum <"$out" | cut -d' ' -f1)
    [[ -n $reference ]] || reference=$sum
    [[ $sum == "$reference" ]] || fail "output differs from --threads ${threads[0]}'s"
    rm -f "$out"
    rss=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$work/time.txt")
    cpu=$(awk -F': ' '/User time/ {u = $2} /System time/ {s = $2} END {printf "%.1f", u + s}' "$work/time.txt")
    awk -v t="$t" -v n="$lines" -v b="$bytes" -v s="$start" -v e="$end" -v rss="$rss" -v cpu="$cpu" -v sum="$sum" 'BEGIN {
        w = e - s
        printf "--threads %s: %.1f s wall, %.0f lines/s, %.1f MB/s in; %s s CPU (%.0f lines, %.1f MB per CPU-second); peak RSS %.1f MiB; output sha256 %s\n",
               t, w, n / w, b / w / 1e6, cpu, n / cpu, b / cpu / 1e6, rss / 1024, substr(sum, 1, 16)
    }'
done
((status == 0)) && echo "ok: every run gave $lines lines in input order, byte-identical across --threads ${threads[*]}"
exit $status
