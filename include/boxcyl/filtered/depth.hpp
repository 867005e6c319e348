// Certified bounds on the penetration depth of an intersecting box and cylinder: the length of the
// shortest translation that separates them (boxcyl/signed_distance.hpp is the query).
//
// With z = c − C (the box's centre relative to the cylinder's), hᵢ the box's half axes, u the unit axis,
// r the radius and k the half height, the Minkowski difference M = box − cylinder has the support function
//     H(v) = v·z + Σ|v·hᵢ| + k·|v·u| + r·|v × u|,
// and the depth is the distance from the origin (inside M) to M's boundary: depth = min over unit v of
// H(v). Every unit v gives an upper bound; a lower bound must hold over the whole sphere.
//
// Where the minimum lies. A ball about the origin inside M touches M's boundary where it is smooth, so
// the minimizing direction is the normal of a two-dimensional patch of that boundary: ±u (a box vertex
// against a cap) or a direction on one of four great circles —
//     v ⊥ u   a box vertex or edge against the side,
//     v ⊥ aᵢ  an edge along the box axis aᵢ against a rim (and the faces, whose normals are ⊥ two axes).
// Off those sets H is smooth, of the form v·w + r·|v × u|, and its critical points on the sphere are
// maxima or negative minima, never the minimum of an H ≥ 0. So
//     depth = min(H(u), H(−u), the minima of H/|v| over the four circles).
//
// How each circle is bounded. It is cut into four quarter arcs, each the directions of the chord
// v(s) = from + s·step, s ∈ [0, 1]. H is convex in v (a linear form, magnitudes of linear forms, the
// norm of a linear map), so H(v(s)) is convex in s, and |v(s)| is convex too, so it lies below the chord
// ℓ(s) between its values at a piece's ends. To prove H/|v| ≥ λ (λ ≥ 0) over a piece it suffices that
// H(v(s)) − λ·ℓ(s), a convex function, is ≥ 0 there, and a convex function lies above its tangents at
// the piece's ends, whose larger one is least where they cross. The ends' values and one-sided slopes
// are enclosed by forward differentiation in running-error arithmetic (|x| gets the slope enclosure
// [−|x′|, |x′|] where x may vanish, which holds both one-sided slopes). A piece that fails is split
// where the tangents cross — at a kink of H (a face, an edge across the axis) they cross at the kink,
// and near a smooth minimum the crossing closes in on it — and the direction at each split point is an
// upper bound. The search runs, failing pieces with the lowest bound first, until every piece proves
// λ = (best upper bound) − gap, a small fraction of the problem's length. Every operation carries a
// running error bound (number/bounded.hpp) that holds in every rounding mode, and so do the bounds.
#pragma once

#include <algorithm>   // std::max, std::min, std::clamp
#include <array>       // the half axes
#include <cmath>       // std::abs, std::ilogb, std::ldexp, std::isfinite
#include <limits>      // infinity
#include <queue>       // the pieces, lowest bound first
#include <vector>      // arcs, kinks, the heap's storage

#include "boxcyl/geometry/vec3.hpp"
#include "boxcyl/number/bounded.hpp"
#include "boxcyl/number/interval.hpp"

namespace boxcyl::filtered::depth {

// The search's arithmetic: running error bounds (number/bounded.hpp), branch-free and inlined, a few
// times cheaper per operation than outward-rounded intervals and as sound in every rounding mode; its
// bounds are a little wider, far below the search's target gap.
using I = Bounded;
using V = Vec3<Bounded>;

// An interval's enclosure as a value with a bound (a bound that is not finite: undecided).
inline I undecided() { return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}; }
inline I enclose(const Interval& x) {
    if (x.lo() == x.hi()) return I(x.lo());
    if (!(std::isfinite(x.lo()) && std::isfinite(x.hi()))) return undecided();
    return I::range(x.lo(), x.hi());
}
inline V enclose(const Vec3<Interval>& v) { return {enclose(v[0]), enclose(v[1]), enclose(v[2])}; }
inline V lift(const Vec3<double>& v) { return {I(v[0]), I(v[1]), I(v[2])}; }
// Every value in [−m, m] (m ≥ 0; NaN or ∞: undecided).
inline I symmetric(double m) {
    if (!std::isfinite(m)) return undecided();
    return I::range(-m, m);
}

// A value and its derivative in s, both enclosed.
struct Dual {
    I v, d;
};
inline Dual operator+(const Dual& a, const Dual& b) { return {a.v + b.v, a.d + b.d}; }
inline Dual operator-(const Dual& a, const Dual& b) { return {a.v - b.v, a.d - b.d}; }

