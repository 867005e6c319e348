// The batch kernel (boxcyl/batch/kernel.hpp) compiled for AVX-512 (F, DQ, VL, BW): 8 doubles per
// vector. Called only through dispatch.cpp, after the CPU check. kernel_prelude.hpp says why the
// includes come first.
#include "kernel_prelude.hpp"

#pragma GCC push_options
#pragma GCC target("avx512f,avx512dq,avx512vl,avx512bw,avx2,avx,fma,bmi,bmi2,lzcnt,popcnt,sse4.2")
// GCC's C++ front end reads the whole file before any #pragma takes effect, so the pragma cannot set
// the instruction-set macros by which <experimental/simd> picks its native width: they are set here,
// for the rest of this file only (nothing but the kernel is included after them).
#define BOXCYL_ISA_LEVEL 3
#include "isa_macros.hpp"

#define BOXCYL_BATCH_ISA dispatch_avx512
#define BOXCYL_KERNEL_ID avx512
#define BOXCYL_KERNEL_TABLE avx512_table
#define BOXCYL_KERNEL_LANES 8
#include "kernel_instance.hpp"

#pragma GCC pop_options
