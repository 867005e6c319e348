// The linear-inequalities method on enclosures of the exact problem, and the hit certificates that go
// with it: stage 1 (N = Bounded, a double with a running error bound; N = Interval, outward-rounded)
// and the middle stage (N = DoubleDouble, round to nearest only). The generic code
// algo::linear_inequalities<N> runs inside an UncertaintyScope: if no comparison was undecided, every
// real problem inside the enclosures takes the same branches to the same answer, and the exact problem
// is one of them (docs/pipeline.md, docs/robustness/enclosures.md).
//
// Every row that uses this header is a function of the prepared query (filtered/prepared.hpp): the
// problem is built once per enclosure type from its facts (the scale, the frame).
#pragma once

#include <algorithm>  // std::min, std::max
#include <cmath>      // std::ldexp, std::fabs
#include <limits>     // infinity
#include <optional>   // undecided
#include <type_traits>  // std::is_same_v

#include "boxcyl/algo/linear_inequalities.hpp"
#include "boxcyl/filtered/clipped_candidates.hpp"
#include "boxcyl/filtered/prepared.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/reduce.hpp"
#include "boxcyl/number/bounded.hpp"
#include "boxcyl/number/double_double.hpp"
#include "boxcyl/number/interval.hpp"

namespace boxcyl::filtered::enclosed {

// ---- Enclosures of the inputs ----

// An upper bound of |x| for every x in the enclosure (NaN stays NaN and is caught by the callers).
template <class N>
double magnitude(const N& x) {
    return std::max(-x.lo(), x.hi());
}
// The exact value x·2^k: a point when the product is exact (it rounds only into the subnormal range,
// or overflows), otherwise the result widened by one double each way, which encloses it in every
// rounding mode. The check is exact: scaling back up by 2^-k cannot round.
template <class N>
N scaled(double x, int k) {
    if (k == 0) return N(x);
    const double y = k == -1 ? x * 0.5 : std::ldexp(x, k);  // one rounding (the common h/2: no call)
    if (std::ldexp(y, -k) == x) return N(y);
    return N::range(boxcyl::detail::next_down(y), boxcyl::detail::next_up(y));
}
// The same for a quantity known to be ≥ 0 (sizes): the lower bound is clamped at 0 (still ≤ x·2^k).
template <class N>
N nonneg(const N& x) {
    if (x.lo() >= 0) return x;
    return N::range(0.0, x.hi());
}
template <class N>
N scaled_nonneg(double x, int k) {
    return nonneg(scaled<N>(x, k));
}
template <class N>
Vec3<N> scaled(const Vec3<double>& v, int k) {
    return {scaled<N>(v[0], k), scaled<N>(v[1], k), scaled<N>(v[2], k)};
}
// |v|² as a sum of squares of magnitudes: never below 0, also for components that straddle 0.
template <class N>
N norm2(const Vec3<N>& v) {
    const N a = abs_value(v[0]), b = abs_value(v[1]), c = abs_value(v[2]);
    return a * a + b * b + c * c;
}
// An enclosure of v/|v| (|v| bounded away from 0 by the caller).
template <class N>
Vec3<N> normalised(const Vec3<N>& v) {
    const N len = sqrt(norm2(v));
    return {v[0] / len, v[1] / len, v[2] / len};
}
// The cylinder axis scaled by a power of two when its largest component is beyond 2^±500, so that a·a
// can neither overflow nor lose the whole axis to underflow (a direction: any positive multiple will do).
template <class N>
Vec3<N> prescaled_axis(const Vec3<double>& axis) {
    double m = 0;
    update_max(m, axis);
    int e = m > 0 ? std::ilogb(m) : 0;  // m = 0 only for a zero axis (invalid): no INT_MIN to negate
    if (e >= -500 && e <= 500) e = 0;  // a·a cannot overflow; underflow of tiny terms is accounted for
    return scaled<N>(axis, -e);
}
// An enclosure of the exact unit axis u = axis/|axis|. An axis with one non-zero component gives the
// exact ±1 (the common axis-aligned cylinder keeps exact values; nothing rounds).
template <class N>
Vec3<N> unit_direction(const Vec3<double>& axis) {
    int nonzero = 0, which = 0;
    for (int i = 0; i < 3; ++i)
        if (axis[i] != 0) ++nonzero, which = i;
    if (nonzero == 1) {
        Vec3<N> d{N(0), N(0), N(0)};
        d[which] = N(axis[which] > 0 ? 1.0 : -1.0);
        return d;
    }
    return normalised(prescaled_axis<N>(axis));
}

// A test of enclosures counts only when every comparison in it was decided.
template <class Test>
bool certainly(Test&& test) {
    UncertaintyScope scope;
    const bool ok = test();
    return ok && scope.certain();
}

// ---- The linear-inequalities method, and certificates where it cannot decide ----

// The method on the enclosed problem: the answer if every comparison was decided, else nullopt.
template <class N>
std::optional<bool> run_li(const CanonicalQuery<N>& q) {
    UncertaintyScope scope;
    const bool answer = algo::linear_inequalities(q.box, q.cylinder);
    if (!scope.certain()) return std::nullopt;
    return answer;
}

// A size (extent, radius, half-height) that may be below δ replaced by max(size, δ): an enclosure of
// a problem that contains the exact one.
template <class N>
bool thicken(N& size, double delta) {
    if (size.lo() >= delta) return false;
    size = N::range(std::max(size.lo(), delta), std::max(size.hi(), delta));
    return true;
}

// A cheap certificate of a miss ahead of the method: the box axes U_i separate when
// |c_i| − e_i − H|d_i| > r·√(d_j² + d_k²) (the cylinder's extent along U_i, √(1 − d_i²) written without
// cancellation): that left side s > 0 and s² > r²(d_j² + d_k²).
template <class N>
bool apart_along_box_axes(const CanonicalQuery<N>& q) {
    UncertaintyScope scope;
    const Vec3<N>& c = q.cylinder.center;
    const Vec3<N>& d = q.cylinder.direction;
    const Vec3<N>& e = q.box.extents;
    const N& H = q.cylinder.half_height;
    const N r2 = q.cylinder.radius * q.cylinder.radius;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        const N s = abs_value(c[i]) - e[i] - H * abs_value(d[i]);
        if (N(0) < s && r2 * (d[j] * d[j] + d[k] * d[k]) < s * s) return scope.certain();
    }
    return false;
}

