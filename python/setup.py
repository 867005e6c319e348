"""Builds boxcyl._core with setuptools and pybind11's helpers; the metadata is in pyproject.toml.

The extension's sources and flags are those listed in extension.txt, which CMake
(python/CMakeLists.txt) builds from as well. The sources compile in parallel (BOXCYL_BUILD_JOBS
jobs, default: the CPUs this process may use), heaviest first, each reported with a line
"boxcyl: [k/n] path (seconds)" (pip shows them with -v).

The C++ sources live outside python/, so this builds from a checkout of the repository: pip builds a
local directory in place (`pip install ./python`, `pip wheel ./python`), and no sdist is made.
Source paths are given relative to this file's directory, as setuptools requires (it refuses absolute
ones, except that it silently skips any absolute path containing "build").
"""
import os
import platform
import re
import sysconfig
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from pybind11.setup_helpers import Pybind11Extension, build_ext
from setuptools import setup

here = Path(__file__).resolve().parent
root = here.parent
include = root / "include"
if not (include / "boxcyl" / "version.hpp").is_file():
    raise SystemExit(f"boxcyl: {include} not found; build the Python package from a checkout of the "
                     "repository (pip install ./python from its root), not from a copy of python/ alone")
version = re.search(r'#define BOXCYL_VERSION_STRING "([^"]+)"',
                    (include / "boxcyl" / "version.hpp").read_text()).group(1)


def relative(path: Path) -> str:
    """path as setuptools wants a source: relative to setup.py's directory, '/'-separated."""
    return Path(os.path.relpath(path, here)).as_posix()


def read_manifest():
    """extension.txt's entries for this compiler and machine: {kind: [values]}, and each source's own
    options {path: [options]}."""
    compiler = os.environ.get("CXX") or os.environ.get("CC") or sysconfig.get_config_var("CXX") or ""
    x86_64_gcc = platform.machine() in ("x86_64", "AMD64") and "clang" not in compiler
    entries = {"source": [], "define": [], "option": [], "standard": [], "library": []}
    source_options = {}
    for number, line in enumerate((here / "extension.txt").read_text().splitlines(), 1):
        words = line.split("#", 1)[0].split()
        if not words:
            continue
        if words[0] == "x86_64-gcc":
            if not x86_64_gcc:
                continue
            words = words[1:]
        if len(words) < 2 or words[0] not in entries or (len(words) > 2 and words[0] != "source"):
            raise SystemExit(f"boxcyl: extension.txt:{number}: cannot read {line!r}")
        entries[words[0]].append(words[1])
        if words[0] == "source":
            source_options[relative(root / words[1])] = words[2:]
    return entries, source_options


manifest, source_options = read_manifest()
core = Pybind11Extension(
    "boxcyl._core",
    [relative(root / s) for s in manifest["source"]],
    include_dirs=[str(include)],
    define_macros=[tuple(d.split("=", 1)) if "=" in d else (d, None) for d in manifest["define"]],
    libraries=manifest["library"],
    extra_compile_args=manifest["option"],
    cxx_std=int(manifest["standard"][0]),
)


def jobs():
    value = os.environ.get("BOXCYL_BUILD_JOBS", "")
    if value.isdigit() and int(value) > 0:
        return int(value)
    return len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)


class BuildExt(build_ext):
    """pybind11's build_ext, compiling the sources in parallel with a progress line per step."""

    def build_extension(self, ext):
        compiler = self.compiler
        compile_one = compiler._compile
        link = compiler.link_shared_object
        started = time.monotonic()

        def say(text):
            print(f"boxcyl: {text}", flush=True)

        def compile_all(sources, output_dir=None, macros=None, include_dirs=None, debug=0, extra_preargs=None,
                        extra_postargs=None, depends=None):
            macros, objects, extra_postargs, pp_opts, build = compiler._setup_compile(
                output_dir, macros, include_dirs, sources, depends, extra_postargs)
            cc_args = compiler._get_cc_args(pp_opts, debug, extra_preargs)
            # In extension.txt's order, heaviest first (setuptools sorts the sources by name).
            rank = {path: k for k, path in enumerate(source_options)}
            todo = sorted((obj for obj in objects if obj in build), key=lambda o: rank.get(Path(build[o][0]).as_posix(), 0))
            n, j = len(todo), min(jobs(), max(1, len(todo)))
            say(f"compiling {n} sources, {j} at a time (BOXCYL_BUILD_JOBS)")
            done = []

            def one(obj):
                src, src_ext = build[obj]
                t0 = time.monotonic()
                own = source_options.get(Path(src).as_posix(), [])
                compile_one(obj, src, src_ext, cc_args, extra_postargs + own, pp_opts)
                done.append(obj)
                say(f"[{len(done)}/{n}] {Path(os.path.relpath(src, root)).as_posix()} ({time.monotonic() - t0:.1f} s)")

            with ThreadPoolExecutor(j) as pool:
                for future in [pool.submit(one, obj) for obj in todo]:
                    future.result()  # the first failure, with the compiler's message above it
            return objects

        def link_and_say(*args, **kwargs):
            t0 = time.monotonic()
            say("linking")
            link(*args, **kwargs)
            say(f"linked {Path(args[1]).name} ({time.monotonic() - t0:.1f} s); {time.monotonic() - started:.0f} s in all")

        compiler.compile = compile_all
        compiler.link_shared_object = link_and_say
        try:
            super().build_extension(ext)
        finally:
            del compiler.compile, compiler.link_shared_object


# setup.py may be run from another directory (pip runs it from here): the relative paths are from here.
os.chdir(here)
setup(version=version, ext_modules=[core], cmdclass={"build_ext": BuildExt})