// The operations H needs on either scalar: values alone (I) or values and derivatives (Dual).
inline I times(const I& x, const I& y) { return x * y; }
inline Dual times(const Dual& x, const I& y) { return {x.v * y, x.d * y}; }
inline I negated(const I& x) { return -x; }
inline Dual negated(const Dual& x) { return {-x.v, -x.d}; }
// √x of a quantity known to be ≥ 0, enclosed even where x's enclosure reaches 0 or below (sqrt itself
// declines there): [0, √(upper bound)].
inline I root(const I& x) {
    if (x.exact_zero()) return I(0.0);
    if (x.lo() > 0) return sqrt(x);
    const double hi = x.hi();
    if (!(hi >= 0)) return hi <= 0 ? I(0.0) : x;  // NaN stays NaN
    return I::range(0, boxcyl::detail::next_up(std::sqrt(hi)));
}
inline I magnitude(const I& x) { return enclosure_abs(x); }
// |x|: where x may vanish, the slope enclosure [−|x′|, |x′|], which holds both one-sided slopes.
inline Dual magnitude(const Dual& x) {
    if (x.v.lo() >= 0) return x;
    if (x.v.hi() <= 0) return negated(x);
    const double m = std::max(-x.d.lo(), x.d.hi());
    return {enclosure_abs(x.v), symmetric(m)};
}
template <class S>
S inner(const Vec3<S>& a, const V& b) {
    return times(a[0], b[0]) + times(a[1], b[1]) + times(a[2], b[2]);
}

// The Minkowski difference's support function, and the vectors it is evaluated on.
struct Problem {
    V z;                  // box centre − cylinder centre
    std::array<V, 3> h;   // the box's half axes
    V u;                  // the unit axis, enclosed
    I r, k;               // radius, half height
};

// |(c0, c1, c2)|: where it may vanish (v along the axis), the derivative enclosure [−|c′|, |c′|] (the
// norm's generalized gradient), not the quotient, which would be unbounded there.
inline I norm(const I& c0, const I& c1, const I& c2) { return root(c0 * c0 + c1 * c1 + c2 * c2); }
inline Dual norm(const Dual& c0, const Dual& c1, const Dual& c2) {
    const I n = norm(c0.v, c1.v, c2.v);
    if (n.lo() > 0) {
        // The quotient declines (NaN) where n's bound is not below half its value.
        const I slope = (c0.v * c0.d + c1.v * c1.d + c2.v * c2.d) / n;
        if (slope.lo() == slope.lo() && slope.hi() == slope.hi()) return {n, slope};
    }
    const double m = norm(c0.d, c1.d, c2.d).hi();
    return {n, symmetric(m)};
}

// H(v), and its derivative along the arc for Dual. Each term is convex in v (a linear form, the
// magnitude of one, the norm of a linear map), so H is convex along every line of vectors.
template <class S>
S support(const Problem& p, const Vec3<S>& v) {
    S H = inner(v, p.z);
    for (const V& h : p.h) H = H + magnitude(inner(v, h));
    H = H + times(magnitude(inner(v, p.u)), p.k);
    // |v × u| from the cross product's components, not as √(|v|² − (v·u)²): near v ∥ u (a circle
    // passing by the axis) that difference cancels.
    const S c0 = times(v[1], p.u[2]) - times(v[2], p.u[1]);
    const S c1 = times(v[2], p.u[0]) - times(v[0], p.u[2]);
    const S c2 = times(v[0], p.u[1]) - times(v[1], p.u[0]);
    return H + times(norm(c0, c1, c2), p.r);
}

// The linear forms of H at a vector x: x·hᵢ (i < 3), x·u, x·z, and x × u.
struct Forms {
    std::array<I, 5> dots;
    V cross_u;
};
inline Forms forms(const Problem& p, const V& x) {
    return {{dot(x, p.h[0]), dot(x, p.h[1]), dot(x, p.h[2]), dot(x, p.u), dot(x, p.z)}, cross(x, p.u)};
}
inline Forms negated(const Forms& f) {
    return {{-f.dots[0], -f.dots[1], -f.dots[2], -f.dots[3], -f.dots[4]}, -f.cross_u};
}