// Hit certificates for flat shapes (disks, flat boxes, segments), whose branches in the method compare
// rounding noise but whose hits usually have a witness far from touching (docs/robustness/degenerate.md):
//   (a) the axis itself: {c + t·d} ∩ box reaches [−H, H];
//   (b) a chord {Q + t·d} through a box point Q near c whose distance to the axis line is < r, reaching
//       the slab: for every i with d_i ≠ 0, a_i = (−e_i − Q_i)/d_i ≤ H − s and b_i = (e_i − Q_i)/d_i ≥
//       −H − s (swapped if d_i < 0), s = d·(Q − c): pairwise comparisons only, no min/max to decide.
template <class N>
bool chord_reaches_slab(const CanonicalQuery<N>& q, const Vec3<N>& point, const Vec3<N>& diff, bool on_axis) {
    const Vec3<N>& d = q.cylinder.direction;
    const Vec3<N>& e = q.box.extents;
    const N& H = q.cylinder.half_height;
    const N s = on_axis ? N(0) : dot(d, diff);  // diff = point − c
    N a[3], b[3];
    bool used[3] = {false, false, false};
    for (int i = 0; i < 3; ++i) {
        if (d[i].lo() == 0 && d[i].hi() == 0) {  // exactly parallel to the face pair: no bound on t
            if (on_axis && !(abs_value(point[i]) <= e[i])) return false;  // (b): Q is in the box
            continue;
        }
        const N lo = (-e[i] - point[i]) / d[i], hi = (e[i] - point[i]) / d[i];
        const bool positive = N(0) < d[i];
        a[i] = positive ? lo : hi;
        b[i] = positive ? hi : lo;
        used[i] = true;
    }
    for (int i = 0; i < 3; ++i) {
        if (!used[i]) continue;
        if (!(a[i] <= H - s) || !(-H - s <= b[i])) return false;
        for (int j = 0; j < 3; ++j)  // (a): the axis line's entry and exit; (b): holds (Q in the box)
            if (on_axis && used[j] && j != i && !(a[i] <= b[j])) return false;
    }
    return true;
}
// (c) The cross-section through the axis point p meets the box: the point of (plane ∩ box) nearest to p
// is p itself (done by (a)), the foot on a side (face x_i = f: X = p + λ(E_i − d_i·d), λ = (f − p_i)/w_i,
// w_i = d_j² + d_k², within r iff (f − p_i)² < r²·w_i), or a vertex (an edge ∥ x_k crossing the plane).
// Each candidate is exactly a point of the plane, so one certainly in the box and the disk is a witness.
template <class N>
bool disk_meets_box(const CanonicalQuery<N>& q, const Vec3<N>& p) {
    const Vec3<N>& d = q.cylinder.direction;
    const Vec3<N>& e = q.box.extents;
    const N r2 = q.cylinder.radius * q.cylinder.radius;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        const N w = d[j] * d[j] + d[k] * d[k];
        if (!(w.lo() > 0)) continue;  // w = 0 exactly, or too small to divide by
        for (const N& f : {e[i], -e[i]})
            if (certainly([&] {
                    const N g = f - p[i];
                    if (!(g * g < r2 * w)) return false;
                    const N m = g * d[i] / w;
                    return abs_value(p[j] - m * d[j]) < e[j] && abs_value(p[k] - m * d[k]) < e[k];
                }))
                return true;
    }
    for (int k = 0; k < 3; ++k) {
        if (d[k].lo() == 0 && d[k].hi() == 0) continue;
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        for (const N& xi : {e[i], -e[i]})
            for (const N& xj : {e[j], -e[j]})
                if (certainly([&] {
                        const N gi = xi - p[i], gj = xj - p[j];
                        const N gk = -(d[i] * gi + d[j] * gj) / d[k];  // x_k − p_k
                        return abs_value(p[k] + gk) <= e[k] && gi * gi + gj * gj + gk * gk < r2;
                    }))
                    return true;
    }
    return false;
}

