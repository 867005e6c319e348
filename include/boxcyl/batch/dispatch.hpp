// The kernels of boxcyl::batch_dispatch (src/batch/), declared for boxcyl/batch.hpp, which includes
// this header when that library is linked (it defines BOXCYL_BATCH_DISPATCH for its users).
#pragma once

#include "boxcyl/batch/types.hpp"
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"

namespace boxcyl::batch::dispatch {

// The table of kernel k (Kernel::avx2 or Kernel::avx512) if the library was built with it and this CPU
// and its operating system run it, else nullptr. Decided once per process (CPUID and XGETBV, through
// GCC's __builtin_cpu_supports); cheap to call.
const KernelTable* find(Kernel k) noexcept;

// The scalar exact default (filtered::query(box, cyl).intersect), compiled once for plain x86-64
// (src/batch/scalar.cpp): the kernels built for AVX2 and AVX-512 send the lanes their filter leaves
// here (BOXCYL_BATCH_SCALAR_APART, batch/kernel.hpp) instead of each compiling the whole exact query
// again, which was most of their build time. A program that links the kernels defines these once.
bool scalar_intersects(const AlignedBox<double>& box, const Cylinder<double>& cyl);
bool scalar_intersects(const OrientedBox<double>& box, const Cylinder<double>& cyl);

}  // namespace boxcyl::batch::dispatch
