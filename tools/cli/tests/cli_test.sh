#!/usr/bin/env bash
# End-to-end tests of the boxcyl command-line tool, one case per CTest test.
# Usage: cli_test.sh CASE BOXCYL_EXE EXAMPLES_DIR EXPECTED_DIR WORK_DIR
set -u

case_name=$1
exe=$2
examples=$3
expected=$4
work=$5/$case_name
rm -rf "$work" && mkdir -p "$work" || exit 2

failures=0
fail() {
    echo "FAIL [$case_name]: $*" >&2
    failures=$((failures + 1))
}

# run EXPECTED_RC ARGS... : runs the tool with stdin from $work/stdin (if any), captures out/err/rc.
run() {
    local want=$1
    shift
    local in=/dev/null
    [[ -f $work/stdin ]] && in=$work/stdin
    "$exe" "$@" <"$in" >"$work/out" 2>"$work/err"
    rc=$?
    [[ $rc == "$want" ]] || fail "'boxcyl $*' exited $rc, expected $want; stderr: $(head -c 500 "$work/err")"
}

# same_bytes FILE EXPECTED_FILE
same_bytes() {
    if ! cmp -s "$1" "$2"; then
        fail "$1 differs from $2:"
        diff "$1" "$2" | head -20 >&2
    fi
}

contains() {  # contains FILE TEXT
    grep -qF -- "$2" "$1" || fail "$1 lacks '$2'"
}

case $case_name in
examples_default)
    run 0 intersect "$examples/queries.jsonl"
    same_bytes "$work/out" "$expected/queries.out"
    [[ -s $work/err ]] && fail "stderr not empty"
    ;;
examples_oracle)
    # The expected answers are the exact oracle's; the default algorithm must agree (above).
    run 0 intersect --algorithm oracle "$examples/queries.jsonl"
    same_bytes "$work/out" "$expected/queries.out"
    run 0 intersect --algorithm=oracle --arithmetic=float "$examples/queries.jsonl"
    same_bytes "$work/out" "$expected/queries.out"
    ;;
examples_every_algorithm)
    # Every algorithm gives the exact answers on the examples in double and in exact arithmetic.
    for alg in inequalities hull lcp; do
        for ari in double exact filtered; do
            if [[ $alg != hull && $ari == exact ]]; then continue; fi  # oriented examples: see below
            run 0 intersect --algorithm "$alg" --arithmetic "$ari" "$examples/queries.jsonl"
            same_bytes "$work/out" "$expected/queries.out"
        done
    done
    # Exact §2/§4 refuse an oriented box whose axes are orthonormal only up to rounding, naming why,
    # and answer the aligned and exactly orthonormal ones.
    printf '%s\n' \
      '{"box": {"min": [0,0,0], "max": [1,1,1]}, "cylinder": {"center": [1.5,0.5,0.5], "axis": [0,0,1], "radius": 0.5, "height": 1}}' \
      '{"box": {"center": [0,0,0], "axes": [[0.6,0.8,0],[-0.8,0.6,0],[0,0,1]], "extents": [1,1,1]}, "cylinder": {"center": [3,0,0], "axis": [0,0,1], "radius": 1, "height": 1}}' \
      > "$work/in"
    for alg in inequalities lcp; do
        run 1 intersect --algorithm "$alg" --arithmetic exact "$work/in"
        head -1 "$work/out" | grep -qx '{"intersect": true}' || fail "$alg exact: aligned line"
        sed -n 2p "$work/out" | grep -q 'exactly orthonormal' || fail "$alg exact: refusal message"
    done
    run 0 intersect --algorithm hull --arithmetic exact "$work/in"
    ;;
examples_bad_lines)
    run 1 intersect "$examples/bad_lines.jsonl"
    same_bytes "$work/out" "$expected/bad_lines.out"
    run 1 intersect --algorithm oracle "$examples/bad_lines.jsonl"
    same_bytes "$work/out" "$expected/bad_lines.out"
    ;;
stdin)
    cp "$examples/queries.jsonl" "$work/stdin"
    run 0 intersect -
    same_bytes "$work/out" "$expected/queries.out"
    run 0 intersect
    same_bytes "$work/out" "$expected/queries.out"
    cat "$examples/bad_lines.jsonl" >"$work/stdin"
    run 1 intersect -
    same_bytes "$work/out" "$expected/bad_lines.out"
    ;;
