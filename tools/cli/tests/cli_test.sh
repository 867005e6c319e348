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
    # Exact lcp/inequalities refuse an oriented box whose axes are orthonormal only up to rounding, naming why,
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
parallelepipeds)
    # "kind": "parallelepiped" (any axes): the default, the oracle and exact §3 agree, in every
    # arithmetic that answers exactly; §2/§4 in exact arithmetic refuse these axes, line by line.
    for args in "" "--algorithm oracle" "--algorithm hull --arithmetic exact" "--algorithm hull" "--algorithm lcp" \
                "--algorithm oracle --arithmetic double"; do
        # shellcheck disable=SC2086
        run 0 intersect $args "$examples/parallelepipeds.jsonl"
        same_bytes "$work/out" "$expected/parallelepipeds.out"
    done
    run 1 intersect --algorithm inequalities --arithmetic exact "$examples/parallelepipeds.jsonl"
    contains "$work/out" '"error": "line 1: query failed: boxcyl: §2/§4 need an orthonormal box frame'
    ;;
parallelepipeds_touching)
    # Exactly touching integer parallelepipeds (any axes, flat ones included): the plane m·X = m·V
    # through the vertex V maximising m·X touches the box (|m| an integer, a Pythagorean quadruple); a
    # cylinder of radius k|m| whose axis is ⊥ m through V + k·m touches the box at V. Each line "t…"
    # must answer true, and its twin "m…", with the radius one ulp or so smaller, false.
    awk 'BEGIN {
        srand(7)
        split("1 2 2 3|2 3 6 7|1 4 8 9|4 4 7 9|2 6 9 11|6 6 7 11", quads, "|")
        for (n = 0; n < 300; ++n) {
            for (j = 1; j <= 3; ++j) c[j] = int(rand() * 13) - 6
            for (i = 1; i <= 3; ++i) { e[i] = int(rand() * 4); for (j = 1; j <= 3; ++j) w[i, j] = int(rand() * 13) - 6 }
            if (n % 3 == 0) {  # orthogonal axes of equal length from an integer quaternion
                qw = int(rand() * 7) - 3; qx = int(rand() * 7) - 3; qy = int(rand() * 7) - 3; qz = int(rand() * 7) - 3
                w[1,1] = qw*qw + qx*qx - qy*qy - qz*qz; w[1,2] = 2*(qx*qy + qw*qz); w[1,3] = 2*(qx*qz - qw*qy)
                w[2,1] = 2*(qx*qy - qw*qz); w[2,2] = qw*qw - qx*qx + qy*qy - qz*qz; w[2,3] = 2*(qy*qz + qw*qx)
                w[3,1] = 2*(qx*qz + qw*qy); w[3,2] = 2*(qy*qz - qw*qx); w[3,3] = qw*qw - qx*qx - qy*qy + qz*qz
            }
            split(quads[int(rand() * 6) + 1], q, " ")
            p = int(rand() * 3)
            for (j = 1; j <= 3; ++j) { m[j] = q[(j + p - 1) % 3 + 1]; if (rand() < 0.5) m[j] = -m[j] }
            for (j = 1; j <= 3; ++j) v[j] = c[j]
            for (i = 1; i <= 3; ++i) {
                d = m[1] * w[i,1] + m[2] * w[i,2] + m[3] * w[i,3]; s = d >= 0 ? e[i] : -e[i]
                for (j = 1; j <= 3; ++j) v[j] += s * w[i,j]
            }
            do { for (j = 1; j <= 3; ++j) z[j] = int(rand() * 7) - 3
                 a1 = m[2]*z[3] - m[3]*z[2]; a2 = m[3]*z[1] - m[1]*z[3]; a3 = m[1]*z[2] - m[2]*z[1] } while (a1 == 0 && a2 == 0 && a3 == 0)
            k = int(rand() * 3) + 1; r = k * q[4]; h = int(rand() * 4)
            box = sprintf("{\"kind\": \"parallelepiped\", \"center\": [%d, %d, %d], \"axes\": [[%d, %d, %d], [%d, %d, %d], [%d, %d, %d]], \"extents\": [%d, %d, %d]}",
                          c[1], c[2], c[3], w[1,1], w[1,2], w[1,3], w[2,1], w[2,2], w[2,3], w[3,1], w[3,2], w[3,3], e[1], e[2], e[3])
            cyl = sprintf("\"center\": [%d, %d, %d], \"axis\": [%d, %d, %d]", v[1] + k*m[1], v[2] + k*m[2], v[3] + k*m[3], a1, a2, a3)
            printf "{\"id\": \"t%d\", \"box\": %s, \"cylinder\": {%s, \"radius\": %d, \"height\": %d}}\n", n, box, cyl, r, h
            printf "{\"id\": \"m%d\", \"box\": %s, \"cylinder\": {%s, \"radius\": %.17g, \"height\": %d}}\n", n, box, cyl, r * (1 - 2^-53), h
        }
    }' >"$work/in"
    run 0 intersect --threads 2 "$work/in"
    [[ $(wc -l <"$work/out") == 600 ]] || fail "expected 600 answers"
    [[ $(grep -c '"id": "t[0-9]*", "intersect": true}' "$work/out") == 300 ]] || fail "a touching case did not answer true"
    [[ $(grep -c '"id": "m[0-9]*", "intersect": false}' "$work/out") == 300 ]] || fail "a near miss did not answer false"
    run 0 intersect --algorithm oracle "$work/in"
    cp "$work/out" "$work/oracle"
    run 0 intersect "$work/in"
    same_bytes "$work/out" "$work/oracle"
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
large_line_count)
    # 200,000 generated lines (every 997th bad: empty, truncated, invalid value, invalid UTF-8):
    # exactly one output line per input line, in order (the ids), and exit 1 for the bad ones.
    n=200000
    bash "$(dirname "$0")/gen_queries.sh" $n 7 997 >"$work/in"
    [[ $(wc -l <"$work/in") == "$n" ]] || fail "generator wrote $(wc -l <"$work/in") lines"
    run 1 intersect "$work/in"
    [[ $(wc -l <"$work/out") == "$n" ]] || fail "got $(wc -l <"$work/out") output lines for $n input lines"
    LC_ALL=C awk -v n=$n '{
        i = NR
        if (i % 997 == 0) { want = (i / 997) % 4 == 0 ? "{\"error\": \"line " i ": " : "{\"id\": " i ", \"error\": \"line " i ": " }
        else want = "{\"id\": " i ", \"intersect\": "
        if (substr($0, 1, length(want)) != want) { print "line " i ": got " $0 " want " want "..."; bad = 1; exit }
    } END { if (NR != n) { print "count " NR; bad = 1 } exit bad }' "$work/out" >&2 || fail "output lines out of order or wrong"
    # The answers are the oracle's (the default query is exact), line for line.
    head -n 5000 "$work/in" >"$work/head"
    run 1 intersect --algorithm oracle "$work/head"
    cp "$work/out" "$work/oracle"
    run 1 intersect "$work/head"
    same_bytes "$work/out" "$work/oracle"
    ;;
