#!/usr/bin/env bash
# End-to-end tests of `boxcyl explain`, one case per CTest test.
# Usage: explain_test.sh CASE BOXCYL_EXE EXAMPLES_DIR WORK_DIR
# The SVG must parse as XML: with xmllint when installed, else python3's xml.etree (Debian's
# /usr/bin/python3 first; a python3 on PATH otherwise). Neither present is a failure, not a skip.
set -u

case_name=$1
exe=$2
examples=$3
work=$4/explain_$case_name
rm -rf "$work" && mkdir -p "$work" || exit 2

failures=0
fail() {
    echo "FAIL [explain_$case_name]: $*" >&2
    failures=$((failures + 1))
}

if command -v xmllint >/dev/null; then
    well_formed() { xmllint --noout "$1"; }
else
    py=/usr/bin/python3
    [[ -x $py ]] || py=$(command -v python3 || true)
    if [[ -z $py ]]; then
        echo "explain_test.sh: needs xmllint (Debian: libxml2-utils) or python3 to parse the SVG" >&2
        exit 1
    fi
    well_formed() { "$py" -c 'import sys, xml.etree.ElementTree as E; E.parse(sys.argv[1])' "$1"; }
fi

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

contains() {  # contains FILE TEXT
    grep -qF -- "$2" "$1" || fail "$1 lacks '$2'"
}

lacks() {  # lacks FILE TEXT
    grep -qF -- "$2" "$1" && fail "$1 has '$2'"
}

query='{"id": "q", "box": {"min": [0, 0, 0], "max": [1, 1, 1]}, "cylinder": {"center": [1.5, 0.5, 0.5], "axis": [0, 0, 1], "radius": 0.4375, "height": 1}}'

case $case_name in
examples)
    # Every example: a well-formed SVG with the main elements, whose verdict is `intersect`'s answer.
    run 0 intersect "$examples/queries.jsonl"
    cp "$work/out" "$work/answers"
    n=$(wc -l <"$examples/queries.jsonl")
    for ((i = 1; i <= n; ++i)); do
        run 0 explain --line "$i" "$examples/queries.jsonl" -o "$work/$i.svg"
        [[ -s $work/out ]] && fail "line $i: -o given, yet standard output not empty"
        well_formed "$work/$i.svg" || fail "line $i: not well-formed XML"
        for id in verdict disk axis-point box-shadow axial legend view-top view-front view-side nearest; do
            contains "$work/$i.svg" "id=\"$id\""
        done
        answer=$(sed -n "${i}p" "$work/answers")
        if [[ $answer == *'"intersect": true'* ]]; then
            contains "$work/$i.svg" ': Intersects'
        else
            contains "$work/$i.svg" ': Does not intersect'
        fi
        # A polygon, its closest point and the gap segment exactly when box ∩ slab is not empty.
        if grep -qF 'box ∩ slab is empty' "$work/$i.svg"; then
            lacks "$work/$i.svg" 'id="polygon"'
        else
            for id in polygon closest gap; do contains "$work/$i.svg" "id=\"$id\""; done
        fi
    done
    ;;
