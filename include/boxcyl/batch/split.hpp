// The thread split of the batch API: contiguous ranges of whole 64-box blocks, so that no two threads
// write the same output word (bit masks) and the answers do not depend on the split.
#pragma once

#include <algorithm>  // std::min, std::max
#include <cstddef>    // std::size_t
#include <exception>  // std::exception_ptr: a worker's exception is rethrown by the caller
#include <thread>     // std::thread
#include <vector>     // the workers

namespace boxcyl::batch::split {

// Below this many boxes per thread, starting a thread costs more than it saves (~10 µs against the
// filter's few ns per box).
inline constexpr std::size_t kMinBoxesPerThread = 32768;

// threads == 0: std::thread::hardware_concurrency(); never more threads than n / kMinBoxesPerThread.
inline unsigned thread_count(unsigned threads, std::size_t n) {
    std::size_t t = threads != 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
    t = std::min(t, std::max<std::size_t>(1, n / kMinBoxesPerThread));
    return static_cast<unsigned>(t);
}

// Calls work(first_block, last_block, thread_index) over [0, blocks) split into `threads` ranges; the
// calling thread takes the first range. Rethrows the first exception a worker threw.
template <class Work>
void for_each_range(std::size_t blocks, unsigned threads, Work&& work) {
    if (threads <= 1 || blocks <= 1) {
        work(std::size_t{0}, blocks, 0u);
        return;
    }
    threads = static_cast<unsigned>(std::min<std::size_t>(threads, blocks));
    std::vector<std::exception_ptr> errors(threads);
    std::vector<std::thread> workers;
    workers.reserve(threads - 1);
    auto range = [&](unsigned t) {
        const std::size_t b = blocks * t / threads, e = blocks * (t + 1) / threads;
        try {
            work(b, e, t);
        } catch (...) {
            errors[t] = std::current_exception();
        }
    };
    for (unsigned t = 1; t < threads; ++t) workers.emplace_back(range, t);
    range(0);
    for (std::thread& w : workers) w.join();
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
}

}  // namespace boxcyl::batch::split
