// The kernels of boxcyl::batch_dispatch (src/batch/), declared for boxcyl/batch.hpp, which includes
// this header when that library is linked (it defines BOXCYL_BATCH_DISPATCH for its users).
#pragma once

#include "boxcyl/batch/types.hpp"

namespace boxcyl::batch::dispatch {

// The table of kernel k (Kernel::avx2 or Kernel::avx512) if the library was built with it and this CPU
// and its operating system run it, else nullptr. Decided once per process (CPUID and XGETBV, through
// GCC's __builtin_cpu_supports); cheap to call.
const KernelTable* find(Kernel k) noexcept;

}  // namespace boxcyl::batch::dispatch
