// The batch API's kernels in the tests (tests/test_batch.cpp, tests/test_batch_clearance.cpp): every
// kernel this machine runs, and kernels printed by name in test names and messages.
#pragma once

#include <ostream>  // PrintTo
#include <vector>   // the kernels

#include "boxcyl/batch.hpp"

// Kernels print by name in test names and messages (not as "4-byte object <03-00 00-00>").
namespace boxcyl::batch {
inline void PrintTo(Kernel k, std::ostream* os) { *os << name(k); }
}  // namespace boxcyl::batch

namespace boxcyl::testing {

// Every kernel this machine runs. avx2 and avx512 come from boxcyl::batch_dispatch (linked by the
// test), where it was built with them (GCC, x86-64) and the CPU has them.
inline std::vector<batch::Kernel> runnable_kernels() {
    std::vector<batch::Kernel> ks;
    for (batch::Kernel k : {batch::Kernel::compiled, batch::Kernel::avx2, batch::Kernel::avx512})
        if (batch::available(k)) ks.push_back(k);
    return ks;
}

}  // namespace boxcyl::testing