threads)
    # --threads N: byte for byte the single-threaded output and exit status, on a large generated file
    # with bad lines (every 499th: empty, truncated, invalid value, invalid UTF-8), from a file and from
    # a pipe; one output line per input line.
    n=40000  # about 10 blocks of 4096 lines
    bash "$(dirname "$0")/gen_queries.sh" $n 11 499 >"$work/in"
    [[ $(wc -l <"$work/in") == "$n" ]] || fail "generator wrote $(wc -l <"$work/in") lines"
    run 1 intersect --threads 1 "$work/in"
    mv "$work/out" "$work/serial"
    [[ $(wc -l <"$work/serial") == "$n" ]] || fail "got $(wc -l <"$work/serial") output lines for $n input lines"
    for t in 2 3 0; do
        run 1 intersect --threads $t "$work/in"
        same_bytes "$work/out" "$work/serial"
    done
    cat "$work/in" | "$exe" intersect --threads 2 >"$work/out" 2>"$work/err"
    rc=$?
    [[ $rc == 1 ]] || fail "piped --threads 2 exited $rc, expected 1"
    same_bytes "$work/out" "$work/serial"
    # The same on good lines only (exit 0) and a last line without newline.
    grep -v error "$work/serial" >/dev/null || fail "no answers"
    head -n 498 "$work/in" | head -c -1 >"$work/good"
    run 0 intersect "$work/good"
    mv "$work/out" "$work/good_serial"
    run 0 intersect --threads 2 "$work/good"
    same_bytes "$work/out" "$work/good_serial"
    run 2 intersect --threads -1 "$work/good"
    run 2 intersect --threads many "$work/good"
    ;;
hostile_bytes)
    # Raw bytes through the executable: invalid UTF-8, NUL, CR-only line, a 10 MB line (of blanks
    # inside a good query), a truncated last line. One output line each, all valid UTF-8, the good
    # lines answered, exit 1.
    good='{"id": 1, "box": {"min": [0, 0, 0], "max": [1, 1, 1]}, "cylinder": {"center": [2, 0.5, 0.5], "axis": [0, 0, 1], "radius": 1, "height": 1}}'
    {
        printf '%s\n' "$good"
        printf '{"id": "\377\376", "box": 1}\n'
        printf '\303\050\n'
        printf '{"id": 2\000, "box": 1}\n'
        printf '\r\r\n'
        head -c 10485760 /dev/zero | tr '\0' '['; printf '\n'
        printf '{"id": 3,'; head -c 10485760 /dev/zero | tr '\0' ' '; printf '%s\n' "${good#\{\"id\": 1,}"
        printf '%s' "${good:0:60}"
    } >"$work/in"
    run 1 intersect "$work/in"
    [[ $(wc -l <"$work/out") == 8 ]] || fail "got $(wc -l <"$work/out") output lines for 8 input lines"
    if command -v iconv >/dev/null; then
        iconv -f UTF-8 -t UTF-8 "$work/out" >/dev/null 2>&1 || fail "output is not valid UTF-8"
    fi
    sed -n 1p "$work/out" | grep -qx '{"id": 1, "intersect": true}' || fail "line 1"
    sed -n 2p "$work/out" | grep -q '^{"error": "line 2: invalid JSON: .*ill-formed UTF-8' || fail "line 2"
    sed -n 3p "$work/out" | grep -q '^{"error": "line 3: invalid JSON: ' || fail "line 3"
    sed -n 4p "$work/out" | grep -q '^{"id": 2, "error": "line 4: invalid JSON: ' || fail "line 4"
    sed -n 5p "$work/out" | grep -qx '{"error": "line 5: empty line"}' || fail "line 5"
    sed -n 6p "$work/out" | grep -qx '{"error": "line 6: invalid JSON: nested deeper than 256 levels"}' || fail "line 6"
    sed -n 7p "$work/out" | grep -qx '{"id": 3, "intersect": true}' || fail "line 7"
    sed -n 8p "$work/out" | grep -q '^{"id": 1, "error": "line 8: invalid JSON: ' || fail "line 8"
    ;;
exit_codes)
    cp "$examples/queries.jsonl" "$work/stdin"
    run 0 intersect "$examples/queries.jsonl"
    run 2
    contains "$work/err" "subcommand"
    run 2 frobnicate
    contains "$work/err" "unknown subcommand 'frobnicate'; valid subcommands: intersect, explain, grid"
    run 2 query "$examples/queries.jsonl"
    contains "$work/err" "unknown subcommand 'query'; valid subcommands: intersect, explain, grid"
    run 2 --frobnicate
    contains "$work/err" "unknown option '--frobnicate'"
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
        "one JSON line per input line" "empty line" "standard input" "--threads" "--max-line-bytes"; do
        contains "$work/out" "$phrase"
    done
    run 0 -h
    contains "$work/out" "EXIT STATUS"
    run 0 intersect --help
    for phrase in "--algorithm" "--arithmetic" "--threads" "--max-line-bytes" "inequalities" "oracle" "EXIT STATUS" "parallelepiped"; do
        contains "$work/out" "$phrase"
    done
    # The algorithms are named by their methods, as the --algorithm values are, not by section numbers.
    for phrase in "inequalities: the linear-inequalities method" "hull: the convex-hull method" \
        "lcp: the LCP method (convex quadratic programming" "oracle: the exact oracle"; do
        contains "$work/out" "$phrase"
    done
    grep -qi "section [0-9]" "$work/out" && fail "intersect --help names a section number"
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
    # The same with --threads 2: a partial block is answered while the input is still open.
    : >"$work/out"
    "$exe" intersect --threads 2 <"$work/fifo" >"$work/out" 2>"$work/err" &
    pid=$!
    exec 3>"$work/fifo"
    head -n 2 "$examples/queries.jsonl" >&3
    got=""
    for _ in $(seq 1 200); do
        [[ $(wc -l <"$work/out") == 2 ]] && { got=$(cat "$work/out"); break; }
        sleep 0.05
    done
    [[ $got == "$(head -n 2 "$expected/queries.out")" ]] || fail "--threads 2: no answers before end of input (got '$got')"
    exec 3>&-
    wait "$pid" || fail "--threads 2: exit status $? after end of input"
    ;;
