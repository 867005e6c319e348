#!/usr/bin/env bash
# Generates the API reference from the public headers with Doxygen (Debian's package, installed by
# scripts/deps.sh when missing): build-docs/html/index.html. Any Doxygen warning fails the run and is
# printed. Usage: scripts/docs.sh [output-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh doxygen
out="${1:-build-docs}"
mkdir -p "$out"
log="$out/doxygen-warnings.log"
rm -f "$log"
rc=0
( cat docs/Doxyfile
  echo "OUTPUT_DIRECTORY = $out"
  echo "WARN_LOGFILE = $log" ) | doxygen - || rc=$?
if [ -s "$log" ]; then
  cat "$log" >&2
  echo "docs: $(grep -c -E 'warning:|error:' "$log") Doxygen warnings (WARN_AS_ERROR)" >&2
  exit 1
fi
if [ "$rc" -ne 0 ]; then echo "docs: doxygen failed (exit $rc)" >&2; exit "$rc"; fi
echo "docs: $out/html/index.html"
