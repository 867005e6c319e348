// The distance bounds of filtered/separation.hpp again, for the pairs whose distance lies too close to
// the margin for bounds evaluated in double (within about 2^-40 of it, relatively; pairs within one ulp
// of their margin always): the box point is refined by Newton's method on the box feature it lies on,
// and both bounds are evaluated in double-double with proved error bounds (number/double_double.hpp:
// about 2^-100 relative per operation), so that only distances within about 2^-90 of the margin, or
// exactly at it, are left undecided. Newton's steps run in double first (a tenth of the cost of one in
// double-double) until they stop gaining; the bounds at that point often suffice, and only where they
// do not do the steps go on in double-double.
//
// The refinement needs no proof: the point stays in the box by construction (c + Σ μi·hi with
// |μi| ≤ 1), and a poor direction only loosens the lower bound. The bounds are those of
// separation.hpp: upper = dist(X, cylinder) for the box point X, lower = the gap between supporting
// planes along a direction n, here the best of
//   - the refined pair's direction Y(X) − X (Y(X) the cylinder point nearest X): exact to second order
//     when X is the nearest box point, whatever feature holds it;
//   - the double search's best direction (face normals, the axis and edges crossed with the axis
//     separate face, cap and side contacts exactly).
// Why Newton: the gap along a direction that is off by an angle θ loses about θ times the contact
// feature's length when the feature is an edge or a face (the support point jumps), so the direction
// must be right to the precision sought, and with it the point: Newton's quadratic convergence from
// the double search's point gives that in two or three steps.
//
// Double-double's error bounds hold in round to nearest only; in any other mode this stage declines
// (nothing proved) and the exact decision answers.
#pragma once

#include <algorithm>  // std::max
#include <array>      // the box's half axes
#include <bit>        // std::bit_cast: doubles ≥ 0 ordered as integers
#include <cstdint>    // std::uint64_t
#include <limits>     // the largest double
#include <utility>    // std::swap
#include <cmath>      // std::abs, std::ldexp, std::ilogb
#include <optional>   // undecided
#include <type_traits>  // std::is_same_v

#include "boxcyl/filtered/nearest_box_point.hpp"  // Newton's steps
#include "boxcyl/filtered/rim.hpp"         // scaled_axis
#include "boxcyl/filtered/separation.hpp"  // Bounds, Approximate
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/number/double_double.hpp"
#include "boxcyl/number/double_double_value.hpp"
#include "boxcyl/number/traits.hpp"  // abs_value

