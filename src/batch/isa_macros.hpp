// The instruction-set macros (__AVX2__, __AVX512F__, …) of BOXCYL_ISA_LEVEL (2: AVX2 + FMA, 3: also
// AVX-512 F/DQ/VL/BW), for a kernel translation unit, after its `#pragma GCC target` and before
// <experimental/simd> (kernel_avx512.cpp explains why). Each only where the compile flags have not
// already set it. No include guard: meant for one inclusion per translation unit.
#if !defined(BOXCYL_ISA_LEVEL)
#error "define BOXCYL_ISA_LEVEL before including isa_macros.hpp"
#endif

#if BOXCYL_ISA_LEVEL >= 2
#ifndef __SSE3__
#define __SSE3__ 1
#endif
#ifndef __SSSE3__
#define __SSSE3__ 1
#endif
#ifndef __SSE4_1__
#define __SSE4_1__ 1
#endif
#ifndef __SSE4_2__
#define __SSE4_2__ 1
#endif
#ifndef __POPCNT__
#define __POPCNT__ 1
#endif
#ifndef __AVX__
#define __AVX__ 1
#endif
#ifndef __AVX2__
#define __AVX2__ 1
#endif
#ifndef __FMA__
#define __FMA__ 1
#endif
#ifndef __BMI__
#define __BMI__ 1
#endif
#ifndef __BMI2__
#define __BMI2__ 1
#endif
#ifndef __LZCNT__
#define __LZCNT__ 1
#endif
#endif

#if BOXCYL_ISA_LEVEL >= 3
#ifndef __AVX512F__
#define __AVX512F__ 1
#endif
#ifndef __AVX512DQ__
#define __AVX512DQ__ 1
#endif
#ifndef __AVX512VL__
#define __AVX512VL__ 1
#endif
#ifndef __AVX512BW__
#define __AVX512BW__ 1
#endif
#endif
