// The certificates of the exact default for any parallelepiped (boxcyl::Parallelepiped: axes of any
// length and angle, exactly as given), and its prepared query. The rows that use them are in
// filtered/schedule.hpp; the exact stage answers what none certifies (exact/answer.hpp).
//
// Misses: a separating direction n (any double vector) whose support-function gap
// |n·(C − K)| − Σ eᵢ|n·Wᵢ| − H|n·u| exceeds r·|n × u|. Hits: a box point (box coordinates |xᵢ| ≤ eᵢ in
// doubles: exactly a point of the solid) inside the cylinder, or a cylinder point (C + t·u + ρ·w/|w|)
// whose box coordinates are within ±eᵢ. Frame: linear inequalities in the unit frame Wᵢ/|Wᵢ|, widened
// by its distance from orthonormal. Candidates come from a plain-double search (alternating projections
// between the shrunk solids); only the certificates, on enclosures, decide. docs/robustness/parallelepipeds.md
// has the proofs; no magnitude is out of range (overflow and underflow make comparisons undecided).
#pragma once

#include <algorithm>  // std::min, std::max
#include <array>      // the approximate axes
#include <cmath>      // std::fabs, std::sqrt, std::ilogb, std::ldexp
#include <limits>     // infinity
#include <optional>   // undecided

#include "boxcyl/filtered/enclosed.hpp"
#include "boxcyl/filtered/prepared.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/number/bounded.hpp"
#include "boxcyl/number/interval.hpp"

