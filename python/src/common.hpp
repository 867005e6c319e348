// What the binding files of boxcyl._core share: the shape types, argument helpers, the float64 array
// fields of the batch forms, and the interruptible run (Ctrl-C) of long work with the GIL released.
//
// The library is reached through boxcyl/compiled.hpp's declarations (light headers); library.cpp
// compiles what the module uses of it, once, so that each binding file compiles quickly.
#pragma once

#include <pybind11/pybind11.h>

#include <array>               // Vec3 <-> std::array
#include <chrono>              // the signal-check period
#include <condition_variable>  // the caller waits for the runner with a timeout
#include <cstring>             // std::memcpy: array elements need not be aligned
#include <exception>           // the runner's exception, rethrown by the caller
#include <initializer_list>    // the fields of a batch
#include <mutex>               // the runner's completion
#include <stdexcept>           // std::runtime_error
#include <stop_token>          // the runner's stop
#include <string>              // messages
#include <thread>              // the runner

#include "boxcyl/compiled.hpp"
#include "boxcyl/number/interval.hpp"  // fp_environment_ok

#if !defined(BOXCYL_HAS_EXACT)
#error "the boxcyl Python module needs the exact backend (GMP): define BOXCYL_HAS_EXACT and link gmpxx"
#endif

namespace boxcyl_python {

namespace py = pybind11;

using Vec = boxcyl::Vec3<double>;
using Array3 = std::array<double, 3>;
using Matrix3 = std::array<Array3, 3>;
using Matrix4 = std::array<std::array<double, 4>, 4>;
using Cylinder = boxcyl::Cylinder<double>;
using AlignedBox = boxcyl::AlignedBox<double>;
using OrientedBox = boxcyl::OrientedBox<double>;
using Parallelepiped = boxcyl::Parallelepiped<double>;
using Index = py::ssize_t;

inline Vec vec(const Array3& a) { return {a[0], a[1], a[2]}; }
inline py::tuple tuple(const Vec& v) { return py::make_tuple(v[0], v[1], v[2]); }

// x, or a ValueError naming its first bad field ("box.max[0]: is less than box.min[0]").
template <class Object>
Object validated(Object x, const char* name) {
    if (!boxcyl::is_valid(x)) throw py::value_error(boxcyl::validate(x, name).message());
    return x;
}

// The filter's exactness assumes gradual underflow; a library loaded into the same process may have
// set flush-to-zero (e.g. one built with -ffast-math). Checked on the thread that runs the query.
inline void require_fp_environment() {
    if (!boxcyl::fp_environment_ok())
        throw std::runtime_error(
            "boxcyl: the floating-point environment flushes subnormals to zero (FTZ/DAZ, often set by a "
            "library built with -ffast-math); exact answers cannot be guaranteed in it");
}

// "boxes[17]" for an element of an array argument, "box" for a single object broadcast.
inline std::string element_name(const char* singular, const char* plural, bool single, Index i) {
    return single ? std::string(singular) : std::string(plural) + "[" + std::to_string(i) + "]";
}

// ---- Long work, interruptible. ----

// How often the calling thread looks for signals (Ctrl-C) while a runner works.
inline constexpr auto kSignalPeriod = std::chrono::milliseconds(10);

// Runs work(token) with the GIL released. Called with the GIL held. `brief`: the work is known to be
// short (a few milliseconds at most), so it runs on this thread, uninterrupted. Otherwise a runner
// thread does it (the batch API then adds its own threads) while this one runs Python's signal
// handlers every kSignalPeriod: when one raises (KeyboardInterrupt for Ctrl-C), the token's stop is
// requested — the library's batch threads look at it before every 64-box block, the module's loops
// between elements — and that exception propagates once the runner has returned. Otherwise the
// work's own exception, if any, is rethrown here.
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

// The registration of each area, called by the module's init in this order (classes first, so that
// the functions after them show their Python names in signatures).
void def_shapes(py::module_& m);
void def_poses(py::module_& m);
void def_query(py::module_& m);
void def_batch(py::module_& m);
void def_grid(py::module_& m);

}  // namespace boxcyl_python