template <class N>
bool certain_hit(const CanonicalQuery<N>& q) {
    const Vec3<N>& c = q.cylinder.center;
    const Vec3<N>& e = q.box.extents;
    if (certainly([&] { return chord_reaches_slab(q, c, Vec3<N>{N(0), N(0), N(0)}, true); })) return true;
    if (disk_meets_box(q, c)) return true;
    return certainly([&] {
        if (!(N(0) < q.cylinder.radius)) return false;
        // Q: c clamped into the box, chosen from the enclosures without comparisons (any box point is a
        // valid start; an ambiguous coordinate takes the face it is nearest to, else 0).
        Vec3<N> point, diff;
        for (int i = 0; i < 3; ++i) {
            if (c[i].lo() >= -e[i].lo() && c[i].hi() <= e[i].lo()) {
                point[i] = c[i], diff[i] = N(0);
            } else if (c[i].lo() > 0) {
                point[i] = e[i], diff[i] = e[i] - c[i];
            } else if (c[i].hi() < 0) {
                point[i] = -e[i], diff[i] = -e[i] - c[i];
            } else {
                point[i] = N(0), diff[i] = -c[i];
            }
        }
        const N s = dot(q.cylinder.direction, diff);
        if (!(dot(diff, diff) - s * s < q.cylinder.radius * q.cylinder.radius)) return false;
        return chord_reaches_slab(q, point, diff, false);
    });
}

