// When may a rounded (float/double) algorithm disagree with the exact answer? Only when the exact
// answer is decided by a tiny gap. "Tiny" is made exact and checkable: grow and shrink the cylinder by
// δ = τ·S (S = problem_scale, the largest input magnitude): radius ± δ, height ± 2δ, computed in
// rationals. If the exact answers for the grown and the shrunk cylinders differ, the true gap (or
// overlap) is below δ and a rounded answer either way is within tolerance. Otherwise the case is
// "far from touching" and every algorithm in every arithmetic must get it exactly right.
#pragma once

#include "support/cases.hpp"
#include "support/numeric.hpp"

namespace boxcyl::testing {

// τ for double-precision algorithms: 2^-40 ≈ 9.1e-13 relative to the problem's largest magnitude
// (about 2^12 ulps: room for the rounding of normalisation, reductions and the §4 formulas, while a
// wrong formula shows up as an O(1) gap). Single precision gets 2^-16 ≈ 1.5e-5.
inline constexpr double double_tolerance = 0x1p-40;
inline constexpr double float_tolerance = 0x1p-16;

inline Rational margin_of(const Case& c, double tau) { return to_rational(problem_scale(c)) * to_rational(tau); }

inline bool oracle_resized(const Case& c, const Rational& delta, bool grow) {
    Cylinder<Rational> cyl = to_exact(c.cylinder);
    if (grow) {
        cyl.radius += delta;
        cyl.height += 2 * delta;
    } else {
        cyl.radius = cyl.radius > delta ? Rational(cyl.radius - delta) : Rational(0);
        cyl.height = cyl.height > 2 * delta ? Rational(cyl.height - 2 * delta) : Rational(0);
    }
    switch (c.kind) {
        case BoxKind::aligned: return oracle::intersects(to_exact(c.aligned), cyl);
        case BoxKind::oriented: return oracle::intersects(to_exact(c.oriented), cyl);
        case BoxKind::canonical: return oracle::intersects(to_exact(c.canonical), cyl);
    }
    return false;
}

// True when the exact answer flips within ±τ·S: a disagreement there is rounding, not a bug.
inline bool near_touching(const Case& c, double tau) {
    const Rational delta = margin_of(c, tau);
    return oracle_resized(c, delta, true) != oracle_resized(c, delta, false);
}

}  // namespace boxcyl::testing
