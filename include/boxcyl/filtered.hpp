// The exact default: the exact answer for double inputs, at close to floating-point speed. Semantics as
// the oracle's: every double is the rational it denotes, the cylinder axis is axis/|axis| exactly, an
// oriented box is the parallelepiped its axes span exactly as given, both solids are closed (touching
// intersects).
//
// A filtered predicate: the query is prepared once (filtered/prepared.hpp), then the rows of its box
// kind's schedule (filtered/schedule.hpp) run in order — each a certificate that answers hit, miss or
// "not certified" — until one decides; the last row is the exact stage (exact/answer.hpp), in integers
// and Z[√d], which always does. docs/pipeline.md describes the rows, docs/robustness/ the proofs.
//
// Preconditions: validate() holds for the box and the cylinder (asserted in debug builds).
//
// Floating-point environment: every certificate is sound in every IEEE rounding mode (the rows on
// double-double arithmetic run only in round to nearest), with or without FMA contraction, with
// subnormals, overflow and underflow (they make comparisons undecided, never wrong), but NOT with
// flush-to-zero or denormals-are-zero (-ffast-math startup code, or MXCSR FTZ/DAZ set by another
// library): check boxcyl::fp_environment_ok() once at start-up if that can happen.
//
// Debug switches (compile-time macros; define them before including this header, in every TU):
//   BOXCYL_FORCE_EXACT=1   skip the certificates: every query answers with the exact stage.
//   BOXCYL_CHECK_FILTER=1  whenever a certificate decides, also run the exact stage; on a mismatch throw
//                          std::logic_error naming the row and the case (hex floats, copy-pasteable).
#pragma once

#include <cassert>    // debug-build precondition checks
#include <cstdio>     // std::snprintf for the CHECK_FILTER message
#include <stdexcept>  // std::logic_error (BOXCYL_CHECK_FILTER)
#include <string>     // the CHECK_FILTER message
#include <type_traits>  // std::is_same_v

#include "boxcyl/exact/answer.hpp"
#include "boxcyl/filtered/prepared.hpp"
#include "boxcyl/filtered/schedule.hpp"
#include "boxcyl/filtered/stats.hpp"
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/validate.hpp"