namespace boxcyl::filtered::parallelepiped {

using enclosed::certainly;
using enclosed::norm2;
inline double root(double x) { return std::sqrt(x); }
template <class N>
N root(const N& x) {
    return sqrt(x);
}

// ---- Enclosed data ----

template <class N>
Vec3<N> enclose(const Vec3<double>& v) {
    return {N(v[0]), N(v[1]), N(v[2])};
}

template <class N>
struct Problem {
    Vec3<N> delta;   // C − K
    Vec3<N> w[3];    // the axes (exact)
    Vec3<N> e;       // the extents (exact)
    Vec3<N> u;       // the unit axis
    N r, h;          // radius (exact), half height
    N det;           // det[W0 W1 W2]
};

// `u` encloses the unit axis (the plain-double problem takes the search's rounded one).
template <class N>
Problem<N> problem(const Parallelepiped<double>& b, const Cylinder<double>& c, const Vec3<N>& u) {
    Problem<N> p;
    p.delta = enclose<N>(c.center) - enclose<N>(b.center);
    for (int i = 0; i < 3; ++i) p.w[i] = enclose<N>(b.axes[i]);
    p.e = enclose<N>(b.extents);
    p.u = u;
    p.r = N(c.radius);
    p.h = N(c.height) * N(0.5);
    p.det = dot(p.w[0], cross(p.w[1], p.w[2]));
    return p;
}

// n separates: s = |n·δ| − Σ eᵢ|n·Wᵢ| − H|n·u| > 0 and s² > r²|n × u|².
template <class N>
bool separates(const Problem<N>& p, const Vec3<double>& nd) {
    return certainly([&] {
        const Vec3<N> n = enclose<N>(nd);
        const N s = abs_value(dot(n, p.delta)) -
                    (p.e[0] * abs_value(dot(n, p.w[0])) + p.e[1] * abs_value(dot(n, p.w[1])) +
                     p.e[2] * abs_value(dot(n, p.w[2]))) -
                    p.h * abs_value(dot(n, p.u));
        if (!(N(0) < s)) return false;
        return p.r * p.r * norm2(cross(n, p.u)) < s * s;
    });
}

// The box point K + Σ xᵢWᵢ (|xᵢ| ≤ eᵢ exactly, checked by the caller) lies in the cylinder.
template <class N>
bool box_point_inside(const Problem<N>& p, const Vec3<double>& x) {
    return certainly([&] {
        const Vec3<N> v = N(x[0]) * p.w[0] + N(x[1]) * p.w[1] + N(x[2]) * p.w[2] - p.delta;  // P − C
        if (!(abs_value(dot(p.u, v)) <= p.h)) return false;
        return norm2(cross(v, p.u)) <= p.r * p.r;
    });
}

// The cylinder point X = C + t·u + ρ·w/|w|, w = m − (m·u)u (|t| ≤ H and 0 ≤ ρ ≤ r exactly, checked by
// the caller; ρ = 0: an axis point) lies in the box: |det(·)/det| ≤ eᵢ for X − K (Cramer).
template <class N>
bool cylinder_point_inside(const Problem<N>& p, double t, double rho, const Vec3<double>& m) {
    return certainly([&] {
        if (!(N(0) < abs_value(p.det))) return false;
        Vec3<N> y = p.delta + N(t) * p.u;  // X − K
        if (rho != 0) {
            const Vec3<N> mn = enclose<N>(m);
            const Vec3<N> w = mn - dot(mn, p.u) * p.u;
            const N len = root(norm2(w));
            if (!(N(0) < len)) return false;
            y = y + (N(rho) / len) * w;
        }
        const N x0 = dot(y, cross(p.w[1], p.w[2])) / p.det;
        const N x1 = dot(p.w[0], cross(y, p.w[2])) / p.det;
        const N x2 = dot(p.w[0], cross(p.w[1], y)) / p.det;
        return abs_value(x0) <= p.e[0] && abs_value(x1) <= p.e[1] && abs_value(x2) <= p.e[2];
    });
}

// ---- Nearly orthogonal axes of any lengths: linear inequalities in the frame of the unit axes. ----
//
// With Lᵢ = |Wᵢ| and Aᵢ = Wᵢ/Lᵢ (enclosures of the real numbers), the solid is exactly
// {K + Σ yᵢAᵢ : |yᵢ| ≤ eᵢLᵢ}: an oriented box with the real frame A, widened by its distance from
// orthonormal as a rounded rotation is (enclosed::frame_problem). Exactly orthogonal axes ((3,4,0),
// (−4,3,0), (0,0,5)) leave g at the enclosures' width, so only queries within a few ulps of touching
// stay undecided.
template <class N>
std::optional<bool> frame_stage(const Problem<N>& p, double scale) {
    Vec3<N> a[3], extents;
    for (int i = 0; i < 3; ++i) {
        const N len = sqrt(enclosed::norm2(p.w[i]));
        if (!(len.lo() > 0)) return std::nullopt;  // a zero (or tiny) axis: a flat solid
        a[i] = {p.w[i][0] / len, p.w[i][1] / len, p.w[i][2] / len};
        extents[i] = p.e[i] * len;
    }
    const auto w = enclosed::frame_problem(a, p.delta, extents, p.u, p.r, p.h);
    if (!w) return std::nullopt;
    return enclosed::decide(*w, scale);
}

// ---- Candidates, in plain double (any value is sound; only the certificates decide). ----

struct Candidates {
    static constexpr int max = 40;
    Vec3<double> dirs[max];
    int n_dirs = 0;
    Vec3<double> box_points[max];  // box coordinates x, |xᵢ| ≤ eᵢ exactly
    int n_box = 0;
    struct CylPoint {
        double t, rho;
        Vec3<double> m;
    };
    CylPoint cyl_points[max];
    int n_cyl = 0;