// An arc of a circle: the directions of the vectors from + s·step, s ∈ [0, 1] (the shorter arc
// between two directions less than a half turn apart).
// Along it every linear form of v is affine in s, and v × u too: their values at the ends and slopes
// (the forms at `to` less those at `from`: the forms are linear) are formed once per arc, from the
// forms of its ends, so that each point costs a product and a sum per form.
struct Arc {
    Arc(const V& from_, const V& to, const Forms& at_from, const Forms& at_to)
        : from(from_), step(to - from_), F(at_from.cross_u), G(at_to.cross_u - at_from.cross_u) {
        for (std::size_t i = 0; i < 5; ++i) at0[i] = at_from.dots[i], slope[i] = at_to.dots[i] - at_from.dots[i];
    }
    V from, step;
    std::array<I, 5> at0, slope;  // v·hᵢ (i < 3), v·u, v·z at s = 0, and their slopes
    V F, G;                       // v × u = F + s·G
};

// H and its slope along an arc at a point where the forms are `at` and v × u is `c`, the arc's slopes
// being `slope` and G.
inline Dual support_at(const Problem& p, const std::array<I, 5>& at, const V& c, const std::array<I, 5>& slope, const V& G) {
    auto form = [&](std::size_t i) { return Dual{at[i], slope[i]}; };
    Dual H = form(4);
    for (std::size_t i = 0; i < 3; ++i) H = H + magnitude(form(i));
    H = H + times(magnitude(form(3)), p.k);
    return H + times(norm(Dual{c[0], G[0]}, Dual{c[1], G[1]}, Dual{c[2], G[2]}), p.r);
}
// H(v(s)) and its slope along the arc.
inline Dual support_along(const Problem& p, const Arc& arc, double s) {
    const I t(s);
    std::array<I, 5> at;
    for (std::size_t i = 0; i < 5; ++i) at[i] = arc.at0[i] + t * arc.slope[i];
    const V c{arc.F[0] + t * arc.G[0], arc.F[1] + t * arc.G[1], arc.F[2] + t * arc.G[2]};
    return support_at(p, at, c, arc.slope, arc.G);
}

inline Vec3<double> mid(const V& v) {
    return {0.5 * v[0].lo() + 0.5 * v[0].hi(), 0.5 * v[1].lo() + 0.5 * v[1].hi(), 0.5 * v[2].lo() + 0.5 * v[2].hi()};
}

// The circle ⊥ x (x a nonzero double vector) as four quarter arcs between ±a, ±b, a basis a ⊥ b of the
// plane (x × e, e the coordinate axis x leans on least, and x × a), appended in order round the circle:
// each ends where the next (cyclically) starts. H's kinks on it (where v·hᵢ or v·u
// changes sign: x × hᵢ, x × u) lie inside the arcs: the tangent bound below meets a kink where the two
// sides' tangents cross. They are common minimizers (faces, edges across the axis), so `kinks` receives
// them to be tried first as upper bounds.
inline void add_arcs(const Problem& p, const Vec3<double>& x, std::vector<Arc>& arcs, std::vector<V>& kinks) {
    int k = 0;
    for (int i = 1; i < 3; ++i)
        if (std::abs(x[i]) < std::abs(x[k])) k = i;
    Vec3<double> e{0, 0, 0};
    e[k] = 1;
    const V X = lift(x);
    const V a = cross(X, lift(e));
    const V b = cross(X, a);
    const Forms A = forms(p, a), B = forms(p, b), minus_A = negated(A), minus_B = negated(B);
    arcs.emplace_back(a, b, A, B), arcs.emplace_back(b, -a, B, minus_A), arcs.emplace_back(-a, -b, minus_A, minus_B),
        arcs.emplace_back(-b, a, minus_B, A);
    for (const V& w : p.h) {
        const V c = cross(X, w);
        kinks.push_back(c), kinks.push_back(-c);
    }
    const V c = cross(X, p.u);
    kinks.push_back(c), kinks.push_back(-c);
}

struct Bounds {
    double lower = 0, upper = std::numeric_limits<double>::infinity();
    Vec3<double> normal{};  // the direction whose H gave `upper` (not unit; from the box towards the cylinder)
};

// What a piece of an arc keeps of each end: s, H and its derivative along the arc, and |v|.
struct End {
    double s;
    I H, dH, len;
};

