#!/usr/bin/env bash
# What building boxcyl costs a newcomer, from a clean build directory:
#   1. the README's default C++ build (library + command-line tool, Release): total CPU seconds and the
#      largest memory of any one compiler process (each compile runs under /usr/bin/time through a
#      compiler launcher), with -j1 so that the CPU figure is not inflated by contention;
#   2. `pip install --no-build-isolation ./python` into a fresh venv: CPU seconds and peak memory.
# Goals it is held to (docs/design.md records the figures): the C++ build ≤ 120 s CPU and ≤ 500 MB per compiler
# process, pip ≤ 90 s CPU. Prints the figures and the five heaviest translation units.
# Usage: scripts/build-cost.sh [cpp|python ...]   (default both). Machines under load give higher CPU.
set -euo pipefail
cd "$(dirname "$0")/.."
parts=("$@")
((${#parts[@]})) || parts=(cpp python)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for part in "${parts[@]}"; do
    case "$part" in
        cpp)
            bash scripts/deps.sh build time >/dev/null
            launcher="$work/measure"
            cat > "$launcher" <<EOF
#!/usr/bin/env bash
# One compiler process under /usr/bin/time: user+sys seconds, max RSS (KB), the source file.
src=unknown
for a in "\$@"; do case "\$a" in *.cpp) src="\$a" ;; esac; done
exec /usr/bin/time -a -o "$work/compiles" -f "%U %S %M \$src" "\$@"
EOF
            chmod +x "$launcher"
            : > "$work/compiles"
            cmake -S . -B "$work/build" -DCMAKE_CXX_COMPILER_LAUNCHER="$launcher" >/dev/null
            /usr/bin/time -o "$work/total" -f "%U %S %e" cmake --build "$work/build" -j1 >/dev/null
            read -r user sys wall < "$work/total"
            awk -v u="$user" -v s="$sys" -v w="$wall" '
                { cpu = $1 + $2; total += cpu; if ($3 > peak) { peak = $3; peak_src = $4 } n++; printf "%.1f %.0f %s\n", cpu, $3 / 1024, $4 > "/dev/stderr" }
                END { printf "C++ default build (library + tool, -j1): %.0f s CPU (%d compiles %.0f s, the rest linking and CMake), %.0f s wall, largest compiler process %.0f MB (%s)\n", u + s, n, total, w, peak / 1024, peak_src }' \
                "$work/compiles" 2> "$work/per_file"
            echo "heaviest compiles (CPU s, MB, source):"
            sort -rn "$work/per_file" | head -5 | sed 's/^/  /'
            ;;
        python)
            bash scripts/deps.sh python time >/dev/null
            /usr/bin/python3 -m venv --system-site-packages "$work/venv"
            # From a copy of the sources without what git ignores: a python/build/ left by an earlier
            # install would otherwise be reused and the figure would say nothing about a fresh clone.
            mkdir "$work/src"
            git ls-files -z --cached --others --exclude-standard |
                tar --null --ignore-failed-read -T - -cf - 2>/dev/null | tar -xf - -C "$work/src"
            /usr/bin/time -o "$work/pip" -f "%U %S %e %M" "$work/venv/bin/python" -m pip install --no-build-isolation -q "$work/src/python" >/dev/null
            read -r user sys wall mem < "$work/pip"
            awk -v u="$user" -v s="$sys" -v w="$wall" -v m="$mem" \
                'BEGIN { printf "pip install ./python: %.0f s CPU, %.0f s wall, largest process %.0f MB\n", u + s, w, m / 1024 }'
            ;;
        *) echo "build-cost: unknown part $part (cpp, python)" >&2; exit 2 ;;
    esac
done
