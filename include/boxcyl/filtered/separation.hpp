// Certified bounds on the distance between a box and a cylinder, from an approximate closest pair
// (algo/gjk.hpp), evaluated in interval arithmetic so that each bound holds for the exact inputs (each
// double the rational it denotes, u = D/|D| exactly), in every rounding mode:
//
//   upper  dist(X, cylinder) for a point X = c + Σ μi·hi of the box (|μi| ≤ 1 doubles, so X lies in
//          the exact box): the point's distance to the cylinder is closed form,
//          √(max(ρ − r, 0)² + max(|t| − h/2, 0)²), ρ its distance from the axis and t its height.
//   lower  for any direction n, the gap between the solids' supporting planes:
//          dist ≥ (min over the cylinder of n·Y − max over the box of n·X) / |n|
//               = (n·(C − c) − Σ|n·hi| − (h/2)·|n·u| − r·√(|n|² − (n·u)²)) / |n|,
//          for a direction n chosen in double among GJK's and those that separate common contacts
//          exactly (face normals, the axis, edges crossed with the axis).
// Both are as tight as the pair is good; a poor pair only widens them. The clearance query
// (boxcyl/clearance.hpp) answers "within m" when upper ≤ m and "not within m" when lower > m.
#pragma once

#include <algorithm>  // std::max
#include <cmath>      // std::isfinite
#include <limits>     // infinity: nothing proved
#include <utility>    // std::pair

#include "boxcyl/algo/gjk.hpp"
#include "boxcyl/filtered/rim.hpp"  // the box and cylinder as interval enclosures
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/number/interval.hpp"

