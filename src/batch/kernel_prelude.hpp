// What a kernel translation unit (kernel_avx2.cpp, kernel_avx512.cpp) includes *before* its
// `#pragma GCC target`: every header of the library and of the standard library that the kernel uses,
// other than <experimental/simd> and the kernel's own two (batch/filter.hpp, batch/kernel.hpp).
//
// Why: a function gets the instruction set of the pragma in force where it is *defined*. What is
// defined here (the scalar exact query, the enclosure arithmetic, std::) is thus compiled for plain
// x86-64 even in these translation units, so the linker can pick any copy of such an inline function
// and the program still runs on any x86-64; only the kernel itself — in its own namespace, called only
// after the CPU check in dispatch.cpp — uses AVX2 or AVX-512. Not quite by construction: a constexpr
// template is instantiated where first used, under the pragma, so these files are compiled at -O2 in
// every build type (where such helpers are inlined; CMakeLists.txt), and scripts/check_isa_leaks.py
// verifies the built objects (CTest: batch.kernels_keep_their_instruction_sets).
//
// The scalar exact default, which the kernels call for the lanes their filter leaves, is not compiled
// here at all: BOXCYL_PIPELINE_EXTERN (CMakeLists.txt) declares its instantiations extern, and they link
// pipeline.cpp's one plain x86-64 copy, which saves most of these files' build time.
#pragma once

// <experimental/simd>'s own includes (libstdc++ 12).
#include <array>
#include <bit>
#include <bitset>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iomanip>
#include <iosfwd>
#include <utility>
#include <x86intrin.h>  // each intrinsic carries its own target attribute

// The kernel's.
#include <algorithm>
#include <cassert>
#include <exception>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <thread>
#include <vector>

#include "boxcyl/batch/dispatch.hpp"
#include "boxcyl/batch/split.hpp"
#include "boxcyl/batch/types.hpp"
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/validate.hpp"
#include "boxcyl/number/bounded.hpp"