    void dir(const Vec3<double>& n) {
        if (n_dirs < max && (n[0] != 0 || n[1] != 0 || n[2] != 0)) dirs[n_dirs++] = n;
    }
    void box(const Vec3<double>& x) {
        if (n_box < max) box_points[n_box++] = x;
    }
    void cyl(double t, double rho, const Vec3<double>& m) {
        if (n_cyl < max) cyl_points[n_cyl++] = {t, rho, m};
    }
    void append(const Candidates& o) {
        for (int i = 0; i < o.n_dirs; ++i) dir(o.dirs[i]);
        for (int i = 0; i < o.n_box; ++i) box(o.box_points[i]);
        for (int i = 0; i < o.n_cyl; ++i) cyl(o.cyl_points[i].t, o.cyl_points[i].rho, o.cyl_points[i].m);
    }
};

// The approximate problem in double for the search.
struct Approx {
    Vec3<double> k, c, u;
    std::array<Vec3<double>, 3> w;
    std::array<double, 3> step;  // 1/|Wᵢ|² (0 for a zero axis or one whose |Wᵢ|² overflows: that coordinate stays put)
    Vec3<double> e;
    double r, height, h;
};

inline Approx approx(const Parallelepiped<double>& b, const Cylinder<double>& c) {
    Approx a;
    a.k = b.center;
    a.c = c.center;
    a.w = b.axes;
    for (int i = 0; i < 3; ++i) {
        const double ww = dot(a.w[i], a.w[i]);
        a.step[i] = ww > 0 ? 1 / ww : 0.0;
    }
    a.e = b.extents;
    double m = std::max({std::fabs(c.axis[0]), std::fabs(c.axis[1]), std::fabs(c.axis[2])});
    const int s = m > 0 ? -std::ilogb(m) : 0;
    const Vec3<double> d{std::ldexp(c.axis[0], s), std::ldexp(c.axis[1], s), std::ldexp(c.axis[2], s)};
    const double len = std::sqrt(dot(d, d));
    a.u = {d[0] / len, d[1] / len, d[2] / len};
    a.r = c.radius;
    a.height = c.height;
    a.h = c.height * 0.5;
    return a;
}

// Box coordinates x clamped to |xᵢ| ≤ eᵢ exactly (NaN becomes 0).
inline Vec3<double> clamp_coords(const Vec3<double>& x, const Vec3<double>& e) {
    Vec3<double> y;
    for (int i = 0; i < 3; ++i) y[i] = std::fabs(x[i]) <= e[i] ? x[i] : (x[i] > e[i] ? e[i] : x[i] < -e[i] ? -e[i] : 0.0);
    return y;
}
// An axial parameter with |t| ≤ H exactly (|2t| ≤ height: doubling is exact), else 0.
inline double clamp_axial(double t, const Approx& a) {
    if (!(std::fabs(t) * 2 <= a.height)) t = t > 0 ? a.h : -a.h;
    if (!(std::fabs(t) * 2 <= a.height)) t = 0;  // a.h rounded up (subnormal height) or NaN
    return t;
}

inline Vec3<double> box_point(const Approx& a, const Vec3<double>& x) {
    return a.k + x[0] * a.w[0] + x[1] * a.w[1] + x[2] * a.w[2];
}
// The box coordinates of the box point nearest to y: coordinate descent from x (a few sweeps).
// The residual box_point(x) − y is updated by each coordinate's move rather than recomputed (a sum of
// four vectors per coordinate), and each move multiplies by the axis's precomputed 1/|Wᵢ|² rather than
// dividing in the loop's dependency chain; their rounding only perturbs the search, which proves nothing.
inline Vec3<double> onto_box(const Approx& a, const Vec3<double>& y, Vec3<double> x, int sweeps) {
    for (int i = 0; i < 3; ++i)
        if (a.step[i] == 0) x[i] = 0;
    Vec3<double> res = box_point(a, x) - y;
    for (int s = 0; s < sweeps; ++s)
        for (int i = 0; i < 3; ++i) {
            if (a.step[i] == 0) continue;
            const double next = std::min(std::max(x[i] - dot(a.w[i], res) * a.step[i], -a.e[i]), a.e[i]);
            res = res + (next - x[i]) * a.w[i];
            x[i] = next;
        }
    return clamp_coords(x, a.e);
}
// The cylinder point nearest to y: its parameters (t, ρ, m), X = C + t·u + ρ·m/|m| with m ⊥ u, and
// the point itself (from the same |m|).
struct CylinderPoint {
    Candidates::CylPoint q;
    Vec3<double> x;
};
inline CylinderPoint onto_cylinder(const Approx& a, const Vec3<double>& y) {
    const Vec3<double> v = y - a.c;
    const double t = clamp_axial(dot(a.u, v), a);
    const Vec3<double> m = v - dot(a.u, v) * a.u;
    const double len = std::sqrt(dot(m, m));
    const double rho = std::min(len, a.r);
    const double s = len > 0 ? rho / len : 0.0;
    return {{t, rho, m}, a.c + t * a.u + s * m};
}

// The cheap, fixed candidates.
inline void fixed_candidates(const Approx& a, const Cylinder<double>& c, Candidates& cs) {
    for (int i = 0; i < 3; ++i) cs.dir(cross(a.w[(i + 1) % 3], a.w[(i + 2) % 3]));
    cs.dir(c.axis);
    for (int i = 0; i < 3; ++i) cs.dir(cross(c.axis, a.w[i]));
    cs.box({0, 0, 0});
    // The axis point nearest to the box centre, and the box point nearest to it.
    const double t = clamp_axial(dot(a.u, a.k - a.c), a);
    cs.cyl(0, 0, {0, 0, 0});
    cs.cyl(t, 0, {0, 0, 0});
    const Vec3<double> x = onto_box(a, a.c + t * a.u, {0, 0, 0}, 2);
    cs.box(x);
    // The cross-section point 0.9·r towards the box centre.
    const Vec3<double> to_k = a.k - (a.c + t * a.u);
    cs.cyl(t, a.r * 0.9, to_k);
}

// Alternating projections between the solids shrunk about their centres to `shrink` of their sizes,
// from the box centre: for overlapping solids the iterates approach a point of the shrunk
// intersection, which lies inside both full solids with a margin (unshrunk, they would approach the
// intersection's boundary, where no certificate has room); for disjoint ones, a nearest pair.
// Candidates after steps 1, 2, 4, 8, ... and at a fixed point: a step that leaves x as it was (in
// doubles) would leave it so for every later step, so the search stops there with the candidates the
// later steps would have repeated.
inline void searched_candidates(const Approx& full, double shrink, Candidates& cs, int steps = 16) {
    Approx a = full;
    // The cylinder shrunk by one depth along and across its axis (a factor would take a thick disk's
    // whole thin rim), kept ≤ the true sizes exactly by max(·, 0) of values computed below them.
    const double depth = (1 - shrink) * std::min(full.r, full.h);
    a.r = std::max(0.0, full.r - depth * 1.0000001);
    a.h = std::max(0.0, full.h - depth * 1.0000001);
    a.height = a.h * 2 <= full.height ? a.h * 2 : full.height * shrink;
    for (int i = 0; i < 3; ++i) a.e[i] = full.e[i] * shrink;
    Vec3<double> x{0, 0, 0};
    for (int step = 1; step <= steps; ++step) {
        const Vec3<double> p = box_point(a, x);
        const auto [q, y] = onto_cylinder(a, p);
        const Vec3<double> next = onto_box(a, y, x, 3);
        const bool fixed = next == x;
        x = next;
        if ((step & (step - 1)) != 0 && !fixed) continue;
        const Vec3<double> pb = box_point(a, x);
        cs.box(clamp_coords(x, full.e));
        cs.cyl(q.t, q.rho, q.m);
        cs.dir(y - pb);
        if (fixed) break;
    }
}

// The search's phases: shrink factor, steps. Deeper shrinks find witnesses with more room; the last
// finds those of thin overlaps (on random skewed parallelepipeds, 64 steps per phase left 0.2% of the
// queries to the exact stage where 16 left 1%: thin overlaps converge slowly).
struct Phase {
    double shrink;
    int steps;
};
inline constexpr Phase search_phases[] = {{0.9, 64}, {0.99, 64}, {0.9999, 64}};

// The certificates, each tried on enclosures only if the same test passes in plain double on the
// problem `pre` (the double computation decides nothing: it only skips candidates whose computed
// margins already say no, and costs a fraction of an enclosure's evaluation).
template <class N>
std::optional<bool> certify(const Problem<N>& p, const Problem<double>& pre, const Candidates& cs) {
    for (int i = 0; i < cs.n_dirs; ++i)
        if (separates(pre, cs.dirs[i]) && separates(p, cs.dirs[i])) return false;
    for (int i = 0; i < cs.n_box; ++i)
        if (box_point_inside(pre, cs.box_points[i]) && box_point_inside(p, cs.box_points[i])) return true;
    for (int i = 0; i < cs.n_cyl; ++i) {
        const Candidates::CylPoint& q = cs.cyl_points[i];
        if (cylinder_point_inside(pre, q.t, q.rho, q.m) && cylinder_point_inside(p, q.t, q.rho, q.m)) return true;
    }
    return std::nullopt;
}

// The same question at a convenient scale: each axis Wᵢ scaled by 2^-aᵢ to a largest component in
// [1, 2) with its extent scaled by 2^aᵢ (the same solid), then every length (centres, extents, radius,
// height) by one 2^-k when the largest is beyond 2^±200 (the same question: the axis direction does
// not change). A step is taken only where every scaled value is exact (checked by scaling back), so
// the exact answer is unchanged; the enclosures then neither overflow nor underflow on most inputs.
inline bool scaled_exactly(double x, int k, double& out) {
    out = std::ldexp(x, k);
    return std::ldexp(out, -k) == x;
}
inline void normalise(Parallelepiped<double>& b, Cylinder<double>& c) {
    for (int i = 0; i < 3; ++i) {
        const double m = std::max({std::fabs(b.axes[i][0]), std::fabs(b.axes[i][1]), std::fabs(b.axes[i][2])});
        if (!(m > 0) || !(m <= std::numeric_limits<double>::max())) continue;
        const int a = std::ilogb(m);
        Vec3<double> w;
        double e = 0;
        if (scaled_exactly(b.axes[i][0], -a, w[0]) && scaled_exactly(b.axes[i][1], -a, w[1]) &&
            scaled_exactly(b.axes[i][2], -a, w[2]) && scaled_exactly(b.extents[i], a, e))
            b.axes[i] = w, b.extents[i] = e;
    }
    double l = std::max({c.radius, c.height, b.extents[0], b.extents[1], b.extents[2]});
    for (int j = 0; j < 3; ++j) l = std::max({l, std::fabs(b.center[j]), std::fabs(c.center[j])});
    if (!(l > 0) || !(l <= std::numeric_limits<double>::max())) return;
    const int k = -std::ilogb(l);
    if (k >= -200 && k <= 200) return;
    Parallelepiped<double> nb = b;
    Cylinder<double> nc = c;
    bool exact = scaled_exactly(c.radius, k, nc.radius) && scaled_exactly(c.height, k, nc.height);
    for (int j = 0; j < 3; ++j)
        exact = exact && scaled_exactly(b.center[j], k, nb.center[j]) && scaled_exactly(c.center[j], k, nc.center[j]) &&
                scaled_exactly(b.extents[j], k, nb.extents[j]);
    if (exact) b = nb, c = nc;
}


}  // namespace boxcyl::filtered::parallelepiped

