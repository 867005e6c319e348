// Running the three methods (docs/algorithms.md) in exact arithmetic (Arithmetic::exact): each input double
// becomes the rational it denotes, the unit axis u = D/|D| becomes (D/d)·√d in Q(√d), d = D·D, and
// the algorithm runs on QFRational — no rounding anywhere.
//
// Frames: aligned and canonical boxes reduce exactly (a translation). An oriented box is the parallelepiped
// its axes span; the convex-hull method works on it directly in world coordinates. The LCP and
// linear-inequalities methods need the canonical frame, which
// is exact only when the axes are exactly orthonormal (checked exactly; true for signed permutations
// and rational rotations, almost never for rounded rotations); otherwise they cannot answer exactly for
// that box and throw std::domain_error rather than answer for a different box.
#pragma once

#include <optional>   // the LCP method's result
#include <stdexcept>  // std::domain_error, std::logic_error

#include "boxcyl/algo/convex_hull.hpp"
#include "boxcyl/algo/linear_inequalities.hpp"
#include "boxcyl/algo/quadratic_programming.hpp"
#include "boxcyl/exact/convert.hpp"
#include "boxcyl/exact/reduce.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/reduce.hpp"

namespace boxcyl::exact {

enum class Method { inequalities, hull, lcp };

namespace detail {

inline AlignedBox<QFRational> lift(const AlignedBox<Rational>& b) { return {boxcyl::lift(b.min), boxcyl::lift(b.max)}; }
inline CanonicalBox<QFRational> lift(const CanonicalBox<Rational>& b) { return {boxcyl::lift(b.extents)}; }
inline OrientedBox<QFRational> lift(const OrientedBox<Rational>& b) {
    return {boxcyl::lift(b.center), {boxcyl::lift(b.axes[0]), boxcyl::lift(b.axes[1]), boxcyl::lift(b.axes[2])},
            boxcyl::lift(b.extents)};
}

inline bool exactly_orthonormal(const OrientedBox<Rational>& b) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (dot(b.axes[i], b.axes[j]) != Rational(i == j ? 1 : 0)) return false;
    return true;
}

inline bool run_canonical(Method m, const CanonicalQuery<QFRational>& q) {
    switch (m) {
        case Method::inequalities: return algo::linear_inequalities(q.box, q.cylinder);
        case Method::lcp: {
            const std::optional<bool> r = algo::quadratic_programming(q.box, q.cylinder);
            if (!r) throw std::logic_error("boxcyl: exact LCP solver failed (a bug: it cannot in exact arithmetic)");
            return *r;
        }
        case Method::hull: return algo::convex_hull(q.box, q.cylinder);
    }
    throw std::logic_error("boxcyl: unknown exact method");
}

}  // namespace detail

inline bool intersects(Method m, const AlignedBox<Rational>& box, const Cylinder<Rational>& cyl) {
    const QuadraticField<Rational> field(dot(cyl.axis, cyl.axis));
    return detail::run_canonical(m, to_canonical(detail::lift(box), to_unit(cyl, field)));
}

inline bool intersects(Method m, const CanonicalBox<Rational>& box, const Cylinder<Rational>& cyl) {
    const QuadraticField<Rational> field(dot(cyl.axis, cyl.axis));
    return detail::run_canonical(m, to_canonical(detail::lift(box), to_unit(cyl, field)));
}

inline bool intersects(Method m, const OrientedBox<Rational>& box, const Cylinder<Rational>& cyl) {
    const QuadraticField<Rational> field(dot(cyl.axis, cyl.axis));
    const UnitCylinder<QFRational> u = to_unit(cyl, field);
    if (m == Method::hull) return algo::convex_hull(algo::as_parallelepiped(detail::lift(box)), u);
    if (!detail::exactly_orthonormal(box))
        throw std::domain_error(
            "boxcyl: exact lcp/inequalities need an exactly orthonormal box frame; these oriented-box axes are only "
            "orthonormal up to rounding (use Algorithm::hull or Algorithm::oracle for an exact answer)");
    return detail::run_canonical(m, to_canonical(detail::lift(box), u));
}

// Any parallelepiped, axes exactly as given: the convex-hull method only (the other two need an
// orthonormal frame).
inline bool intersects(Method m, const Parallelepiped<Rational>& box, const Cylinder<Rational>& cyl) {
    if (m != Method::hull)
        throw std::domain_error("boxcyl: exact lcp/inequalities need an orthonormal box frame (use Algorithm::hull)");
    const QuadraticField<Rational> field(dot(cyl.axis, cyl.axis));
    algo::Parallelepiped<QFRational> p;
    p.center = lift(box.center);
    for (int i = 0; i < 3; ++i) p.half_edges[i] = lift(Vec3<Rational>(box.extents[i] * box.axes[i]));
    return algo::convex_hull(p, to_unit(cyl, field));
}

}  // namespace boxcyl::exact
