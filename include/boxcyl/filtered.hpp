// The filtered exact query: the exact answer for double inputs, at close to floating-point
// speed. Semantics as the oracle's (docs/robustness.md): every double is the rational it denotes, the
// cylinder axis is axis/|axis| exactly, an oriented box is the parallelepiped its axes span exactly as
// given, both solids are closed (touching intersects).
//
//   Stage 0, the semi-static filter (filtered/semi_static.hpp): a dozen separating-axis and witness
//   tests in plain double, each decided only beyond an error bound computed at compile time; about
//   93% of random queries end here.
//   Stage 0b, searched certificates (filtered/witness_search.hpp): the axis point nearest to the box
//   and a few alternating projections give a separating direction or a witness point, which stage
//   0's tests (and two-point forms of them) certify; ≈95% of the queries stage 0 leaves end here.
//   The exact stage right after stage 0 for narrow inputs (integer or binary-fraction coordinates):
//   there it costs less than any further filter (exact/integer_inequalities.hpp).
//   The exact stage before the middle stage for narrow inputs of two scales (a subnormal axis
//   component beside 1, a box of 2^-1000 at a cylinder of 2^1000, each group narrow): integers in
//   powers of a tiny ε (number/epsilon_series.hpp) cost less there than the middle stage's failure.
//   The middle stage (round to nearest): the canonical problem (the box's frame) built in double-double
//   enclosures with a running error bound (number/double_double.hpp, ≈2^-100 relative per operation),
//   and the generic linear-inequalities code, algo::linear_inequalities<N>, run on it inside an
//   UncertaintyScope: if no comparison was undecided, every real problem inside the enclosures takes
//   the same branches to the same answer; the exact problem is one of them, so that answer is exact.
//   Degenerate shapes (disks, flat boxes, segments) add hit certificates (certain_hit, frame_hit: a
//   witness point solved exactly in real arithmetic, only inequalities checked on enclosures) and
//   thickened sizes (misses) (docs/robustness.md §5). Rotated frames (not exactly orthonormal) run the
//   clipped-candidates test on the exact parallelepiped (filtered/clipped_candidates.hpp). Near-touching
//   inputs that are not exactly touching are decided here (docs/robustness.md §12).
//   Stage 1: the same evaluation on Bounded (number/bounded.hpp: a double and a running error bound)
//   — in round to nearest before the middle stage, for queries not near touching only (a plain-double
//   hint, witness_search::near_touching); in the other rounding modes instead of the middle stage,
//   followed by the same on Interval (number/interval.hpp);
//   oriented boxes whose axes are not exactly orthonormal are widened by a proved bound η
//   (docs/robustness.md §4); then a thorough witness search tries once more to certify a hit.
//   Stage 2, the exact fallback (only when nothing before could decide): linear inequalities evaluated in integers and
//   Z[√d] after scaling by a power of two (exact/integer_inequalities.hpp: no rationals; inputs of two
//   far-apart scales in powers of ε) for aligned
//   and canonical boxes and for exactly orthonormal frames (signed permutations: the only exactly
//   orthonormal frames of doubles), the parallelepiped's clipped edges and face cuts in integers for
//   other frames (exact/integer_parallelepiped.hpp), the convex-hull method in Q(√d) for flat oriented boxes
//   (exact_paths.hpp). The oracle is not used: it stays the independent judge of this code.
//
// Preconditions: validate() holds for the box and the cylinder (asserted in debug builds). Invalid
// finite input never gets a wrong stage-1 answer (frames further than 2^-10 from orthonormal skip the
// filter), but the exact stage may throw for it. Needs the exact backend (link boxcyl::exact: GMP).
//
// Floating-point environment: keeping the default environment is the caller's responsibility. The
// filter is sound in every IEEE rounding mode, with or without FMA contraction, with subnormals,
// overflow and underflow (they make comparisons undecided, never wrong), but NOT with flush-to-zero
// or denormals-are-zero (e.g. -ffast-math/-Ofast startup code, or MXCSR FTZ/DAZ set by another
// library): check boxcyl::fp_environment_ok() once at start-up if that can happen.
//
// Debug switches (compile-time macros; define them before including this header, in every TU):
//   BOXCYL_FORCE_EXACT=1   skip the filters: every query answers with stage 2 (exact_used == true).
//   BOXCYL_CHECK_FILTER=1  whenever a filter decides, also run stage 2; on a mismatch throw
//                          std::logic_error naming the case (hex floats, copy-pasteable).
//   BOXCYL_MIDDLE_STAGE=0  skip the middle stage (what it saves is measured by bench/bench_sets.cpp).
//
// The convex-hull method is deliberately not offered as a filtered stage 1: it sorts points with std::sort,
// which needs a strict weak order, and an undecided interval comparison answers arbitrarily, so the
// sort itself could misbehave before the scope reports the doubt (docs/robustness.md).
#pragma once

#include <algorithm>  // std::min, std::max
#include <bit>        // std::bit_cast: powers of two
#include <cassert>    // debug-build precondition checks
#include <cmath>      // std::ldexp, std::ilogb, std::fabs
#include <cstdint>    // std::uint64_t
#include <cstdio>     // std::snprintf for the CHECK_FILTER message
#include <limits>     // infinity
#include <optional>   // stage 1's "undecided"
#include <stdexcept>  // std::logic_error (BOXCYL_CHECK_FILTER)
#include <string>     // the CHECK_FILTER message
#include <type_traits>  // std::is_same_v: the middle stage per box kind

#include "boxcyl/algo/convex_hull.hpp"
#include "boxcyl/algo/linear_inequalities.hpp"
#include "boxcyl/exact/integer_inequalities.hpp"
#include "boxcyl/exact/integer_parallelepiped.hpp"
#include "boxcyl/exact_paths.hpp"
#include "boxcyl/filtered/clipped_candidates.hpp"
#include "boxcyl/filtered/semi_static.hpp"
#include "boxcyl/filtered/witness_search.hpp"
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/reduce.hpp"
#include "boxcyl/geometry/validate.hpp"
#include "boxcyl/number/bounded.hpp"
#include "boxcyl/number/double_double.hpp"
#include "boxcyl/number/interval.hpp"
#include "boxcyl/oracle/oracle.hpp"  // to_exact: the rationals the doubles denote