// The decision on an enclosure `outer` of a problem that contains the exact one (a miss of outer
// certifies a miss) and an enclosure `inner` of a problem contained in it (a hit of inner certifies a
// hit), or null if there is none. Usually both are the exact problem's enclosure (&inner == &outer).
//
// When undecided and a size may be 0 or nearly (flat box, segment, disk), the method meets degenerate
// clipped segments whose two ends are one point computed by two formulas: their difference is rounding
// noise of either sign. Thickening every size below δ = 2^-30·scale to δ gives a problem that still
// contains the exact one and is not degenerate: if it certainly misses, so does the exact problem.
// `scale` is the problem's largest length (after scaling).
template <class N>
std::optional<bool> decide(const CanonicalQuery<N>& outer, const CanonicalQuery<N>* inner, double scale) {
    if (apart_along_box_axes(outer)) return false;
    std::optional<bool> o;
    if (inner != nullptr && inner != &outer) {
        // Two problems (a rounded frame): most queries that get here are hits, which only the inner
        // problem certifies, so it goes first. Inner ⊂ exact ⊂ outer: the two cannot contradict.
        const std::optional<bool> i = run_li(*inner);
        if (i && *i) return true;
        o = run_li(outer);
        if (o && !*o) return false;
        if (certain_hit(*inner)) return true;
        if (o) return std::nullopt;  // outer meets, nothing certifies a hit
    } else {
        o = run_li(outer);
        if (o && (!*o || inner == &outer)) return o;
        if (o) return std::nullopt;  // outer meets, no inner problem
        if (inner != nullptr && certain_hit(*inner)) return true;
    }
    const double delta = std::ldexp(scale, -30);
    if (!(delta > 0)) return std::nullopt;
    CanonicalQuery<N> thick = outer;
    bool degenerate = thicken(thick.cylinder.radius, delta);
    degenerate |= thicken(thick.cylinder.half_height, delta);
    for (int i = 0; i < 3; ++i) degenerate |= thicken(thick.box.extents[i], delta);
    if (!degenerate) return std::nullopt;
    const std::optional<bool> t = run_li(thick);
    if (t && !*t) return false;
    return std::nullopt;
}

// The problem q with every cylinder size grown by `on_cyl` and every box extent by `on_box` (outer: it
// contains a solid pair that contains the exact one), and shrunk by the same (inner: contained in it;
// exists only if no size goes below 0). The sizes become points (a size enclosure would let the method
// see e − e ≠ 0 and lose the sign of every degenerate difference): outer sizes are rounded up after
// adding, inner ones down after subtracting.
template <class N>
struct Widened {
    CanonicalQuery<N> outer, inner;
    bool has_inner = true;
};
template <class N>
Widened<N> widen(const CanonicalQuery<N>& q, double on_cyl, double on_box) {
    Widened<N> w{q, q, true};
    auto up = [](const N& x, double by) { return N(by == 0 ? x.hi() : (N(x.hi()) + N(by)).hi()); };
    auto down = [&w](const N& x, double by) {
        if (by == 0) return N(x.lo());
        if (!(x.lo() >= by)) w.has_inner = false;
        return N(std::max(0.0, (N(x.lo()) - N(by)).lo()));
    };
    w.outer.cylinder.radius = up(q.cylinder.radius, on_cyl);
    w.outer.cylinder.half_height = up(q.cylinder.half_height, on_cyl);
    w.inner.cylinder.radius = down(q.cylinder.radius, on_cyl);
    w.inner.cylinder.half_height = down(q.cylinder.half_height, on_cyl);
    for (int i = 0; i < 3; ++i) {
        w.outer.box.extents[i] = up(q.box.extents[i], on_box);
        w.inner.box.extents[i] = down(q.box.extents[i], on_box);
    }
    return w;
}
// The decision on a widened pair of problems.
template <class N>
std::optional<bool> decide(const Widened<N>& w, double scale) {
    return decide(w.outer, w.has_inner ? &w.inner : nullptr, scale);
}

// ---- Tiny axis components (docs/robustness/enclosures.md) ----
//
// A non-zero component below 2^-30 of the largest is exact in the input but lost in the enclosures of the
// unit axis. With those components zeroed the axis turns by θ ≤ 2^-28, and the cylinder widened by
// η = θ(H + r) contains the exact one, narrowed by η is contained in it: the widened problem certifies
// misses, the narrowed one hits. The double-double form zeroes components below 2^-200 and takes every
// size as [s − η, s + η] instead (a decided answer holds for both problems; a hit only if every size is
// ≥ η). docs/robustness/enclosures.md has the derivation. False when η overflows; `thin` says whether
// some size was below η.
template <class N>
bool spread_sizes_by_eta(N& radius, N& half_height, bool& thin) {
    const double reach = (N(half_height.hi()) + N(radius.hi())).hi();
    const double eta = boxcyl::detail::next_up(0x1p-198 * reach);
    if (!(eta < std::numeric_limits<double>::infinity())) return false;
    thin = false;
    for (N* size : {&radius, &half_height}) {
        if (!(size->lo() >= eta)) thin = true;
        *size = nonneg(N(size->high(), size->low(), boxcyl::detail::next_up(size->error() + eta)));
    }
    return true;
}