// A proved lower bound of min over s in [a.s, b.s] of H(v(s)) − λ·|v(s)| (λ ≥ 0), by convexity: |v(s)|
// lies below the chord ℓ(s) between its ends' upper bounds, so H − λ·ℓ is convex and at most the
// function, and a convex function lies above its tangents at both ends; the least of the larger tangent
// is where they cross. `at`, when given, receives that crossing (where to split the piece).
inline double tangent_bound(const End& a, const End& b, double lambda, double* at = nullptr) {
    const double inf = std::numeric_limits<double>::infinity();
    const I la(a.len.hi()), lb(b.len.hi()), w = I(b.s) - I(a.s), L(lambda);
    const I slope = (lb - la) / w;
    const double A = (a.H - L * la).lo(), B = (b.H - L * lb).lo();
    double ga = (a.dH - L * slope).lo(), gb = (b.dH - L * slope).hi();  // below / above the one-sided slopes
    if (ga != ga) ga = -inf;
    if (gb != gb) gb = inf;
    if (A != A || B != B) return -inf;
    if (at) *at = 0.5 * a.s + 0.5 * b.s;
    if (ga >= 0) return A;
    if (gb <= 0) return B;
    if (ga == -inf && gb == inf) return -inf;
    if (ga == -inf) return (I(B) - I(gb) * w).lo();
    if (gb == inf) return (I(A) + I(ga) * w).lo();
    const I Ga(ga), Gb(gb);
    const I V = (w * Ga * Gb + Gb * I(A) - Ga * I(B)) / (Gb - Ga);
    if (at) *at = a.s + (V.lo() - A) / ga;
    return V.lo();
}

// The search's target width: 2⁻⁴⁴ of the problem's own length L (the largest of |z|∞, the half axes'
// components, r and k), and at least 8 times the width z and the half axes carry in from their own
// rounding (z = c − C is exact only where the centres are close). The tangent bounds at a piece's ends
// carry the enclosures of H, its slope and λ·ℓ, together up to about 2⁻⁴⁵·L wide: with a gap of 2⁻⁴⁵
// a piece at a smooth minimum often could not prove it, the search ended on it split down to single
// doubles, and every piece still open took a bisection on λ (on bench_distance's overlapping pairs
// about a dozen a query; with 2⁻⁴⁴, one or two). The stated width, 2⁻⁴³·L, leaves room for the upper
// bound's own enclosure.
inline double target_gap(const Problem& p) {
    double L = std::max(p.r.hi(), p.k.hi()), carried = 0;
    auto take = [&](const V& v) {
        for (int i = 0; i < 3; ++i) {
            L = std::max({L, std::abs(v[i].lo()), std::abs(v[i].hi())});
            carried = std::max(carried, v[i].hi() - v[i].lo());
        }
    };
    take(p.z);
    for (const V& h : p.h) take(h);
    const double relative = L > 0 && std::isfinite(L) ? std::ldexp(1.0, std::ilogb(L) - 44) : 0;
    return std::max({relative, 8 * carried, std::numeric_limits<double>::denorm_min()});
}

