// How much of this thread's stack is left below the caller's frame. The exact stage's two-scale runs
// (exact/integer_inequalities.hpp) keep their wide integers on the stack: the query's deepest path
// takes about 115 KB at -O2 (test ExactStage.StackHighWaterMark prints it). A thread with a small
// stack (musl's default is 128 KB) would overflow there, so with too little room the stage answers in
// mpz_class instead: tens of KB of stack, slower, as exact.
#pragma once

#include <cstddef>  // std::size_t
#include <cstdint>  // std::uintptr_t
#include <limits>   // "unknown": no limit

#if defined(__linux__)
#include <pthread.h>  // pthread_getattr_np (glibc, musl)
#endif

namespace boxcyl::exact {

// Bytes from the caller's frame down to the lowest address of this thread's stack (stacks grow down
// on the platforms this reads); the largest size_t where the platform does not say. The stack's
// bounds are read once per thread. The frame address, not a local's: a sanitizer may put locals on a
// heap-allocated fake stack.
inline std::size_t stack_room() {
#if defined(__linux__)
    thread_local const std::uintptr_t low = [] {
        pthread_attr_t attr;
        if (pthread_getattr_np(pthread_self(), &attr) != 0) return std::uintptr_t{0};
        void* addr = nullptr;
        std::size_t size = 0;
        const bool known = pthread_attr_getstack(&attr, &addr, &size) == 0;
        pthread_attr_destroy(&attr);
        return known ? reinterpret_cast<std::uintptr_t>(addr) : std::uintptr_t{0};
    }();
    if (low == 0) return std::numeric_limits<std::size_t>::max();
    const auto frame = reinterpret_cast<std::uintptr_t>(__builtin_frame_address(0));
    return frame > low ? frame - low : 0;
#else
    return std::numeric_limits<std::size_t>::max();
#endif
}

}  // namespace boxcyl::exact