namespace boxcyl::filtered {

// The prepared query of a parallelepiped: the question at a convenient scale (parallelepiped::normalise,
// exact), the plain-double problem and search, the fixed candidates, and the enclosed problems on first
// use; the searched candidates are kept for the interval rows.
template <>
class Prepared<Parallelepiped<double>> {
public:
    using box_type = Parallelepiped<double>;
    Prepared(const Parallelepiped<double>& b, const Cylinder<double>& c)
        : box(b), cyl(c), approx((parallelepiped::normalise(box, cyl), parallelepiped::approx(box, cyl))),
          plain(parallelepiped::problem<double>(box, cyl, approx.u)) {
        parallelepiped::fixed_candidates(approx, cyl, fixed);
    }

    Parallelepiped<double> box;  // the query, normalised (the same solid and question)
    Cylinder<double> cyl;
    parallelepiped::Approx approx;              // the search's rounded problem
    parallelepiped::Problem<double> plain;      // the certificates' preselection in plain double
    parallelepiped::Candidates fixed, searched;  // the candidates, fixed and searched (filled by its row)
    bool exact_in_pairs = false;                 // (the schedule has no tiny sizes' row)

    const parallelepiped::Problem<Bounded>& bounded() { return enclosed_problem(bounded_); }
    const parallelepiped::Problem<Interval>& interval() { return enclosed_problem(interval_); }
    double scale() const { return largest_length(box, cyl); }
    bool nearest() { return memo(nearest_, [] { return boxcyl::detail::round_to_nearest(); }); }

private:
    template <class N>
    const parallelepiped::Problem<N>& enclosed_problem(std::optional<parallelepiped::Problem<N>>& slot) {
        if (!slot) slot = parallelepiped::problem<N>(box, cyl, enclosed::unit_direction<N>(cyl.axis));
        return *slot;
    }
    std::optional<parallelepiped::Problem<Bounded>> bounded_;
    std::optional<parallelepiped::Problem<Interval>> interval_;
    std::int8_t nearest_ = -1;
};

}  // namespace boxcyl::filtered
