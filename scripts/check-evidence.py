#!/usr/bin/env python3
"""Refuses recorded evidence that no longer describes the code.

docs/long-run.md and docs/accuracy.md are written by scripts/long-run.sh and scripts/accuracy.sh. Each
recorded section carries a marker

    <!-- evidence: commit=<hash> paths="<path> <path> ..." -->

naming the commit it ran at and the sources its figures depend on. This check fails when any of those
paths changed between that commit and HEAD (or the commit is unknown), naming the section and the
command that regenerates it. CTest runs it (test docs.evidence_current), so CI refuses stale figures.

A directory among the paths stands for the files of it that the run compiles: when the paths name the
run's own sources (tests/*.cpp), a changed file under a directory counts only if those sources reach it
through #include (followed textually, every branch of a conditional included, so the set is never
smaller than what the compiler reads). A header the run never includes cannot change its figures.

Usage: scripts/check-evidence.py [FILE ...]   (default: docs/long-run.md docs/accuracy.md)
"""
import pathlib
import re
import subprocess
import sys

MARKER = re.compile(r'<!-- evidence: commit=([0-9a-f]+) paths="([^"]*)"(?: command="([^"]*)")? -->')


def git(*args):
    return subprocess.run(["git", *args], capture_output=True, text=True)


INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)


def include_closure(root, sources):
    """The repository files that `sources` reach through #include "..." (quoted includes only: the
    project's own headers), the sources included."""
    seen = set()
    todo = [pathlib.Path(s) for s in sources]
    while todo:
        rel = todo.pop()
        if rel.as_posix() in seen or not (root / rel).is_file():
            continue
        seen.add(rel.as_posix())
        for name in INCLUDE.findall((root / rel).read_text(encoding="utf-8", errors="replace")):
            for base in (rel.parent, pathlib.Path("include"), pathlib.Path("tests")):
                candidate = base / name
                if (root / candidate).is_file():
                    todo.append(pathlib.Path(*candidate.parts))
                    break
    return seen


def relevant(root, paths, changed):
    """The changed files that can affect a run whose sources (tests/*.cpp) are among `paths`."""
    sources = [p for p in paths if p.startswith("tests/") and p.endswith(".cpp")]
    if not sources:
        return changed
    closure = include_closure(root, sources)
    return [c for c in changed if c in closure or c in paths]


def main(argv):
    root = pathlib.Path(__file__).resolve().parent.parent
    files = argv or ["docs/long-run.md", "docs/accuracy.md"]
    if git("-C", str(root), "rev-parse", "--git-dir").returncode != 0:
        print("check-evidence: not a git checkout; nothing to compare")
        return 0
    stale = 0
    for name in files:
        text = (root / name).read_text(encoding="utf-8")
        markers = MARKER.findall(text)
        if not markers:
            print(f"{name}: no evidence marker (regenerate it with its script)")
            stale += 1
        for commit, paths, command in markers:
            if git("-C", str(root), "cat-file", "-e", commit + "^{commit}").returncode != 0:
                print(f"{name}: recorded at {commit}, which this checkout does not have")
                stale += 1
                continue
            changed = git("-C", str(root), "diff", "--name-only", commit, "HEAD", "--", *paths.split()).stdout.split()
            changed = relevant(root, paths.split(), changed)
            if changed:
                shown = ", ".join(changed[:5]) + (" ..." if len(changed) > 5 else "")
                print(f"{name}: recorded at {commit}, but {shown} changed since; rerun: {command or 'its script'}")
                stale += 1
    if stale == 0:
        print(f"evidence current: {', '.join(files)}")
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