// The method for the cylinder axis as given, after the zeroed axis where it has tiny components
// (`direction_of` turns a unit-axis enclosure into the box frame's direction, e.g. a signed permutation).
template <class N, class Frame>
std::optional<bool> decide_axis(CanonicalQuery<N> q, const Vec3<double>& a, Frame&& direction_of, double scale) {
    Vec3<double> a0;
    if constexpr (std::is_same_v<N, DoubleDouble>) {
        if (tiny_components_zeroed(a, a0, -200)) {
            CanonicalQuery<N> z = q;
            z.cylinder.direction = direction_of(unit_direction<N>(a0));
            bool thin = false;
            if (spread_sizes_by_eta(z.cylinder.radius, z.cylinder.half_height, thin)) {
                const std::optional<bool> r = decide(z, &z, scale);
                if (r && (!*r || !thin)) return r;
                // Undecided with every size ≥ η: within about 2η of touching, far below what
                // double-double on the axis as given resolves. The exact stage answers.
                if (!thin) return std::nullopt;
            }
        }
    } else if (tiny_components_zeroed(a, a0, -30)) {
        CanonicalQuery<N> z = q;
        z.cylinder.direction = direction_of(unit_direction<N>(a0));
        const double reach = (N(q.cylinder.half_height.hi()) + N(q.cylinder.radius.hi())).hi();
        const double eta = (N(0x1p-28) * N(reach)).hi();
        if (eta < std::numeric_limits<double>::infinity())
            if (const std::optional<bool> r = decide(widen(z, eta, 0.0), scale)) return r;
    }
    q.cylinder.direction = direction_of(unit_direction<N>(a));
    return decide(q, &q, scale);
}

// ---- Rotated frames: the real frame A is only nearly orthonormal ----

// The η-widening of a nearly orthonormal frame A (docs/robustness/frames.md): with g ≥ ‖AᵀA − I‖₂, the
// canonical problem C' = Aᵀ(C − K), d' = Aᵀu/|Aᵀu| widened by η = g·(|e|₁ + |C − K|₁ + 2H + 2r) —
// a ≤ min(r, H) of it on the cylinder, the rest on the box — misses only if the exact one does, and
// narrowed by η meets only if the exact one does. `frame` is A (enclosed), `axis` any positive multiple
// of u; nullopt when g > 2^-10 or η overflows. The widening is a policy so that tests can drop it.
struct ProvedWidening {
    static double eta(double bound) { return bound; }
};
template <class N, class Widening = ProvedWidening>
std::optional<Widened<N>> frame_problem(const Vec3<N> (&frame)[3], const Vec3<N>& delta, const Vec3<N>& extents,
                                        const Vec3<N>& axis, const N& radius, const N& half_height) {
    double g = 0;
    for (int i = 0; i < 3; ++i) {
        N row(0);
        for (int j = 0; j < 3; ++j) {
            N gij = dot(frame[i], frame[j]);
            if (i == j) gij -= N(1);
            row += N(magnitude(gij));
        }
        g = std::max(g, row.hi());
    }
    if (!(g <= 0x1p-10)) return std::nullopt;  // validate() allows |G_ij| ≤ 1e-4; the derivation needs g < 1
    CanonicalQuery<N> q;
    Vec3<N> v;
    for (int i = 0; i < 3; ++i) {
        q.cylinder.center[i] = dot(frame[i], delta);
        v[i] = dot(frame[i], axis);
    }
    q.cylinder.direction = normalised(v);  // encloses Aᵀu/|Aᵀu|
    q.cylinder.radius = radius;
    q.cylinder.half_height = half_height;
    q.box.extents = extents;
    N lengths(0);
    for (int i = 0; i < 3; ++i) lengths += N(magnitude(extents[i])) + N(magnitude(delta[i]));
    lengths += N(2) * N(magnitude(half_height)) + N(2) * N(magnitude(radius));
    const double eta = Widening::eta((N(g) * lengths).hi());
    if (!(eta < std::numeric_limits<double>::infinity())) return std::nullopt;
    const double on_cyl = std::min(std::min(radius.lo(), half_height.lo()), eta);
    const double on_box = on_cyl == eta ? 0.0 : (N(eta) - N(on_cyl)).hi();
    return widen(q, on_cyl, on_box);
}