namespace boxcyl::filtered::separation {

namespace refined {

using D = DoubleDouble;
using DV = Vec3<DoubleDouble>;

inline DV lift(const Vec3<double>& v) { return {D(v[0]), D(v[1]), D(v[2])}; }
// The value alone, its error bound dropped: for the search, whose results need no proof.
inline D value(const D& x) { return {x.high(), x.low(), 0.0}; }
inline DV value(const DV& v) { return {value(v[0]), value(v[1]), value(v[2])}; }
inline double approx(const D& x) { return x.high() + x.low(); }

using Box = BoxOf<D>;
inline Box exact_box(const Parallelepiped<double>& b) {
    Box box{lift(b.center), {}};
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) box.half[i][k] = D(b.extents[i]) * D(b.axes[i][k]);
    return box;
}
inline Box exact_box(const OrientedBox<double>& b) { return exact_box(Parallelepiped<double>{b.center, b.axes, b.extents}); }
inline Box exact_box(const CanonicalBox<double>& b) {
    Box box{lift({0, 0, 0}), {}};
    for (int i = 0; i < 3; ++i) {
        box.half[i] = lift({0, 0, 0});
        box.half[i][i] = D(b.extents[i]);
    }
    return box;
}
inline Box exact_box(const AlignedBox<double>& b) {
    Box box;
    for (int i = 0; i < 3; ++i) {
        box.center[i] = (D(b.min[i]) + D(b.max[i])) * D(0.5);
        box.half[i] = lift({0, 0, 0});
        box.half[i][i] = (D(b.max[i]) - D(b.min[i])) * D(0.5);
    }
    return box;
}

using Cyl = CylOf<D>;

inline W unbounded(const D& x) { return W(x); }
inline WV unbounded(const DV& v) { return {W(v[0]), W(v[1]), W(v[2])}; }
inline BoxOf<W> unbounded(const Box& b) {
    return {unbounded(b.center), {unbounded(b.half[0]), unbounded(b.half[1]), unbounded(b.half[2])}};
}
inline CylOf<W> unbounded(const Cyl& k) { return {unbounded(k.C), unbounded(k.u), W(k.r), W(k.half_h)}; }
inline Vec3<double> approx(const DV& v) { return {approx(v[0]), approx(v[1]), approx(v[2])}; }
inline BoxOf<double> rounded(const Box& b) { return {approx(b.center), {approx(b.half[0]), approx(b.half[1]), approx(b.half[2])}}; }
inline CylOf<double> rounded(const Cyl& k) { return {approx(k.C), approx(k.u), approx(k.r), approx(k.half_h)}; }

// max(x, 0) enclosed: x itself when certainly positive, 0 when certainly not, else every value between.
inline D positive_part(const D& x) {
    if (x.lo() > 0) return x;
    if (!(x.hi() > 0)) return x.hi() <= 0 ? D(0.0) : x;  // NaN stays NaN
    return D::range(0, x.hi());
}

// √x of a quantity known to be ≥ 0, enclosed even where the enclosure of x reaches 0 or below (sqrt
// itself declines there): [0, √(upper bound)].
inline D sqrt_nonnegative(const D& x) {
    if (x.exact_zero()) return D(0.0);
    if (x.lo() > 0) return sqrt(x);
    const double hi = x.hi();
    if (!(hi >= 0)) return hi <= 0 ? D(0.0) : x;  // NaN stays NaN
    return D::range(0, boxcyl::detail::next_up(std::sqrt(hi)));
}

// X's distance to the cylinder, enclosed, and the step from X to the cylinder point nearest it,
// Y − X = (clamp(t) − t)·u + (min(r/ρ, 1) − 1)·P (P = Z − t·u the part of Z = X − C across the axis):
// a value, for the lower bound's direction and the witness, formed from the same Z and t and without
// Y's cancellation against X. `toward` is not finite where the parts leave double's range.
struct AtPoint {
    D distance;
    DV toward;
    bool axial = false, radial = false;  // whether the step has a part along the axis, across it
};
inline AtPoint at_point(const Cyl& k, const DV& X) {
    const DV Z = X - k.C;
    const DV Zxu = cross(Z, k.u);
    const D rho = sqrt_nonnegative(dot(Zxu, Zxu));
    const D t = dot(Z, k.u);
    const D dr = positive_part(rho - k.r);
    const D da = positive_part(enclosure_abs(t) - k.half_h);
    AtPoint out{sqrt_nonnegative(dr * dr + da * da), {}};
    // The step needs no proof: values without bounds (the same values, for less work).
    const WV u = unbounded(k.u), Zv = unbounded(Z);
    const W tv(t), rv(rho), r(k.r), hh(k.half_h);
    const WV P = Zv - WV{tv * u[0], tv * u[1], tv * u[2]};
    W axial(0.0), radial(0.0);
    if (approx(tv) > approx(hh)) axial = hh - tv;
    else if (approx(tv) < -approx(hh)) axial = -hh - tv;
    if (approx(rv) > approx(r)) radial = (r - rv) / rv;
    for (std::size_t i = 0; i < 3; ++i) out.toward[i] = (axial * u[i] + radial * P[i]).exact();
    out.axial = approx(axial) != 0, out.radial = approx(radial) != 0;
    return out;
}
inline D point_distance(const Cyl& k, const DV& X) { return at_point(k, X).distance; }

// The lower bound's direction at the box point μ: the step `at.toward` to the cylinder point nearest
// it, put into both shapes' normal cones there. Where a support function has a kink (across a box edge
// or face, whose exact direction is orthogonal to the free half axes; at the side, orthogonal to the
// axis; at a cap, along it) the gap loses the direction's error to first order, and the step, formed
// from coordinates far larger than the distance, is off by about ε·|X|/dist: as many ulps. In the
// normal cone only the smooth part's second-order loss is left (an edge against a rim: across the
// edge; a vertex against the side: across the axis). Values only: any direction gives a proved gap.
inline DV in_normal_cones(const Box& box, const Cyl& k, const std::array<D, 3>& mu, const AtPoint& at) {
    const DV& t = at.toward;
    auto toward_cylinder = [&t](const DV& n) { return approx(dot(n, t)) < 0 ? value(-n) : n; };
    auto across = [](const DV& n, const DV& a) {  // n less its part along a
        const D aa = value(dot(a, a));
        if (!(approx(aa) > 0)) return n;
        const D f = value(dot(n, a) / aa);
        return value(n - DV{f * a[0], f * a[1], f * a[2]});
    };
    auto normal = [&](const DV& a, const DV& b, const DV& otherwise) {  // a × b, unless a ∥ b
        const DV n = value(cross(a, b));
        return approx(dot(n, n)) > 0 ? toward_cylinder(n) : otherwise;
    };
    if (at.axial && !at.radial) return toward_cylinder(k.u);  // a cap
    std::array<std::size_t, 3> free{};
    std::size_t count = 0;
    for (std::size_t i = 0; i < 3; ++i)
        if (std::abs(approx(mu[i])) < 1 && approx(dot(box.half[i], box.half[i])) > 0) free[count++] = i;
    const bool side = at.radial && !at.axial;
    if (count == 2) return normal(box.half[free[0]], box.half[free[1]], t);  // a face
    if (count == 1) {
        const DV edge = across(t, box.half[free[0]]);
        return side ? normal(box.half[free[0]], k.u, edge) : edge;
    }
    if (count == 0 && side) return across(t, k.u);
    return t;
}

// The gap along n (any nonzero vector), over |n|: a lower bound of the distance when positive.
inline D gap(const Box& box, const Cyl& k, const DV& n) {
    D L = dot(n, k.C - box.center);
    for (int i = 0; i < 3; ++i) L = L - enclosure_abs(dot(n, box.half[i]));
    const DV nxu = cross(n, k.u);
    L = L - k.half_h * enclosure_abs(dot(n, k.u)) - k.r * sqrt_nonnegative(dot(nxu, nxu));
    return L / sqrt(dot(n, n));
}

// The gap along n (from the box towards the cylinder) in double, over |n|: no proof, it orders the
// directions whose gaps are proved.
inline double gap_in_double(const BoxOf<double>& box, const CylOf<double>& k, const Vec3<double>& n) {
    const double nn = dot(n, n);
    if (!(nn > 0)) return -1;
    const Vec3<double> nxu = cross(n, k.u);
    const double L = dot(n, k.C - box.center) - std::abs(dot(n, box.half[0])) - std::abs(dot(n, box.half[1])) -
                     std::abs(dot(n, box.half[2])) - k.half_h * std::abs(dot(n, k.u)) - k.r * std::sqrt(dot(nxu, nxu));
    return L / std::sqrt(nn);
}

// The box coordinates μ (|μi| ≤ 1, doubles) of a box point near P: the least-squares coordinates of P
// over the box's nonzero half axes, clamped to the box (P's foot on the face it lies beyond, for a
// box whose axes are orthogonal; a point near it otherwise).
inline std::array<D, 3> foot(const algo::gjk::Box& b, const Vec3<double>& P) {
    std::array<std::size_t, 3> idx{};
    std::size_t n = 0;
    for (std::size_t i = 0; i < 3; ++i)
        if (dot(b.half[i], b.half[i]) > 0) idx[n++] = i;
    double G[3][4] = {};
    const Vec3<double> d = P - b.c;
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < n; ++j) G[i][j] = dot(b.half[idx[i]], b.half[idx[j]]);
        G[i][3] = dot(b.half[idx[i]], d);
    }
    // Gaussian elimination with partial pivoting on the n × n system (n ≤ 3).
    for (std::size_t col = 0; col < n; ++col) {
        std::size_t piv = col;
        for (std::size_t r = col + 1; r < n; ++r)
            if (std::abs(G[r][col]) > std::abs(G[piv][col])) piv = r;
        for (std::size_t c = 0; c < 4; ++c) std::swap(G[col][c], G[piv][c]);
        if (!(std::abs(G[col][col]) > 0)) return {D(0.0), D(0.0), D(0.0)};
        for (std::size_t r = 0; r < n; ++r) {
            if (r == col) continue;
            const double f = G[r][col] / G[col][col];
            for (std::size_t c = col; c < 4; ++c) G[r][c] -= f * G[col][c];
        }
    }
    std::array<D, 3> mu{D(0.0), D(0.0), D(0.0)};
    for (std::size_t i = 0; i < n; ++i) {
        const double m = G[i][3] / G[i][i];
        mu[idx[i]] = D(m > 1 ? 1.0 : m < -1 ? -1.0 : m == m ? m : 0.0);
    }
    return mu;
}

}  // namespace refined