io)
    # Standard input and standard output; the same picture from a file with -o.
    printf '%s\n' "$query" >"$work/stdin"
    run 0 explain
    well_formed "$work/out" || fail "stdin → stdout: not well-formed XML"
    contains "$work/out" ">Does not intersect<"
    contains "$work/out" ">gap 0.0625<"
    cp "$work/out" "$work/from_stdin.svg"
    rm "$work/stdin"
    printf '%s' "$query" >"$work/q.json"  # no trailing newline
    run 0 explain "$work/q.json" --output "$work/from_file.svg"
    cmp -s "$work/from_stdin.svg" "$work/from_file.svg" || fail "file and stdin give different pictures"
    cp "$work/q.json" "$work/stdin"
    run 0 explain -
    cmp -s "$work/out" "$work/from_file.svg" || fail "'-' and the file give different pictures"
    rm "$work/stdin"
    # A pretty-printed (multi-line) query is one JSON object too.
    printf '{\n  "box": {"min": [0, 0, 0], "max": [1, 1, 1]},\n  "cylinder": {"center": [0.5, 0.5, 0.5],\n    "axis": [0, 0, 1], "radius": 0.25, "height": 0.5}\n}\n' >"$work/pretty.json"
    run 0 explain "$work/pretty.json"
    contains "$work/out" ">Intersects<"
    # --line picks one query of a JSON Lines file.
    run 0 explain --line 4 "$examples/queries.jsonl"
    contains "$work/out" 'gap-side-face'

    # A bad query: intersect's message (on stderr), exit 1, no picture.
    printf '%s\n' '{"box": {"min": [0, 0, 0], "max": [1, 1, 1]}, "cylinder": {"center": [0, 0, 0], "axis": [0, 0, 1], "radius": -1, "height": 1}}' >"$work/bad.json"
    run 1 intersect "$work/bad.json"
    message=$(sed -e 's/^{"error": "//' -e 's/"}$//' "$work/out")
    [[ $message == "line 1: cylinder.radius: is negative" ]] || fail "intersect's message changed: $message"
    run 1 explain "$work/bad.json" -o "$work/bad.svg"
    contains "$work/err" "$message"
    [[ -e $work/bad.svg ]] && fail "a bad query still wrote its output file"
    [[ -s $work/out ]] && fail "a bad query wrote to standard output"
    run 1 explain --line 2 "$examples/bad_lines.jsonl"
    contains "$work/err" "line 2: empty line"
    : >"$work/empty.json"
    run 1 explain "$work/empty.json"
    contains "$work/err" "empty line"
    # A JSON Lines file without --line: the parse error, and a hint.
    run 1 explain "$examples/queries.jsonl"
    contains "$work/err" "invalid JSON"
    contains "$work/err" "--line N"
    run 1 explain --line 1000 "$examples/queries.jsonl"
    contains "$work/err" "line 1000: no such line"

    # Usage errors: exit 2.
    run 2 explain "$work/does-not-exist.json"
    contains "$work/err" "cannot open"
    run 2 explain "$work"
    contains "$work/err" "directory"
    run 2 explain --frobnicate "$work/q.json"
    run 2 explain --line 0 "$work/q.json"
    run 2 explain "$work/q.json" "$work/q.json"
    run 2 explain "$work/q.json" -o "$work/no-such-dir/out.svg"
    contains "$work/err" "cannot write"

    run 0 explain --help
    for phrase in "--line" "--output" "EXIT STATUS" "exact"; do contains "$work/out" "$phrase"; done
    run 0 --help
    contains "$work/out" "explain"
    ;;
line_streams)
    # --line N reads lines 1 to N only: from a pipe that stays open (it would never end), and from a
    # file whose later lines are not UTF-8 nor JSON, the picture comes.
    mkfifo "$work/fifo" || exit 2
    "$exe" explain --line 2 -o "$work/fifo.svg" <"$work/fifo" >"$work/out" 2>"$work/err" &
    pid=$!
    exec 3>"$work/fifo"
    printf '%s\n%s\n' '{"id": "first"}' "$query" >&3
    for _ in $(seq 1 400); do
        kill -0 "$pid" 2>/dev/null || break
        sleep 0.05
    done
    if kill -0 "$pid" 2>/dev/null; then
        fail "--line 2 from an open pipe did not finish (it reads past line 2)"
        kill "$pid"
    fi
    wait "$pid"
    rc=$?
    exec 3>&-
    [[ $rc == 0 ]] || fail "--line 2 from a pipe exited $rc; stderr: $(head -c 300 "$work/err")"
    contains "$work/fifo.svg" ">Does not intersect<"
    { printf '%s\n' "$query"; printf '\377\376 not JSON\n'; head -c 1000000 /dev/zero; } >"$work/tail"
    run 0 explain --line 1 "$work/tail"
    contains "$work/out" ">gap 0.0625<"
    # The line asked for is longer than --max-line-bytes: an error, exit 1.
    run 1 explain --line 1 --max-line-bytes 20 "$work/tail"
    contains "$work/err" "line 1: line is longer than 20 bytes (--max-line-bytes)"
    # Beyond the end: how many lines there are.
    printf '%s\n%s' "$query" "$query" >"$work/two"
    run 1 explain --line 3 "$work/two"
    contains "$work/err" "line 3: no such line (the input has 2)"
    run 0 explain --line 2 "$work/two"
    # A signal while waiting for the line: no picture, exit 128 + the signal.
    "$exe" explain --line 2 <"$work/fifo" >"$work/out" 2>"$work/err" &
    pid=$!
    exec 3>"$work/fifo"
    printf '%s\n' "$query" >&3
    sleep 0.3
    kill -TERM "$pid"
    wait "$pid"
    rc=$?
    exec 3>&-
    [[ $rc == 143 ]] || fail "SIGTERM while reading: exited $rc, expected 143"
    contains "$work/err" "stopped by a signal before the query was read"
    [[ -s $work/out ]] && fail "a picture although the query was not read"
    ;;