// Hit certificates for the parallelepiped {K + Σ x_m·A_m : |x_m| ≤ e_m} with the axes exactly as given
// (no η: where η leaves no inner problem — flat boxes, disks — these certify hits without exact
// arithmetic; docs/robustness/degenerate.md). Each candidate point solves a linear system by
// construction, so only inequalities are checked: (a) C in the box, or the axis segment crossing a face;
// (c) a cross-section meeting a box edge or a face.
template <class N>
N det3(const Vec3<N>& a, const Vec3<N>& b, const Vec3<N>& c) {
    return dot(a, cross(b, c));
}
template <class N>
bool frame_disk_hit(const Vec3<N>& delta, const Vec3<N> (&A)[3], const Vec3<N>& e, const Vec3<N>& u, const N& r) {
    auto nonzero = [](const N& x) { return N(0) < abs_value(x); };
    const N r2 = r * r;
    const N D[3] = {dot(u, A[0]), dot(u, A[1]), dot(u, A[2])};
    const N ud = dot(u, delta);
    // Edges ∥ A_k at (x_i, x_j) = (±e_i, ±e_j): x_k = (u·delta − x_i·D_i − x_j·D_j)/D_k.
    for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        for (const N& xi : {e[i], -e[i]})
            for (const N& xj : {e[j], -e[j]})
                if (certainly([&] {
                        if (!nonzero(D[k])) return false;
                        const N xk = (ud - xi * D[i] - xj * D[j]) / D[k];
                        const Vec3<N> v = xi * A[i] + xj * A[j] + xk * A[k] - delta;  // X − C
                        return abs_value(xk) <= e[k] && dot(v, v) < r2;
                    }))
                    return true;
    }
    // Faces x_i = f: the plane cuts the face's plane along D_j·y + D_k·z = ρ = u·delta − f·D_i; its point
    // (y0, z0) = ρ·(D_j, D_k)/(D_j² + D_k²), direction L = D_k·A_j − D_j·A_k (⊥ u), and the point nearest
    // to C at λ = −L·V0/(L·L), V0 = X0 − C.
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        for (const N& f : {e[i], -e[i]})
            if (certainly([&] {
                    const N n = D[j] * D[j] + D[k] * D[k];
                    if (!(N(0) < n)) return false;
                    const N rho = ud - f * D[i];
                    const N y0 = rho * D[j] / n, z0 = rho * D[k] / n;
                    const Vec3<N> L = D[k] * A[j] - D[j] * A[k];
                    const N ll = dot(L, L);
                    if (!(N(0) < ll)) return false;
                    const Vec3<N> v0 = f * A[i] + y0 * A[j] + z0 * A[k] - delta;
                    const N lambda = -dot(L, v0) / ll;
                    const Vec3<N> v = v0 + lambda * L;
                    return abs_value(y0 + lambda * D[k]) <= e[j] && abs_value(z0 - lambda * D[j]) <= e[k] &&
                           dot(v, v) < r2;
                }))
                return true;
    }
    return false;
}
template <class N>
bool frame_hit(const Vec3<N>& delta, const Vec3<N> (&A)[3], const Vec3<N>& e, const Vec3<N>& u, const N& H,
               const N& r) {
    auto nonzero = [](const N& x) { return N(0) < abs_value(x); };
    if (certainly([&] {  // (a) C inside: x = A⁻¹·delta
            const N det = det3(A[0], A[1], A[2]);
            if (!nonzero(det)) return false;
            return abs_value(det3(delta, A[1], A[2]) / det) <= e[0] && abs_value(det3(A[0], delta, A[2]) / det) <= e[1] &&
                   abs_value(det3(A[0], A[1], delta) / det) <= e[2];
        }))
        return true;
    const Vec3<N> mu = -u;
    for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        for (const N& f : {e[k], -e[k]})
            if (certainly([&] {
                    const N det = det3(A[i], A[j], mu);
                    if (!nonzero(det)) return false;
                    const Vec3<N> rhs = delta - f * A[k];
                    return abs_value(det3(rhs, A[j], mu) / det) <= e[i] && abs_value(det3(A[i], rhs, mu) / det) <= e[j] &&
                           abs_value(det3(A[i], A[j], rhs) / det) <= H;
                }))
                return true;
    }
    if (!certainly([&] { return N(0) < r; })) return false;
    // (c) the cross-sections at t = 0 (the central disk), at the box centre's level t = −u·delta when that
    // is certainly within [−H, H], and at the end caps t = ±H: each is a subset of the cylinder.
    const N tk = -dot(u, delta);
    const bool level = certainly([&] { return abs_value(tk) <= H; });
    const N heights[4] = {N(0), tk, H, -H};
    for (int h = 0; h < 4; ++h)
        if ((h != 1 || level) && frame_disk_hit(delta + heights[h] * u, A, e, u, r)) return true;
    return false;
}