grid_basic)
    # `boxcyl grid`: cell indices in lexicographic order, the count, ids echoed; stdin and a file.
    g4='"grid": {"origin": [0, 0, 0], "cell_size": [1, 1, 1], "counts": [4, 4, 4]}'
    g3='"grid": {"origin": [0, 0, 0], "cell_size": [1, 1, 1], "counts": [3, 3, 3]}'
    {
        echo "{\"id\": \"segment on a grid line\", $g4, \"cylinder\": {\"center\": [1, 2, 2], \"axis\": [1, 0, 0], \"radius\": 0, \"height\": 1}}"
        echo "{\"id\": 2, \"grid\": {\"origin\": [0, 0, 0], \"cell_size\": [1, 1, 1], \"counts\": [3, 0, 3]}, \"cylinder\": {\"center\": [1, 1, 1], \"axis\": [0, 0, 1], \"radius\": 1, \"height\": 1}}"
        echo "{$g3, \"cylinder\": {\"center\": [4, 1.5, 1.5], \"axis\": [0, 0, 1], \"radius\": 1, \"height\": 1}}"
        echo "{$g3, \"cylinder\": {\"center\": [4, 1.5, 1.5], \"axis\": [0, 0, 1], \"radius\": 0.99999999999999989, \"height\": 1}}"
        # With a margin: the cells within it. The segment's cells grow by half a cell; the cylinder one
        # ulp short of x = 3 reaches the face at a margin of exactly that gap, 2^-53.
        echo "{$g4, \"cylinder\": {\"center\": [1, 2, 2], \"axis\": [1, 0, 0], \"radius\": 0, \"height\": 1}, \"margin\": 0.5}"
        echo "{$g3, \"cylinder\": {\"center\": [4, 1.5, 1.5], \"axis\": [0, 0, 1], \"radius\": 0.99999999999999989, \"height\": 1}, \"margin\": 1.1102230246251565e-16}"
        echo "{$g3, \"cylinder\": {\"center\": [4, 1.5, 1.5], \"axis\": [0, 0, 1], \"radius\": 0.99999999999999989, \"height\": 1}, \"margin\": 1.1102230246251564e-16}"
    } >"$work/in"
    {
        echo '{"id": "segment on a grid line", "cells": [[0, 1, 1], [0, 1, 2], [0, 2, 1], [0, 2, 2], [1, 1, 1], [1, 1, 2], [1, 2, 1], [1, 2, 2]], "count": 8}'
        echo '{"id": 2, "cells": [], "count": 0}'
        echo '{"cells": [[2, 1, 0], [2, 1, 1], [2, 1, 2]], "count": 3}'
        echo '{"cells": [], "count": 0}'
        echo '{"cells": [[0, 1, 1], [0, 1, 2], [0, 2, 1], [0, 2, 2], [1, 1, 1], [1, 1, 2], [1, 2, 1], [1, 2, 2], [2, 1, 1], [2, 1, 2], [2, 2, 1], [2, 2, 2]], "count": 12}'
        echo '{"cells": [[2, 1, 0], [2, 1, 1], [2, 1, 2]], "count": 3}'
        echo '{"cells": [], "count": 0}'
    } >"$work/want"
    run 0 grid "$work/in"
    same_bytes "$work/out" "$work/want"
    [[ -s $work/err ]] && fail "stderr not empty"
    cp "$work/in" "$work/stdin"
    run 0 grid
    same_bytes "$work/out" "$work/want"
    run 0 grid -
    same_bytes "$work/out" "$work/want"
    rm "$work/stdin"
    run 0 grid --help
    for phrase in '"grid"' '"origin"' '"cell_size"' '"counts"' '"cells"' '"count"' "rounded once to the nearest double" \
        "lexicographic" "touching counts" "EXIT STATUS"; do
        contains "$work/out" "$phrase"
    done
    run 0 --help
    contains "$work/out" "grid"
    run 2 grid "$work/does-not-exist.jsonl"
    contains "$work/err" "cannot open"
    run 2 grid "$work"
    contains "$work/err" "directory"
    run 2 grid --frobnicate
    ;;
grid_bad_lines)
    # Each bad line gets its error line naming the field, the run goes on, exit 1.
    g='"origin": [0, 0, 0], "cell_size": [1, 1, 1]'
    c='"cylinder": {"center": [1, 1, 1], "axis": [0, 0, 1], "radius": 1, "height": 1}'
    {
        echo "{\"id\": 1, $c}"
        echo "{\"id\": 2, \"grid\": {$g, \"counts\": [2.5, 1, 1]}, $c}"
        echo "{\"id\": 3, \"grid\": {\"origin\": [0, 0, 0], \"cell_size\": [1, 0, 1], \"counts\": [1, 1, 1]}, $c}"
        echo "{\"id\": 4, \"grid\": {$g, \"counts\": [-1, 1, 1]}, $c}"
        echo "{\"id\": 5, \"grid\": {$g, \"counts\": [1, 1, 18446744073709551615]}, $c}"
        echo "{\"id\": 6, \"grid\": {$g, \"counts\": [1, 9007199254740993, 1]}, $c}"
        echo "{\"id\": 7, \"grid\": {\"origin\": [0, 0, 0], \"cell_size\": [1e300, 1, 1], \"counts\": [1000000000, 1, 1]}, $c}"
        echo "{\"id\": 8, \"grid\": {$g, \"counts\": [1, 1]}, $c}"
        echo "{\"id\": 9, \"grid\": {$g, \"counts\": [1, 1, 1]}, \"cylinder\": {\"center\": [1, 1, 1], \"axis\": [0, 0, 1], \"radius\": -1, \"height\": 1}}"
        echo ""
        echo "{\"id\": 11, \"grid\": {$g, \"counts\": [1, 1, 1], \"counts\": [2, 2, 2]}, $c}"
        echo "{\"id\": 12, \"grid\": {$g, \"counts\": [2, 2, 2]}, $c}"
        echo "{\"id\": 13, \"grid\": [1, 2, 3], $c}"
        echo "{\"id\": 14, \"grid\": {\"origin\": [0, 0, 1e999], \"cell_size\": [1, 1, 1], \"counts\": [1, 1, 1]}, $c}"
    } >"$work/in"
    {
        echo '{"id": 1, "error": "line 1: grid: missing"}'
        echo '{"id": 2, "error": "line 2: grid.counts: expected an array of 3 integers"}'
        echo '{"id": 3, "error": "line 3: grid.cell_size[1]: is not positive"}'
        echo '{"id": 4, "error": "line 4: grid.counts[0]: is negative"}'
        echo '{"id": 5, "error": "line 5: grid.counts[2]: exceeds 2^53"}'
        echo '{"id": 6, "error": "line 6: grid.counts[1]: exceeds 2^53"}'
        echo '{"id": 7, "error": "line 7: grid.counts[0]: makes the far bound origin + counts*cell_size overflow the double range"}'
        echo '{"id": 8, "error": "line 8: grid.counts: expected an array of 3 integers"}'
        echo '{"id": 9, "error": "line 9: cylinder.radius: is negative"}'
        echo '{"error": "line 10: empty line"}'
        echo '{"id": 11, "error": "line 11: grid.counts: duplicate key"}'
        echo '{"id": 12, "cells": [[0, 0, 0], [0, 0, 1], [0, 1, 0], [0, 1, 1], [1, 0, 0], [1, 0, 1], [1, 1, 0], [1, 1, 1]], "count": 8}'
        echo '{"id": 13, "error": "line 13: grid: expected an object"}'
        echo '{"id": 14, "error": "line 14: grid.origin[2]: out of double range"}'
    } >"$work/want"
    run 1 grid "$work/in"
    same_bytes "$work/out" "$work/want"
    ;;
grid_vs_intersect)
    # The grid's answer equals `intersect` asked about every cell box (dyadic bounds, printed exactly),
    # for cylinders tangent to cell faces, a disk in a grid plane, a segment on a grid line, an oblique one.
    grid='"grid": {"origin": [-1, -1, -0.5], "cell_size": [0.5, 0.5, 0.75], "counts": [6, 5, 4]}'
    cyls=(
        '{"center": [0, 0, 0], "axis": [0, 0, 1], "radius": 0.5, "height": 1.5}'
        '{"center": [0.25, 0.5, 0.25], "axis": [1, 2, 2], "radius": 0.25, "height": 3}'
        '{"center": [0, 0, 1], "axis": [0, 0, -1], "radius": 1, "height": 0}'
        '{"center": [0, 0, 0.25], "axis": [1, 0, 0], "radius": 0, "height": 1}'
        '{"center": [3, 0, 0], "axis": [1, 1, 1], "radius": 1, "height": 1}'
    )
    for n in "${!cyls[@]}"; do
        echo "{$grid, \"cylinder\": ${cyls[$n]}}" >"$work/in"
        run 0 grid "$work/in"
        sed -e 's/.*"cells": \[\(.*\)\], "count".*/\1/' -e 's/\], \[/\n/g' -e 's/[][ ]//g' "$work/out" | grep . >"$work/grid_cells" || true
        awk -v cyl="${cyls[$n]}" 'BEGIN {
            for (i = 0; i < 6; ++i) for (j = 0; j < 5; ++j) for (k = 0; k < 4; ++k)
                printf "{\"id\": \"%d,%d,%d\", \"box\": {\"min\": [%.17g, %.17g, %.17g], \"max\": [%.17g, %.17g, %.17g]}, \"cylinder\": %s}\n",
                    i, j, k, -1 + 0.5 * i, -1 + 0.5 * j, -0.5 + 0.75 * k, -1 + 0.5 * (i + 1), -1 + 0.5 * (j + 1), -0.5 + 0.75 * (k + 1), cyl
        }' >"$work/cells_in"
        run 0 intersect "$work/cells_in"
        grep '"intersect": true' "$work/out" | sed 's/{"id": "\([^"]*\)".*/\1/' >"$work/intersect_cells" || true
        same_bytes "$work/grid_cells" "$work/intersect_cells"
        [[ -s $work/grid_cells ]] || fail "cylinder $n: no cells (the case is meant to hit)"
    done
    ;;