// `circles`: the nonzero double vectors whose perpendicular circles are searched (the axis D and the
// box's edge directions). The lower bound proved is the best upper bound less target_gap (or the least
// of what ±u and the pieces left prove). `budget`: the most pieces split.
inline Bounds bounds(const Problem& p, const std::vector<Vec3<double>>& circles, int budget = 2000) {
    const double gap = target_gap(p);
    Bounds out;
    auto lower_of = [](const I& x) { return x.lo() == x.lo() ? x.lo() : -std::numeric_limits<double>::infinity(); };
    auto try_upper = [&](const I& F, const V& n) {
        if (F.hi() < out.upper) out.upper = F.hi(), out.normal = mid(n);  // NaN never wins
    };
    double lower = std::numeric_limits<double>::infinity();
    for (double sign : {1.0, -1.0}) {  // ±u: a vertex against a cap
        // H(±u) = ±u·z + Σ|u·hᵢ| + k exactly (|u·u| = 1, u × u = 0): the general form's |u × u| would
        // turn u's rounding into a width of its square root's.
        const V n{I(sign) * p.u[0], I(sign) * p.u[1], I(sign) * p.u[2]};
        I H = dot(n, p.z) + p.k;
        for (const V& h : p.h) H = H + enclosure_abs(dot(p.u, h));
        lower = std::min(lower, lower_of(H));
        try_upper(H, n);
    }
    std::vector<Arc> arcs;
    std::vector<V> kinks;
    for (const Vec3<double>& x : circles) add_arcs(p, x, arcs, kinks);
    {  // the kinks ranked by H in double (a guess), the best enclosed: one certified upper bound, not 32
        const Vec3<double> z = mid(p.z), u = mid(p.u);
        const std::array<Vec3<double>, 3> h{mid(p.h[0]), mid(p.h[1]), mid(p.h[2])};
        const double r = 0.5 * p.r.lo() + 0.5 * p.r.hi(), k = 0.5 * p.k.lo() + 0.5 * p.k.hi();
        auto guess = [&](const Vec3<double>& v) {
            const Vec3<double> vxu = cross(v, u);
            return (dot(v, z) + std::abs(dot(v, h[0])) + std::abs(dot(v, h[1])) + std::abs(dot(v, h[2])) + k * std::abs(dot(v, u)) +
                    r * std::sqrt(dot(vxu, vxu))) / std::sqrt(dot(v, v));
        };
        const V* best = nullptr;
        double least = std::numeric_limits<double>::infinity();
        for (const V& n : kinks) {
            const double g = guess(mid(n));
            if (g < least) least = g, best = &n;
        }
        if (best) try_upper(support(p, *best) / norm((*best)[0], (*best)[1], (*best)[2]), *best);
    }

    auto end_at = [&](const Arc& arc, double s) {
        const I t(s);
        const V v{arc.from[0] + t * arc.step[0], arc.from[1] + t * arc.step[1], arc.from[2] + t * arc.step[2]};
        const Dual H = support_along(p, arc, s);
        const I len = norm(v[0], v[1], v[2]);
        try_upper(H.v / len, v);
        return End{s, H.v, H.d, len};
    };
    struct Piece {
        double priority;  // the tangent bound when it was made, over the longer |v|: lowest first
        double lambda;    // the λ it failed when it was made, and where its tangents crossed then
        double at;
        std::size_t arc;
        End a, b;
        bool operator>(const Piece& o) const { return priority > o.priority; }
    };
    std::priority_queue<Piece, std::vector<Piece>, std::greater<>> pieces;
    auto lambda = [&] { return out.upper - gap; };
    auto push = [&](std::size_t arc, const End& a, const End& b) {
        const double l = std::max(0.0, lambda());
        double at = 0;
        const double t = tangent_bound(a, b, l, &at);
        if (t >= 0) return;  // proved: H ≥ λ·|v| over the piece
        pieces.push({t / std::max(a.len.hi(), b.len.hi()), l, at, arc, a, b});
    };
    // The arcs' own ends: the forms there are those an arc starts with (its end is where the next arc
    // of its circle starts), with no products by s.
    auto end_of = [&](const Arc& arc, const Arc& starting_there, double s) {
        const Dual H = support_at(p, starting_there.at0, starting_there.F, arc.slope, arc.G);
        const V& v = starting_there.from;
        const I len = norm(v[0], v[1], v[2]);
        try_upper(H.v / len, v);
        return End{s, H.v, H.d, len};
    };
    for (std::size_t i = 0; i < arcs.size(); ++i)
        push(i, end_of(arcs[i], arcs[i], 0.0), end_of(arcs[i], arcs[i % 4 == 3 ? i - 3 : i + 1], 1.0));
    int splits = 0;
    while (!pieces.empty() && lambda() > 0) {
        const Piece top = pieces.top();
        double at = top.at;  // λ unchanged since it was made: it still fails, its tangents cross there
        if (top.lambda != lambda() && tangent_bound(top.a, top.b, lambda(), &at) >= 0) {  // proved since, by a lower λ
            pieces.pop();
            continue;
        }
        const double w = top.b.s - top.a.s;
        at = std::clamp(at, top.a.s + 0.0625 * w, top.b.s - 0.0625 * w);
        if (splits >= budget || !(top.a.s < at && at < top.b.s)) break;
        pieces.pop();
        ++splits;
        const End m = end_at(arcs[top.arc], at);
        push(top.arc, top.a, m);
        push(top.arc, m, top.b);
    }
    if (lambda() <= 0) {
        lower = 0;  // the solids intersect: the depth is at least 0
    } else {
        // The pieces left (by the budget, or behind one too narrow to split) lower λ to the least that
        // each proves: found by bisection on λ (the bound falls as λ grows) to within 2^-6 of the gap,
        // first between λ − 4·gap and λ (where a piece at a minimum falls), from 0 where that does not prove.
        double proved = lambda();
        auto lower_to = [&](const Piece& q) {
            if (tangent_bound(q.a, q.b, proved) >= 0) return true;
            double lo = std::max(0.0, proved - 4 * gap), hi = proved;
            if (tangent_bound(q.a, q.b, lo) < 0) {
                if (lo == 0 || tangent_bound(q.a, q.b, 0.0) < 0) return false;
                lo = 0;
            }
            while (hi - lo > 0x1p-6 * gap) {
                const double m = 0.5 * lo + 0.5 * hi;
                if (m <= lo || m >= hi) break;
                (tangent_bound(q.a, q.b, m) >= 0 ? lo : hi) = m;
            }
            proved = lo;
            return true;
        };
        bool all = true;
        for (; all && !pieces.empty(); pieces.pop()) all = lower_to(pieces.top());
        lower = std::min(lower, all ? proved : 0.0);
    }
    out.lower = std::max(0.0, lower);
    return out;
}

}  // namespace boxcyl::filtered::depth