// ---- The rows: the method on each box kind's enclosed problem ----

// The canonical problem of an aligned or canonical box, or of an oriented box whose frame is a signed
// permutation (C' = Aᵀ(C − K) and d' = Aᵀu are exact permutations of enclosures): every length times
// 2^k, and the map from the world's unit axis to the box frame's.
template <class N>
CanonicalQuery<N> sizes(const Cylinder<double>& c, int k) {
    CanonicalQuery<N> q;
    q.cylinder.radius = scaled_nonneg<N>(c.radius, k);
    q.cylinder.half_height = scaled_nonneg<N>(c.height, k - 1);  // h/2 exactly, unless subnormal
    return q;
}
template <class N>
std::optional<bool> inequalities(const CanonicalBox<double>& b, const Cylinder<double>& c, int k, double scale) {
    CanonicalQuery<N> q = sizes<N>(c, k);
    for (int i = 0; i < 3; ++i) {
        q.box.extents[i] = scaled_nonneg<N>(b.extents[i], k);
        q.cylinder.center[i] = scaled<N>(c.center[i], k);
    }
    return decide_axis(q, c.axis, [](const Vec3<N>& d) { return d; }, scale);
}
// K = (min + max)/2, E = (max − min)/2, C − K, all enclosed. Halving first keeps finite inputs from
// overflowing; a flat side (min == max) keeps E = 0 and K = min exact.
template <class N>
std::optional<bool> inequalities(const AlignedBox<double>& b, const Cylinder<double>& c, int k, double scale) {
    CanonicalQuery<N> q = sizes<N>(c, k);
    for (int i = 0; i < 3; ++i) {
        N center, extent;
        if (b.min[i] == b.max[i]) {
            center = scaled<N>(b.min[i], k);
            extent = N(0);
        } else {
            const N lo = scaled<N>(b.min[i], k - 1), hi = scaled<N>(b.max[i], k - 1);
            center = lo + hi;
            extent = nonneg(hi - lo);
        }
        q.box.extents[i] = extent;
        q.cylinder.center[i] = scaled<N>(c.center[i], k) - center;
    }
    return decide_axis(q, c.axis, [](const Vec3<N>& d) { return d; }, scale);
}
template <class N, class Widening = ProvedWidening>
std::optional<bool> inequalities(const OrientedBox<double>& b, const Cylinder<double>& c, int k, double scale,
                                 const std::optional<SignedPermutation>& frame) {
    Vec3<N> delta, extents;
    for (int i = 0; i < 3; ++i) {
        delta[i] = scaled<N>(c.center[i], k) - scaled<N>(b.center[i], k);
        extents[i] = scaled_nonneg<N>(b.extents[i], k);
    }
    CanonicalQuery<N> q = sizes<N>(c, k);
    if (frame) {
        const SignedPermutation f = *frame;
        auto permuted = [&f](const Vec3<N>& u) {
            Vec3<N> d;
            for (int i = 0; i < 3; ++i) d[i] = f.sign[i] > 0 ? u[f.perm[i]] : -u[f.perm[i]];
            return d;
        };
        q.cylinder.center = permuted(delta);
        q.box.extents = extents;
        return decide_axis(q, c.axis, permuted, scale);
    }
    Vec3<N> axes[3];
    for (int i = 0; i < 3; ++i) axes[i] = {N(b.axes[i][0]), N(b.axes[i][1]), N(b.axes[i][2])};
    const Vec3<N> a = prescaled_axis<N>(c.axis);
    const auto w = frame_problem<N, Widening>(axes, delta, extents, a, q.cylinder.radius, q.cylinder.half_height);
    if (!w) return std::nullopt;
    if (const std::optional<bool> r = decide(*w, scale)) return r;
    if (frame_hit(delta, axes, extents, normalised(a), q.cylinder.half_height, q.cylinder.radius)) return true;
    return std::nullopt;
}

