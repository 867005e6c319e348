// boxcyl::batch_dispatch: which of the kernels compiled into this library (kernel_avx2.cpp,
// kernel_avx512.cpp; only those CMake built, as BOXCYL_BATCH_HAVE_AVX2/AVX512 say) this CPU runs.
// Compiled for plain x86-64 like the rest of the library.
#include "boxcyl/batch/dispatch.hpp"

namespace boxcyl::batch::dispatch {

#if defined(BOXCYL_BATCH_HAVE_AVX2)
extern const KernelTable avx2_table;
#endif
#if defined(BOXCYL_BATCH_HAVE_AVX512)
extern const KernelTable avx512_table;
#endif

namespace {

// GCC's __builtin_cpu_supports reads CPUID and, for AVX and AVX-512, XGETBV: a feature counts only if
// the operating system saves its registers.
#if defined(BOXCYL_BATCH_HAVE_AVX2) || defined(BOXCYL_BATCH_HAVE_AVX512)
bool cpu_runs_avx2() {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi") &&
           __builtin_cpu_supports("bmi2") && __builtin_cpu_supports("popcnt") && __builtin_cpu_supports("sse4.2");
}
#endif
#if defined(BOXCYL_BATCH_HAVE_AVX512)
bool cpu_runs_avx512() {
    return cpu_runs_avx2() && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
           __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512bw");
}
#endif

}  // namespace

const KernelTable* find(Kernel k) noexcept {
#if defined(BOXCYL_BATCH_HAVE_AVX2)
    if (k == Kernel::avx2) {
        static const bool runs = cpu_runs_avx2();
        return runs ? &avx2_table : nullptr;
    }
#endif
#if defined(BOXCYL_BATCH_HAVE_AVX512)
    if (k == Kernel::avx512) {
        static const bool runs = cpu_runs_avx512();
        return runs ? &avx512_table : nullptr;
    }
#endif
    (void)k;
    return nullptr;
}

}  // namespace boxcyl::batch::dispatch