memory_limit)
    # Under a 1 GiB address-space limit, a huge line between two good ones: the good lines are
    # answered in order, the huge one gets an error line in place, exit status 1 (a bad line).
    # An AddressSanitizer build cannot start under an address-space limit (its shadow memory): there
    # the same input runs unlimited, which still checks the line limit.
    limit=1048576
    if nm "$exe" 2>/dev/null | grep -q __asan_init; then limit=unlimited; fi
    good1='{"id": 1, "box": {"min": [0, 0, 0], "max": [1, 1, 1]}, "cylinder": {"center": [2, 0.5, 0.5], "axis": [0, 0, 1], "radius": 1, "height": 1}}'
    good3='{"id": 3, "box": {"min": [0, 0, 0], "max": [1, 1, 1]}, "cylinder": {"center": [5, 0.5, 0.5], "axis": [0, 0, 1], "radius": 1, "height": 1}}'
    # huge_line BYTES string|values: a JSON line of about BYTES bytes, one long string or many "[]".
    huge_line() {
        if [[ $2 == string ]]; then
            printf '{"id": 2, "pad": "'
            head -c "$1" /dev/zero | tr '\0' x
            printf '"}\n'
        else
            printf '{"id": 2, "pad": ['
            yes '[],' | tr -d '\n' | head -c "$1"
            printf '[]]}\n'
        fi
    }
    # run_limited EXPECTED_RC ARGS...: the tool under the limit, input from the function `input`.
    run_limited() {
        local want=$1
        shift
        input | bash -c 'ulimit -v "$1" || exit 97; shift; exec "$@"' limited "$limit" "$exe" "$@" \
            >"$work/out" 2>"$work/err"
        rc=${PIPESTATUS[1]}
        [[ $rc == "$want" ]] || fail "'boxcyl $*' under ulimit -v $limit exited $rc, expected $want; stderr: $(head -c 500 "$work/err")"
    }
    check_lines() {  # check_lines WHAT LINE2_PATTERN
        [[ $(wc -l <"$work/out") == 3 ]] || fail "$1: $(wc -l <"$work/out") output lines, expected 3"
        sed -n 1p "$work/out" | grep -qx '{"id": 1, "intersect": true}' || fail "$1: line 1: $(sed -n 1p "$work/out" | head -c 200)"
        sed -n 2p "$work/out" | grep -qx -- "$2" || fail "$1: line 2: $(sed -n 2p "$work/out" | head -c 200)"
        sed -n 3p "$work/out" | grep -qx '{"id": 3, "intersect": false}' || fail "$1: line 3: $(sed -n 3p "$work/out" | head -c 200)"
    }
    # A 256 MiB line: longer than --max-line-bytes (default 16 MiB), skipped without being kept.
    input() { echo "$good1"; huge_line 268435456 string; echo "$good3"; }
    for t in 1 2; do
        run_limited 1 intersect --threads "$t"
        check_lines "256 MiB line, --threads $t" '{"error": "line 2: line is longer than 16777216 bytes (--max-line-bytes)"}'
    done
    # The same line allowed by --max-line-bytes: read, then its parse (which copies the string twice)
    # runs out of memory or, where it fits, finds a key the format does not have; an error line in
    # place either way.
    for t in 1 2; do
        run_limited 1 intersect --threads "$t" --max-line-bytes 2000000000
        check_lines "256 MiB line allowed, --threads $t" \
            '{\("id": 2, \)\?"error": "line 2: \(out of memory \(reading\|answering\) the line\|pad: unknown key (accepted: id, box, cylinder, margin)\)"}'
    done
    # 96 MiB of small values ("[],"): the parse would need ~1 GiB; refused by the parse budget
    # (4 bytes per byte of the line) or by memory running out, the other lines answered either way.
    input() { echo "$good1"; huge_line 100663296 values; echo "$good3"; }
    for t in 1 2; do
        run_limited 1 intersect --threads "$t" --max-line-bytes 200000000
        check_lines "96 MiB of small values, --threads $t" \
            '{\("id": 2, \)\?"error": "line 2: \(too large to parse: .*\|out of memory answering the line\)"}'
    done
    # A small --max-line-bytes, and the grid subcommand under the same limit.
    input() { echo "$good1"; echo "$good3"; }
    run_limited 1 intersect --max-line-bytes 100
    grep -qxF '{"error": "line 1: line is longer than 100 bytes (--max-line-bytes)"}' "$work/out" || fail "--max-line-bytes 100"
    input() {
        echo '{"id": 1, "grid": {"origin": [0, 0, 0], "cell_size": [1, 1, 1], "counts": [1, 1, 1]}, "cylinder": {"center": [0, 0, 0], "axis": [0, 0, 1], "radius": 1, "height": 1}}'
        huge_line 268435456 string
        echo '{"id": 3, "grid": {"origin": [0, 0, 0], "cell_size": [1, 1, 1], "counts": [1, 1, 1]}, "cylinder": {"center": [5, 0, 0], "axis": [0, 0, 1], "radius": 1, "height": 1}}'
    }
    run_limited 1 grid
    printf '%s\n' '{"id": 1, "cells": [[0, 0, 0]], "count": 1}' \
        '{"error": "line 2: line is longer than 16777216 bytes (--max-line-bytes)"}' '{"id": 3, "cells": [], "count": 0}' >"$work/want"
    same_bytes "$work/out" "$work/want"
    ;;
grid_max_cells)
    # One answer is bounded: ~4e14 cells in reach is an error line in place, found without listing them.
    g='"grid": {"origin": [0, 0, 0], "cell_size": [1, 1, 1]'
    {
        echo "{\"id\": 1, $g, \"counts\": [2, 2, 2]}, \"cylinder\": {\"center\": [1, 1, 1], \"axis\": [0, 0, 1], \"radius\": 0.5, \"height\": 1}}"
        echo "{\"id\": 2, $g, \"counts\": [10000000, 10000000, 4000000]}, \"cylinder\": {\"center\": [5000000, 5000000, 2000000], \"axis\": [0, 0, 1], \"radius\": 1e8, \"height\": 1e8}}"
        echo "{\"id\": 3, $g, \"counts\": [2, 2, 2]}, \"cylinder\": {\"center\": [1, 1, 1], \"axis\": [0, 0, 1], \"radius\": 0, \"height\": 0}}"
    } >"$work/in"
    all='[[0, 0, 0], [0, 0, 1], [0, 1, 0], [0, 1, 1], [1, 0, 0], [1, 0, 1], [1, 1, 0], [1, 1, 1]]'
    run 1 grid "$work/in"
    printf '%s\n' "{\"id\": 1, \"cells\": $all, \"count\": 8}" \
        '{"id": 2, "error": "line 2: the answer has more than 1000000 cells (--max-cells)"}' \
        "{\"id\": 3, \"cells\": $all, \"count\": 8}" >"$work/want"
    same_bytes "$work/out" "$work/want"
    run 1 grid --max-cells 8 "$work/in"
    sed -n 1p "$work/out" | grep -qxF "{\"id\": 1, \"cells\": $all, \"count\": 8}" || fail "--max-cells 8: line 1"
    sed -n 2p "$work/out" | grep -qxF '{"id": 2, "error": "line 2: the answer has more than 8 cells (--max-cells)"}' || fail "--max-cells 8: line 2"
    head -n 1 "$work/in" >"$work/one"
    run 1 grid --max-cells 7 "$work/one"
    grep -qxF '{"id": 1, "error": "line 1: the answer has more than 7 cells (--max-cells)"}' "$work/out" || fail "--max-cells 7"
    run 0 grid --help
    contains "$work/out" "--max-cells"
    contains "$work/out" "--max-line-bytes"
    run 2 grid --max-cells -1 "$work/in"
    ;;