namespace boxcyl::filtered::separation {

using I = Interval;
using V = Vec3<Interval>;

// lower ≤ dist(box, cylinder) ≤ upper; lower = 0 when nothing better is proved, upper = +∞ (or NaN)
// likewise.
struct Bounds {
    double lower, upper;
};

namespace detail {

inline double mid(const I& x) { return 0.5 * x.lo() + 0.5 * x.hi(); }
inline Vec3<double> mid(const V& v) { return {mid(v[0]), mid(v[1]), mid(v[2])}; }

// max(x, 0) of an enclosure; a NaN bound stays NaN (undecided).
inline I positive_part(const I& x) {
    if (x.lo() != x.lo() || x.hi() != x.hi()) return x;
    return {std::max(0.0, x.lo()), std::max(0.0, x.hi())};
}

}  // namespace detail

// The search in double: GJK's box point and the best lower-bound direction, with both bounds as
// doubles (unproved). The refined stage (separation_refined.hpp) starts from it.
struct Approximate {
    algo::gjk::Box box;
    Vec3<double> u;           // the axis, unit up to rounding
    algo::gjk::Closest closest;
    Vec3<double> p;           // the box point c + Σ μi·hi
    double upper;             // p's distance to the cylinder
    double lower;             // the best direction's gap (−1: none positive)
    Vec3<double> direction;   // that direction, from the box towards the cylinder
    bool found = false;       // false: the search did not run (an axis whose enclosure is not finite)
};

// The search's axis: components below 2^-250 of the largest set to 0. The search needs no proof (what
// it finds is proved below, on the exact axis's enclosure), and such a component — an axis like
// (1e-300, 0.6, 0.8), or a subnormal one — made every product with it subnormal, which x86 runs in
// microcode: the search took about 2.8 µs on such axes where it takes 1 µs on others.
inline Vec3<double> without_tiny_components(Vec3<double> u) {
    const double floor = 0x1p-250 * std::max(std::max(std::abs(u[0]), std::abs(u[1])), std::abs(u[2]));
    for (int i = 0; i < 3; ++i)
        if (std::abs(u[i]) < floor) u[i] = 0;
    return u;
}

// `rel_gap`: GJK's convergence test (the double-double refinement that follows needs much less).
inline Approximate approximate(const rim::Box& box, const rim::Rims& f, const Cylinder<double>& c, double decide_at,
                               double rel_gap = 0x1p-44) {
    using detail::mid;
    Approximate a;
    a.box = {mid(box.center), {mid(box.half[0]), mid(box.half[1]), mid(box.half[2])}};
    a.u = without_tiny_components(mid(f.u));
    const Vec3<double>& u = a.u;
    a.closest = algo::gjk::closest(a.box, {c.center, u, c.radius, 0.5 * c.height}, decide_at, 48, rel_gap);
    a.p = algo::gjk::detail::box_point(a.box, a.closest.mu);
    {
        const Vec3<double> Z = a.p - c.center, Zxu = cross(Z, u);
        const double dr = std::max(0.0, std::sqrt(dot(Zxu, Zxu)) - c.radius);
        const double da = std::max(0.0, std::abs(dot(Z, u)) - 0.5 * c.height);
        a.upper = std::sqrt(dr * dr + da * da);
    }
    // The lower bound's direction: GJK's, or one of the directions that separate the common contacts
    // exactly (a box face's normal: face to side or cap; the axis: cap to vertex, edge or face; an
    // edge's direction crossed with the axis: edge to side), whichever gives the largest gap in double.
    const Vec3<double> towards = c.center - a.box.c;
    auto gap = [&](Vec3<double> n) {  // (n·(C − c) − Σ|n·hi| − (h/2)|n·u| − r·|n × u|) / |n|, rounded
        if (dot(n, towards) < 0) n = -n;
        const double nn = dot(n, n), nu = dot(n, u);
        const Vec3<double> nxu = cross(n, u);
        const double L = dot(n, towards) - std::abs(dot(n, a.box.half[0])) - std::abs(dot(n, a.box.half[1])) -
                         std::abs(dot(n, a.box.half[2])) - 0.5 * c.height * std::abs(nu) - c.radius * std::sqrt(dot(nxu, nxu));
        return std::pair{nn > 0 ? L / std::sqrt(nn) : -1.0, n};
    };
    std::pair<double, Vec3<double>> best{-1.0, {}};
    auto consider = [&](const Vec3<double>& n) {
        const auto candidate = gap(n);
        if (candidate.first > best.first) best = candidate;  // NaN never wins
    };
    if (!a.closest.overlap) consider(a.closest.q - a.p);
    for (int i = 0; i < 3; ++i) {
        consider(cross(a.box.half[(i + 1) % 3], a.box.half[(i + 2) % 3]));
        consider(cross(a.box.half[i], u));
    }
    consider(u);
    a.lower = best.first;
    a.direction = best.second;
    a.found = true;
    return a;
}

// The bounds for the box enclosed by `box` (rim.hpp's enclosure) and the cylinder. With `decide_at`
// ≥ 0 the search stops once the distance is clearly on one side of it, or is known to 2^-26
// relatively (closer to decide_at, bounds in double cannot decide; the refined stage, Newton's method
// from this pair, takes it on), and only the bound that can decide "dist ≤ decide_at" is proved (the
// other is left at 0 or +∞). `search`, when given, receives the search's result.
inline Bounds bounds(const rim::Box& box, const Cylinder<double>& c, double decide_at = -1, Approximate* search = nullptr) {
    const rim::Rims f(c, 0.0);
    if (!f.valid) return {0, std::numeric_limits<double>::infinity()};
    const Approximate a = approximate(box, f, c, decide_at, decide_at >= 0 ? 0x1p-26 : 0x1p-44);
    if (search) *search = a;
    const algo::gjk::Closest& g = a.closest;
    const double approx_upper = a.upper;
    const std::pair<double, Vec3<double>> best{a.lower, a.direction};
    const bool want_upper = decide_at < 0 || approx_upper <= decide_at;
    const bool want_lower = decide_at < 0 || (!want_upper && best.first > decide_at);

    double upper = std::numeric_limits<double>::infinity();
    if (want_upper) {  // the box point, exactly in the box for the doubles μ
        V X = box.center;
        for (int i = 0; i < 3; ++i) X = X + V{I(g.mu[i]) * box.half[i][0], I(g.mu[i]) * box.half[i][1], I(g.mu[i]) * box.half[i][2]};
        const V Z = X - f.C;
        const I t = dot(Z, f.u);
        const V Zxu = cross(Z, f.u);  // |Z × u| is ρ: no cancellation where ρ is small, as in |Z|² − t²
        const I rho = sqrt(detail::positive_part(dot(Zxu, Zxu)));
        const I dr = detail::positive_part(rho - f.r);
        const I da = detail::positive_part(enclosure_abs(t) - f.half_h);
        upper = sqrt(dr * dr + da * da).hi();
    }
    double lower = 0;
    if (want_lower && best.first > 0) {
        const V N = rim::lift(best.second);
        const I nn = dot(N, N);
        I L = dot(N, f.C - box.center);
        for (int i = 0; i < 3; ++i) L = L - enclosure_abs(dot(N, box.half[i]));
        const V Nxu = cross(N, f.u);
        L = L - f.half_h * enclosure_abs(dot(N, f.u)) - f.r * sqrt(detail::positive_part(dot(Nxu, Nxu)));
        if (L.lo() > 0 && nn.lo() > 0) {
            const double lo = (L / sqrt(nn)).lo();
            if (lo > 0) lower = lo;  // NaN stays 0
        }
    }
    return {lower, upper};
}

template <class AnyBox>
Bounds bounds(const AnyBox& b, const Cylinder<double>& c, double decide_at = -1, Approximate* search = nullptr) {
    return bounds(rim::enclose(b), c, decide_at, search);
}

}  // namespace boxcyl::filtered::separation
