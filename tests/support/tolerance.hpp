// When may a rounded (float/double) algorithm disagree with the exact answer? Only when some input
// within δ = τ·S of the given one (S = problem_scale, the largest input magnitude) has the rounded
// answer as its exact answer — i.e. the given input is within δ of the boundary between "intersect"
// and "miss". The candidate perturbations, each decided by the exact oracle in rationals:
//   - everything grown by δ: radius + δ, height + 2δ, every box extent + δ;
//   - everything shrunk by δ (sizes clamped at 0);
//   - the cylinder moved by δ along ±x, ±y, ±z.
// Growing/shrinking covers gaps and overlaps of solids with volume; the moves cover knife-edge contacts
// of degenerate solids (a segment grazing an edge, a point on a segment), where no size can shrink.
// Any disagreement not explained this way fails the test as "far from touching".
#pragma once

#include "support/cases.hpp"
#include "support/numeric.hpp"

namespace boxcyl::testing {

// τ for double-precision algorithms: 2^-40 ≈ 9.1e-13 relative to the problem's largest magnitude
// (about 2^12 ulps: room for the rounding of normalisation, reductions and the linear-inequalities
// formulas, while a wrong formula shows up as an O(1) gap). Single precision gets 2^-16 ≈ 1.5e-5.
inline constexpr double double_tolerance = 0x1p-40;
inline constexpr double float_tolerance = 0x1p-16;

inline Rational margin_of(const Case& c, double tau) { return to_rational(problem_scale(c)) * to_rational(tau); }

// The exact answer for the case with sizes grown (sign = +1) or shrunk (−1) by delta and the cylinder
// centre moved by `move`.
inline bool oracle_perturbed(const Case& c, const Rational& delta, int sign, const Vec3<Rational>& move) {
    Cylinder<Rational> cyl = to_exact(c.cylinder);
    auto resize = [&](const Rational& x, const Rational& by) {
        if (sign > 0) return Rational(x + by);
        return x > by ? Rational(x - by) : Rational(0);
    };
    if (sign != 0) {
        cyl.radius = resize(cyl.radius, delta);
        cyl.height = resize(cyl.height, Rational(2 * delta));
    }
    cyl.center = cyl.center + move;
    OrientedBox<Rational> box = c.kind == BoxKind::aligned    ? as_oriented_box(to_exact(c.aligned))
                                : c.kind == BoxKind::oriented ? to_exact(c.oriented)
                                                              : as_oriented_box(to_exact(c.canonical));
    if (sign != 0)
        for (int i = 0; i < 3; ++i) box.extents[i] = resize(box.extents[i], delta);
    return oracle::intersects(box, cyl);
}

// True when an input within δ = τ·S has `rounded_answer` as its exact answer (see above).
inline bool near_touching(const Case& c, double tau, bool rounded_answer) {
    const Rational delta = margin_of(c, tau);
    const Vec3<Rational> none{0, 0, 0};
    if (oracle_perturbed(c, delta, +1, none) == rounded_answer) return true;
    if (oracle_perturbed(c, delta, -1, none) == rounded_answer) return true;
    for (int i = 0; i < 3; ++i)
        for (int s : {+1, -1}) {
            Vec3<Rational> move = none;
            move[i] = s * delta;
            if (oracle_perturbed(c, delta, 0, move) == rounded_answer) return true;
        }
    return false;
}

// True when some input within δ = τ·S has the opposite exact answer: the case is near touching.
inline bool near_touching(const Case& c, double tau) { return near_touching(c, tau, !oracle_answer(c)); }

}  // namespace boxcyl::testing
