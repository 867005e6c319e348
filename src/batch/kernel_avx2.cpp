// The batch kernel (boxcyl/batch/kernel.hpp) compiled for AVX2 + FMA: 4 doubles per vector. Called
// only through dispatch.cpp, after the CPU check. kernel_prelude.hpp says why the includes come first;
// kernel_avx512.cpp why the macros are set by hand.
#include "kernel_prelude.hpp"

#pragma GCC push_options
#pragma GCC target("avx2,avx,fma,bmi,bmi2,lzcnt,popcnt,sse4.2")
#define BOXCYL_ISA_LEVEL 2
#include "isa_macros.hpp"

#define BOXCYL_BATCH_ISA dispatch_avx2
#define BOXCYL_KERNEL_ID avx2
#define BOXCYL_KERNEL_TABLE avx2_table
#define BOXCYL_KERNEL_LANES 4
#include "kernel_instance.hpp"

#pragma GCC pop_options