namespace refined {
// Whether enclosure a's lower end lies above b's, or its upper end below b's, to double-double
// precision (the ends as doubles, lo() and hi(), would hide a gain below one ulp). Either choice keeps a
// proved bound: the comparison only picks the tighter. A NaN never wins, and loses to any number.
inline bool lower_end_above(const D& a, const D& b) {
    if (b.high() != b.high()) return a.high() == a.high();
    return (a.high() - b.high()) + ((a.low() - a.error()) - (b.low() - b.error())) > 0;
}
inline bool upper_end_below(const D& a, const D& b) {
    if (b.high() != b.high()) return a.high() == a.high();
    return (a.high() - b.high()) + ((a.low() + a.error()) - (b.low() + b.error())) < 0;
}
}  // namespace refined

// The refined bounds as double-double enclosures: lower ≤ dist ≤ upper holds for every value each
// encloses (a lower bound's enclosure may dip below 0: then it proves nothing).
struct RefinedBounds {
    DoubleDouble lower, upper;
    bool found;  // false: declined (not round to nearest, or no search to start from)
    refined::DV witness{};  // the box point whose distance is `upper` (its value; exactly in the box)
    refined::DV toward{};   // from the witness to the cylinder point nearest it (a value)
};

namespace refined {
// x·2^p, exactly unless it leaves the range (values only).
inline D scaled(const D& x, int p) { return {times_two_to(x.high(), p), times_two_to(x.low(), p), 0.0}; }

// The cylinder point nearest X (values: no proof). X − C is scaled by a power of two to magnitude ~1
// first, so that its squares neither overflow nor underflow, whatever the coordinates' range.
inline DV nearest_on_cylinder(const Cyl& k, const DV& X) {
    const DV Z = value(X - k.C);
    const double big = std::max({std::abs(approx(Z[0])), std::abs(approx(Z[1])), std::abs(approx(Z[2]))});
    if (!(big > 0) || !std::isfinite(big)) return value(X);  // X is the centre (or not finite)
    const int e = -std::ilogb(big);
    const DV Zs{scaled(Z[0], e), scaled(Z[1], e), scaled(Z[2], e)};
    const D t = value(dot(Zs, k.u));
    const DV P = value(Zs - DV{t * k.u[0], t * k.u[1], t * k.u[2]});
    const D pp = value(dot(P, P));
    const D rho = approx(pp) > 0 ? value(sqrt(pp)) : D(0.0);
    const D r = scaled(k.r, e), hh = scaled(k.half_h, e);  // +∞ when far beyond Z: no clamp then
    D radial = D(1.0);
    if (approx(rho) > approx(r)) radial = value(r / rho);
    D axial = t;
    if (approx(t) > approx(hh)) axial = hh;
    else if (approx(t) < -approx(hh)) axial = -hh;
    const DV Ys = value(DV{axial * k.u[0], axial * k.u[1], axial * k.u[2]} + DV{radial * P[0], radial * P[1], radial * P[2]});
    return value(k.C + DV{scaled(Ys[0], -e), scaled(Ys[1], -e), scaled(Ys[2], -e)});
}
// The cylinder as double-double values: u = D/|D| to within the arithmetic's error.
inline Cyl cylinder(const Cylinder<double>& c) {
    Cyl k;
    k.C = lift(c.center);
    const DV D_axis = lift(rim::scaled_axis(c.axis));
    const D inverse = D(1.0) / sqrt(dot(D_axis, D_axis));  // one quotient, not three
    k.u = {D_axis[0] * inverse, D_axis[1] * inverse, D_axis[2] * inverse};
    k.r = D(c.radius);
    k.half_h = D(c.height) * D(0.5);
    return k;
}
}  // namespace refined

