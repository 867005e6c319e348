"""Builds boxcyl._core with pybind11's setuptools helpers; the metadata is in pyproject.toml.

The extension compiles ../include/boxcyl (header-only) with the exact backend (GMP's gmpxx), as
boxcyl::exact does in CMake, and with -ffp-contract=off as boxcyl's own builds do.
"""
import re
from pathlib import Path

from pybind11.setup_helpers import Pybind11Extension, build_ext
from setuptools import setup

root = Path(__file__).resolve().parent.parent
include = root / "include"
version = re.search(r'#define BOXCYL_VERSION_STRING "([^"]+)"',
                    (include / "boxcyl" / "version.hpp").read_text()).group(1)

core = Pybind11Extension(
    "boxcyl._core",
    ["src/boxcyl_python.cpp"],
    include_dirs=[str(include)],
    define_macros=[("BOXCYL_HAS_EXACT", "1")],
    libraries=["gmpxx", "gmp"],
    extra_compile_args=["-ffp-contract=off"],
    cxx_std=20,
)

setup(version=version, ext_modules=[core], cmdclass={"build_ext": build_ext})
