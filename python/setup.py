"""Builds boxcyl._core with pybind11's setuptools helpers; the metadata is in pyproject.toml.

The extension compiles ../include/boxcyl (header-only) with the exact backend (GMP's gmpxx), as
boxcyl::exact does in CMake, and with -ffp-contract=off as boxcyl's own builds do. With GCC on x86-64
it also compiles ../src/batch (boxcyl::batch_dispatch in CMake: the batch kernel for AVX2 and AVX-512,
chosen at run time), so that the batch forms use the machine's full SIMD width.

The C++ sources live outside python/, so this builds from a checkout of the repository: pip builds a
local directory in place (`pip install ./python`, `pip wheel ./python`), and no sdist is made.
Source paths are given relative to this file's directory, as setuptools requires (it refuses absolute
ones, except that it silently skips any absolute path containing "build").
"""
import os
import platform
import re
import sysconfig
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


sources = ["src/boxcyl_python.cpp"]
macros = [("BOXCYL_HAS_EXACT", "1")]
batch = root / "src" / "batch"
compiler = os.environ.get("CXX") or os.environ.get("CC") or sysconfig.get_config_var("CXX") or ""
if platform.machine() in ("x86_64", "AMD64") and "clang" not in compiler and batch.is_dir():
    # The kernels' `#pragma GCC target` needs GCC (src/batch/kernel_avx512.cpp); they build at -O2 like
    # Python's own flags (src/batch/CMakeLists.txt says why that matters).
    sources += [relative(batch / f) for f in ("dispatch.cpp", "kernel_avx2.cpp", "kernel_avx512.cpp")]
    macros += [("BOXCYL_BATCH_DISPATCH", "1"), ("BOXCYL_BATCH_HAVE_AVX2", "1"), ("BOXCYL_BATCH_HAVE_AVX512", "1")]

core = Pybind11Extension(
    "boxcyl._core",
    sources,
    include_dirs=[str(include)],
    define_macros=macros,
    libraries=["gmpxx", "gmp"],
    extra_compile_args=["-ffp-contract=off", "-O2", "-Wno-maybe-uninitialized"],
    cxx_std=20,
)

# setup.py may be run from another directory (pip runs it from here): the relative paths are from here.
os.chdir(here)
setup(version=version, ext_modules=[core], cmdclass={"build_ext": build_ext})