// Contacts at a kink of the distance along an edge: where the edge crosses from a cap's region into
// the rim's (ρ = r) or from the side's into the rim's (|t| = h/2), the distance has a corner that
// Newton's method does not find (a face within 10⁻¹¹ of parallel to a cap, touching past its edge).
// On each edge through the point μ (two coordinates at ±1), those crossings are candidate points for
// the upper bound, and for the lower one the direction across the edge within the cylinder's normal
// cone there (spanned by the cap's normal and the radial direction).
inline void kinks(const refined::Box& box, const refined::Cyl& k, const std::array<DoubleDouble, 3>& mu,
                  RefinedBounds& out) {
    using namespace refined;
    const DV u = value(k.u);
    const D r = value(k.r), hh = value(k.half_h);
    for (std::size_t i = 0; i < 3; ++i) {
        const std::size_t j = (i + 1) % 3, l = (i + 2) % 3;
        if (std::abs(approx(mu[j])) != 1 || std::abs(approx(mu[l])) != 1) continue;
        const DV E = box.half[i];
        if (!(approx(dot(E, E)) > 0)) continue;
        std::array<D, 3> at = mu;
        at[i] = D(0.0);
        const DV Z0 = value(point(box, at) - k.C);
        const D t0 = value(dot(Z0, u)), te = value(dot(E, u));
        const DV P0 = value(Z0 - DV{t0 * u[0], t0 * u[1], t0 * u[2]});
        const DV Pe = value(E - DV{te * u[0], te * u[1], te * u[2]});
        // ρ(s)² = A s² + B s + C0 along the edge X0 + s·E.
        const D A = value(dot(Pe, Pe)), B = value(D(2.0) * dot(P0, Pe)), C0 = value(dot(P0, P0));
        std::array<D, 4> roots;
        std::size_t n = 0;
        if (approx(A) > 0) {
            const D disc = value(B * B - D(4.0) * A * (C0 - r * r));
            if (approx(disc) >= 0) {
                const D sq = approx(disc) > 0 ? value(sqrt(disc)) : D(0.0);
                roots[n++] = value((-B - sq) / (D(2.0) * A));
                roots[n++] = value((-B + sq) / (D(2.0) * A));
            }
        }
        if (approx(te) != 0) {
            roots[n++] = value((hh - t0) / te);
            roots[n++] = value((-hh - t0) / te);
        }
        for (std::size_t q = 0; q < n; ++q) {
            const double sq = approx(roots[q]);
            if (!(std::abs(sq) <= 1)) continue;
            // A normalised value whose rounded sum is below 1 in magnitude is below 1 itself; one that
            // rounds to ±1 is taken as exactly ±1 (the point must lie in the box).
            at[i] = std::abs(sq) == 1 ? D(sq) : roots[q];
            const DV X = point(box, at);
            const AtPoint up = at_point(k, X);
            if (upper_end_below(up.distance, out.upper)) out.upper = up.distance, out.witness = value(X), out.toward = up.toward;
            // The normal cone at the crossing: the cap's normal sgn(t)·u and the radial direction.
            const DV Z = value(X - k.C);
            const D t = value(dot(Z, u));
            const DV P = value(Z - DV{t * u[0], t * u[1], t * u[2]});
            if (!(approx(dot(P, P)) > 0)) continue;
            const D rho = value(sqrt(dot(P, P)));
            const DV e_rho = value(DV{P[0] / rho, P[1] / rho, P[2] / rho});
            const DV cap = approx(t) < 0 ? value(-u) : u;
            const D a = value(dot(e_rho, E)), b = value(-dot(cap, E));
            const DV n_out = value(DV{a * cap[0] + b * e_rho[0], a * cap[1] + b * e_rho[1], a * cap[2] + b * e_rho[2]});
            for (const DV& nn : {value(-n_out), n_out}) {  // from the box towards the cylinder: either sign
                if (!(approx(dot(nn, nn)) > 0)) continue;
                const D g = gap(box, k, nn);
                if (lower_end_above(g, out.lower)) out.lower = g;
            }
        }
    }
}

