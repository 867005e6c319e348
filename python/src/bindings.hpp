// The Python side of boxcyl._core, shared by module.cpp (the module and its functions) and shapes.cpp
// (its classes): pybind11, and the interruptible run of long work with the GIL released.
#pragma once

#include <pybind11/pybind11.h>

#include <chrono>              // the signal-check period
#include <condition_variable>  // the caller waits for the runner with a timeout
#include <exception>           // the runner's exception, rethrown by the caller
#include <mutex>               // the runner's completion
#include <stop_token>          // the runner's stop
#include <thread>              // the runner

#include "common.hpp"

namespace boxcyl_python {

namespace py = pybind11;

inline py::tuple tuple(const Vec& v) { return py::make_tuple(v[0], v[1], v[2]); }

// The option enums and the shape classes (shapes.cpp).
void def_shapes(py::module_& m);

// How often the calling thread looks for signals (Ctrl-C) while a runner works.
inline constexpr auto kSignalPeriod = std::chrono::milliseconds(10);

// Runs work(token) with the GIL released. Called with the GIL held. `brief`: the work is known to be
// short (a few milliseconds at most), so it runs on this thread, uninterrupted. Otherwise a runner
// thread does it (the batch API then adds its own threads) while this one runs Python's signal
// handlers every kSignalPeriod: when one raises (KeyboardInterrupt for Ctrl-C), the token's stop is
// requested — the library's batch threads look at it before each group of 64-box blocks and each
// block's exact work, the module's loops between elements — and that exception propagates once the
// runner has returned. Otherwise the work's own exception, if any, is rethrown here.
template <class Work>
void run_interruptibly(bool brief, Work&& work) {
    if (brief) {
        py::gil_scoped_release release;
        require_fp_environment();
        work(std::stop_token{});
        return;
    }
    std::stop_source stop;
    std::exception_ptr error;
    std::mutex mutex;
    std::condition_variable finished;
    bool done = false, interrupted = false;
    {
        py::gil_scoped_release release;
        std::thread runner([&] {
            try {
                require_fp_environment();
                work(stop.get_token());
            } catch (...) {
                error = std::current_exception();
            }
            const std::lock_guard<std::mutex> lock(mutex);
            done = true;
            finished.notify_one();
        });
        for (;;) {
            {
                std::unique_lock<std::mutex> lock(mutex);
                if (finished.wait_for(lock, kSignalPeriod, [&] { return done; })) break;
            }
            if (interrupted) continue;
            const py::gil_scoped_acquire acquire;
            if (PyErr_CheckSignals() != 0) {  // the handler's exception stays set on this thread
                interrupted = true;
                stop.request_stop();
            }
        }
        runner.join();
    }
    if (interrupted) throw py::error_already_set();
    if (error) std::rethrow_exception(error);
}

}  // namespace boxcyl_python
