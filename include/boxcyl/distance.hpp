// The distance question: boxcyl::distance(box, cylinder) — how far apart are they, and where? The
// answer is an enclosure [lower, upper] PROVED to hold the exact Euclidean distance between the closed
// solids (each double the rational it denotes, the axis D/|D| exact), in every rounding mode, and
// narrow: upper − lower ≤ 4 ulp(upper), subnormal results included (in practice one or two ulps). It is
// [0, 0] exactly when they intersect. Every box kind; float inputs are widened exactly. With it comes
// a nearest pair, one point near each solid: approximate, not proved (distance_types.hpp says how near).
// Invalid input throws std::invalid_argument naming the field (validate()); distance_unchecked()
// skips that check. Needs the exact backend (boxcyl::exact).
//
// How (docs/distance.md has the argument):
//   1. Whether they meet: a hit is [0, 0]. Asked of the exact intersection query only where the bounds
//      of step 3 do not prove a gap first.
//   2. Both shapes scaled by a power of two, exactly, to lengths near 1.
//   3. Certified bounds from an approximate closest pair (filtered/separation.hpp), refined by Newton's
//      method (in double, then in double-double where the bounds need it) and evaluated in
//      double-double with proved error bounds (filtered/separation_refined.hpp): the upper bound is a
//      box point's distance to the cylinder, the lower one the gap between two supporting planes. Each
//      double-double enclosure is then rounded outward to the nearest doubles it proves.
//   4. Whatever is still wider than 4 doubles (directed rounding modes, where the double-double stage
//      declines; distances the refinement does not pin down) is bisected over the doubles with the
//      exact clearance query: within_distance(box, cyl, m) true makes m an upper bound, false a lower
//      one. Each bisection step halves the count of doubles in between, so at most 64 steps remain.
#pragma once

#include <algorithm>    // std::max, std::clamp
#include <array>        // half axes
#include <bit>          // std::bit_cast: doubles ≥ 0 ordered as integers
#include <cmath>        // std::isfinite, std::ilogb, std::sqrt
#include <cstdint>      // std::uint64_t
#include <limits>       // infinity
#include <optional>     // the intersection query, asked once
#include <stdexcept>    // std::invalid_argument
#include <type_traits>  // std::is_same_v

#include "boxcyl/clearance.hpp"
#include "boxcyl/distance_types.hpp"
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/validate.hpp"
#include "boxcyl/geometry/vec3.hpp"
#include "boxcyl/query.hpp"