// The row's certifier: the method on N enclosures of the prepared query.
template <class N, class Box>
std::optional<bool> inequalities(Prepared<Box>& q) {
    const auto& f = q.facts();
    const double scale = std::ldexp(f.scale, f.k);
    if constexpr (is_oriented<Box>)
        return inequalities<N>(q.box, q.cyl, f.k, scale, f.frame);
    else
        return inequalities<N>(q.box, q.cyl, f.k, scale);
}

// ---- The middle stage's other method (round to nearest; double-double enclosures) ----

// The box's part of the clipped-candidates problem (filtered/clipped_candidates.hpp): G = K − C and the
// half-edge vectors, for each box kind (every length times 2^k).
template <class N, class Box>  // OrientedBox, Parallelepiped: the axes exactly as given
void clipped_box(const Box& b, const Cylinder<double>& c, int k, clipped::Problem<N>& p) {
    for (std::size_t i = 0; i < 3; ++i) {
        p.G[i] = scaled<N>(b.center[i], k) - scaled<N>(c.center[i], k);
        const N e = scaled_nonneg<N>(b.extents[i], k);
        for (std::size_t j = 0; j < 3; ++j) p.a[i][j] = e * N(b.axes[i][j]);
        p.zero[i] = b.extents[i] == 0;
    }
}
template <class N>
void clipped_box(const AlignedBox<double>& b, const Cylinder<double>& c, int k, clipped::Problem<N>& p) {
    for (std::size_t i = 0; i < 3; ++i) {
        const N lo = scaled<N>(b.min[i], k - 1), hi = scaled<N>(b.max[i], k - 1);
        p.G[i] = lo + hi - scaled<N>(c.center[i], k);
        p.a[i] = Vec3<N>{N(0), N(0), N(0)};
        p.a[i][i] = nonneg(hi - lo);
        p.zero[i] = b.min[i] == b.max[i];
    }
}
template <class N>
void clipped_box(const CanonicalBox<double>& b, const Cylinder<double>& c, int k, clipped::Problem<N>& p) {
    for (std::size_t i = 0; i < 3; ++i) {
        p.G[i] = -scaled<N>(c.center[i], k);
        p.a[i] = Vec3<N>{N(0), N(0), N(0)};
        p.a[i][i] = scaled_nonneg<N>(b.extents[i], k);
        p.zero[i] = b.extents[i] == 0;
    }
}
// The test on Bounded first, on double-double where that is undecided; nullopt when the unit axis is not
// certainly enclosed.
template <class Box>
std::optional<bool> clipped_candidates(const Box& b, const Cylinder<double>& c, int k) {
    auto problem = [&]<class N>(clipped::Problem<N>& p) {
        clipped_box(b, c, k, p);
        p.r = scaled_nonneg<N>(c.radius, k);
        p.H = scaled_nonneg<N>(c.height, k - 1);
        p.disk = c.height == 0;
        UncertaintyScope scope;
        p.u = unit_direction<N>(c.axis);
        return scope.certain();
    };
    clipped::Problem<Bounded> fast;
    if (!problem(fast)) return std::nullopt;
    bool tight_ok = true;
    const std::optional<bool> r = clipped::decide<Bounded, DoubleDouble>(fast, [&] {
        clipped::Problem<DoubleDouble> p;
        tight_ok = problem(p);
        return p;
    });
    if (!tight_ok) return std::nullopt;
    return r;
}

}  // namespace boxcyl::filtered::enclosed
