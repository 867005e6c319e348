// The front door: boxcyl::intersects(box, cylinder[, options]) for aligned, oriented and canonical
// boxes and any parallelepiped. Closed solids: touching counts as intersecting. Invalid input (see
// validate(): NaN or ±Inf, a zero axis, a negative size, min > max, oriented-box axes not orthonormal)
// throws std::invalid_argument naming the field, in every build type; intersects_unchecked() skips the
// check (a precondition then, asserted in debug builds).
//
// boxcyl::intersects(box, cylinder) — no options — is EXACT for the inputs as given: certificates in
// floating point decide most queries, the exact stage the rest (filtered.hpp, docs/pipeline.md; its cost
// relative to plain double is measured in docs/performance.md).
// It needs the exact backend (link boxcyl::exact); without it, that call fails to compile, and the plain
// double path stays available by explicit choice: intersects(box, cyl, {Algorithm::inequalities,
// Arithmetic::float64}).
//
// Options choose the algorithm (the three methods of docs/algorithms.md, or the oracle) and the arithmetic:
//   Algorithm::inequalities  linear inequalities (default)         algo/linear_inequalities.hpp
//   Algorithm::hull          clip, project, convex hull            algo/convex_hull.hpp
//   Algorithm::lcp           convex QP as an LCP (Lemke)           algo/quadratic_programming.hpp
//   Algorithm::oracle        the exact reference, any arithmetic    oracle/oracle.hpp
//   Arithmetic::float32 / float64: rounded; may misjudge inputs within a tiny gap of touching.
//   Arithmetic::exact: rationals and a + b·√d, exact for the inputs as given (exact/paths.hpp).
//   Arithmetic::filtered (default): the exact answer; with inequalities through the filter above, with
//   hull/lcp
//                        (which have no filter) through Arithmetic::exact.
// The LCP method in float/double can fail (Lemke's method is not robust in floating point, as the
// published note warns); the query then answers exactly instead of guessing (exact LCP, or the exact
// convex-hull method for an oriented box whose axes are
// not exactly orthonormal). The oracle and Arithmetic::exact need
// the exact backend (link boxcyl::exact, which defines BOXCYL_HAS_EXACT); without it, choosing them
// throws std::invalid_argument. The exact LCP and linear-inequalities methods on an oriented box whose
// axes are not exactly orthonormal throw std::domain_error (see exact/paths.hpp); the convex-hull
// method and the oracle handle any box.
#pragma once

#include <cassert>    // debug-build precondition checks
#include <optional>   // results of algorithms that may fail
#include <stdexcept>  // std::invalid_argument for an unavailable option, std::domain_error
#include <type_traits>  // std::is_same_v

#include "boxcyl/algo/convex_hull.hpp"
#include "boxcyl/algo/linear_inequalities.hpp"
#include "boxcyl/algo/quadratic_programming.hpp"
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/reduce.hpp"
#include "boxcyl/geometry/validate.hpp"
#include "boxcyl/options.hpp"
#if defined(BOXCYL_HAS_EXACT)
#include "boxcyl/exact/answer.hpp"
#include "boxcyl/exact/paths.hpp"
#include "boxcyl/filtered.hpp"
#include "boxcyl/oracle/oracle.hpp"
#endif