namespace boxcyl::filtered {

// intersect: the exact answer. exact_used: stage 1 could not decide and stage 2 answered.
struct Result {
    bool intersect;
    bool exact_used;
};

namespace detail {

// Stage 1 is written once over the enclosure type N: Bounded (a value with a running error bound:
// cheap) first, Interval (outward-rounded: tighter, exact sums stay points) when Bounded cannot decide.
// N provides exact embedding N(x), N::range(lo, hi) (an enclosure of [lo, hi]), lo()/hi() (certain
// bounds), the arithmetic, sqrt, and comparisons that record undecided outcomes in an UncertaintyScope.

inline double next_down(double x) { return boxcyl::detail::next_down(x); }
inline double next_up(double x) { return boxcyl::detail::next_up(x); }

// An upper bound of |x| for every x in the enclosure (NaN stays NaN and is caught by the callers).
template <class N>
double magnitude(const N& x) {
    return std::max(-x.lo(), x.hi());
}

// The exact value x·2^k: a point when ldexp is exact (it rounds only into the subnormal range, or
// overflows), otherwise the result widened by one double each way, which encloses it in every
// rounding mode. The check is exact: scaling back up by 2^-k cannot round.
template <class N>
N scaled(double x, int k) {
    if (k == 0) return N(x);
    const double y = k == -1 ? x * 0.5 : std::ldexp(x, k);  // the common h/2 and (min + max)/2: no call
    if (std::ldexp(y, -k) == x) return N(y);
    return N::range(next_down(y), next_up(y));
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

// Problem scaling: the question is invariant under scaling every length by 2^k (the axis direction
// is unchanged). When the largest length M is far from 1 the computation would over- or underflow
// (the linear-inequalities code forms products of up to four lengths), so the lengths are scaled to
// M ∈ [1, 2).
inline int scale_exponent(double m) {
    if (!(m > 0) || !(m < std::numeric_limits<double>::infinity())) return 0;
    const int e = std::ilogb(m);
    return (e < -200 || e > 200) ? -e : 0;
}
inline void update_max(double& m, double x) { m = std::max(m, std::fabs(x)); }
inline void update_max(double& m, const Vec3<double>& v) {
    for (int i = 0; i < 3; ++i) update_max(m, v[i]);
}

// The cylinder axis, scaled by a power of two when its largest component is beyond 2^±500, so that
// a·a can neither overflow nor lose the whole axis to underflow (the scaling usually costs a libm
// call and is not needed in between; reduce.hpp's to_unit always scales, in plain double).
template <class N>
Vec3<N> prescaled_axis(const Vec3<double>& axis) {
    double m = 0;
    update_max(m, axis);
    int e = m > 0 ? std::ilogb(m) : 0;  // m = 0 only for a zero axis (invalid): no INT_MIN to negate
    if (e >= -500 && e <= 500) e = 0;  // a·a cannot overflow; underflow of tiny terms is accounted for
    return {scaled<N>(axis[0], -e), scaled<N>(axis[1], -e), scaled<N>(axis[2], -e)};
}

// An enclosure of v/|v| (|v| bounded away from 0 by the caller).
template <class N>
Vec3<N> normalised(const Vec3<N>& v) {
    const N len = sqrt(dot(v, v));
    return {v[0] / len, v[1] / len, v[2] / len};
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

// Runs the linear-inequalities method on the enclosed problem: the answer if every comparison was decided,
// else nullopt.
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

// A cheap certificate of a miss ahead of the linear-inequalities method (not in the published note): the
// separating axes U_i of the box. The cylinder's extent along U_i is w_i = H|d_i| + r·√(d_j² + d_k²) (the
// axis segment plus the widest chord of a cross-section, √(1 − d_i²) written without cancellation), so the
// solids are apart if |c_i| − e_i − H|d_i| > r·√(d_j² + d_k²), i.e. if that left side s is > 0 and
// s² > r²(d_j² + d_k²). Only a certain "apart" counts; an undecided comparison just leaves the question to the
// linear-inequalities method.
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

// Cheap certificates of a hit (not in the published note), tried only where the linear-inequalities
// method was undecided: the degenerate shapes (disks, flat boxes, segments) whose branches there
// compare rounding noise, but whose
// hits usually have a witness far from touching. A witness is a segment of points that lie in the box
// for sure, parallel to the cylinder axis d (so all at the same distance from the axis line), that
// reaches the slab |t| ≤ H for sure:
//   (a) the axis itself (distance 0): {c + t·d} ∩ box reaches [−H, H];
//   (b) the chord through a box point Q near c, when Q's distance to the axis line is < r for sure.
// The chord {Q + t·d : t ∈ [t0, t1]} lies in the box where, for every i with d_i ≠ 0,
// a_i = (−e_i − Q_i)/d_i, b_i = (e_i − Q_i)/d_i (swapped if d_i < 0), t0 = max a_i ≤ 0 ≤ t1 = min b_i
// (axes with d_i = 0 exactly impose |Q_i| ≤ e_i, true for Q in the box). It meets the slab, whose
// points have s + t ∈ [−H, H] with s = d·(Q − c), iff every a_i ≤ H − s and every b_i ≥ −H − s — all
// pairwise comparisons, so no min/max needs deciding; pairs (a_i, b_i) of one axis hold by
// construction. Every comparison is recorded; any doubt rejects the certificate, never the query.
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
// (c) The cross-section through the axis point p, the disk {p + w : w ⊥ d, |w| ≤ r}, meets the box:
// the point of the polygon (plane ∩ box) nearest to p is p itself (done by (a)), the foot on a side
// (a face's line in the plane), or a vertex (a box edge crossing the plane). So the candidates are
//   face x_i = f:  X = p + λ(E_i − d_i·d), λ = (f − p_i)/w_i, w_i = 1 − d_i² = d_j² + d_k² (no
//                  cancellation); |X − p|² = λ²·w_i, so within r iff (f − p_i)² < r²·w_i; X_i = f
//                  exactly and X_j = p_j − (f − p_i)·d_i·d_j/w_i must lie inside (−e_j, e_j);
//   edge ∥ x_k at (x_i, x_j) = (σ_i e_i, σ_j e_j):  x_k = p_k − (d_i(x_i − p_i) + d_j(x_j − p_j))/d_k
//                  inside [−e_k, e_k], and |X − p|² < r².
// Each candidate is a point of the plane (exact in real arithmetic), so any one certainly in the box
// and the disk is a witness; the enclosures carry the rounding.
template <class N>
bool disk_meets_box(const CanonicalQuery<N>& q, const Vec3<N>& p) {
    const Vec3<N>& d = q.cylinder.direction;
    const Vec3<N>& e = q.box.extents;
    const N r2 = q.cylinder.radius * q.cylinder.radius;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        const N w = d[j] * d[j] + d[k] * d[k];
        if (!(w.lo() > 0)) continue;  // w = 0 exactly, or too small to divide by
        for (const N& f : {e[i], -e[i]}) {
            UncertaintyScope scope;  // per candidate: an undecided one must not veto a later certain one
            const N g = f - p[i];
            if (!(g * g < r2 * w)) continue;
            const N m = g * d[i] / w;
            if (abs_value(p[j] - m * d[j]) < e[j] && abs_value(p[k] - m * d[k]) < e[k] && scope.certain())
                return true;
        }
    }
    for (int k = 0; k < 3; ++k) {
        if (d[k].lo() == 0 && d[k].hi() == 0) continue;
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        for (const N& xi : {e[i], -e[i]})
            for (const N& xj : {e[j], -e[j]}) {
                UncertaintyScope scope;
                const N gi = xi - p[i], gj = xj - p[j];
                const N gk = -(d[i] * gi + d[j] * gj) / d[k];  // x_k − p_k
                if (abs_value(p[k] + gk) <= e[k] && gi * gi + gj * gj + gk * gk < r2 && scope.certain()) return true;
            }
    }
    return false;
}

template <class N>
bool certain_hit(const CanonicalQuery<N>& q) {
    const Vec3<N>& c = q.cylinder.center;
    const Vec3<N>& e = q.box.extents;
    {
        UncertaintyScope scope;
        if (chord_reaches_slab(q, c, Vec3<N>{N(0), N(0), N(0)}, true) && scope.certain()) return true;
    }
    if (disk_meets_box(q, c)) return true;
    UncertaintyScope scope;
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
    return chord_reaches_slab(q, point, diff, false) && scope.certain();
}

// Stage 1 proper, on an enclosure `outer` of a problem that contains the exact one (a miss of outer
// certifies a miss) and an enclosure `inner` of a problem contained in it (a hit of inner certifies a
// hit), or null if there is none. Usually both are the exact problem's enclosure (&inner == &outer).
//
// When undecided and a size may be 0 or nearly (flat box, segment, disk), the method meets degenerate clipped
// segments whose two ends are one point computed by two formulas: their difference is rounding noise
// of either sign, and the branch on it cannot be decided. Thickening every size below
// δ = 2^-30·scale to δ gives a problem that still contains the exact one and is not degenerate: if it
// certainly misses, so does the exact problem (its "true" proves nothing). `scale` is the problem's
// largest length (after scaling).
template <class N>
std::optional<bool> decide(const CanonicalQuery<N>& outer, const CanonicalQuery<N>* inner, double scale) {
    if (apart_along_box_axes(outer)) return false;
    std::optional<bool> o;
    if (inner != nullptr && inner != &outer) {
        // Two problems (a rounded frame): most queries that get here are hits (about 70% on random
        // data), which only the inner problem certifies, so it goes first; a miss then costs the
        // second run that a hit used to cost. Inner ⊂ exact ⊂ outer, so the two cannot contradict.
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
template <class N>
std::optional<bool> decide(const CanonicalQuery<N>& q, double scale) {
    return decide(q, &q, scale);
}

// The problem q with every cylinder size grown by `on_cyl` and every box extent by `on_box` (outer:
// it contains a solid pair that contains the exact one), and shrunk by the same (inner: contained in
// it; exists only if no size goes below 0). The sizes become points (a size enclosure would let the method
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

// Tiny axis components (docs/robustness.md §4b). A non-zero component below 2^-30 of the largest makes
// a unit-axis component near or below the rounding of the others (often subnormal): its sign is exact
// in the input but lost in the enclosures, and every comparison that depends on it (the direction class, the
// reflection) is undecided. The axis a' with those (at most two) components set to 0 is within angle
// θ = |u − u'| ≤ 2|a − a'|/|a| ≤ 2·2·2^-30 = 2^-28 of a, and a cylinder turned by θ about its centre
// moves each point of the axis segment by at most θH and each point of a cross-section by at most θr:
//   cyl(u; r, H) ⊆ cyl(u'; r + θH, H + θr) ⊆ cyl(u'; r + η, H + η),  η = θ(H + r),
// and by the same argument with u and u' swapped, cyl(u'; r − η, H − η) ⊆ cyl(u; r, H). So the method on the
// axis a' with the cylinder widened by η certifies misses, and narrowed by η certifies hits, exactly
// as for the nearly orthonormal frames. The widened problems have exact zero components (the cheap
// direction classes) and only cases within η ≈ 2^-28·(H + r) of touching remain undecided: those run on
// the axis as given next.
inline bool tiny_components_zeroed(const Vec3<double>& a, Vec3<double>& zeroed, int exponent = -30) {
    double m = 0;
    update_max(m, a);
    const double limit = std::ldexp(m, exponent);
    bool any = false;
    zeroed = a;
    for (int i = 0; i < 3; ++i)
        if (a[i] != 0 && std::fabs(a[i]) <= limit) zeroed[i] = 0, any = true;
    return any;
}
// The linear-inequalities method for the cylinder axis a (the other sizes of q already set; `direction_of` turns a unit-axis
// enclosure into the box frame's direction, e.g. a signed permutation).
// The middle stage's form of the same (DoubleDouble): components below 2^-200 of the largest are
// zeroed (θ ≤ 2^-198, so η = θ(H + r) is far below any gap it can decide), and instead of two widened
// problems with point sizes (rounding a size to a double would cost its 2^-100 precision) one run
// takes every size as the enclosure [s − η, s + η]: a decided answer holds for every problem in it,
// the widened one (a miss certifies a miss) and the narrowed one (a hit certifies a hit — only if
// every size is ≥ η, so that the narrowed cylinder exists and lies inside the exact one).
// The spread itself, shared by both methods: radius and half-height become [s − η, s + η],
// η = 2^-198·(H + r) rounded up. False when η overflows (nothing is decided then); `thin` says whether
// some size was below η (then only a miss certifies).
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
// `settled` is set when the run was undecided with every size ≥ η: the query is then within about 2η
// of touching, far below what any double-double evaluation on the axis as given can resolve.
template <class N, class Frame>
std::optional<bool> decide_tiny_axis_spread(const CanonicalQuery<N>& q, const Vec3<double>& a0, Frame&& direction_of,
                                            double scale, bool& settled) {
    settled = false;
    CanonicalQuery<N> z = q;
    z.cylinder.direction = direction_of(unit_direction<N>(a0));
    bool thin = false;
    if (!spread_sizes_by_eta(z.cylinder.radius, z.cylinder.half_height, thin)) return std::nullopt;
    const std::optional<bool> r = decide(z, scale);
    if (r && (!*r || !thin)) return r;
    settled = !thin;
    return std::nullopt;
}
template <class N, class Frame>
std::optional<bool> decide_axis(CanonicalQuery<N> q, const Vec3<double>& a, Frame&& direction_of, double scale) {
    Vec3<double> a0;
    if constexpr (std::is_same_v<N, DoubleDouble>) {
        if (tiny_components_zeroed(a, a0, -200)) {
            bool settled = false;
            if (const std::optional<bool> r = decide_tiny_axis_spread(q, a0, direction_of, scale, settled)) return r;
            if (settled) return std::nullopt;  // the exact stage answers
        }
    } else if (tiny_components_zeroed(a, a0)) {
        CanonicalQuery<N> z = q;
        z.cylinder.direction = direction_of(unit_direction<N>(a0));
        const double reach = (N(q.cylinder.half_height.hi()) + N(q.cylinder.radius.hi())).hi();
        const double eta = (N(0x1p-28) * N(reach)).hi();
        if (eta < std::numeric_limits<double>::infinity()) {
            const Widened<N> w = widen(z, eta, 0.0);
            if (const std::optional<bool> r = decide(w.outer, w.has_inner ? &w.inner : nullptr, scale)) return r;
        }
    }
    q.cylinder.direction = direction_of(unit_direction<N>(a));
    return decide(q, scale);
}
template <class N>
std::optional<bool> decide_axis(const CanonicalQuery<N>& q, const Vec3<double>& a, double scale) {
    return decide_axis(q, a, [](const Vec3<N>& d) { return d; }, scale);
}

// ---- Stage 1 for each box kind: nullopt when undecided. ----

// Canonical box: the box is exact; only the unit axis and, for extreme magnitudes, the scaling round.
template <class N>
std::optional<bool> filter(const CanonicalBox<double>& b, const Cylinder<double>& c) {
    double m = 0;
    update_max(m, b.extents);
    update_max(m, c.center);
    update_max(m, c.radius);
    update_max(m, c.height);
    const int k = scale_exponent(m);
    CanonicalQuery<N> q;
    for (int i = 0; i < 3; ++i) {
        q.box.extents[i] = scaled_nonneg<N>(b.extents[i], k);
        q.cylinder.center[i] = scaled<N>(c.center[i], k);
    }
    q.cylinder.radius = scaled_nonneg<N>(c.radius, k);
    q.cylinder.half_height = scaled_nonneg<N>(c.height, k - 1);  // h/2 exactly, unless subnormal
    return decide_axis(q, c.axis, std::ldexp(m, k));
}

// Aligned box: K = (min + max)/2, E = (max − min)/2, C − K, all enclosed. Halving first (min/2 + max/2)
// keeps finite inputs from overflowing; a flat side (min == max) keeps E = 0 and K = min exact.
template <class N>
std::optional<bool> filter(const AlignedBox<double>& b, const Cylinder<double>& c) {
    double m = 0;
    update_max(m, b.min);
    update_max(m, b.max);
    update_max(m, c.center);
    update_max(m, c.radius);
    update_max(m, c.height);
    const int k = scale_exponent(m);
    CanonicalQuery<N> q;
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
    q.cylinder.radius = scaled_nonneg<N>(c.radius, k);
    q.cylinder.half_height = scaled_nonneg<N>(c.height, k - 1);
    return decide_axis(q, c.axis, std::ldexp(m, k));
}

// A signed permutation frame (axes[i] = s_i·e_{p_i}), the only exactly orthonormal frames of doubles
// (a dyadic unit vector in 3-D is ±e_j: x² + y² + z² = 4^n has only the trivial integer solutions).
inline bool signed_permutation(const std::array<Vec3<double>, 3>& axes, int perm[3], double sign[3]) {
    unsigned used = 0;
    for (int i = 0; i < 3; ++i) {
        int nonzero = 0;
        for (int j = 0; j < 3; ++j) {
            const double a = axes[i][j];
            if (a == 0) continue;
            if (a != 1 && a != -1) return false;
            ++nonzero;
            perm[i] = j;
            sign[i] = a;
        }
        if (nonzero != 1 || (used >> perm[i] & 1u)) return false;
        used |= 1u << perm[i];
    }
    return true;
}

// Hit certificates for the parallelepiped {K + Σ x_m·A_m : |x_m| ≤ e_m} with the axes A_m exactly as
// given (no η: where η leaves no inner problem — flat boxes, disks — these are the only way to certify
// a hit without exact arithmetic). delta = C − K, u the unit axis, all enclosures. Each candidate is
// built from a linear system that its exact point solves by construction (Cramer's rule, or the
// plane equation u·(X − C) = 0 solved for one coordinate), so only inequalities are checked:
//   (a) C in the box; the axis segment crossing a face x_k = ±e_k: y·A_i + z·A_j − t·u = delta ∓ e_k·A_k
//       with |y| ≤ e_i, |z| ≤ e_j, |t| ≤ H (works for r = 0 too);
//   (c) the central disk meeting a box edge (as disk_meets_box, in the frame's coordinates) or a face
//       (the nearest point to C of the line where the disk's plane cuts the face's plane).
template <class N>
N det3(const Vec3<N>& a, const Vec3<N>& b, const Vec3<N>& c) {
    return dot(a, cross(b, c));
}
template <class N>
bool frame_disk_hit(const Vec3<N>& delta, const Vec3<N> (&A)[3], const Vec3<N>& e, const Vec3<N>& u, const N& r);
template <class N>
bool frame_hit(const Vec3<N>& delta, const Vec3<N> (&A)[3], const Vec3<N>& e, const Vec3<N>& u, const N& H,
               const N& r) {
    auto certainly = [](auto&& test) {
        UncertaintyScope scope;
        const bool ok = test();
        return ok && scope.certain();
    };
    auto nonzero = [](const N& x) { return N(0) < abs_value(x); };
    // (a) C inside: x = A⁻¹·delta.
    if (certainly([&] {
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
    // (c) for the cross-sections at t = 0 (the central disk), at the box centre's level t = −u·delta
    // when that is certainly within [−H, H], and at the end caps t = ±H: each is a subset of the
    // cylinder; the one at p = C + t·u has delta_t = C + t·u − K.
    const N tk = -dot(u, delta);
    const bool level = certainly([&] { return abs_value(tk) <= H; });
    const N heights[4] = {N(0), tk, H, -H};
    for (int h = 0; h < 4; ++h)
        if ((h != 1 || level) && frame_disk_hit(delta + heights[h] * u, A, e, u, r)) return true;
    return false;
}
template <class N>
bool frame_disk_hit(const Vec3<N>& delta, const Vec3<N> (&A)[3], const Vec3<N>& e, const Vec3<N>& u, const N& r) {
    auto certainly = [](auto&& test) {
        UncertaintyScope scope;
        const bool ok = test();
        return ok && scope.certain();
    };
    auto nonzero = [](const N& x) { return N(0) < abs_value(x); };
    const N r2 = r * r;
    const N D[3] = {dot(u, A[0]), dot(u, A[1]), dot(u, A[2])};
    const N ud = dot(u, delta);
    // (c) edges ∥ A_k at (x_i, x_j) = (±e_i, ±e_j): x_k = (u·delta − x_i·D_i − x_j·D_j)/D_k.
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
    // (c) faces x_i = f: the plane cuts the face's plane along D_j·y + D_k·z = ρ = u·delta − f·D_i; its
    // point (y0, z0) = ρ·(D_j, D_k)/(D_j² + D_k²), direction L = D_k·A_j − D_j·A_k (⊥ u), and the point
    // nearest to C at λ = −L·V0/(L·L), V0 = X0 − C.
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

// Oriented box, with the axes as given. For a signed permutation, C' = Aᵀ(C − K) and D' = Aᵀu are exact
// permutations of enclosures. Otherwise A = QS (polar decomposition) is only nearly orthogonal and the
// problem is widened by η (docs/robustness.md §4):
//   g ≥ ‖AᵀA − I‖₂ (max row sum of |G|, G symmetric), γ = g·|e|, ε = g·(|C − K| + h + 2r),
//   η = γ + ε = g·(|e| + |C − K| + h + 2r)   (1-norms as upper bounds of the 2-norms),
// split as a on the cylinder (r ± a, h/2 ± a) and b = η − a on the box (e ± b), a ≤ min(r, h/2).
// The inflated problem misses ⇒ the exact one misses; the deflated problem meets ⇒ the exact one
// meets — the latter only if b ≤ min e too, else "true" stays undecided.
// `apply_eta = false` drops the widening: unsound, for the tests that show η is needed.
template <class N>
std::optional<bool> filter(const OrientedBox<double>& b, const Cylinder<double>& c, bool apply_eta = true) {
    double m = 0;
    update_max(m, b.center);
    update_max(m, b.extents);
    update_max(m, c.center);
    update_max(m, c.radius);
    update_max(m, c.height);
    const int k = scale_exponent(m);
    Vec3<N> delta, extents;
    for (int i = 0; i < 3; ++i) {
        delta[i] = scaled<N>(c.center[i], k) - scaled<N>(b.center[i], k);
        extents[i] = scaled_nonneg<N>(b.extents[i], k);
    }
    const N radius = scaled_nonneg<N>(c.radius, k);
    const N half_height = scaled_nonneg<N>(c.height, k - 1);

    CanonicalQuery<N> q;
    int perm[3];
    double sign[3];
    if (signed_permutation(b.axes, perm, sign)) {
        for (int i = 0; i < 3; ++i) q.cylinder.center[i] = sign[i] > 0 ? delta[perm[i]] : -delta[perm[i]];
        q.box.extents = extents;
        q.cylinder.radius = radius;
        q.cylinder.half_height = half_height;
        auto permuted = [&](const Vec3<N>& u) {
            Vec3<N> d;
            for (int i = 0; i < 3; ++i) d[i] = sign[i] > 0 ? u[perm[i]] : -u[perm[i]];
            return d;
        };
        return decide_axis(q, c.axis, permuted, std::ldexp(m, k));
    }

    // g: an upper bound of the spectral norm of G = AᵀA − I.
    Vec3<N> axes[3];
    for (int i = 0; i < 3; ++i) axes[i] = {N(b.axes[i][0]), N(b.axes[i][1]), N(b.axes[i][2])};
    double g = 0;
    for (int i = 0; i < 3; ++i) {
        N row(0);
        for (int j = 0; j < 3; ++j) {
            N gij = dot(axes[i], axes[j]);
            if (i == j) gij -= N(1);
            row += N(magnitude(gij));
        }
        g = std::max(g, row.hi());
    }
    // validate() allows |G_ij| ≤ 1e-4, i.e. g ≤ 3e-4; the derivation needs g < 1.
    if (!(g <= 0x1p-10)) return std::nullopt;

    const Vec3<N> a = prescaled_axis<N>(c.axis);
    Vec3<N> v;
    for (int i = 0; i < 3; ++i) {
        q.cylinder.center[i] = dot(axes[i], delta);
        v[i] = dot(axes[i], a);
    }
    q.cylinder.direction = normalised(v);  // encloses Aᵀu/|Aᵀu|

    // η (upper bound) and its split.
    N lengths(0);
    for (int i = 0; i < 3; ++i) lengths += N(magnitude(extents[i])) + N(magnitude(delta[i]));
    lengths += N(2) * N(magnitude(half_height)) + N(2) * N(magnitude(radius));
    const double eta = apply_eta ? (N(g) * lengths).hi() : 0.0;
    if (!(eta < std::numeric_limits<double>::infinity())) return std::nullopt;
    const double cyl_room = std::min(radius.lo(), half_height.lo());  // ≤ min(r, h/2)
    const double on_cyl = std::min(cyl_room, eta);
    const double on_box = on_cyl == eta ? 0.0 : (N(eta) - N(on_cyl)).hi();
    q.cylinder.radius = radius;
    q.cylinder.half_height = half_height;
    q.box.extents = extents;
    const Widened<N> w = widen(q, on_cyl, on_box);
    if (const std::optional<bool> r = decide(w.outer, w.has_inner ? &w.inner : nullptr, std::ldexp(m, k))) return r;
    if (frame_hit(delta, axes, extents, normalised(a), half_height, radius)) return true;
    return std::nullopt;
}

// Stage 1: the cheap enclosure first, the tight one only when it could not decide.
template <class Box>
std::optional<bool> filter(const Box& box, const Cylinder<double>& cyl) {
    if (const std::optional<bool> fast = filter<Bounded>(box, cyl)) return fast;
    return filter<Interval>(box, cyl);
}

// The middle stage: stage 1's evaluation again, in double-double with a running error bound
// (number/double_double.hpp: about 2^-100 relative per operation), so that every input that is not
// exactly touching and whose exact problem stage 1 encloses without widening is decided here, not in
// exact arithmetic. Round to nearest only: in any other mode it declines (the exact stage answers).
//
// An oriented box whose frame is not a signed permutation (a rotation rounded to double) is not a
// rectangular box: stage 1 widens it by η (about 2^-52 relative), within which near-touching inputs
// stay undecided at any precision. The middle stage runs the clipped-candidates test on the exact
// parallelepiped instead (middle_clipped), and where that is undecided the convex-hull method
// (algo/convex_hull.hpp), every length an enclosure: if no comparison was undecided, the exact
// computation takes the same branches (the hull's sort included: an undecided comparison answers by
// the order of the values, so the sort always sees a strict weak order) and gives the same answer.
inline std::optional<bool> middle_hull(const OrientedBox<double>& b, const Cylinder<double>& c) {
    using N = DoubleDouble;
    double m = 0;
    update_max(m, b.center);
    update_max(m, b.extents);
    update_max(m, c.center);
    update_max(m, c.radius);
    update_max(m, c.height);
    const int k = scale_exponent(m);
    algo::Parallelepiped<N> p;
    UnitCylinder<N> u;
    for (int i = 0; i < 3; ++i) {
        p.center[i] = scaled<N>(b.center[i], k);
        u.center[i] = scaled<N>(c.center[i], k);
        const N e = scaled_nonneg<N>(b.extents[i], k);
        for (int j = 0; j < 3; ++j) p.half_edges[i][j] = e * N(b.axes[i][j]);
    }
    u.radius = scaled_nonneg<N>(c.radius, k);
    u.half_height = scaled_nonneg<N>(c.height, k - 1);
    auto run = [&p](const UnitCylinder<N>& cyl) -> std::optional<bool> {
        UncertaintyScope scope;
        const bool answer = algo::convex_hull(p, cyl);
        if (!scope.certain()) return std::nullopt;
        return answer;
    };
    // Axis components below 2^-200 of the largest: zeroed, with the sizes spread by η (as
    // decide_tiny_axis_spread does for the linear-inequalities method).
    Vec3<double> a0;
    if (tiny_components_zeroed(c.axis, a0, -200)) {
        UnitCylinder<N> z = u;
        z.direction = unit_direction<N>(a0);
        bool thin = false;
        if (spread_sizes_by_eta(z.radius, z.half_height, thin)) {
            const std::optional<bool> r = run(z);
            if (r && (!*r || !thin)) return r;
        }
    }
    {
        UncertaintyScope scope;
        u.direction = unit_direction<N>(c.axis);
        if (!scope.certain()) return std::nullopt;
    }
    return run(u);
}
// The parallelepiped test of the exact stage on double-double enclosures (filtered/clipped_candidates.hpp):
// decides the rotated-frame queries the convex-hull method cannot, those whose axis is parallel to a box
// edge or face.
// A zero size: a flat box, a disk or a segment (where hits have no inner problem to certify).
inline bool degenerate(const AlignedBox<double>& b, const Cylinder<double>& c) {
    return b.min[0] == b.max[0] || b.min[1] == b.max[1] || b.min[2] == b.max[2] || c.radius == 0 || c.height == 0;
}
template <class Box>
bool degenerate(const Box& b, const Cylinder<double>& c) {
    return b.extents[0] == 0 || b.extents[1] == 0 || b.extents[2] == 0 || c.radius == 0 || c.height == 0;
}

// The box's part of the problem, G = K − C and the half-edge vectors, for each box kind (scaled by 2^k).
template <class N>
void clipped_box(const OrientedBox<double>& b, const Cylinder<double>& c, int k, clipped::Problem<N>& p) {
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
inline void update_max_box(double& m, const OrientedBox<double>& b) {
    update_max(m, b.center);
    update_max(m, b.extents);
}
inline void update_max_box(double& m, const AlignedBox<double>& b) {
    update_max(m, b.min);
    update_max(m, b.max);
}
inline void update_max_box(double& m, const CanonicalBox<double>& b) { update_max(m, b.extents); }

template <class Box>
std::optional<bool> middle_clipped(const Box& b, const Cylinder<double>& c) {
    double m = 0;
    update_max_box(m, b);
    update_max(m, c.center);
    update_max(m, c.radius);
    update_max(m, c.height);
    const int k = scale_exponent(m);
    // False when the unit axis is not certainly enclosed.
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

template <class Box>
std::optional<bool> middle(const Box& box, const Cylinder<double>& cyl) {
    if (!boxcyl::detail::round_to_nearest()) return std::nullopt;
    if constexpr (std::is_same_v<Box, OrientedBox<double>>) {
        int perm[3];
        double sign[3];
        if (!signed_permutation(box.axes, perm, sign)) {
            if (const std::optional<bool> r = middle_clipped(box, cyl)) return r;
            // The convex-hull method decides what η leaves undecided; the certificates of filter() (frame_hit) decide
            // some hits whose hull comparisons are degenerate (e.g. an edge parallel to the axis).
            if (const std::optional<bool> r = middle_hull(box, cyl)) return r;
        }
    }
    if (const std::optional<bool> r = filter<DoubleDouble>(box, cyl)) return r;
    // Where §4 leaves a degenerate shape undecided (a flat box, a disk, a segment: a hit has no inner
    // problem), the clipped-candidates test certifies it by a candidate segment within r. Not for an
    // axis with components below 2^-200 of the others: what §4 leaves there hangs on them
    // (docs/robustness.md §12); nor for solid shapes, where what §4 leaves is exactly touching.
    Vec3<double> a0;
    if (!degenerate(box, cyl) || tiny_components_zeroed(cyl.axis, a0, -200)) return std::nullopt;
    return middle_clipped(box, cyl);
}

// x·2^k rounded as any product is (so exact unless it leaves the normal range), for |k| ≤ 2044: by
// one or two products with normal powers of two, not a libm call (std::ldexp was two fifths of the
// time of random queries at extreme scales, which all come through rescaled_exactly).
inline double times_two_to(double x, int k) {
    auto power = [](int e) { return std::bit_cast<double>(static_cast<std::uint64_t>(e + 1023) << 52); };
    if (k >= -1022 && k <= 1023) return x * power(k);
    const int half = k / 2;
    return x * power(half) * power(k - half);
}

// Every length times 2^k, the axis kept: the query at another scale (exact unless a value underflows;
// used only for the hint below).
inline AlignedBox<double> times_power_of_two(const AlignedBox<double>& b, int k) {
    AlignedBox<double> r = b;
    for (int i = 0; i < 3; ++i) r.min[i] = times_two_to(b.min[i], k), r.max[i] = times_two_to(b.max[i], k);
    return r;
}
inline CanonicalBox<double> times_power_of_two(const CanonicalBox<double>& b, int k) {
    CanonicalBox<double> r = b;
    for (int i = 0; i < 3; ++i) r.extents[i] = times_two_to(b.extents[i], k);
    return r;
}
inline OrientedBox<double> times_power_of_two(const OrientedBox<double>& b, int k) {
    OrientedBox<double> r = b;
    for (int i = 0; i < 3; ++i) r.center[i] = times_two_to(b.center[i], k), r.extents[i] = times_two_to(b.extents[i], k);
    return r;
}

inline bool same_lengths(const AlignedBox<double>& a, const AlignedBox<double>& b) { return a.min == b.min && a.max == b.max; }
inline bool same_lengths(const CanonicalBox<double>& a, const CanonicalBox<double>& b) { return a.extents == b.extents; }
inline bool same_lengths(const OrientedBox<double>& a, const OrientedBox<double>& b) {
    return a.center == b.center && a.extents == b.extents;
}

// The query with every length times 2^k, k bringing the largest to [1, 2), when its largest length is
// beyond stage 0's range of scales and every length scales exactly (scaling back gives it again): the
// same question, whose answer is the same.
template <class Box>
bool rescaled_exactly(const Box& box, const Cylinder<double>& cyl, Box& out_box, Cylinder<double>& out_cyl) {
    double m = 0;
    update_max_box(m, box);
    update_max(m, cyl.center);
    update_max(m, cyl.radius);
    update_max(m, cyl.height);
    if (!(m > 0) || !(m < std::numeric_limits<double>::infinity()) || semi_static::in_range(2 * m)) return false;
    const int k = -std::ilogb(m);
    // Scaled back, a value comes back exactly when its scaling rounded nothing: the way back is exact
    // (it only grows values, or shrinks them again by what they grew), every rounding mode alike.
    bool exact = true;
    auto scale = [&](double x) {
        const double y = times_two_to(x, k);
        exact &= times_two_to(y, -k) == x;
        return y;
    };
    out_box = times_power_of_two(box, k);
    out_cyl = cyl;
    for (int i = 0; i < 3; ++i) out_cyl.center[i] = scale(cyl.center[i]);
    out_cyl.radius = scale(cyl.radius);
    out_cyl.height = scale(cyl.height);
    const Box back = times_power_of_two(out_box, -k);
    return exact && same_lengths(back, box);
}

// Whether the plain-double linear-inequalities answer changes between the cylinder grown and shrunk by
// 2^-30 of the query's scale (radius and half-height ± δ: the grown cylinder holds every point within δ
// of the given one, the given one every point within δ of the shrunk one). A hint only, like
// near_touching: it catches the contacts whose gap no single separating axis or axis distance shows
// (a cap's rim on a box edge, a side on a vertex), at two rounded runs (a few hundred ns), asked only
// of queries that stages 0 and 0b left.
template <class Box>
bool answer_moves(const Box& box, const Cylinder<double>& cyl) {
    double m = 0;
    update_max_box(m, box);
    update_max(m, cyl.center);
    update_max(m, cyl.radius);
    update_max(m, cyl.height);
    const double delta = 0x1p-30 * m;
    if (!(delta > 0) || !(m < std::numeric_limits<double>::max() / 4)) return true;
    const CanonicalQuery<double> q = to_canonical(box, to_unit(cyl));
    CanonicalQuery<double> grown = q, shrunk = q;
    grown.cylinder.radius += delta;
    grown.cylinder.half_height += delta;
    shrunk.cylinder.radius = std::max(0.0, q.cylinder.radius - delta);
    shrunk.cylinder.half_height = std::max(0.0, q.cylinder.half_height - delta);
    return algo::linear_inequalities(grown.box, grown.cylinder) != algo::linear_inequalities(shrunk.box, shrunk.cylinder);
}

// Whether the query looks near touching (witness_search::near_touching, then answer_moves), for the
// order of the stages only. A query out of stage 0's range (its scale beyond 2^±200) is looked at
// scaled to about 1.
template <class Box>
bool looks_near_touching(const Box& box, const Cylinder<double>& cyl, const semi_static::Problem& p, bool in_range) {
    if (in_range) return witness_search::near_touching(p, box) || answer_moves(box, cyl);
    double m = 0;
    update_max_box(m, box);
    update_max(m, cyl.center);
    update_max(m, cyl.radius);
    update_max(m, cyl.height);
    if (!(m > 0) || !(m < std::numeric_limits<double>::infinity())) return true;
    const int k = -std::ilogb(m);
    const Box b = times_power_of_two(box, k);
    Cylinder<double> c = cyl;
    for (int i = 0; i < 3; ++i) c.center[i] = std::ldexp(cyl.center[i], k);
    c.radius = std::ldexp(cyl.radius, k);
    c.height = std::ldexp(cyl.height, k);
    semi_static::Problem q;
    return !semi_static::problem(b, c, q) || witness_search::near_touching(q, b) || answer_moves(b, c);
}

// Whether stage 1's Bounded run goes before the middle stage (round to nearest): only for queries that
// do not look near touching, and not for a turned frame (an oriented box whose axes are not a signed
// permutation). There the middle stage's clipped-candidates test already runs on Bounded first, and
// stage 1's run adds the η-widened problem and the frame's hit certificates, which near touching fail
// at several µs — the hint misses about 40% of one-ulp boundary pairs on turned frames — to save under
// a µs on the few far queries that reach it (0.15% of random queries).
template <class Box>
bool bounded_first(const Box& box, const Cylinder<double>& cyl, const semi_static::Problem& p, bool in_range) {
    if constexpr (std::is_same_v<Box, OrientedBox<double>>) {
        int perm[3];
        double sign[3];
        if (!signed_permutation(box.axes, perm, sign)) return false;
    }
    return !looks_near_touching(box, cyl, p, in_range);
}

// Stage 1: Bounded, then Interval, then the thorough witness search for hits.
template <class Box>
std::optional<bool> stage_one(const Box& box, const Cylinder<double>& cyl, const semi_static::Problem& p, bool in_range) {
    if (const std::optional<bool> r = filter(box, cyl)) return r;
    if (in_range && witness_search::certain_hit(p, box, cyl)) return true;
    return std::nullopt;
}

// Whether the middle stage runs: built in (BOXCYL_MIDDLE_STAGE, on by default) and the rounding mode
// is to nearest.
inline bool middle_runs() {
#if !defined(BOXCYL_MIDDLE_STAGE) || BOXCYL_MIDDLE_STAGE
    return boxcyl::detail::round_to_nearest();
#else
    return false;
#endif
}

// ---- Stage 2: exact, without the oracle. ----

// Linear inequalities in integers (exact/integer_inequalities.hpp) wherever the canonical frame is exact, the
// parallelepiped test in integers (exact/integer_parallelepiped.hpp) for other frames, the convex-hull method in Q(√d)
// for flat oriented boxes.
inline bool exact_answer(const AlignedBox<double>& b, const Cylinder<double>& c) {
    return exact::integer::intersects(b, c);
}
inline bool exact_answer(const CanonicalBox<double>& b, const Cylinder<double>& c) {
    return exact::integer::intersects(b, c);
}
inline bool exact_answer(const OrientedBox<double>& b, const Cylinder<double>& c) {
    if (const std::optional<bool> r = exact::integer::intersects(b, c)) return *r;
    if (const std::optional<bool> r = exact::integer::intersects_parallelepiped(b, c)) return *r;
    return exact::intersects(exact::Method::hull, to_exact(b), to_exact(c));
}

// ---- The case as copy-pasteable C++ (hex floats), for BOXCYL_CHECK_FILTER's message. ----

inline std::string hex(double x) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%a", x);
    return buf;
}
inline std::string hex(const Vec3<double>& v) { return "{" + hex(v[0]) + ", " + hex(v[1]) + ", " + hex(v[2]) + "}"; }
inline std::string describe(const AlignedBox<double>& b) {
    return "AlignedBox<double>{" + hex(b.min) + ", " + hex(b.max) + "}";
}
inline std::string describe(const CanonicalBox<double>& b) { return "CanonicalBox<double>{" + hex(b.extents) + "}"; }
inline std::string describe(const OrientedBox<double>& b) {
    return "OrientedBox<double>{" + hex(b.center) + ", {Vec3<double>" + hex(b.axes[0]) + ", Vec3<double>" +
           hex(b.axes[1]) + ", Vec3<double>" + hex(b.axes[2]) + "}, " + hex(b.extents) + "}";
}
inline std::string describe(const Cylinder<double>& c) {
    return "Cylinder<double>{" + hex(c.center) + ", " + hex(c.axis) + ", " + hex(c.radius) + ", " + hex(c.height) + "}";
}

template <class Box>
Result run(const Box& box, const Cylinder<double>& cyl) {
    assert(is_valid(box) && "boxcyl::filtered::query: invalid box (see boxcyl::validate)");
    assert(is_valid(cyl) && "boxcyl::filtered::query: invalid cylinder (see boxcyl::validate)");
#if defined(BOXCYL_FORCE_EXACT) && BOXCYL_FORCE_EXACT
    return {exact_answer(box, cyl), true};
#else
    // Stages 0, 0b and the thorough search share one computed problem (false: out of stage 0's range).
    semi_static::Problem p;
    const bool in_range = semi_static::problem(box, cyl, p);
    if (!in_range) {
        // Scales beyond stage 0's range (2^±200): the same question scaled by a power of two to about 1,
        // when that is exact for every length (no value under- or overflows), gets the cheap stages.
        Box scaled_box;
        Cylinder<double> scaled_cyl;
        if (rescaled_exactly(box, cyl, scaled_box, scaled_cyl)) return run(scaled_box, scaled_cyl);
    }
    std::optional<bool> fast;
    if (in_range) fast = semi_static::decide(p, box, cyl);  // stage 0
    if (!fast) {  // narrow inputs: the exact stage costs less than stages 0b and 1 (exact/integer_inequalities.hpp)
        if (const std::optional<bool> e = exact::integer::answer_if_narrow(box, cyl)) return {*e, true};
    }
    // Stage 0b, except near touching in round to nearest: its searched certificates need a margin
    // there, and fail at most of a µs before the middle stage decides. Near means two plain-double
    // hints: one of stage 0's separating-axis tests near its bound (semi_static::near_touching, a few
    // tens of ns: most of what stage 0 leaves is decided by 0b, which must not pay more), and a rounded
    // answer that changes when the cylinder grows or shrinks by 2^-30 of the scale — degenerate shapes
    // (a flat box, a segment) meet the first alone at a margin that stage 0b certifies.
    const bool near =
        !fast && in_range && middle_runs() && semi_static::near_touching(p, box) && answer_moves(box, cyl);
    if (!fast && in_range && !near) fast = witness_search::decide(p, box, cyl);  // stage 0b
    if (!fast) {
        if (middle_runs()) {
            // In round to nearest the middle stage decides everything stage 1 would, and more. Near
            // touching (looks_near_touching, a plain-double hint) and for turned frames it runs alone
            // (bounded_first): stage 1's Bounded run would fail there first. Elsewhere
            // Bounded runs first: it decides nearly all such queries (degenerate shapes, hits stage 0
            // cannot certify) at a third of the middle stage's cost. What the middle stage leaves is
            // (nearly always) exactly touching or hangs on a subnormal, where the exact stage costs
            // less than any further filter. Except for degenerate shapes (flat boxes, disks,
            // segments), where the thorough witness search still certifies deep hits with no inner
            // problem (a flat box crossed by a thick disk), and stage 1's coarser zeroing of tiny
            // axis components (2^-30, not 2^-200) some hits of segments and disks whose axis has
            // subnormal components — after the exact stage's series run where the axis is of two
            // scales, which costs less than that filter's failure.
            if (!near && bounded_first(box, cyl, p, in_range)) fast = filter<Bounded>(box, cyl);
            if (!fast) {  // two-scale inputs whose groups are narrow: exact costs less than the middle stage
                if (const std::optional<bool> e = exact::integer::answer_if_narrow_two_scale(box, cyl)) return {*e, true};
            }
            if (!fast) fast = middle(box, cyl);
            if (!fast && degenerate(box, cyl)) {
                Vec3<double> a0;
                if (tiny_components_zeroed(cyl.axis, a0, -200)) {
                    if (const std::optional<bool> e = exact::integer::answer_two_scale(box, cyl)) return {*e, true};
                    fast = filter(box, cyl);
                }
                if (!fast && in_range && witness_search::certain_hit(p, box, cyl)) fast = true;
            }
        } else {
            fast = stage_one(box, cyl, p, in_range);
        }
    }
    if (!fast) return {exact_answer(box, cyl), true};
#if defined(BOXCYL_CHECK_FILTER) && BOXCYL_CHECK_FILTER
    if (exact_answer(box, cyl) != *fast)
        throw std::logic_error("boxcyl::filtered: the filter answered " + std::string(*fast ? "true" : "false") +
                               " but the exact answer differs for " + describe(box) + ", " + describe(cyl));
#endif
    return {*fast, false};
#endif
}

}  // namespace detail

// The exact answer for an aligned, oriented or canonical box (for a canonical box the cylinder is in
// the box's frame). Stage 1 decides almost every query; exact_used reports the rest.
inline Result query(const AlignedBox<double>& box, const Cylinder<double>& cyl) { return detail::run(box, cyl); }
inline Result query(const OrientedBox<double>& box, const Cylinder<double>& cyl) { return detail::run(box, cyl); }
inline Result query(const CanonicalBox<double>& box, const Cylinder<double>& cyl) { return detail::run(box, cyl); }

template <class Box>
bool intersects(const Box& box, const Cylinder<double>& cyl) {
    return query(box, cyl).intersect;
}

}  // namespace boxcyl::filtered