write_errors)
    # A write error is reported and exits 3, never 0 with the answers lost: a full device, and a
    # closed standard output (the tool keeps descriptor 1 taken, so no file it opens lands there).
    g='{"grid": {"origin": [0, 0, 0], "cell_size": [1, 1, 1], "counts": [2, 2, 2]}, "cylinder": {"center": [1, 1, 1], "axis": [0, 0, 1], "radius": 0.5, "height": 1}}'
    printf '%s\n' "$g" "$g" >"$work/grid.jsonl"
    # expect_write_error WHAT: rc 3 and a message naming the write failure.
    expect_write_error() {
        [[ $rc == 3 ]] || fail "$1: exited $rc, expected 3; stderr: $(head -c 300 "$work/err")"
        grep -q "^boxcyl: cannot write standard output: " "$work/err" || fail "$1: no message: $(head -c 300 "$work/err")"
    }
    if [[ -w /dev/full ]]; then
        for args in "intersect" "intersect --threads 2" "intersect --threads 3 --algorithm oracle"; do
            # shellcheck disable=SC2086
            "$exe" $args "$examples/queries.jsonl" >/dev/full 2>"$work/err"
            rc=$?
            expect_write_error "$args >/dev/full"
            contains "$work/err" "No space left on device"
        done
        "$exe" grid "$work/grid.jsonl" >/dev/full 2>"$work/err"
        rc=$?
        expect_write_error "grid >/dev/full"
        "$exe" intersect <"$examples/queries.jsonl" >/dev/full 2>"$work/err"
        rc=$?
        expect_write_error "intersect (stdin) >/dev/full"
        "$exe" --help >/dev/full 2>"$work/err"
        rc=$?
        expect_write_error "--help >/dev/full"
        # A large output fails in mid-run: the tool stops reading (it does not answer the rest in vain).
        bash "$(dirname "$0")/gen_queries.sh" 50000 3 >"$work/big"
        "$exe" intersect "$work/big" >/dev/full 2>"$work/err"
        rc=$?
        expect_write_error "50000 lines >/dev/full"
        contains "$work/err" "stopped after"
    fi
    for args in "intersect" "intersect --threads 2"; do
        # shellcheck disable=SC2086
        "$exe" $args "$examples/queries.jsonl" >&- 2>"$work/err"
        rc=$?
        expect_write_error "$args >&-"
    done
    "$exe" grid "$work/grid.jsonl" >&- 2>"$work/err"
    rc=$?
    expect_write_error "grid >&-"
    ;;
read_errors)
    # A read error is reported and exits 3 (reading a directory given as standard input: EISDIR).
    for args in "intersect" "intersect --threads 2" "grid"; do
        # shellcheck disable=SC2086
        "$exe" $args <"$work" >"$work/out" 2>"$work/err"
        rc=$?
        [[ $rc == 3 ]] || fail "$args <dir: exited $rc, expected 3"
        contains "$work/err" "boxcyl: cannot read standard input: Is a directory"
    done
    ;;
threads_unavailable)
    # Threads that cannot be started (here: their stacks do not fit an address-space limit) are not a
    # usage error: a message and exit 4, nothing read. An AddressSanitizer build cannot start under an
    # address-space limit (its shadow memory): skipped there.
    if nm "$exe" 2>/dev/null | grep -q __asan_init; then
        echo "threads_unavailable: skipped (AddressSanitizer build)"
        exit 0
    fi
    bash -c 'ulimit -v 600000 || exit 97; exec "$@"' limited "$exe" intersect --threads 1024 "$examples/queries.jsonl" \
        >"$work/out" 2>"$work/err"
    rc=$?
    [[ $rc == 4 ]] || fail "--threads 1024 under ulimit -v 600000: exited $rc, expected 4; stderr: $(head -c 300 "$work/err")"
    contains "$work/err" "boxcyl: cannot start the threads of --threads 1024: "
    [[ -s $work/out ]] && fail "output although nothing was answered"
    run 0 --help
    contains "$work/out" "4  out of resources"
    ;;
signals)
    # SIGTERM / SIGINT: reading stops; every line read in full is answered and written, in input order,
    # each with its newline; a line cut short is not answered; exit 128 + the signal, and a message.
    mkfifo "$work/fifo" || exit 2
    n=3000
    bash "$(dirname "$0")/gen_queries.sh" $n 5 >"$work/in"
    run 0 intersect "$work/in"
    mv "$work/out" "$work/all"
    # start ARGS...: the tool on the FIFO in the background (pid in $pid), the FIFO open on fd 3.
    start() {
        "$exe" "$@" <"$work/fifo" >"$work/out" 2>"$work/err" &
        pid=$!
        exec 3>"$work/fifo"
    }
    # stop SIGNAL RC: signals the tool, waits for it, checks its exit status.
    stop() {
        kill -s "$1" "$pid"
        wait "$pid"
        rc=$?
        exec 3>&-
        [[ $rc == "$2" ]] || fail "$1: exited $rc, expected $2; stderr: $(head -c 300 "$work/err")"
    }
    # wait_lines N: until the output has N lines (at most 30 s).
    wait_lines() {
        for _ in $(seq 1 600); do
            [[ $(wc -l <"$work/out") -ge $1 ]] && return 0
            sleep 0.05
        done
        return 1
    }
    # answered_prefix: the output is the answers to the first K lines, complete and in order, K as
    # the message says.
    answered_prefix() {
        local k
        k=$(sed -n 's/.*the \([0-9]*\) lines read in full are answered.*/\1/p' "$work/err")
        [[ -n $k ]] || { fail "$1: no 'stopped by' message: $(head -c 300 "$work/err")"; return; }
        head -n "$k" "$work/all" >"$work/want"
        same_bytes "$work/out" "$work/want"
    }
    for args in "intersect" "intersect --threads 3"; do
        # 1. Idle when the signal comes: the 40 lines sent are answered, the partial 41st is not.
        # shellcheck disable=SC2086
        start $args
        head -n 40 "$work/in" >&3
        wait_lines 40 || fail "$args: the first 40 answers did not come"
        sed -n 41p "$work/in" | head -c 50 >&3
        sleep 0.5
        stop TERM 143
        head -n 40 "$work/all" >"$work/want"
        same_bytes "$work/out" "$work/want"
        contains "$work/err" "boxcyl: stopped by SIGTERM: the 40 lines read in full are answered"
        # 2. Busy when the signal comes: whatever was read in full is answered, nothing else.
        # shellcheck disable=SC2086
        start $args
        cat "$work/in" >&3 &
        feeder=$!
        sleep 0.3
        stop TERM 143
        wait "$feeder" 2>/dev/null
        answered_prefix "$args, busy"
        # 3. SIGINT (job control on, so that the background tool does not ignore it).
        set -m
        # shellcheck disable=SC2086
        start $args
        set +m
        head -n 7 "$work/in" >&3
        wait_lines 7 || fail "$args: the first 7 answers did not come"
        stop INT 130
        head -n 7 "$work/all" >"$work/want"
        same_bytes "$work/out" "$work/want"
        contains "$work/err" "boxcyl: stopped by SIGINT"
    done
    # grid: the same; the answers to the two lines come while part of the third waits (they are
    # handed over before a read that waits).
    g='{"grid": {"origin": [0, 0, 0], "cell_size": [1, 1, 1], "counts": [2, 2, 2]}, "cylinder": {"center": [1, 1, 1], "axis": [0, 0, 1], "radius": 0.5, "height": 1}}'
    start grid
    printf '%s\n%s\n%s' "$g" "$g" "${g:0:30}" >&3
    wait_lines 2 || fail "grid: the first 2 answers did not come"
    sleep 0.3
    stop TERM 143
    printf '%s\n' '{"cells": [[0, 0, 0], [0, 0, 1], [0, 1, 0], [0, 1, 1], [1, 0, 0], [1, 0, 1], [1, 1, 0], [1, 1, 1]], "count": 8}' \
        '{"cells": [[0, 0, 0], [0, 0, 1], [0, 1, 0], [0, 1, 1], [1, 0, 0], [1, 0, 1], [1, 1, 0], [1, 1, 1]], "count": 8}' >"$work/want"
    same_bytes "$work/out" "$work/want"
    run 0 --help
    contains "$work/out" "143 for SIGTERM"
    ;;