namespace boxcyl::filtered {

// The box kinds of the exact default.
template <class Box>
concept DoubleBox = std::is_same_v<Box, AlignedBox<double>> || std::is_same_v<Box, OrientedBox<double>> ||
                    std::is_same_v<Box, CanonicalBox<double>> || std::is_same_v<Box, Parallelepiped<double>>;

// intersect: the exact answer. exact_used: no certificate decided and the exact stage answered.
struct Result {
    bool intersect;
    bool exact_used;
};

namespace detail {

// The case as copy-pasteable C++ (hex floats), for BOXCYL_CHECK_FILTER's message.
inline std::string hex(double x) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%a", x);
    return buf;
}
inline std::string hex(const Vec3<double>& v) { return "{" + hex(v[0]) + ", " + hex(v[1]) + ", " + hex(v[2]) + "}"; }
inline std::string describe(const AlignedBox<double>& b) {
    return "AlignedBox<double>{" + hex(b.min) + ", " + hex(b.max) + "}";
}
inline std::string describe(const CanonicalBox<double>& b) { return "CanonicalBox<double>{" + hex(b.extents) + "}"; }
template <class Box>  // OrientedBox, Parallelepiped
std::string describe(const Box& b) {
    const char* kind = std::is_same_v<Box, OrientedBox<double>> ? "OrientedBox<double>{" : "Parallelepiped<double>{";
    return kind + hex(b.center) + ", {Vec3<double>" + hex(b.axes[0]) + ", Vec3<double>" + hex(b.axes[1]) +
           ", Vec3<double>" + hex(b.axes[2]) + "}, " + hex(b.extents) + "}";
}
inline std::string describe(const Cylinder<double>& c) {
    return "Cylinder<double>{" + hex(c.center) + ", " + hex(c.axis) + ", " + hex(c.radius) + ", " + hex(c.height) + "}";
}

template <class Box, class Recorder>
BOXCYL_FORCE_INLINE inline Result run(const Box& box, const Cylinder<double>& cyl, Recorder& stats) {
    assert(is_valid(box) && "boxcyl::filtered::query: invalid box (see boxcyl::validate)");
    assert(is_valid(cyl) && "boxcyl::filtered::query: invalid cylinder (see boxcyl::validate)");
#if defined(BOXCYL_FORCE_EXACT) && BOXCYL_FORCE_EXACT
    (void)stats;
    return {*exact::answer(box, cyl), true};
#else
    // A parallelepiped whose axes are a signed permutation of the unit vectors is that oriented box,
    // whose schedule starts from an exact frame.
    if constexpr (std::is_same_v<Box, Parallelepiped<double>>) {
        if (signed_permutation(box.axes)) [[unlikely]]
            return run(OrientedBox<double>{box.center, box.axes, box.extents}, cyl, stats);
    }
    if constexpr (Recorder::enabled) ++stats.queries;
    RowId by = RowId::exact;
    const auto checked = [&](const Verdict& v) -> const Verdict& {
#if defined(BOXCYL_CHECK_FILTER) && BOXCYL_CHECK_FILTER
        if (!is_exact_row(by) && *exact::answer(box, cyl) != *v)
            throw std::logic_error("boxcyl::filtered: row " + std::string(name(by)) + " answered " +
                                   std::string(*v ? "true" : "false") + " but the exact answer differs for " +
                                   describe(box) + ", " + describe(cyl));
#endif
        return v;
    };
    Given<Box> given{box, cyl};
    if constexpr (std::is_same_v<Box, Parallelepiped<double>>) {
        if (const Verdict v = walk(given, stats, by)) return {*checked(v), false};
        Prepared<Box> q(box, cyl);
        const Verdict v = walk(q, stats, by);
        return {*checked(v), is_exact_row(by)};
    } else {
        Prepared<Box> q(box, cyl, [&] { return walk(given, stats, by); });
        if (q.early) return {*checked(q.early), false};
        const Verdict v = walk(q, stats, by);
        return {*checked(v), is_exact_row(by) || q.exact_in_pairs};
    }
#endif
}

}  // namespace detail

// The exact answer for an aligned, oriented, canonical box or any parallelepiped (for a canonical box
// the cylinder is in the box's frame).
template <DoubleBox Box>
Result query(const Box& box, const Cylinder<double>& cyl) {
    NoStats none;
    return detail::run(box, cyl, none);
}
// The same, counting and timing each row in `stats` (filtered/stats.hpp).
template <DoubleBox Box>
Result query(const Box& box, const Cylinder<double>& cyl, Stats& stats) {
    return detail::run(box, cyl, stats);
}

template <DoubleBox Box>
bool intersects(const Box& box, const Cylinder<double>& cyl) {
    return query(box, cyl).intersect;
}

// Translation units that link a copy compiled elsewhere (the batch kernels and the compiled library
// take it from boxcyl::batch_dispatch, src/batch/pipeline.cpp) declare the pipeline extern, so that its
// templates are compiled once.
#if defined(BOXCYL_PIPELINE_EXTERN) && BOXCYL_PIPELINE_EXTERN
extern template Result query(const AlignedBox<double>&, const Cylinder<double>&);
extern template Result query(const OrientedBox<double>&, const Cylinder<double>&);
extern template Result query(const CanonicalBox<double>&, const Cylinder<double>&);
extern template Result query(const Parallelepiped<double>&, const Cylinder<double>&);
extern template Result query(const AlignedBox<double>&, const Cylinder<double>&, Stats&);
extern template Result query(const OrientedBox<double>&, const Cylinder<double>&, Stats&);
extern template Result query(const CanonicalBox<double>&, const Cylinder<double>&, Stats&);
extern template Result query(const Parallelepiped<double>&, const Cylinder<double>&, Stats&);
#endif

}  // namespace boxcyl::filtered