errors)
    # Write and read errors are reported (exit 3), never a silent exit.
    printf '%s\n' "$query" >"$work/q.json"
    if [[ -w /dev/full ]]; then
        "$exe" explain "$work/q.json" >/dev/full 2>"$work/err"
        rc=$?
        [[ $rc == 3 ]] || fail ">/dev/full: exited $rc, expected 3"
        contains "$work/err" "boxcyl: cannot write standard output: No space left on device"
        run 3 explain "$work/q.json" -o /dev/full
        contains "$work/err" "boxcyl: cannot write '/dev/full': No space left on device"
    fi
    "$exe" explain "$work/q.json" >&- 2>"$work/err"
    rc=$?
    [[ $rc == 3 ]] || fail ">&-: exited $rc, expected 3"
    contains "$work/err" "boxcyl: cannot write standard output: Bad file descriptor"
    # With standard output closed, -o still writes its file (and nothing else lands in it).
    "$exe" explain "$work/q.json" -o "$work/closed.svg" >&- 2>"$work/err"
    rc=$?
    [[ $rc == 0 ]] || fail "-o with standard output closed: exited $rc; stderr: $(head -c 300 "$work/err")"
    well_formed "$work/closed.svg" || fail "-o with standard output closed: not well-formed XML"
    # Reading standard input fails (a directory): exit 3, a message.
    "$exe" explain <"$work" >"$work/out" 2>"$work/err"
    rc=$?
    [[ $rc == 3 ]] || fail "<dir: exited $rc, expected 3"
    contains "$work/err" "boxcyl: cannot read standard input: Is a directory"
    "$exe" explain --line 1 <"$work" >"$work/out" 2>"$work/err"
    rc=$?
    [[ $rc == 3 ]] || fail "--line 1 <dir: exited $rc, expected 3"
    ;;
margin)
    # "margin": the verdict is within_distance's and the grown cylinder is drawn; the box of $query is
    # exactly 0.0625 from the cylinder, so that margin turns "does not intersect" into "within".
    with_margin() { printf '%s\n' "${query%\}}, \"margin\": $1}"; }
    with_margin 0.0625 >"$work/stdin"
    run 0 explain -o "$work/at.svg"
    well_formed "$work/at.svg" || fail "margin 0.0625: not well-formed XML"
    contains "$work/at.svg" ">Within distance 0.0625<"
    contains "$work/at.svg" 'id="margin"'
    contains "$work/at.svg" "height 1; margin 0.0625<"
    contains "$work/at.svg" "boxcyl::within_distance"
    with_margin 0.062499999999999993 >"$work/stdin"
    run 0 explain -o "$work/below.svg"
    well_formed "$work/below.svg" || fail "margin below: not well-formed XML"
    contains "$work/below.svg" ">Not within distance 0.06249999999999999<"
    printf '%s\n' "$query" >"$work/stdin"
    run 0 explain -o "$work/none.svg"
    contains "$work/none.svg" ">Does not intersect<"
    lacks "$work/none.svg" 'id="margin"'
    # A bad margin is refused as `intersect` refuses it, naming the field.
    with_margin -1 >"$work/stdin"
    run 1 explain
    contains "$work/err" "boxcyl: line 1: margin: is negative"
    [[ -s $work/out ]] && fail "margin -1: wrote a picture"
    with_margin '"1"' >"$work/stdin"
    run 1 explain
    contains "$work/err" "margin: expected a number"
    ;;