namespace boxcyl {

namespace detail {

template <class U, class T>
Vec3<U> cast(const Vec3<T>& v) {
    return {static_cast<U>(v[0]), static_cast<U>(v[1]), static_cast<U>(v[2])};
}
template <class U, class T>
Cylinder<U> cast(const Cylinder<T>& c) {
    return {cast<U>(c.center), cast<U>(c.axis), static_cast<U>(c.radius), static_cast<U>(c.height)};
}
template <class U, class T>
AlignedBox<U> cast(const AlignedBox<T>& b) {
    return {cast<U>(b.min), cast<U>(b.max)};
}
template <class U, class T>
OrientedBox<U> cast(const OrientedBox<T>& b) {
    return {cast<U>(b.center), {cast<U>(b.axes[0]), cast<U>(b.axes[1]), cast<U>(b.axes[2])}, cast<U>(b.extents)};
}
template <class U, class T>
Parallelepiped<U> cast(const Parallelepiped<T>& b) {
    return {cast<U>(b.center), {cast<U>(b.axes[0]), cast<U>(b.axes[1]), cast<U>(b.axes[2])}, cast<U>(b.extents)};
}
template <class U, class T>
CanonicalBox<U> cast(const CanonicalBox<T>& b) {
    return {cast<U>(b.extents)};
}

// One algorithm in rounded arithmetic U on the box and cylinder converted to U.
template <class U, class Box, class T>
std::optional<bool> rounded(Algorithm a, const Box& box, const Cylinder<T>& cyl) {
    const UnitCylinder<U> u = to_unit(cast<U>(cyl));
    switch (a) {
        case Algorithm::inequalities: {
            const auto q = to_canonical(cast<U>(box), u);
            return algo::linear_inequalities(q.box, q.cylinder);
        }
        case Algorithm::hull: return algo::convex_hull(algo::as_parallelepiped(cast<U>(box)), u);
        case Algorithm::lcp: {
            const auto q = to_canonical(cast<U>(box), u);
            return algo::quadratic_programming(q.box, q.cylinder);
        }
        case Algorithm::oracle: break;
    }
    throw std::invalid_argument("boxcyl: not a rounded algorithm");
}

#if defined(BOXCYL_HAS_EXACT)
// The exact default, float inputs widened exactly, counted when the options carry statistics.
template <class Box, class T>
bool filtered_query(const Box& box, const Cylinder<T>& cyl, const QueryOptions& opt) {
    if constexpr (!std::is_same_v<T, double>)
        return filtered_query(cast<double>(box), cast<double>(cyl), opt);
    else
        return opt.stats ? filtered::query(box, cyl, *opt.stats).intersect : filtered::query(box, cyl).intersect;
}

inline exact::Method exact_method(Algorithm a) {
    switch (a) {
        case Algorithm::inequalities: return exact::Method::inequalities;
        case Algorithm::hull: return exact::Method::hull;
        case Algorithm::lcp: return exact::Method::lcp;
        case Algorithm::oracle: break;
    }
    throw std::invalid_argument("boxcyl: not a specification algorithm");
}
#endif

template <class Box, class T>
bool dispatch(const Box& box, const Cylinder<T>& cyl, const QueryOptions& opt) {
#if defined(BOXCYL_HAS_EXACT)
    // The default path's filtered::query asserts the same preconditions itself: checked once.
    [[maybe_unused]] const bool asserted_later =
        opt.arithmetic == Arithmetic::filtered && opt.algorithm == Algorithm::inequalities;
#else
    [[maybe_unused]] const bool asserted_later = false;
#endif
    assert((asserted_later || is_valid(box)) && "boxcyl::intersects: invalid box (see boxcyl::validate)");
    assert((asserted_later || is_valid(cyl)) && "boxcyl::intersects: invalid cylinder (see boxcyl::validate)");
    const bool rounded_arithmetic = opt.arithmetic == Arithmetic::float32 || opt.arithmetic == Arithmetic::float64;
    if (opt.algorithm != Algorithm::oracle && rounded_arithmetic) {
        const std::optional<bool> r = opt.arithmetic == Arithmetic::float32 ? rounded<float>(opt.algorithm, box, cyl)
                                                                          : rounded<double>(opt.algorithm, box, cyl);
        if (r) return *r;
        // Only the LCP method can fail (its Lemke solver in floating point); answer exactly rather than
        // guess.
    }
#if defined(BOXCYL_HAS_EXACT)
    // The default first, before any rational is built: the filter decides most queries in plain double,
    // and converting the inputs to GMP rationals alone costs ten times the filter.
    if (opt.arithmetic == Arithmetic::filtered && opt.algorithm == Algorithm::inequalities) return filtered_query(box, cyl, opt);
    const auto ebox = to_exact(cast<double>(box));
    const auto ecyl = to_exact(cast<double>(cyl));
    if (opt.algorithm == Algorithm::oracle) return oracle::intersects(ebox, ecyl);
    if (opt.arithmetic != Arithmetic::exact) {
        // A rounded LCP method failed, or lcp/hull were asked for an exact answer (filtered). Answer with
        // the exact algorithm where its canonical frame is exact, else with the exact convex-hull method
        // (any parallelepiped): only an explicit Arithmetic::exact request for lcp/inequalities refuses
        // a frame it cannot treat exactly.
        if constexpr (std::is_same_v<Box, OrientedBox<T>>)
            if (!exact::detail::exactly_orthonormal(ebox)) return exact::intersects(exact::Method::hull, ebox, ecyl);
    }
    return exact::intersects(exact_method(opt.algorithm), ebox, ecyl);
#else
    throw std::invalid_argument("boxcyl: exact arithmetic and the oracle need the exact backend (boxcyl::exact)");
#endif
}

// A Parallelepiped with options. Arithmetic::filtered: the exact answer whatever the algorithm (the
// certificates of filtered/parallelepiped.hpp for §4, exact §3 for §2/§3). §3 and the oracle take any
// parallelepiped in every arithmetic. §2 and §4 need an orthonormal box frame: axes that pass
// OrientedBox's contract (orthonormal within 1e-4) are that oriented box, with its rules; any other
// axes throw std::domain_error rather than answer for a different solid.
template <class T>
bool dispatch(const Parallelepiped<T>& box, const Cylinder<T>& cyl, const QueryOptions& opt) {
    assert(is_valid(box) && "boxcyl::intersects: invalid box (see boxcyl::validate)");
    assert(is_valid(cyl) && "boxcyl::intersects: invalid cylinder (see boxcyl::validate)");
    const bool rounded_arithmetic = opt.arithmetic == Arithmetic::float32 || opt.arithmetic == Arithmetic::float64;
    if (opt.algorithm == Algorithm::hull && rounded_arithmetic) {
        auto hull = [&](auto zero) {
            using U = decltype(zero);
            const Parallelepiped<U> b = cast<U>(box);
            algo::Parallelepiped<U> p;
            p.center = b.center;
            for (int i = 0; i < 3; ++i) p.half_edges[i] = b.extents[i] * b.axes[i];
            return algo::convex_hull(p, to_unit(cast<U>(cyl)));
        };
        return opt.arithmetic == Arithmetic::float32 ? hull(0.0f) : hull(0.0);
    }
#if defined(BOXCYL_HAS_EXACT)
    if (opt.arithmetic == Arithmetic::filtered) return filtered_query(box, cyl, opt);
    if (opt.algorithm == Algorithm::oracle || opt.algorithm == Algorithm::hull) {
        const Parallelepiped<double> b = cast<double>(box);
        if (opt.algorithm == Algorithm::oracle) return oracle::intersects(to_exact(b), to_exact(cast<double>(cyl)));
        return *exact::answer(b, cast<double>(cyl));
    }
#else
    if (!rounded_arithmetic || opt.algorithm == Algorithm::oracle)
        throw std::invalid_argument("boxcyl: exact arithmetic and the oracle need the exact backend (boxcyl::exact)");
#endif
    const OrientedBox<T> oriented{box.center, box.axes, box.extents};
    if (!is_valid(oriented))
        throw std::domain_error(
            "boxcyl: §2/§4 need an orthonormal box frame and these parallelepiped axes are not orthonormal "
            "(use the default options, Algorithm::hull or Algorithm::oracle)");
    return dispatch(oriented, cyl, opt);
}

template <class T>
inline constexpr bool dependent_false = false;

// The front door refuses invalid input in every build type: std::invalid_argument whose message is
// validate()'s ("box.max[0]: is NaN"). The check is a few branch-free comparisons per field; the
// message is built only when it fails.
template <class Box, class T>
[[noreturn, gnu::cold, gnu::noinline]] void throw_invalid(const Box& box, const Cylinder<T>& cyl) {
    const Validity b = validate(box);
    throw std::invalid_argument(b.ok() ? validate(cyl).message() : b.message());
}
template <class Box, class T>
BOXCYL_FORCE_INLINE inline void require_valid(const Box& box, const Cylinder<T>& cyl) {
    if (!(is_valid(box) && is_valid(cyl))) [[unlikely]]
        throw_invalid(box, cyl);
}

}  // namespace detail

#if defined(BOXCYL_HAS_EXACT)
#define BOXCYL_DEFAULT_QUERY(box, cyl) return detail::dispatch(box, cyl, QueryOptions{})
#else
#define BOXCYL_DEFAULT_QUERY(box, cyl)                                                                   \
    (void)(box), (void)(cyl);                                                                            \
    static_assert(detail::dependent_false<T>,                                                            \
                  "boxcyl: the default query is exact and needs the exact backend: link boxcyl::exact "  \
                  "(GMP), or choose the plain double path explicitly: "                                   \
                  "intersects(box, cyl, {Algorithm::inequalities, Arithmetic::float64})");               \
    return false
#endif

// The exact answer for the inputs as given (closed solids: touching intersects). Invalid input (see
// validate()) throws std::invalid_argument naming the field; `intersects_unchecked` skips that check
// for callers who validated once (invalid input is then a precondition violation, asserted in debug
// builds).
template <class T>
bool intersects_unchecked(const AlignedBox<T>& box, const Cylinder<T>& cyl) {
    BOXCYL_DEFAULT_QUERY(box, cyl);
}
template <class T>
bool intersects_unchecked(const OrientedBox<T>& box, const Cylinder<T>& cyl) {
    BOXCYL_DEFAULT_QUERY(box, cyl);
}
// Any parallelepiped, axes exactly as given (geometry/parallelepiped.hpp).
template <class T>
bool intersects_unchecked(const Parallelepiped<T>& box, const Cylinder<T>& cyl) {
    BOXCYL_DEFAULT_QUERY(box, cyl);
}
// The cylinder is given in the canonical box's frame (box centred at the origin, axis-aligned).
template <class T>
bool intersects_unchecked(const CanonicalBox<T>& box, const Cylinder<T>& cyl) {
    BOXCYL_DEFAULT_QUERY(box, cyl);
}
#undef BOXCYL_DEFAULT_QUERY

// With an explicit choice of algorithm and arithmetic.
template <class Box, class T>
bool intersects_unchecked(const Box& box, const Cylinder<T>& cyl, const QueryOptions& opt) {
    return detail::dispatch(box, cyl, opt);
}

template <class T>
bool intersects(const AlignedBox<T>& box, const Cylinder<T>& cyl) {
    detail::require_valid(box, cyl);
    return intersects_unchecked(box, cyl);
}
template <class T>
bool intersects(const OrientedBox<T>& box, const Cylinder<T>& cyl) {
    detail::require_valid(box, cyl);
    return intersects_unchecked(box, cyl);
}
template <class T>
bool intersects(const Parallelepiped<T>& box, const Cylinder<T>& cyl) {
    detail::require_valid(box, cyl);
    return intersects_unchecked(box, cyl);
}
template <class T>
bool intersects(const CanonicalBox<T>& box, const Cylinder<T>& cyl) {
    detail::require_valid(box, cyl);
    return intersects_unchecked(box, cyl);
}
template <class T>
bool intersects(const AlignedBox<T>& box, const Cylinder<T>& cyl, const QueryOptions& opt) {
    detail::require_valid(box, cyl);
    return detail::dispatch(box, cyl, opt);
}
template <class T>
bool intersects(const OrientedBox<T>& box, const Cylinder<T>& cyl, const QueryOptions& opt) {
    detail::require_valid(box, cyl);
    return detail::dispatch(box, cyl, opt);
}
template <class T>
bool intersects(const Parallelepiped<T>& box, const Cylinder<T>& cyl, const QueryOptions& opt) {
    detail::require_valid(box, cyl);
    return detail::dispatch(box, cyl, opt);
}
template <class T>
bool intersects(const CanonicalBox<T>& box, const Cylinder<T>& cyl, const QueryOptions& opt) {
    detail::require_valid(box, cyl);
    return detail::dispatch(box, cyl, opt);
}

}  // namespace boxcyl
