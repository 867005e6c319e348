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
#include <array>      // Newton's coordinates
#include <cmath>      // std::isfinite
#include <limits>     // infinity: nothing proved
#include <utility>    // std::pair

#include "boxcyl/algo/gjk.hpp"
#include "boxcyl/filtered/nearest_box_point.hpp"  // Newton's steps after the projections
#include "boxcyl/filtered/rim.hpp"  // the box and cylinder as interval enclosures
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/number/bounded.hpp"
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
// The same with a running error bound: max(·, 0) moves no value farther, so the bound holds (a value
// below 0 becomes 0, and the exact one lies within the bound of it or below 0); a NaN value stays.
inline Bounded positive_part(const Bounded& x) {
    return x.value() < 0 ? Bounded(0.0, x.error()) : x;
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

namespace detail {

// The search's result from a pair (box point, cylinder point), both bounds as doubles (unproved): the
// box point's distance to the cylinder, and the lower bound's direction: the pair's, or one of those
// that separate the common contacts exactly (a box face's normal: face to side or cap; the axis: cap
// to vertex, edge or face; an edge's direction crossed with the axis: edge to side), whichever gives
// the largest gap in double.
inline void complete(Approximate& a, const Cylinder<double>& c, bool common_directions = true) {
    const Vec3<double>& u = a.u;
    a.p = algo::gjk::detail::box_point(a.box, a.closest.mu);
    {
        const Vec3<double> Z = a.p - c.center, Zxu = cross(Z, u);
        const double dr = std::max(0.0, std::sqrt(dot(Zxu, Zxu)) - c.radius);
        const double da = std::max(0.0, std::abs(dot(Z, u)) - 0.5 * c.height);
        a.upper = std::sqrt(dr * dr + da * da);
    }
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
    if (common_directions) {
        for (int i = 0; i < 3; ++i) {
            consider(cross(a.box.half[(i + 1) % 3], a.box.half[(i + 2) % 3]));
            consider(cross(a.box.half[i], u));
        }
        consider(u);
    }
    a.lower = best.first;
    a.direction = best.second;
    a.found = true;
}

// The box and the axis of the search, in double.
inline Approximate start(const rim::Box& box, const rim::Rims& f) {
    Approximate a;
    a.box = {mid(box.center), {mid(box.half[0]), mid(box.half[1]), mid(box.half[2])}};
    a.u = without_tiny_components(mid(f.u));
    return a;
}

}  // namespace detail

// `rel_gap`: GJK's convergence test (the double-double refinement that follows needs much less).
inline Approximate approximate(const rim::Box& box, const rim::Rims& f, const Cylinder<double>& c, double decide_at,
                               double rel_gap = 0x1p-44) {
    Approximate a = detail::start(box, f);
    a.closest = algo::gjk::closest(a.box, {c.center, a.u, c.radius, 0.5 * c.height}, decide_at, 48, rel_gap);
    detail::complete(a, c);
    return a;
}

// Whether the search's bounds show a side of decide_at clearly (by 2^-20 of it).
inline bool clear_of(const Approximate& a, double decide_at) {
    return a.upper < decide_at * (1 - 0x1p-20) || a.lower > decide_at * (1 + 0x1p-20);
}
// Whether the search's pair lies within 2^-20 of decide_at: most likely at it, where no search in
// double shows a side.
inline bool near_of(const Approximate& a, double decide_at) { return std::abs(a.upper - decide_at) <= 0x1p-20 * decide_at; }

namespace detail {
// The point of the cylinder c (u its unit axis, in double) nearest x, or with on_rim the point of its
// rims nearest x; in double, no proof.
inline Vec3<double> nearest_on_cylinder(const Cylinder<double>& c, const Vec3<double>& u, const Vec3<double>& x, bool on_rim) {
    const double h = 0.5 * c.height;
    const Vec3<double> z = x - c.center;
    const double t = dot(z, u);
    const Vec3<double> across = z - t * u;
    const double l = std::sqrt(dot(across, across));
    const double k = on_rim ? (l > 0 ? c.radius / l : 0.0) : (l > c.radius ? c.radius / l : 1.0);
    const double along = on_rim ? (t >= 0 ? h : -h) : std::clamp(t, -h, h);
    return c.center + along * u + k * across;
}
}  // namespace detail

// A quick search for a box near the rim, where GJK's first steps go round: the box point nearest the
// rim point nearest the box centre, then two steps of alternating projections (the box point nearest
// the cylinder point nearest the last one). Box points are clamped in the box's axes (for the
// parallelepiped's skewed axes only an approximation, which the proof does not need).
// `a` brings the box and the axis in double (a.box, a.u). With `decide_at` ≥ 0, where the search's
// bounds do not show a side of decide_at clearly (by 2^-20 of it) and its pair is not within 2^-20 of
// it, up to four of Newton's steps in double follow (nearest_box_point.hpp): the projections converge
// only linearly where the box lies along the rim (on bench_clearance's at-margin pairs, 16 of them
// leave 28% of the pairs short of 2^-20, at the cost of four Newton steps).
inline void projected(Approximate& a, const Cylinder<double>& c, double decide_at = -1) {
    const Vec3<double>& u = a.u;
    const double h = 0.5 * c.height;
    Vec3<double> inverse;  // 1/|hi|², or 0 for a flat side
    for (int i = 0; i < 3; ++i) {
        const double hh = dot(a.box.half[i], a.box.half[i]);
        inverse[i] = hh > 0 ? 1 / hh : 0.0;
    }
    auto nearest_mu = [&a, &inverse](const Vec3<double>& x) {  // the box's coordinates of the box point nearest x
        const Vec3<double> z = x - a.box.c;
        Vec3<double> mu;
        for (int i = 0; i < 3; ++i) mu[i] = std::clamp(dot(z, a.box.half[i]) * inverse[i], -1.0, 1.0);  // a NaN stays (undecided)
        return mu;
    };
    auto nearest_on_cylinder = [&](const Vec3<double>& x, bool on_rim) { return detail::nearest_on_cylinder(c, u, x, on_rim); };
    Vec3<double> q = nearest_on_cylinder(a.box.c, true);
    for (int i = 0; i <= 2; ++i) {
        a.closest.mu = nearest_mu(q);
        q = nearest_on_cylinder(algo::gjk::detail::box_point(a.box, a.closest.mu), false);
    }
    a.closest.q = q;
    a.closest.overlap = false;
    detail::complete(a, c, false);  // the common directions: stage 0's tests, in the clearance query
    if (decide_at < 0 || clear_of(a, decide_at) || near_of(a, decide_at)) return;
    std::array<double, 3> mu{};
    std::array<bool, 3> free{};
    if (!refined::held_start(a.closest.mu, mu, free)) return;
    refined::refine(refined::BoxOf<double>{a.box.c, a.box.half}, refined::CylOf<double>{c.center, u, c.radius, h}, mu,
                    free, 4);
    a.closest.mu = {mu[0], mu[1], mu[2]};
    a.closest.q = nearest_on_cylinder(algo::gjk::detail::box_point(a.box, a.closest.mu), false);
    detail::complete(a, c, false);
}

// A nearest pair in double, no proof: the search's box point refined by up to `newton_steps` of Newton's
// steps in double (nearest_box_point.hpp), and the cylinder point nearest it. {box point, cylinder point}.
inline std::pair<Vec3<double>, Vec3<double>> nearest_pair(const Approximate& a, const Cylinder<double>& c, int newton_steps) {
    std::array<double, 3> mu{};
    std::array<bool, 3> free{};
    Vec3<double> X = a.p;
    if (refined::held_start(a.closest.mu, mu, free)) {
        const refined::BoxOf<double> box{a.box.c, a.box.half};
        refined::refine(box, refined::CylOf<double>{c.center, a.u, c.radius, 0.5 * c.height}, mu, free, newton_steps);
        X = refined::point(box, mu);
    }
    return {X, detail::nearest_on_cylinder(c, a.u, X, false)};
}

// The bounds that a search's result `a` shows, proved for the box enclosed by `box` (rim.hpp's
// enclosure, or bounded_box()) and the cylinder enclosed by `f` (rim.hpp's Rims, or bounded_cylinder()),
// in their number type N (Interval or Bounded). With `decide_at` ≥ 0, only the bound that can decide
// "dist ≤ decide_at" is proved (the other is left at 0 or +∞).
template <class N = I, class BoxEnclosure, class CylinderEnclosure>
Bounds certified(const BoxEnclosure& box, const CylinderEnclosure& f, const Approximate& a, double decide_at) {
    using W = Vec3<N>;
    using detail::positive_part;
    const algo::gjk::Closest& g = a.closest;
    const double approx_upper = a.upper;
    const std::pair<double, Vec3<double>> best{a.lower, a.direction};
    const bool want_upper = decide_at < 0 || approx_upper <= decide_at;
    const bool want_lower = decide_at < 0 || (!want_upper && best.first > decide_at);

    double upper = std::numeric_limits<double>::infinity();
    if (want_upper) {  // the box point, exactly in the box for the doubles μ
        W X = box.center;
        for (int i = 0; i < 3; ++i) X = X + W{N(g.mu[i]) * box.half[i][0], N(g.mu[i]) * box.half[i][1], N(g.mu[i]) * box.half[i][2]};
        const W Z = X - f.C;
        const N t = dot(Z, f.u);
        const W Zxu = cross(Z, f.u);  // |Z × u| is ρ: no cancellation where ρ is small, as in |Z|² − t²
        const N rho = sqrt(positive_part(dot(Zxu, Zxu)));
        const N dr = positive_part(rho - f.r);
        const N da = positive_part(enclosure_abs(t) - f.half_h);
        upper = sqrt(dr * dr + da * da).hi();
    }
    double lower = 0;
    if (want_lower && best.first > 0) {
        const W n{N(best.second[0]), N(best.second[1]), N(best.second[2])};
        const N nn = dot(n, n);
        N L = dot(n, f.C - box.center);
        for (int i = 0; i < 3; ++i) L = L - enclosure_abs(dot(n, box.half[i]));
        const W nxu = cross(n, f.u);
        L = L - f.half_h * enclosure_abs(dot(n, f.u)) - f.r * sqrt(positive_part(dot(nxu, nxu)));
        if (L.lo() > 0 && nn.lo() > 0) {
            const double lo = (L / sqrt(nn)).lo();
            if (lo > 0) lower = lo;  // NaN stays 0
        }
    }
    return {lower, upper};
}

// The bounds from GJK's pair. With `decide_at` ≥ 0 the search stops once the distance is clearly on one
// side of it, or is known to 2^-26 relatively (closer to decide_at, bounds in double cannot decide; the
// refined stage, Newton's method from this pair, takes it on). `search`, when given, receives the
// search's result.
inline Bounds bounds(const rim::Box& box, const Cylinder<double>& c, double decide_at = -1, Approximate* search = nullptr) {
    const rim::Rims f(c, 0.0);
    if (!f.valid) return {0, std::numeric_limits<double>::infinity()};
    const Approximate a = approximate(box, f, c, decide_at, decide_at >= 0 ? 0x1p-26 : 0x1p-44);
    if (search) *search = a;
    return certified(box, f, a, decide_at);
}

template <class AnyBox>
Bounds bounds(const AnyBox& b, const Cylinder<double>& c, double decide_at = -1, Approximate* search = nullptr) {
    return bounds(rim::enclose(b), c, decide_at, search);
}

// The box and the cylinder in running-error arithmetic (number/bounded.hpp): a few flops per
// operation, several times cheaper than rim.hpp's intervals, a little wider. u = D/|D| from the axis
// scaled exactly by a power of two (rim.hpp's scaled_axis), so that |D|² neither underflows nor overflows.
struct BoundedBox {
    Vec3<Bounded> center;
    std::array<Vec3<Bounded>, 3> half;
};
struct BoundedCylinder {
    Vec3<Bounded> C, u;
    Bounded r, half_h;
};
inline BoundedBox bounded_box(const AlignedBox<double>& b) {
    BoundedBox box;
    for (int i = 0; i < 3; ++i) {
        box.center[i] = (Bounded(b.min[i]) + Bounded(b.max[i])) * Bounded(0.5);
        box.half[i] = {0.0, 0.0, 0.0};
        box.half[i][i] = (Bounded(b.max[i]) - Bounded(b.min[i])) * Bounded(0.5);
    }
    return box;
}
inline BoundedBox bounded_box(const Parallelepiped<double>& b) {
    BoundedBox box{{b.center[0], b.center[1], b.center[2]}, {}};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) box.half[i][j] = Bounded(b.extents[i]) * Bounded(b.axes[i][j]);
    return box;
}
inline BoundedBox bounded_box(const OrientedBox<double>& b) { return bounded_box(Parallelepiped<double>{b.center, b.axes, b.extents}); }
inline BoundedBox bounded_box(const CanonicalBox<double>& b) {
    BoundedBox box{{0.0, 0.0, 0.0}, {}};
    for (int i = 0; i < 3; ++i) {
        box.half[i] = {0.0, 0.0, 0.0};
        box.half[i][i] = b.extents[i];
    }
    return box;
}
inline BoundedCylinder bounded_cylinder(const Cylinder<double>& c) {
    const Vec3<double> d = rim::scaled_axis(c.axis);
    const Vec3<Bounded> D{d[0], d[1], d[2]};
    const Bounded len = sqrt(dot(D, D));
    return {{c.center[0], c.center[1], c.center[2]}, {D[0] / len, D[1] / len, D[2] / len}, c.radius,
            Bounded(c.height) * Bounded(0.5)};
}

// The same bounds from the quick search, projected(), proved in running-error arithmetic: for a box near
// the rim, most often as decisive as GJK's bounds at a fraction of their cost. Only a side of
// `decide_at` that the search shows clearly (by 2^-20 of it) is proved; otherwise nothing is ({0, ∞}).
// `search`, when given, receives the search's result.
template <class AnyBox>
Bounds projected_bounds(const AnyBox& b, const Cylinder<double>& c, double decide_at, Approximate* search = nullptr) {
    const BoundedBox box = bounded_box(b);
    Approximate a;
    a.box = {{box.center[0].value(), box.center[1].value(), box.center[2].value()}, {}};
    for (int i = 0; i < 3; ++i) a.box.half[i] = {box.half[i][0].value(), box.half[i][1].value(), box.half[i][2].value()};
    const double len = std::sqrt(dot(c.axis, c.axis));
    a.u = without_tiny_components({c.axis[0] / len, c.axis[1] / len, c.axis[2] / len});
    projected(a, c, decide_at);
    if (search) *search = a;
    if (!clear_of(a, decide_at)) return {0, std::numeric_limits<double>::infinity()};
    return certified<Bounded>(box, bounded_cylinder(c), a, decide_at);
}

}  // namespace boxcyl::filtered::separation