nul_and_trailing_bytes)
    # A valid query followed by a NUL byte or by anything but blanks is a bad line, never answered as
    # the query before it.
    good='{"id": 1, "box": {"min": [0, 0, 0], "max": [1, 1, 1]}, "cylinder": {"center": [2, 0.5, 0.5], "axis": [0, 0, 1], "radius": 1, "height": 1}}'
    {
        printf '%s\000 junk\n' "$good"
        printf '%s\000\n' "$good"
        printf '%s junk\n' "$good"
        printf '%s }\n' "$good"
        printf '%s \t\r\n' "$good"
        printf '{"id": 6, "box": {"min": [0, 0, 0], "max": [1, 1, 1]}, "cylinder": {"center": [2, 0.5, 0.5], "axis": [0, 0, 1], "radius": 1, "height": 1\000}}\n'
    } >"$work/in"
    for t in 1 2; do
        run 1 intersect --threads $t "$work/in"
        [[ $(wc -l <"$work/out") == 6 ]] || fail "got $(wc -l <"$work/out") output lines for 6 input lines"
        col=$((${#good} + 1))
        sed -n 1p "$work/out" | grep -qxF "{\"id\": 1, \"error\": \"line 1: invalid JSON: column $col: a NUL byte (not allowed in JSON text; inside a string write \\\\u0000)\"}" || fail "line 1: $(sed -n 1p "$work/out")"
        sed -n 2p "$work/out" | grep -q "^{\"id\": 1, \"error\": \"line 2: invalid JSON: column $col: a NUL byte" || fail "line 2: $(sed -n 2p "$work/out")"
        sed -n 3p "$work/out" | grep -q '^{"id": 1, "error": "line 3: invalid JSON: .*expected end of input' || fail "line 3: $(sed -n 3p "$work/out")"
        sed -n 4p "$work/out" | grep -q '^{"id": 1, "error": "line 4: invalid JSON: .*expected end of input' || fail "line 4: $(sed -n 4p "$work/out")"
        sed -n 5p "$work/out" | grep -qx '{"id": 1, "intersect": true}' || fail "line 5: $(sed -n 5p "$work/out")"
        sed -n 6p "$work/out" | grep -q '^{"id": 6, "error": "line 6: invalid JSON: column [0-9]*: a NUL byte' || fail "line 6: $(sed -n 6p "$work/out")"
    done
    g='{"grid": {"origin": [0, 0, 0], "cell_size": [1, 1, 1], "counts": [1, 1, 1]}, "cylinder": {"center": [0, 0, 0], "axis": [0, 0, 1], "radius": 1, "height": 1}}'
    printf '%s\000 junk\n' "$g" >"$work/grid"
    run 1 grid "$work/grid"
    contains "$work/out" "\"error\": \"line 1: invalid JSON: column $((${#g} + 1)): a NUL byte"
    ;;
unknown_keys)
    # A key the format does not have makes the line bad, named with the key nearest to it; every
    # object the tool reads (the line, box, cylinder, grid).
    b='"box": {"min": [0, 0, 0], "max": [1, 1, 1]}'
    c='"center": [2, 0.5, 0.5], "axis": [0, 0, 1], "radius": 1'
    {
        echo "{\"id\": 1, $b, \"cylinder\": {$c, \"height\": 1, \"heigth\": 5}}"
        echo "{\"id\": 2, $b, \"cylinder\": {$c, \"half_height\": 0.5}}"
        echo "{\"id\": 3, \"box\": {\"min\": [0, 0, 0], \"max\": [1, 1, 1], \"colour\": \"red\"}, \"cylinder\": {$c, \"height\": 1}}"
        echo "{\"id\": 4, \"comment\": \"x\", $b, \"cylinder\": {$c, \"height\": 1}}"
        echo "{\"id\": 5, \"boxx\": {}, $b, \"cylinder\": {$c, \"height\": 1}}"
        echo "{\"id\": 6, \"box\": {\"kind\": \"oriented\", \"center\": [0, 0, 0], \"axis\": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], \"extents\": [1, 1, 1]}, \"cylinder\": {$c, \"height\": 1}}"
        echo "{\"id\": 7, $b, \"cylinder\": {$c, \"height\": 1}}"
    } >"$work/in"
    {
        echo '{"id": 1, "error": "line 1: cylinder.heigth: unknown key; did you mean \"height\"? (accepted: center, axis, radius, height)"}'
        echo '{"id": 2, "error": "line 2: cylinder.half_height: unknown key; did you mean \"height\" (the full height, end to end, not half of it)? (accepted: center, axis, radius, height)"}'
        echo '{"id": 3, "error": "line 3: box.colour: unknown key (accepted: kind, min, max, center, axes, extents)"}'
        echo '{"id": 4, "error": "line 4: comment: unknown key (accepted: id, box, cylinder, margin)"}'
        echo '{"id": 5, "error": "line 5: boxx: unknown key; did you mean \"box\"? (accepted: id, box, cylinder, margin)"}'
        echo '{"id": 6, "error": "line 6: box.axis: unknown key; did you mean \"axes\"? (accepted: kind, min, max, center, axes, extents)"}'
        echo '{"id": 7, "intersect": true}'
    } >"$work/want"
    run 1 intersect "$work/in"
    same_bytes "$work/out" "$work/want"
    g='"grid": {"origin": [0, 0, 0], "cell_size": [1, 1, 1], "counts": [1, 1, 1]'
    {
        echo "{$g, \"cellsize\": [1, 1, 1]}, \"cylinder\": {\"center\": [0, 0, 0], \"axis\": [0, 0, 1], \"radius\": 1, \"height\": 1}}"
        echo "{$g}, \"cylinder\": {\"center\": [0, 0, 0], \"axis\": [0, 0, 1], \"radius\": 1, \"heigth\": 1}}"
        echo "{$g}, \"box\": {}, \"cylinder\": {\"center\": [0, 0, 0], \"axis\": [0, 0, 1], \"radius\": 1, \"height\": 1}}"
    } >"$work/in"
    {
        echo '{"error": "line 1: grid.cellsize: unknown key; did you mean \"cell_size\"? (accepted: origin, cell_size, counts)"}'
        echo '{"error": "line 2: cylinder.heigth: unknown key; did you mean \"height\"? (accepted: center, axis, radius, height)"}'
        echo '{"error": "line 3: box: unknown key (accepted: id, grid, cylinder, margin)"}'
    } >"$work/want"
    run 1 grid "$work/in"
    same_bytes "$work/out" "$work/want"
    ;;
skewed_frames)
    # An oriented box whose axes are 4e-5 from orthonormal (valid: within 1e-4) is the parallelepiped
    # they span: near the corner (1000.04, 1000) its face x0 = 1000 lies 0.04 beyond x = 1000. A
    # cylinder overlapping that face by 0.02 intersects; one 0.02 short of it does not. Every algorithm
    # in every arithmetic agrees (in float and double the axes send the query to the convex-hull method).
    box='"box": {"center": [0, 0, 0], "axes": [[1, 0, 0], [4e-5, 1, 0], [0, 0, 1]], "extents": [1000, 1000, 1000]}'
    {
        echo "{\"id\": \"overlap 0.02\", $box, \"cylinder\": {\"center\": [1000.51996, 999, 0], \"axis\": [0, 0, 1], \"radius\": 0.5, \"height\": 10}}"
        echo "{\"id\": \"gap 0.02\", $box, \"cylinder\": {\"center\": [1000.55996, 999, 0], \"axis\": [0, 0, 1], \"radius\": 0.5, \"height\": 10}}"
        echo "{\"id\": \"kind parallelepiped\", \"box\": {\"kind\": \"parallelepiped\", \"center\": [0, 0, 0], \"axes\": [[1, 0, 0], [4e-5, 1, 0], [0, 0, 1]], \"extents\": [1000, 1000, 1000]}, \"cylinder\": {\"center\": [1000.51996, 999, 0], \"axis\": [0, 0, 1], \"radius\": 0.5, \"height\": 10}}"
    } >"$work/in"
    printf '%s\n' '{"id": "overlap 0.02", "intersect": true}' '{"id": "gap 0.02", "intersect": false}' \
        '{"id": "kind parallelepiped", "intersect": true}' >"$work/want"
    run 0 intersect --algorithm oracle "$work/in"
    same_bytes "$work/out" "$work/want"
    for alg in inequalities hull lcp; do
        for ari in filtered double float; do
            run 0 intersect --algorithm $alg --arithmetic $ari "$work/in"
            same_bytes "$work/out" "$work/want"
        done
    done
    run 0 intersect --help
    contains "$work/out" "2^-49"
    ;;
distance_basic)
    # boxcyl distance: a proved enclosure [lower, upper] of the distance and a nearest pair, one line
    # per input line; bad lines as intersect reports them; a margin refused; no arithmetic to choose.
    box='"box": {"min": [0, 0, 0], "max": [1, 1, 1]}'
    printf '%s\n' \
      "{\"id\": \"one\", $box, \"cylinder\": {\"center\": [3, 0.5, 0.5], \"axis\": [0, 0, 1], \"radius\": 1, \"height\": 1}}" \
      "{\"id\": \"touch\", $box, \"cylinder\": {\"center\": [2, 0.5, 0.5], \"axis\": [0, 0, 1], \"radius\": 1, \"height\": 1}}" \
      "{\"id\": \"bad\", $box, \"cylinder\": {\"center\": [2, 0.5, 0.5], \"axis\": [0, 0, 0], \"radius\": 1, \"height\": 1}}" \
      "{\"id\": \"m\", $box, \"cylinder\": {\"center\": [2, 0.5, 0.5], \"axis\": [0, 0, 1], \"radius\": 1, \"height\": 1}, \"margin\": 1}" \
      '{"id": "far", "box": {"min": [-1e308, 0, 0], "max": [-1e308, 1, 1]}, "cylinder": {"center": [1e308, 0.5, 0.5], "axis": [0, 0, 1], "radius": 1, "height": 1}}' \
      >"$work/in"
    run 1 distance "$work/in"
    [[ $(wc -l <"$work/out") == 5 ]] || fail "expected 5 output lines, got $(wc -l <"$work/out")"
    [[ -s $work/err ]] && fail "stderr not empty: $(head -c 300 "$work/err")"
    # Distance exactly 1: lower <= 1 <= upper, a few ulps wide (awk reads each number as the nearest double).
    sed -n 1p "$work/out" | grep -q '^{"id": "one", "lower": [0-9.e+-]*, "upper": [0-9.e+-]*, "on_box": \[.*\], "on_cylinder": \[.*\]}$' ||
        fail "line 1 is not a distance line: $(sed -n 1p "$work/out")"
    sed -n 1p "$work/out" | awk -F'[:,] *' '{ lo = $4 + 0; hi = $6 + 0; exit !(lo <= 1 && hi >= 1 && hi - lo <= 1e-15) }' ||
        fail "line 1: not a tight enclosure of 1: $(sed -n 1p "$work/out")"
    sed -n 2p "$work/out" | grep -q '^{"id": "touch", "lower": 0, "upper": 0, "on_box": \[' ||
        fail "touching: not exactly 0: $(sed -n 2p "$work/out")"
    sed -n 3p "$work/out" | grep -qxF '{"id": "bad", "error": "line 3: cylinder.axis: is the zero vector"}' ||
        fail "invalid line: $(sed -n 3p "$work/out")"
    sed -n 4p "$work/out" | grep -qF '{"id": "m", "error": "line 4: margin: not a key of distance lines' ||
        fail "margin: $(sed -n 4p "$work/out")"
    # Beyond the largest double the upper bound is null (JSON has no infinity).
    sed -n 5p "$work/out" | grep -q '^{"id": "far", "lower": 1.7976931348623157e+308, "upper": null, ' ||
        fail "far: $(sed -n 5p "$work/out")"
    # A bad line's error is intersect's, word for word.
    head -n 3 "$work/in" | tail -n 1 >"$work/bad"
    run 1 intersect "$work/bad"
    mv "$work/out" "$work/bad_intersect"
    run 1 distance "$work/bad"
    same_bytes "$work/out" "$work/bad_intersect"
    # Standard input reads as the file does; good lines only exit 0.
    head -n 2 "$work/in" >"$work/good"
    run 0 distance "$work/good"
    mv "$work/out" "$work/from_file"
    cp "$work/good" "$work/stdin"
    run 0 distance
    same_bytes "$work/out" "$work/from_file"
    run 0 distance -
    same_bytes "$work/out" "$work/from_file"
    rm "$work/stdin"
    # Options that do not apply are refused, saying why; usage errors as for intersect.
    run 2 distance --arithmetic float "$work/good"
    contains "$work/err" "--arithmetic does not apply: every distance is certified"
    run 2 distance --algorithm oracle "$work/good"
    contains "$work/err" "--algorithm does not apply"
    run 2 distance --threads -1 "$work/good"
    run 2 distance "$work/missing.jsonl"
    contains "$work/err" "cannot open"
    run 0 distance --help
    for phrase in '"lower"' '"upper"' '"on_box"' '"on_cylinder"' "null" "margin" "--threads" "--max-line-bytes" \
        "4 doubles apart" "exactly 0" "no --algorithm or" "EXIT STATUS"; do
        contains "$work/out" "$phrase"
    done
    run 0 --help
    contains "$work/out" "distance"
    # A write error exits 3 with its message, as for intersect.
    if [[ -w /dev/full ]]; then
        for t in 1 2; do
            "$exe" distance --threads $t "$work/good" >/dev/full 2>"$work/err"
            rc=$?
            [[ $rc == 3 ]] || fail "distance --threads $t >/dev/full: exited $rc, expected 3"
            contains "$work/err" "boxcyl: cannot write standard output: No space left on device"
        done
    fi
    ;;