no_trailing_newline)
    head -n 3 "$examples/queries.jsonl" | head -c -1 >"$work/in"
    [[ $(tail -c 1 "$work/in" | od -An -c | tr -d ' ') == "}" ]] || fail "test input still ends in a newline"
    head -n 3 "$expected/queries.out" >"$work/want"
    run 0 intersect "$work/in"
    same_bytes "$work/out" "$work/want"
    # A bad last line without newline still gets its line.
    { head -n 2 "$examples/queries.jsonl"; printf '{"id": "x"'; } >"$work/in2"
    { head -n 2 "$expected/queries.out"; echo '{"id": "x", "error": "line 3: invalid JSON: column 11: syntax error while parsing object - unexpected end of input; expected '"'}'"'"}'; } >"$work/want2"
    run 1 intersect "$work/in2"
    same_bytes "$work/out" "$work/want2"
    # CRLF line endings are accepted (CR is JSON whitespace).
    sed 's/$/\r/' "$examples/queries.jsonl" >"$work/crlf"
    run 0 intersect "$work/crlf"
    same_bytes "$work/out" "$expected/queries.out"
    ;;
empty_input)
    : >"$work/in"
    run 0 intersect "$work/in"
    [[ -s $work/out ]] && fail "output for empty input is not empty"
    printf '\n' >"$work/in"
    run 1 intersect "$work/in"
    printf '{"error": "line 1: empty line"}\n' >"$work/want"
    same_bytes "$work/out" "$work/want"
    ;;
line_count)
    # 10,000 lines mixing good, bad and empty ones: exactly one output line each, in order.
    good='"box": {"min": [0, 0, 0], "max": [1, 1, 1]}, "cylinder": {"center": [2, 0.5, 0.5], "axis": [0, 0, 1], "radius": 1, "height": 1}'
    n=10000
    awk -v n=$n -v good="$good" 'BEGIN {
        for (i = 1; i <= n; ++i) {
            k = i % 7
            if (k == 0) print ""
            else if (k == 3) print "{\"id\": " i ", \"box\": {\"min\": [0, 0, 0]}}"
            else if (k == 5) print "{\"id\": " i ", " good
            else print "{\"id\": " i ", " good "}"
        }
    }' >"$work/in"
    [[ $(wc -l <"$work/in") == "$n" ]] || fail "generator wrote $(wc -l <"$work/in") lines"
    run 1 intersect "$work/in"
    [[ $(wc -l <"$work/out") == "$n" ]] || fail "got $(wc -l <"$work/out") output lines for $n input lines"
    awk -v n=$n '{
        i = NR; k = i % 7
        if (k == 0) want = "{\"error\": \"line " i ": empty line\"}"
        else if (k == 3) want = "{\"id\": " i ", \"error\": \"line " i ": box.max: missing\"}"
        else if (k == 5) want = "{\"id\": " i ", \"error\": \"line " i ": invalid JSON: "
        else want = "{\"id\": " i ", \"intersect\": true}"
        if (substr($0, 1, length(want)) != want) { print "line " i ": got " $0 " want " want; bad = 1; exit }
    } END { if (NR != n) { print "count " NR; bad = 1 } exit bad }' "$work/out" >&2 || fail "output lines out of order or wrong"
    ;;
exit_codes)
    cp "$examples/queries.jsonl" "$work/stdin"
    run 0 intersect "$examples/queries.jsonl"
    run 2
    contains "$work/err" "subcommand"
    run 2 frobnicate
    run 2 intersect --frobnicate
    run 2 --frobnicate intersect
    run 2 intersect --algorithm nonsense
    contains "$work/err" "nonsense"
    run 2 intersect --arithmetic quad
    run 2 intersect "$work/does-not-exist.jsonl"
    contains "$work/err" "cannot open"
    [[ -s $work/out ]] && fail "output for a missing file"
    run 2 intersect "$work"
    contains "$work/err" "directory"
    run 2 intersect a.jsonl b.jsonl
    if [[ $(id -u) != 0 ]]; then  # root reads anything
        cp "$examples/queries.jsonl" "$work/unreadable" && chmod 000 "$work/unreadable"
        run 2 intersect "$work/unreadable"
        chmod 600 "$work/unreadable"
    fi
    ;;
help_version)
    run 0 --version
    printf 'boxcyl 0.1.0\n' >"$work/want"
    same_bytes "$work/out" "$work/want"
    run 0 --help
    for phrase in "intersect" "--algorithm" "--arithmetic" "inequalities" "oracle" "float" "double" \
        '"box"' '"cylinder"' '"min"' '"max"' '"center"' '"axes"' '"extents"' '"axis"' '"radius"' '"height"' \
        '"id"' '"intersect": true' '"error"' "touching counts as intersecting" "closed" \
        "need not be unit length" "orthonormal within" "1e-4" "parallelepiped" "nearest double" \
        "17 significant digits" "EXIT STATUS" "0  every line" "1  at least one line" "2  usage error" \
        "one JSON line per input line" "empty line" "standard input"; do
        contains "$work/out" "$phrase"
    done
    run 0 -h
    contains "$work/out" "EXIT STATUS"
    run 0 intersect --help
    for phrase in "--algorithm" "--arithmetic" "inequalities" "oracle" "EXIT STATUS" "parallelepiped"; do
        contains "$work/out" "$phrase"
    done
    ;;