namespace boxcyl {

#if defined(BOXCYL_HAS_EXACT)
namespace detail::distance {

// Doubles ≥ 0 are ordered as their bit patterns: the count of doubles between two, and the one
// halfway (by count) between them.
inline std::uint64_t steps(double lo, double hi) {
    return std::bit_cast<std::uint64_t>(hi) - std::bit_cast<std::uint64_t>(lo);
}
inline double halfway(double lo, double hi) {
    const std::uint64_t a = std::bit_cast<std::uint64_t>(lo);
    return std::bit_cast<double>(a + (std::bit_cast<std::uint64_t>(hi) - a) / 2);
}
// The goal: at most 4 doubles apart, which bounds the width by 4 ulp(upper) (the gaps below upper are
// no wider than the one above it).
inline constexpr std::uint64_t max_steps = 4;

inline Vec3<double> round(const filtered::separation::refined::DV& v) {
    using filtered::separation::refined::approx;
    return {approx(v[0]), approx(v[1]), approx(v[2])};
}

// An aligned box's witness clamped into it (exact: each coordinate between the bounds it already
// nearly meets); other boxes' witnesses keep their rounding.
inline Vec3<double> into(const AlignedBox<double>& b, Vec3<double> p) {
    for (int i = 0; i < 3; ++i) p[i] = p[i] < b.min[i] ? b.min[i] : p[i] > b.max[i] ? b.max[i] : p[i];
    return p;
}
template <class Box>
Vec3<double> into(const Box&, const Vec3<double>& p) {
    return p;
}

// Newton steps in double the distance allows the refinement (it stops sooner once converged): more than
// the clearance query's, which needs only to decide against one margin, so that the witnesses converge too.
inline constexpr int newton_steps = 16;

// The shapes scaled by 2^e: exact, or `exact` turns false (an input would lose bits or overflow).
struct Scale {
    int e;
    bool exact = true;
    double operator()(double x) {  // (products with powers of two: std::ldexp is a libm call)
        const double y = filtered::times_two_to(x, e);
        if (filtered::times_two_to(y, -e) != x) exact = false;
        return y;
    }
    Vec3<double> operator()(const Vec3<double>& v) { return {(*this)(v[0]), (*this)(v[1]), (*this)(v[2])}; }
    AlignedBox<double> operator()(const AlignedBox<double>& b) { return {(*this)(b.min), (*this)(b.max)}; }
    OrientedBox<double> operator()(const OrientedBox<double>& b) { return {(*this)(b.center), b.axes, (*this)(b.extents)}; }
    Parallelepiped<double> operator()(const Parallelepiped<double>& b) { return {(*this)(b.center), b.axes, (*this)(b.extents)}; }
    CanonicalBox<double> operator()(const CanonicalBox<double>& b) { return {(*this)(b.extents)}; }
    Cylinder<double> operator()(const Cylinder<double>& c) { return {(*this)(c.center), c.axis, (*this)(c.radius), (*this)(c.height)}; }
};

// ilogb(x) for a finite x ≠ 0, from the bits where x is normal (std::ilogb is a libm call).
inline int exponent(double x) {
    const auto biased = static_cast<int>((std::bit_cast<std::uint64_t>(x) >> 52) & 0x7ff);
    return biased != 0 ? biased - 1023 : std::ilogb(x);
}
// The binary exponent of the largest length the shapes hold (coordinates, half axes, radius, height).
struct Magnitude {
    int e = std::numeric_limits<int>::min();
    void operator()(double x) {
        if (x != 0 && std::isfinite(x)) e = std::max(e, exponent(x));
    }
    void operator()(const Vec3<double>& v) { (*this)(v[0]), (*this)(v[1]), (*this)(v[2]); }
    void half_axes(const std::array<Vec3<double>, 3>& axes, const Vec3<double>& extents) {
        for (std::size_t i = 0; i < 3; ++i) {
            const double a = std::max({std::abs(axes[i][0]), std::abs(axes[i][1]), std::abs(axes[i][2])});
            if (a != 0 && extents[i] != 0 && std::isfinite(a) && std::isfinite(extents[i]))
                e = std::max(e, exponent(a) + exponent(extents[i]) + 1);
        }
    }
    void operator()(const AlignedBox<double>& b) { (*this)(b.min), (*this)(b.max); }
    void operator()(const OrientedBox<double>& b) { (*this)(b.center), half_axes(b.axes, b.extents); }
    void operator()(const Parallelepiped<double>& b) { (*this)(b.center), half_axes(b.axes, b.extents); }
    void operator()(const CanonicalBox<double>& b) { (*this)(b.extents); }
    void operator()(const Cylinder<double>& c) { (*this)(c.center), (*this)(c.radius), (*this)(c.height); }
};

// The double-double stage's bounds and witnesses (filtered/separation_refined.hpp). Its squares and
// products must neither overflow nor underflow: the caller hands it shapes scaled to lengths near 1.
// GJK's convergence test for the distance: loose, as Newton's method refines its point to the end
// (2^-20 measured fastest on bench_distance's sets: looser starts cost Newton more steps, and a few of
// them end on a point whose bounds need the bisection).
inline constexpr double search_gap = 0x1p-20;
// The start: for a separated pair, alternating projections first (a third of GJK's cost; Newton's steps
// converge from their point on nearly every pair), without the refinement's last resorts; where their
// bounds are still wider than the goal, GJK's pair, with them (a box lying nearly along the axis or a
// cap, where the projections' point lies in the wrong valley); test_separation_judged's
// FirstStartMeetsTheDistanceGoal shows how rarely.
// `meets()`: whether the solids intersect (the exact query), asked only where the bounds from the first
// start do not prove them apart (a lower bound above 0); those bounds are not tried where the
// projections' own pair is at distance 0 in double (overlapping solids, most likely).
template <class Box, class Meets>
Distance refined(const Box& box, const Cylinder<double>& cyl, Meets&& meets) {
    namespace sep = filtered::separation;
    sep::Approximate search = clearance::projected_search(box, cyl);
    sep::RefinedBounds r{};
    bool apart = false;
    if (search.upper > 0) {
        r = sep::refined_bounds(box, cyl, search, -1, newton_steps, max_steps, false);
        apart = r.found && sep::refined::lower_double(r.lower) > 0;
    }
    const bool touching = !apart && meets();
    Distance out{0.0, touching ? 0.0 : std::numeric_limits<double>::infinity(), {}, {}};
    if (touching || !r.found || !sep::refined::within_doubles(r, max_steps)) {
        search = clearance::search_in_double(box, cyl, -1, search_gap);
        r = sep::refined_bounds(box, cyl, search, -1, newton_steps, max_steps);
    }
    if (r.found && !touching) {
        out.lower = sep::refined::lower_double(r.lower);
        out.upper = sep::refined::upper_double(r.upper);
    } else if (!touching) {  // not round to nearest: the interval bounds, proved in every mode
        const sep::Bounds db = sep::bounds(box, cyl, -1);
        out.lower = std::max(0.0, db.lower);
        if (db.upper == db.upper) out.upper = db.upper;
    }
    // The witnesses: the refined box point (the double search's where the refinement declines) and the
    // cylinder point nearest it, as values (they need no proof; in a directed rounding mode they are
    // a few ulps less accurate).
    if (r.found) {
        out.on_box = round(r.witness);
        out.on_cylinder = round(r.witness + r.toward);
    } else if (search.found) {
        const sep::refined::DV X = sep::refined::lift(search.p);
        out.on_box = round(X);
        out.on_cylinder = round(sep::refined::nearest_on_cylinder(sep::refined::cylinder(cyl), X));
    }
    return out;
}

template <class Box>
Distance distance(const Box& box, const Cylinder<double>& cyl) {
    std::optional<bool> meet;  // the exact intersection query's answer, once asked
    auto meets = [&] {
        if (!meet) meet = intersects_unchecked(box, cyl);
        return *meet;
    };
    // Scaled so that the largest length is near 1, where the scaling is exact (distances scale with it).
    Magnitude size;
    size(box), size(cyl);
    Scale scale{size.e == std::numeric_limits<int>::min() ? 0 : std::clamp(-size.e, -1000, 1000)};
    const Box sbox = scale(box);
    const Cylinder<double> scyl = scale(cyl);
    Distance out;
    if (scale.exact && scale.e != 0) {
        out = refined(sbox, scyl, meets);
        Scale back{-scale.e};
        out.on_box = back(out.on_box);
        out.on_cylinder = back(out.on_cylinder);
        const double lower = back(out.lower), upper = back(out.upper);
        // Rounded back outward where the result left the normal range.
        out.lower = filtered::times_two_to(lower, scale.e) == out.lower ? lower : std::max(0.0, boxcyl::detail::next_down(lower));
        out.upper = filtered::times_two_to(upper, scale.e) == out.upper ? upper : boxcyl::detail::next_up(upper);
    } else {
        out = refined(box, cyl, meets);
    }
    out.on_box = into(box, out.on_box);
    if (meet.value_or(false)) return out;  // not asked: the bounds proved them apart
    // The exact bisection: what the bounds leave wider than the goal.
    while (steps(out.lower, out.upper) > max_steps) {
        const double m = halfway(out.lower, out.upper);
        if (within_distance_unchecked(box, cyl, m))
            out.upper = m;
        else
            out.lower = m;
    }
    return out;
}

}  // namespace detail::distance
#endif

// The certified distance. Preconditions: a valid box and cylinder.
template <class Box, class T>
Distance distance_unchecked(const Box& box, const Cylinder<T>& cyl) {
#if defined(BOXCYL_HAS_EXACT)
    if constexpr (std::is_same_v<T, double>)
        return detail::distance::distance(box, cyl);
    else
        return detail::distance::distance(detail::cast<double>(box), detail::cast<double>(cyl));
#else
    static_assert(detail::dependent_false<T>, "boxcyl::distance is certified by the exact clearance query and needs "
                                              "the exact backend: link boxcyl::exact (GMP, FLINT)");
    return {};
#endif
}

template <class Box, class T>
Distance distance(const Box& box, const Cylinder<T>& cyl) {
    detail::require_valid(box, cyl);
    return distance_unchecked(box, cyl);
}

}  // namespace boxcyl