distance_signed)
    # boxcyl distance --signed: the same lines; apart, the distance's line with a "normal" too; overlapping,
    # minus the penetration depth, at most 2^-43 times the shapes' size wide; bad lines as
    # without it; without --signed no normal.
    box='"box": {"min": [0, 0, 0], "max": [1, 1, 1]}'
    printf '%s\n' \
      '{"id": "deep", "box": {"min": [-1, -1, -1], "max": [1, 1, 1]}, "cylinder": {"center": [1.5, 0, 0], "axis": [0, 0, 1], "radius": 1, "height": 10}}' \
      "{\"id\": \"one\", $box, \"cylinder\": {\"center\": [3, 0.5, 0.5], \"axis\": [0, 0, 1], \"radius\": 1, \"height\": 1}}" \
      "{\"id\": \"bad\", $box, \"cylinder\": {\"center\": [2, 0.5, 0.5], \"axis\": [0, 0, 0], \"radius\": 1, \"height\": 1}}" \
      "{\"id\": \"m\", $box, \"cylinder\": {\"center\": [2, 0.5, 0.5], \"axis\": [0, 0, 1], \"radius\": 1, \"height\": 1}, \"margin\": 1}" \
      >"$work/in"
    run 1 distance "$work/in"
    mv "$work/out" "$work/unsigned"
    grep -q '"normal"' "$work/unsigned" && fail "a normal without --signed: $(cat "$work/unsigned")"
    run 1 distance --signed "$work/in"
    [[ $(wc -l <"$work/out") == 4 ]] || fail "expected 4 output lines, got $(wc -l <"$work/out")"
    [[ -s $work/err ]] && fail "stderr not empty: $(head -c 300 "$work/err")"
    sed -n 1p "$work/out" |
        grep -q '^{"id": "deep", "lower": [0-9.e+-]*, "upper": [0-9.e+-]*, "normal": \[.*\], "on_box": \[.*\], "on_cylinder": \[.*\]}$' ||
        fail "line 1 is not a signed distance line: $(sed -n 1p "$work/out")"
    # Overlapping by 0.5 along x: lower <= -0.5 <= upper, at most 5 * 2^-43 apart (the half height is 5);
    # the normal (1, 0, 0).
    sed -n 1p "$work/out" | awk -F'[:,] *' '{ lo = $4 + 0; hi = $6 + 0; exit !(lo <= -0.5 && hi >= -0.5 && hi - lo <= 5 * 2 ^ -43) }' ||
        fail "line 1: not a tight enclosure of -0.5: $(sed -n 1p "$work/out")"
    sed -n 1p "$work/out" | grep -o '"normal": \[[^]]*\]' |
        awk -F'[][,] *' '{ x = $2 + 0; y = $3 + 0; z = $4 + 0; exit !(x > 1 - 1e-9 && x < 1 + 1e-9 && y * y + z * z < 1e-18) }' ||
        fail "line 1: the normal is not (1, 0, 0): $(sed -n 1p "$work/out")"
    # Apart, bad lines and a margin: the distance's lines, a normal added to the answers.
    sed -n 2p "$work/out" | grep -q '^{"id": "one", "lower": [0-9.e+-]*, "upper": [0-9.e+-]*, "normal": \[1, ' ||
        fail "line 2: $(sed -n 2p "$work/out")"
    sed 's/, "normal": \[[^]]*\]//' "$work/out" | tail -n 3 >"$work/stripped"
    tail -n 3 "$work/unsigned" >"$work/want"
    same_bytes "$work/stripped" "$work/want"
    # Threads, standard input and the help.
    for t in 2 0; do
        mv "$work/out" "$work/serial"
        run 1 distance --signed --threads $t "$work/in"
        same_bytes "$work/out" "$work/serial"
    done
    cp "$work/in" "$work/stdin"
    run 1 distance --signed
    same_bytes "$work/out" "$work/serial"
    rm "$work/stdin"
    run 2 distance --signed --arithmetic float "$work/in"
    run 0 distance --help
    for phrase in "--signed" '"normal"' "penetration depth" "2^-43"; do
        contains "$work/out" "$phrase"
    done
    ;;