// Edges against the side, where Newton's method stops short: along a face within about 2^-40 of
// parallel to the axis the distance's valley is so flat that the refinement's point stays inside the
// face, while the nearest point is on one of its edges. Each edge's point nearest the axis line (from
// the lines' closest pair in double, clamped to the edge) is a candidate for the upper bound, and each
// edge direction crossed with the axis one for the lower bound.
inline void edges_against_axis(const refined::Box& box, const refined::Cyl& k, RefinedBounds& out) {
    using namespace refined;
    const BoxOf<double> b = rounded(box);
    const CylOf<double> kd = rounded(k);
    for (std::size_t i = 0; i < 3; ++i) {
        const std::size_t j = (i + 1) % 3, l = (i + 2) % 3;
        const Vec3<double>& E = b.half[i];
        const double A = dot(E, E), B = dot(E, kd.u), den = A - B * B;
        if (!(den > 0)) continue;  // a flat box, or an edge along the axis
        for (const double sj : {-1.0, 1.0})
            for (const double sl : {-1.0, 1.0}) {
                const Vec3<double> w = b.center + sj * b.half[j] + sl * b.half[l] - kd.C;
                const double s = (B * dot(kd.u, w) - dot(E, w)) / den;  // minimises |w + s·E − t·u|
                if (s != s) continue;
                std::array<D, 3> mu;
                mu[i] = D(std::clamp(s, -1.0, 1.0)), mu[j] = D(sj), mu[l] = D(sl);
                const DV X = point(box, mu);
                const AtPoint up = at_point(k, X);
                if (upper_end_below(up.distance, out.upper)) out.upper = up.distance, out.witness = value(X), out.toward = up.toward;
            }
        const DV n = value(cross(box.half[i], k.u));
        for (const DV& nn : {n, value(-n)}) {  // from the box towards the cylinder: either sign
            if (!(approx(dot(nn, nn)) > 0)) continue;
            const D g = gap(box, k, nn);
            if (lower_end_above(g, out.lower)) out.lower = g;
        }
    }
}

