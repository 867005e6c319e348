// Exact signs of numbers built from rationals and two square roots:
//     x + y·√g   with x = x0 + x1·√d, y = y0 + y1·√d  (d, g ≥ 0 rationals),
// decided by squaring under sign conditions — no rounding, no root is ever computed. The clearance
// query's rim tests reduce to such signs (exact/clearance.hpp).
#pragma once

#include "boxcyl/number/rational.hpp"

namespace boxcyl::root_sign {

// a + b·√d with rationals a, b and the radicand d ≥ 0 of the computation.
struct Quadratic {
    Rational a;
    Rational b;
};

// sign(a + b·√d).
inline int sign(const Rational& a, const Rational& b, const Rational& d) {
    const int sa = sgn(a);
    const int sb = sgn(d) > 0 ? sgn(b) : 0;
    if (sb == 0) return sa;
    if (sa == 0 || sa == sb) return sb;
    // Opposite signs: the larger magnitude wins; |a| vs |b|√d by their squares.
    return sa * sgn(Rational(a * a - b * b * d));
}
inline int sign(const Quadratic& x, const Rational& d) { return sign(x.a, x.b, d); }

// sign(x + y·√g), x and y in Q(√d).
inline int sign(const Quadratic& x, const Quadratic& y, const Rational& d, const Rational& g) {
    const int sx = sign(x, d);
    const int sy = sgn(g) > 0 ? sign(y, d) : 0;
    if (sy == 0) return sx;
    if (sx == 0 || sx == sy) return sy;
    // x² − g·y², an element of Q(√d): (x0² + x1²d − g(y0² + y1²d)) + 2(x0x1 − g·y0y1)√d.
    const Rational a = x.a * x.a + x.b * x.b * d - g * (y.a * y.a + y.b * y.b * d);
    const Rational b = 2 * (x.a * x.b - g * y.a * y.b);
    return sx * sign(a, b, d);
}

}  // namespace boxcyl::root_sign