distance_threads)
    # --threads N: byte for byte the single-threaded output and exit status, in input order, from a
    # file and from a pipe (several blocks of lines, bad lines among them).
    n=9000
    bash "$(dirname "$0")/gen_queries.sh" $n 13 499 >"$work/in"
    run 1 distance --threads 1 "$work/in"
    mv "$work/out" "$work/serial"
    [[ $(wc -l <"$work/serial") == "$n" ]] || fail "got $(wc -l <"$work/serial") output lines for $n input lines"
    # In input order: output line i answers id i (bad lines name line i).
    awk '{ id = "\"id\": " NR ","; where = "line " NR ":"; if (index($0, id) != 2 && index($0, where) == 0) { print NR; exit 1 } }' \
        "$work/serial" || fail "an output line out of order"
    grep -q '"lower": ' "$work/serial" || fail "no answers"
    for t in 2 3 0; do
        run 1 distance --threads $t "$work/in"
        same_bytes "$work/out" "$work/serial"
    done
    cat "$work/in" | "$exe" distance --threads 2 >"$work/out" 2>"$work/err"
    rc=$?
    [[ $rc == 1 ]] || fail "piped --threads 2 exited $rc, expected 1"
    same_bytes "$work/out" "$work/serial"
    ;;
readme_commands)
    # Every `echo '<input>' | boxcyl <subcommand>` line of the README (the quick start's intersect, the
    # grid and distance examples) with its output shown under it as `# <output>`: run as written, output
    # compared.
    readme=$examples/../README.md
    awk -v work="$work" '
        pending { if ($0 ~ /^# /) { n++; print substr($0, 3) > (work "/want" n); print sub_ > (work "/sub" n); print in_ > (work "/in" n) } pending = 0 }
        /^echo \x27.*\x27 \| boxcyl [a-z]+$/ {
            in_ = $0; sub(/^echo \x27/, "", in_); sub(/\x27 \| boxcyl [a-z]+$/, "", in_)
            sub_ = $0; sub(/.* \| boxcyl /, "", sub_); pending = 1
        }
        END { print n + 0 > (work "/count") }' "$readme"
    count=$(cat "$work/count")
    [[ $count -ge 2 ]] || fail "expected the intersect and grid commands with their output in $readme, found $count"
    grep -qx intersect "$work"/sub* || fail "no 'echo ... | boxcyl intersect' line in $readme"
    for ((i = 1; i <= count; ++i)); do
        cp "$work/in$i" "$work/stdin"
        run 0 "$(cat "$work/sub$i")"
        same_bytes "$work/out" "$work/want$i"
    done
    rm -f "$work/stdin"
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
