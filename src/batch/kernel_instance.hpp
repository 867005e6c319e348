// The body of a kernel translation unit (kernel_avx2.cpp, kernel_avx512.cpp), after its target pragma
// and instruction-set macros: the kernel (batch/filter.hpp, batch/kernel.hpp) in the namespace
// BOXCYL_BATCH_ISA, and its table, dispatch::BOXCYL_KERNEL_TABLE, for dispatch.cpp. The including file
// defines BOXCYL_BATCH_ISA, BOXCYL_KERNEL_ID (a Kernel enumerator), BOXCYL_KERNEL_TABLE and
// BOXCYL_KERNEL_LANES (the width its instruction set must give). No include guard: one inclusion per
// translation unit.
#include <experimental/simd>

#include "boxcyl/batch/filter.hpp"
#include "boxcyl/batch/kernel.hpp"

static_assert(boxcyl::batch::BOXCYL_BATCH_ISA::lane_count == BOXCYL_KERNEL_LANES,
              "the instruction-set macros did not give <experimental/simd> the kernel's width");

namespace boxcyl::batch::dispatch {
extern const KernelTable BOXCYL_KERNEL_TABLE;  // extern: a namespace-scope const is otherwise file-local
const KernelTable BOXCYL_KERNEL_TABLE = BOXCYL_BATCH_ISA::kernel_table(Kernel::BOXCYL_KERNEL_ID);
}  // namespace boxcyl::batch::dispatch
