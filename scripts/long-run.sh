#!/usr/bin/env bash
# The long randomized runs kept out of CI (ctest label "long"), recorded in docs/long-run.md, one section
# per family, each naming the commit it ran at and the sources it depends on (scripts/check-evidence.py,
# run by CTest, refuses a section whose sources changed since):
#   exact    every method in exact arithmetic against the oracle, 1,000,000 cases each (hours on 2 cores)
#   default  the exact default query against the oracle, 10,000,000 cases (about an hour on 2 cores)
#   stage0   stages 0 and 0b against the enclosure rows, 100,000,000 cases (minutes)
# Usage: scripts/long-run.sh [FAMILY ...]   (default: all three). BUILD_DIR (default build-test), JOBS,
# SCALE (a shorter or longer run: BOXCYL_TEST_SCALE for every family named; defaults 50, 100 and 500, the
# counts above; the record states the count it ran).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
build="${BUILD_DIR:-build-test}"
jobs="${JOBS:-$(nproc)}"
families=("$@")
((${#families[@]})) || families=(exact default stage0)
declare -A scale=([exact]=${SCALE:-50} [default]=${SCALE:-100} [stage0]=${SCALE:-500})
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g" -DBOXCYL_BUILD_TESTS=ON \
    -DBOXCYL_LONG_SCALE_EXACT="${scale[exact]}" -DBOXCYL_LONG_SCALE_DEFAULT="${scale[default]}" \
    -DBOXCYL_LONG_SCALE_STAGE0="${scale[stage0]}" >/dev/null
cmake --build "$build" -j "$jobs" --target test_exact_algorithms test_filtered test_semi_static >/dev/null
# Cases per unit of scale times the family's scale, with thousands separators.
count() { echo "$(($1 * ${scale[$family]}))" | sed -E ':a; s/([0-9])([0-9]{3})($|,)/\1,\2\3/; ta'; }
doc=docs/long-run.md
commit=$(git rev-parse --short HEAD)
git diff --quiet HEAD -- include src tests || { echo "long-run: commit your changes first (the record names a commit)" >&2; exit 2; }
status=0
for family in "${families[@]}"; do
    case "$family" in
        exact)
            regex='^exact_.*_long$'
            paths="include/boxcyl/algo include/boxcyl/exact/paths.hpp include/boxcyl/exact/reduce.hpp include/boxcyl/exact/convert.hpp include/boxcyl/oracle include/boxcyl/number/rational.hpp include/boxcyl/number/qfield.hpp include/boxcyl/geometry tests/test_exact_algorithms.cpp tests/support"
            title="Every method in exact arithmetic against the oracle: $(count 20000) cases each"
            about="\`exact_inequalities_long\`, \`exact_hull_long\`, \`exact_lcp_long\`: test_exact_algorithms at
\`BOXCYL_TEST_SCALE=${scale[exact]}\`, 2 seeds × $(count 10000) answered cases per method (§4, §3, §2: the linear-inequalities,
convex-hull and LCP methods), every answer compared with the oracle. The linear-inequalities and LCP methods
refuse, as documented, oriented boxes whose axes are not exactly orthonormal." ;;
        default)
            regex='^filtered_long$'
            paths="include/boxcyl/filtered.hpp include/boxcyl/filtered include/boxcyl/exact include/boxcyl/number include/boxcyl/algo include/boxcyl/geometry include/boxcyl/oracle tests/test_filtered.cpp tests/support"
            title="The default query against the oracle: $(count 100000) cases"
            about="\`filtered_long\`: test_filtered's four random shards at \`BOXCYL_TEST_SCALE=${scale[default]}\`, $(count 25000) cases each
(all box kinds, degenerate shapes included), every answer of the exact default compared with the oracle
with no tolerance; *exact fallback* counts the queries that reached the exact stage." ;;
        stage0)
            regex='^semi_static_long$'
            paths="include/boxcyl/filtered include/boxcyl/number include/boxcyl/algo include/boxcyl/geometry tests/test_semi_static.cpp tests/support"
            title="Stages 0 and 0b against the enclosure rows: $(count 200000) cases"
            about="\`semi_static_long\`: test_semi_static's two \`SemiStaticAtScale\` shards at \`BOXCYL_TEST_SCALE=${scale[stage0]}\`,
every decision of the rows \`semi_static\` and \`search\` ([robustness/stage0.md](robustness/stage0.md))
compared with linear inequalities on enclosures (themselves checked against the oracle above) and, where
those cannot decide, with the oracle." ;;
        *) echo "long-run: unknown family $family (exact, default, stage0)" >&2; exit 2 ;;
    esac
    log=$(mktemp)
    start=$(date -u +%s)
    run_status=0
    ctest --test-dir "$build" -L long -R "$regex" -j "$jobs" -V > "$log" 2>&1 || run_status=$?
    end=$(date -u +%s)
    ((run_status == 0)) || status=$run_status
    section=$(mktemp)
    {
        echo "<!-- long-run:$family begin -->"
        echo "## $title"
        echo
        echo "$about"
        echo
        echo "<!-- evidence: commit=$commit paths=\"$paths\" command=\"SCALE=${scale[$family]} bash scripts/long-run.sh $family\" -->"
        echo "Recorded by \`SCALE=${scale[$family]} bash scripts/long-run.sh $family\` on $(date -u +%Y-%m-%d) at commit $commit, $(uname -m),"
        echo "$(nproc) cores, $(( (end - start) / 60 )) minutes; ctest exit status $run_status."
        echo
        echo '```'
        grep -E "^[0-9]+: (exact|filtered|stage 0|random|boundary|  \(|  exact fallback)" "$log" | sed -E 's/^[0-9]+: //' || true
        grep -E "tests passed|tests failed" "$log" || true
        echo '```'
        echo "<!-- long-run:$family end -->"
    } > "$section"
    python3 - "$doc" "$family" "$section" <<'PY'
import pathlib, re, sys
doc, family, section = pathlib.Path(sys.argv[1]), sys.argv[2], pathlib.Path(sys.argv[3]).read_text()
text = doc.read_text() if doc.exists() else "# Long runs\n"
block = re.compile(rf"<!-- long-run:{family} begin -->.*?<!-- long-run:{family} end -->\n?", re.S)
text = block.sub(lambda m: section, text) if block.search(text) else text.rstrip("\n") + "\n\n" + section
doc.write_text(text)
PY
    rm -f "$log" "$section"
    echo "long-run: $family recorded in $doc (ctest status $run_status)" >&2
done
exit $status