nearest)
    # The nearest pair of boxcyl::distance, marked in every view with the bounds `boxcyl distance`
    # gives: a unit cube 1 from a vertical cylinder of radius 1.
    far='{"box": {"min": [0, 0, 0], "max": [1, 1, 1]}, "cylinder": {"center": [3, 0.5, 0.5], "axis": [0, 0, 1], "radius": 1, "height": 1}}'
    printf '%s\n' "$far" >"$work/stdin"
    run 0 distance
    lower=$(sed -n 's/.*"lower": \([^,]*\),.*/\1/p' "$work/out")
    upper=$(sed -n 's/.*"upper": \([^,]*\),.*/\1/p' "$work/out")
    [[ -n $lower && -n $upper ]] || fail "boxcyl distance: $(cat "$work/out")"
    run 0 explain -o "$work/far.svg"
    well_formed "$work/far.svg" || fail "nearest: not well-formed XML"
    for id in nearest view-top-nearest view-front-nearest view-side-nearest; do
        contains "$work/far.svg" "<g id=\"$id\" class=\"nearest\">"
    done
    contains "$work/far.svg" ">Nearest points, distance in [$lower, $upper] (boxcyl::distance, proved).<"
    contains "$work/far.svg" ">Nearest points, distance in [1"
    # Touching solids: one common point in each view, no segment.
    printf '%s\n' "${query/\"radius\": 0.4375/\"radius\": 0.5}" >"$work/stdin"
    run 0 explain -o "$work/touching.svg"
    well_formed "$work/touching.svg" || fail "touching: not well-formed XML"
    contains "$work/touching.svg" ">Intersects (touching)<"
    contains "$work/touching.svg" ">Nearest points, distance 0: the solids intersect;"
    group=$(sed -n '/<g id="nearest"/,/<\/g>/p' "$work/touching.svg")
    [[ $(grep -c '<circle' <<<"$group") == 1 ]] || fail "touching: not one common point: $group"
    grep -qF '<line' <<<"$group" && fail "touching: a segment drawn: $group"
    ;;
extreme)
    # Coordinates near the double range: distances right or "more than" the range, never NaN.
    printf '%s\n' \
      '{"id": "wide", "box": {"kind": "parallelepiped", "center": [0, -1e308, 0.5], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "extents": [1e308, 0, 0.25]}, "cylinder": {"center": [0, 0, 0.5], "axis": [0, 0, 1], "radius": 1, "height": 1}}' \
      '{"id": "far", "box": {"center": [1e308, 1e308, 0.5], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "extents": [0, 0, 0.5]}, "cylinder": {"center": [-0.5e308, -0.5e308, 0.5], "axis": [0, 0, 1], "radius": 1, "height": 1}}' \
      '{"id": "tiny", "box": {"kind": "parallelepiped", "center": [0, 1e-321, 0.5], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "extents": [1e-320, 0, 0.25]}, "cylinder": {"center": [0, 0, 0.5], "axis": [0, 0, 1], "radius": 2e-321, "height": 1}}' \
      >"$work/in"
    for i in 1 2 3; do
        run 0 explain --line $i "$work/in" -o "$work/$i.svg"
        well_formed "$work/$i.svg" || fail "line $i: not well-formed XML"
        lacks "$work/$i.svg" "NaN"
        lacks "$work/$i.svg" "nan"
    done
    contains "$work/1.svg" ">gap 1e+308 (distance − radius).<"
    contains "$work/2.svg" ">gap more than 1.79769e+308 (distance − radius).<"
    contains "$work/3.svg" ">Intersects<"
    ;;
*)
    echo "unknown case $case_name" >&2
    exit 2
    ;;
esac

if ((failures > 0)); then
    echo "explain_$case_name: $failures failure(s)" >&2
    exit 1
fi
echo "explain_$case_name: ok"