namespace refined {
// The doubles the enclosures prove: the least double certainly ≥ the upper bound's value, the greatest
// certainly ≤ the lower bound's (compare() decides against a double to about 2⁻¹⁰⁰).
inline double upper_double(const DoubleDouble& upper) {
    double up = upper.hi();
    for (int i = 0; i < 4 && up > 0; ++i) {
        const double below = boxcyl::detail::next_down(up);
        const int s = compare(upper, DoubleDouble(below));  // the sign of below − upper; 2: undecided
        if (s != 0 && s != 1) break;
        up = below;
    }
    return up;
}
inline double lower_double(const DoubleDouble& lower) {
    double lo = std::max(0.0, lower.lo());  // NaN → 0
    for (int i = 0; i < 4 && lo < std::numeric_limits<double>::max(); ++i) {
        const double above = boxcyl::detail::next_up(lo);
        const int s = compare(DoubleDouble(above), lower);  // the sign of lower − above
        if (s != 0 && s != 1) break;
        lo = above;
    }
    return lo;
}
// upper − lower to double-double precision, about (the ends as doubles, lo() and hi(), are an ulp apart
// at least): a speed hint, no proof.
inline double width(const RefinedBounds& r) {
    return (r.upper.high() - r.lower.high()) + ((r.upper.low() + r.upper.error()) - (r.lower.low() - r.lower.error()));
}
// Whether the doubles the bounds prove are at most n apart. Where the values' leading doubles are more
// than n + 4 apart, the doubles proved are too (they lie within about one double of them, the error
// bounds far below an ulp), and the comparisons that prove them are skipped (as after the upper bound
// alone, with the lower still 0).
inline bool within_doubles(const RefinedBounds& r, std::uint64_t n) {
    const double up_value = r.upper.high(), lo_value = std::max(0.0, r.lower.high());
    if (up_value >= lo_value && up_value <= std::numeric_limits<double>::max() &&
        std::bit_cast<std::uint64_t>(up_value) - std::bit_cast<std::uint64_t>(lo_value) > n + 4)
        return false;
    const double lo = lower_double(r.lower), up = upper_double(r.upper);
    return lo <= up && std::bit_cast<std::uint64_t>(up) - std::bit_cast<std::uint64_t>(lo) <= n;
}

// Whether the bounds decide dist ≤ m: true (within), false (not), nullopt.
inline std::optional<bool> decides(const RefinedBounds& r, double m) {
    const DoubleDouble margin(m);
    const int up = compare(r.upper, margin);  // the sign of m − upper; 2: undecided
    if (up == 0 || up == 1) return true;
    if (compare(margin, r.lower) == 1) return false;  // lower − m > 0
    return std::nullopt;
}
}  // namespace refined