ids)
    good='"box": {"min": [0, 0, 0], "max": [1, 1, 1]}, "cylinder": {"center": [0, 0, 0], "axis": [0, 0, 1], "radius": 1, "height": 1}'
    {
        echo "{\"id\": 1e2, $good}"
        echo "{\"id\": 123456789012345678901234567890, $good}"
        echo "{\"id\": -0.5E-3, $good}"
        echo "{\"id\": \"caf\\u00e9 \\\"q\\\"\", $good}"
        echo "{$good, \"id\": 42}"
    } >"$work/in"
    {
        echo '{"id": 1e2, "intersect": true}'
        echo '{"id": 123456789012345678901234567890, "intersect": true}'
        echo '{"id": -0.5E-3, "intersect": true}'
        echo '{"id": "café \"q\"", "intersect": true}'
        echo '{"id": 42, "intersect": true}'
    } >"$work/want"
    run 0 intersect "$work/in"
    same_bytes "$work/out" "$work/want"
    ;;
exact_numbers)
    # One ulp decides: the point box sits exactly on the cap plane z = 1, or one ulp above it.
    cyl='"cylinder": {"center": [0, 0, 0], "axis": [0, 0, 1], "radius": 1, "height": 2}'
    {
        echo "{\"id\": 1, \"box\": {\"min\": [0, 0, 1], \"max\": [0, 0, 1]}, $cyl}"
        echo "{\"id\": 2, \"box\": {\"min\": [0, 0, 1.0000000000000002], \"max\": [0, 0, 1.0000000000000002]}, $cyl}"
        echo "{\"id\": 3, \"box\": {\"min\": [0, 0, 1.00000000000000011], \"max\": [0, 0, 2]}, $cyl}"
        echo "{\"id\": 4, \"box\": {\"min\": [0, 0, 1.00000000000000012], \"max\": [0, 0, 2]}, $cyl}"
        echo "{\"id\": 5, \"box\": {\"min\": [0, 0, 1e-400], \"max\": [4.9406564584124654e-324, 1, 1]}, $cyl}"
        echo "{\"id\": 6, \"box\": {\"min\": [0, 0, 1.7976931348623157e308], \"max\": [0, 0, 1.7976931348623157e308]}, $cyl}"
        echo "{\"id\": 7, \"box\": {\"min\": [0, 0, 1.7976931348623159e308], \"max\": [0, 0, 2]}, $cyl}"
    } >"$work/in"
    # 1.00000000000000011 is nearest to 1 (ulp 2.2e-16), 1.00000000000000012 to 1 + 2^-52.
    {
        echo '{"id": 1, "intersect": true}'
        echo '{"id": 2, "intersect": false}'
        echo '{"id": 3, "intersect": true}'
        echo '{"id": 4, "intersect": false}'
        echo '{"id": 5, "intersect": true}'
        echo '{"id": 6, "intersect": false}'
        echo '{"id": 7, "error": "line 7: box.min[2]: out of double range"}'
    } >"$work/want"
    run 1 intersect --algorithm oracle "$work/in"
    same_bytes "$work/out" "$work/want"
    ;;
float_arithmetic)
    printf '%s\n' '{"id": 1, "box": {"min": [0, 0, 0], "max": [1, 1, 1]}, "cylinder": {"center": [0, 0, 0], "axis": [0, 0, 1], "radius": 1e39, "height": 1}}' >"$work/in"
    run 0 intersect "$work/in"
    printf '%s\n' '{"id": 1, "intersect": true}' >"$work/want"
    same_bytes "$work/out" "$work/want"
    run 1 intersect --arithmetic float "$work/in"
    printf '%s\n' '{"id": 1, "error": "line 1: cylinder.radius: is +Inf after rounding to float (--arithmetic float)"}' >"$work/want"
    same_bytes "$work/out" "$work/want"
    ;;
streaming)
    # Answers come back while input is still open (an interactive filter must not wait for EOF).
    mkfifo "$work/fifo" || exit 2
    "$exe" intersect <"$work/fifo" >"$work/out" 2>"$work/err" &
    pid=$!
    exec 3>"$work/fifo"
    head -n 1 "$examples/queries.jsonl" >&3
    got=""
    for _ in $(seq 1 200); do
        [[ -s $work/out ]] && { got=$(head -n 1 "$work/out"); break; }
        sleep 0.05
    done
    [[ $got == "$(head -n 1 "$expected/queries.out")" ]] || fail "no answer before end of input (got '$got')"
    exec 3>&-
    wait "$pid" || fail "exit status $? after end of input"
    ;;
*)
    echo "unknown case $case_name" >&2
    exit 2
    ;;
esac

if ((failures > 0)); then
    echo "$case_name: $failures failure(s)" >&2
    exit 1
fi
echo "$case_name: ok"