// The refined bounds, from the double search `a` (separation.hpp's approximate()). With `decide_at`
// ≥ 0, the further candidates (a foot, the kinks) are tried only while the bounds do not decide
// dist ≤ decide_at, and with `enough_doubles` > 0 only while the bounds prove doubles farther apart than
// that. `newton_steps` bounds the refinement's steps in double (in double-double, at most 4 follow); it ends
// sooner once converged. Without `last_resorts` the bounds end before the costly candidates (for the
// distance, before the steps in double-double), for a caller that has a better start to try next.
template <class AnyBox>
RefinedBounds refined_bounds(const AnyBox& b, const Cylinder<double>& c, const Approximate& a, double decide_at = -1,
                             int newton_steps = 4, std::uint64_t enough_doubles = 0, bool last_resorts = true) {
    using namespace refined;
    if (!a.found || !boxcyl::detail::round_to_nearest()) return {D(0.0), D(0.0), false};
    const UncertaintyScope scope;  // undecided operations are read through their bounds here
    const Box box = exact_box(b);
    const Cyl k = cylinder(c);

    // The double search's μ, coordinates within 2^-30 of ±1 fixed there (the point is on that face).
    std::array<double, 3> mu_double{};
    std::array<bool, 3> free{};
    if (!held_start(a.closest.mu, mu_double, free)) return {D(0.0), D(0.0), false};  // NaN
    RefinedBounds out{D(0.0), D(0.0), true, {}};
    bool first = true, in_cones = false;
    auto enough = [&] {
        return (decide_at >= 0 && refined::decides(out, decide_at)) ||
               (enough_doubles > 0 && refined::within_doubles(out, enough_doubles));
    };
    auto lower = [&](const DV& n) {  // the gap along n, kept where better
        if (!(approx(dot(n, n)) > 0)) return;
        const D g = gap(box, k, n);
        if (lower_end_above(g, out.lower)) out.lower = g;
    };
    // The bounds at the box point μ: its distance to the cylinder, and the gap along the direction to
    // its nearest cylinder point (each kept where better). The direction is the step to that point in
    // both shapes' normal cones (in_normal_cones), or the step itself where the cones turn it by more
    // than 2^-30 (the point is then not on the features it seems to be on: a flat valley along an edge
    // or face nearly parallel to the axis), or, where its parts come near the ends of double's range,
    // it is read from the cylinder point itself (nearest_on_cylinder scales).
    auto upper_at = [&](const std::array<D, 3>& m) {
        const DV X = point(box, m);
        const AtPoint up = at_point(k, X);
        if (first || upper_end_below(up.distance, out.upper)) out.upper = up.distance, out.witness = value(X), out.toward = up.toward;
        first = false;
        const Vec3<double> n = approx(up.toward);
        const double big = std::max({std::abs(n[0]), std::abs(n[1]), std::abs(n[2])});
        in_cones = false;
        if (big >= 0x1p-900 && big <= 0x1p900) {
            const DV cones = in_normal_cones(box, k, m, up);
            const Vec3<double> v = approx(cones), turn = cross(v, n);
            in_cones = dot(turn, turn) <= 0x1p-60 * dot(v, v) * dot(n, n);
            return in_cones ? cones : up.toward;
        }
        return value(nearest_on_cylinder(k, X) - X);
    };
    // The upper bound alone decides dist ≤ decide_at where it holds: the gap is computed only where it
    // does not (half of the pairs at their margin are within it).
    auto bounds_at = [&](const std::array<D, 3>& m) {
        const DV n = upper_at(m);
        if (enough()) return true;
        lower(n);
        return enough();
    };
    // Newton's method in double first, where its steps are cheap and converge to double's resolution:
    // its point's bounds suffice unless the distance is far below the shapes' coordinates. Then in
    // double-double from where it ended, for the last bits: one or two steps where it converges
    // quadratically, at most dd_steps (more only crawl along a nearly flat valley of the distance, a
    // face nearly parallel to the axis, where the foot and the kinks below do better).
    // In double, the shapes relative to the box's centre (their difference formed in double-double):
    // far from the origin (coordinates of 1e7 about shapes of 1e-3) the difference rounded in double
    // would move the cylinder by an ulp of the coordinates, and the point with it, far more than the
    // distance's last bits allow; relative to the box, by an ulp of the shapes' own size.
    BoxOf<double> box_d = rounded(box);
    CylOf<double> k_d = rounded(k);
    const DV origin = lift(box_d.center);
    box_d.center = approx(box.center - origin);
    k_d.C = approx(k.C - origin);
    refine(box_d, k_d, mu_double, free, newton_steps);
    std::array<D, 3> mu{D(mu_double[0]), D(mu_double[1]), D(mu_double[2])};
    const DV toward = upper_at(mu);
    if (enough()) return out;
    // Two directions for the lower bound: the refined pair's, and the double search's best (a face
    // normal, the axis, an edge crossed with the axis: exact for face, cap and side contacts). Each gap
    // costs as much as the upper bound, so one goes first, and the other only where the first does not
    // suffice (for the distance: where it leaves the enclosure wider than two doubles, so that the second
    // direction still tightens what the first proves to within four). First the refined pair's where it
    // lies in the normal cones, else the one whose gap in double is the larger.
    const DV search = lift(a.direction);
    // At a vertex (every coordinate at ±1) the refined direction is the exact one wherever both agree.
    const bool vertex = std::abs(mu_double[0]) == 1 && std::abs(mu_double[1]) == 1 && std::abs(mu_double[2]) == 1;
    const bool search_first = !in_cones && !vertex && a.lower >= gap_in_double(box_d, k_d, approx(toward)) * (1 - 0x1p-30);
    lower(search_first ? search : toward);
    if (enough() && (enough_doubles == 0 || refined::within_doubles(out, 2))) return out;
    lower(search_first ? toward : search);
    if (enough()) return out;
    // The margin inside bounds within 2^-80 of it (double-double's evaluations leave about 2^-94): the
    // distance is at the margin, most likely exactly (a contact at exactly the margin, which only the
    // exact stages decide), and the steps below would cost several times the bounds so far for nothing.
    if (decide_at > 0 && refined::width(out) <= 0x1p-80 * decide_at) return out;
    constexpr int dd_steps = 4;
    auto moved = [&](const std::array<D, 3>& before) {
        for (std::size_t i = 0; i < 3; ++i)
            if (mu[i].high() != before[i].high() || mu[i].low() != before[i].low()) return true;
        return false;
    };
    // The steps' Hessian in double first (a few times cheaper), then in double-double where that
    // leaves the bounds open (a nearly flat valley).
    // The steps on values without bounds (the bounds at their point are proved from it as given).
    const BoxOf<W> box_v = unbounded(box);
    const CylOf<W> k_v = unbounded(k);
    std::array<W, 3> mu_v{unbounded(mu[0]), unbounded(mu[1]), unbounded(mu[2])};
    auto steps = [&](auto hessian_in) {
        const std::array<D, 3> before = mu;
        refine<W, decltype(hessian_in)>(box_v, k_v, mu_v, free, std::min(newton_steps, dd_steps));
        mu = {mu_v[0].exact(), mu_v[1].exact(), mu_v[2].exact()};
        return moved(before);
    };
    auto newton_in_double_double = [&] { return (steps(0.0) && bounds_at(mu)) || (steps(W(0.0)) && bounds_at(mu)); };
    // A second box point where the bounds still differ in double: the foot of the cylinder's point
    // extreme along the best direction (where a face lies nearly parallel to a cap, Newton's model
    // sees no curvature, and that rim point's foot is the nearest box point).
    auto foot_point = [&] {
        if (out.upper.hi() - out.lower.lo() > 0x1p-50 * out.upper.hi()) {
            const DV X2 = point(box, foot(a.box, algo::gjk::detail::support(algo::gjk::Cylinder{c.center, a.u, c.radius, 0.5 * c.height}, -a.direction)));
            const AtPoint upper2 = at_point(k, X2);
            if (upper_end_below(upper2.distance, out.upper)) out.upper = upper2.distance, out.witness = value(X2), out.toward = upper2.toward;
        }
        return enough();
    };
    auto kinks_here = [&] {
        if (out.upper.hi() - out.lower.lo() > 0x1p-80 * out.upper.hi()) kinks(box, k, mu, out);
        return enough();
    };
    // The distance, which has only the enclosure's width to go by, tries the foot and the kinks first:
    // on bench_distance's random set nearly every pair the double stage leaves open lies in a flat
    // valley, where the steps in double-double crawl (several µs) and those candidates, or a better
    // start (last_resorts false), end it. The clearance query's pairs left open lie within rounding of
    // their margin, where the steps are what decides.
    if (enough_doubles > 0) {
        if (foot_point() || kinks_here() || !last_resorts || newton_in_double_double()) return out;
    } else {
        if (newton_in_double_double()) return out;
    }
    if (!last_resorts) return out;
    if (enough_doubles == 0 && (foot_point() || kinks_here())) return out;
    // The kinks of every edge: the refinement can leave its point inside a face that lies nearly
    // parallel to a cap, while the nearest point is where one of the face's edges enters the rim's
    // region. The four vertices of even parity meet each of the 12 edges once.
    if (out.upper.hi() - out.lower.lo() > 0x1p-80 * out.upper.hi())
        for (const double x : {-1.0, 1.0})
            for (const double y : {-1.0, 1.0}) kinks(box, k, {D(x), D(y), D(x * y)}, out);
    if (enough()) return out;
    if (out.upper.hi() - out.lower.lo() > 0x1p-80 * out.upper.hi()) edges_against_axis(box, k, out);
    return out;
}

// Whether dist ≤ m, when the refined bounds prove it either way.
template <class AnyBox>
std::optional<bool> refined_within(const AnyBox& b, const Cylinder<double>& c, double m, const Approximate& a) {
    const RefinedBounds r = refined_bounds(b, c, a, m);
    if (!r.found) return std::nullopt;
    return refined::decides(r, m);
}

}  // namespace boxcyl::filtered::separation
