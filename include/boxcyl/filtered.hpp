// The filtered exact query (issue #4): the exact answer for double inputs, at close to floating-point
// speed. Semantics as the oracle's (docs/robustness.md): every double is the rational it denotes, the
// cylinder axis is axis/|axis| exactly, an oriented box is the parallelepiped its axes span exactly as
// given, both solids are closed (touching intersects).
//
//   Stage 1, the certified filter: the canonical problem (§1.3/§1.4) is built in interval arithmetic
//   (number/interval.hpp) so that it encloses the exact one, and the same generic §4 code,
//   algo::linear_inequalities<Interval>, runs on it inside an UncertaintyScope. If no comparison was
//   undecided, every real problem inside the intervals takes the same branches to the same answer;
//   the exact problem is one of them, so that answer is exact. Oriented boxes whose axes are not
//   exactly orthonormal are first widened by a proved bound η (docs/robustness.md §3).
//   Stage 2, the exact fallback (only when stage 1 could not decide): §4 in Q(√d) for aligned and
//   canonical boxes and for exactly orthonormal frames (signed permutations: the only exactly
//   orthonormal frames of doubles), §3 on the exact parallelepiped otherwise (exact_paths.hpp). The
//   oracle is not used: it stays the independent judge of this code.
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
//   BOXCYL_FORCE_EXACT=1   skip stage 1: every query answers with stage 2 (exact_used == true).
//   BOXCYL_CHECK_FILTER=1  whenever stage 1 decides, also run stage 2; on a mismatch throw
//                          std::logic_error naming the case (hex floats, copy-pasteable).
//
// §3 (convex hull) is deliberately not offered as a filtered stage 1: it sorts points with std::sort,
// which needs a strict weak order, and an undecided interval comparison answers arbitrarily, so the
// sort itself could misbehave before the scope reports the doubt (docs/robustness.md).
#pragma once

#include <algorithm>  // std::min, std::max
#include <cassert>    // debug-build precondition checks
#include <cmath>      // std::ldexp, std::ilogb, std::fabs
#include <cstdio>     // std::snprintf for the CHECK_FILTER message
#include <limits>     // infinity
#include <optional>   // stage 1's "undecided"
#include <stdexcept>  // std::logic_error (BOXCYL_CHECK_FILTER)
#include <string>     // the CHECK_FILTER message

#include "boxcyl/algo/linear_inequalities.hpp"
#include "boxcyl/exact_paths.hpp"
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/reduce.hpp"
#include "boxcyl/geometry/validate.hpp"
#include "boxcyl/number/interval.hpp"
#include "boxcyl/oracle/oracle.hpp"  // to_exact: the rationals the doubles denote

namespace boxcyl::filtered {

// intersect: the exact answer. exact_used: stage 1 could not decide and stage 2 answered.
struct Result {
    bool intersect;
    bool exact_used;
};

namespace detail {

using I = Interval;

inline double next_down(double x) { return boxcyl::detail::next_down(x); }
inline double next_up(double x) { return boxcyl::detail::next_up(x); }

// An upper bound of |x| for every x in the interval (NaN stays NaN and is caught by the callers).
inline double magnitude(const I& x) { return std::max(-x.lo(), x.hi()); }

// The exact value x·2^k as an interval: a point when ldexp is exact (it rounds only into the subnormal
// range, or overflows), otherwise the result widened by one double each way, which encloses it in
// every rounding mode. The check is exact: scaling back up by 2^-k cannot round.
inline I scaled(double x, int k) {
    if (k == 0) return I(x);
    const double y = std::ldexp(x, k);
    if (std::ldexp(y, -k) == x) return I(y);
    return I(next_down(y), next_up(y));
}
// The same for a quantity known to be ≥ 0 (sizes): the lower bound is clamped at 0 (still ≤ x·2^k).
inline I scaled_nonneg(double x, int k) {
    const I s = scaled(x, k);
    return I(std::max(0.0, s.lo()), s.hi());
}
inline I nonneg(const I& x) { return I(std::max(0.0, x.lo()), x.hi()); }

// Problem scaling: the question is invariant under scaling every length by 2^k (the axis direction
// is unchanged). When the largest length M is far from 1 the interval computation would over- or
// underflow (§4 forms products of up to four lengths), so the lengths are scaled to M ∈ [1, 2).
inline int scale_exponent(double m) {
    if (!(m > 0) || !(m < std::numeric_limits<double>::infinity())) return 0;
    const int e = std::ilogb(m);
    return (e < -200 || e > 200) ? -e : 0;
}
inline void update_max(double& m, double x) { m = std::max(m, std::fabs(x)); }
inline void update_max(double& m, const Vec3<double>& v) {
    for (int i = 0; i < 3; ++i) update_max(m, v[i]);
}

// The cylinder axis, scaled by a power of two so that its largest component is in [1, 2): then
// a·a ∈ [1, 12) can neither overflow nor underflow (reduce.hpp's to_unit does the same in double).
inline Vec3<I> prescaled_axis(const Vec3<double>& axis) {
    double m = 0;
    update_max(m, axis);
    const int e = std::ilogb(m);
    return {scaled(axis[0], -e), scaled(axis[1], -e), scaled(axis[2], -e)};
}

// An enclosure of v/|v| (|v| bounded away from 0 by the caller).
inline Vec3<I> normalised(const Vec3<I>& v) {
    const I len = sqrt(dot(v, v));
    return {v[0] / len, v[1] / len, v[2] / len};
}

// An enclosure of the exact unit axis u = axis/|axis|. An axis with one non-zero component gives the
// exact ±1 (the common axis-aligned cylinder keeps exact values; nothing rounds).
inline Vec3<I> unit_direction(const Vec3<double>& axis) {
    int nonzero = 0, which = 0;
    for (int i = 0; i < 3; ++i)
        if (axis[i] != 0) ++nonzero, which = i;
    if (nonzero == 1) {
        Vec3<I> d{I(0), I(0), I(0)};
        d[which] = I(axis[which] > 0 ? 1.0 : -1.0);
        return d;
    }
    return normalised(prescaled_axis(axis));
}

// Runs §4 on the interval problem: the answer if every comparison was decided, else nullopt.
inline std::optional<bool> run_li(const CanonicalQuery<I>& q) {
    UncertaintyScope scope;
    const bool answer = algo::linear_inequalities(q.box, q.cylinder);
    if (!scope.certain()) return std::nullopt;
    return answer;
}

// A size (extent, radius, half-height) that may be below δ replaced by max(size, δ): an enclosure of
// a problem that contains the exact one.
inline bool thicken(I& size, double delta) {
    if (size.lo() >= delta) return false;
    size = I(std::max(size.lo(), delta), std::max(size.hi(), delta));
    return true;
}

// Stage 1 proper, on an enclosure `outer` of a problem that contains the exact one (a miss of outer
// certifies a miss) and an enclosure `inner` of a problem contained in it (a hit of inner certifies a
// hit), or null if there is none. Usually both are the exact problem's enclosure (&inner == &outer).
//
// When undecided and a size may be 0 or nearly (flat box, segment, disk), §4 meets degenerate clipped
// segments whose two ends are one point computed by two formulas: their difference is rounding noise
// of either sign, and the branch on it cannot be decided. Thickening every size below
// δ = 2^-30·scale to δ gives a problem that still contains the exact one and is not degenerate: if it
// certainly misses, so does the exact problem (its "true" proves nothing). `scale` is the problem's
// largest length (after scaling).
inline std::optional<bool> decide(const CanonicalQuery<I>& outer, const CanonicalQuery<I>* inner, double scale) {
    const std::optional<bool> o = run_li(outer);
    if (o && (!*o || inner == &outer)) return o;
    if (o) {  // outer meets: ask the inner problem
        if (inner == nullptr) return std::nullopt;
        const std::optional<bool> i = run_li(*inner);
        if (i && *i) return true;
        return std::nullopt;
    }
    if (inner != nullptr && inner != &outer) {
        const std::optional<bool> i = run_li(*inner);
        if (i && *i) return true;
    }
    const double delta = std::ldexp(scale, -30);
    if (!(delta > 0)) return std::nullopt;
    CanonicalQuery<I> thick = outer;
    bool degenerate = thicken(thick.cylinder.radius, delta);
    degenerate |= thicken(thick.cylinder.half_height, delta);
    for (int i = 0; i < 3; ++i) degenerate |= thicken(thick.box.extents[i], delta);
    if (!degenerate) return std::nullopt;
    const std::optional<bool> t = run_li(thick);
    if (t && !*t) return false;
    return std::nullopt;
}
inline std::optional<bool> decide(const CanonicalQuery<I>& q, double scale) { return decide(q, &q, scale); }

// ---- Stage 1 for each box kind: nullopt when undecided. ----

// §1.2: the box is exact; only the unit axis and, for extreme magnitudes, the scaling round.
inline std::optional<bool> filter(const CanonicalBox<double>& b, const Cylinder<double>& c) {
    double m = 0;
    update_max(m, b.extents);
    update_max(m, c.center);
    update_max(m, c.radius);
    update_max(m, c.height);
    const int k = scale_exponent(m);
    CanonicalQuery<I> q;
    for (int i = 0; i < 3; ++i) {
        q.box.extents[i] = scaled_nonneg(b.extents[i], k);
        q.cylinder.center[i] = scaled(c.center[i], k);
    }
    q.cylinder.direction = unit_direction(c.axis);
    q.cylinder.radius = scaled_nonneg(c.radius, k);
    q.cylinder.half_height = scaled_nonneg(c.height, k - 1);  // h/2 exactly, unless subnormal
    return decide(q, std::ldexp(m, k));
}

// §1.3: K = (min + max)/2, E = (max − min)/2, C − K, all enclosed. Halving first (min/2 + max/2)
// keeps finite inputs from overflowing; a flat side (min == max) keeps E = 0 and K = min exact.
inline std::optional<bool> filter(const AlignedBox<double>& b, const Cylinder<double>& c) {
    double m = 0;
    update_max(m, b.min);
    update_max(m, b.max);
    update_max(m, c.center);
    update_max(m, c.radius);
    update_max(m, c.height);
    const int k = scale_exponent(m);
    CanonicalQuery<I> q;
    for (int i = 0; i < 3; ++i) {
        I center, extent;
        if (b.min[i] == b.max[i]) {
            center = scaled(b.min[i], k);
            extent = I(0);
        } else {
            const I lo = scaled(b.min[i], k - 1), hi = scaled(b.max[i], k - 1);
            center = lo + hi;
            extent = nonneg(hi - lo);
        }
        q.box.extents[i] = extent;
        q.cylinder.center[i] = scaled(c.center[i], k) - center;
    }
    q.cylinder.direction = unit_direction(c.axis);
    q.cylinder.radius = scaled_nonneg(c.radius, k);
    q.cylinder.half_height = scaled_nonneg(c.height, k - 1);
    return decide(q, std::ldexp(m, k));
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

// §1.4 with the axes as given. For a signed permutation, C' = Aᵀ(C − K) and D' = Aᵀu are exact
// permutations of enclosures. Otherwise A = QS (polar decomposition) is only nearly orthogonal and the
// problem is widened by η (docs/robustness.md §4):
//   g ≥ ‖AᵀA − I‖₂ (max row sum of |G|, G symmetric), γ = g·|e|, ε = g·(|C − K| + h + 2r),
//   η = γ + ε = g·(|e| + |C − K| + h + 2r)   (1-norms as upper bounds of the 2-norms),
// split as a on the cylinder (r ± a, h/2 ± a) and b = η − a on the box (e ± b), a ≤ min(r, h/2).
// The inflated problem misses ⇒ the exact one misses; the deflated problem meets ⇒ the exact one
// meets — the latter only if b ≤ min e too, else "true" stays undecided.
// `apply_eta = false` drops the widening: unsound, for the tests that show η is needed.
inline std::optional<bool> filter(const OrientedBox<double>& b, const Cylinder<double>& c, bool apply_eta = true) {
    double m = 0;
    update_max(m, b.center);
    update_max(m, b.extents);
    update_max(m, c.center);
    update_max(m, c.radius);
    update_max(m, c.height);
    const int k = scale_exponent(m);
    Vec3<I> delta, extents;
    for (int i = 0; i < 3; ++i) {
        delta[i] = scaled(c.center[i], k) - scaled(b.center[i], k);
        extents[i] = scaled_nonneg(b.extents[i], k);
    }
    const I radius = scaled_nonneg(c.radius, k);
    const I half_height = scaled_nonneg(c.height, k - 1);

    CanonicalQuery<I> q;
    int perm[3];
    double sign[3];
    if (signed_permutation(b.axes, perm, sign)) {
        const Vec3<I> u = unit_direction(c.axis);
        for (int i = 0; i < 3; ++i) {
            q.cylinder.center[i] = sign[i] > 0 ? delta[perm[i]] : -delta[perm[i]];
            q.cylinder.direction[i] = sign[i] > 0 ? u[perm[i]] : -u[perm[i]];
        }
        q.box.extents = extents;
        q.cylinder.radius = radius;
        q.cylinder.half_height = half_height;
        return decide(q, std::ldexp(m, k));
    }

    // g: an upper bound of the spectral norm of G = AᵀA − I.
    Vec3<I> axes[3];
    for (int i = 0; i < 3; ++i) axes[i] = {I(b.axes[i][0]), I(b.axes[i][1]), I(b.axes[i][2])};
    double g = 0;
    for (int i = 0; i < 3; ++i) {
        I row(0);
        for (int j = 0; j < 3; ++j) {
            I gij = dot(axes[i], axes[j]);
            if (i == j) gij -= I(1);
            row += I(magnitude(gij));
        }
        g = std::max(g, row.hi());
    }
    // validate() allows |G_ij| ≤ 1e-4, i.e. g ≤ 3e-4; the derivation needs g < 1.
    if (!(g <= 0x1p-10)) return std::nullopt;

    const Vec3<I> a = prescaled_axis(c.axis);
    Vec3<I> v;
    for (int i = 0; i < 3; ++i) {
        q.cylinder.center[i] = dot(axes[i], delta);
        v[i] = dot(axes[i], a);
    }
    q.cylinder.direction = normalised(v);  // encloses Aᵀu/|Aᵀu|

    // η (upper bound) and its split.
    I lengths(0);
    for (int i = 0; i < 3; ++i) lengths += I(magnitude(extents[i])) + I(magnitude(delta[i]));
    lengths += I(2) * I(magnitude(half_height)) + I(2) * I(magnitude(radius));
    const double eta = apply_eta ? (I(g) * lengths).hi() : 0.0;
    if (!(eta < std::numeric_limits<double>::infinity())) return std::nullopt;
    const double cyl_room = std::min(radius.lo(), half_height.lo());  // ≤ min(r, h/2)
    const double on_cyl = std::min(cyl_room, eta);
    const double on_box = on_cyl == eta ? 0.0 : (I(eta) - I(on_cyl)).hi();
    // The two problems as point sizes (a size interval would let §4 see e − e ≠ 0 and lose the sign of
    // every degenerate difference): outer = sizes rounded up after adding, inner = rounded down after
    // subtracting; the inner one exists only if every deflated size stays ≥ 0.
    bool deflatable = true;
    auto up = [](const I& x, double by) { return I(by == 0 ? x.hi() : (I(x.hi()) + I(by)).hi()); };
    auto down = [&deflatable](const I& x, double by) {
        if (by == 0) return I(x.lo());
        if (!(x.lo() >= by)) deflatable = false;
        return I(std::max(0.0, (I(x.lo()) - I(by)).lo()));
    };
    CanonicalQuery<I> inner = q;
    q.cylinder.radius = up(radius, on_cyl);
    q.cylinder.half_height = up(half_height, on_cyl);
    inner.cylinder.radius = down(radius, on_cyl);
    inner.cylinder.half_height = down(half_height, on_cyl);
    for (int i = 0; i < 3; ++i) {
        q.box.extents[i] = up(extents[i], on_box);
        inner.box.extents[i] = down(extents[i], on_box);
    }
    return decide(q, deflatable ? &inner : nullptr, std::ldexp(m, k));
}

// ---- Stage 2: exact, without the oracle. ----

inline bool exact_answer(const AlignedBox<double>& b, const Cylinder<double>& c) {
    return exact::intersects(exact::Method::inequalities, to_exact(b), to_exact(c));
}
inline bool exact_answer(const CanonicalBox<double>& b, const Cylinder<double>& c) {
    return exact::intersects(exact::Method::inequalities, to_exact(b), to_exact(c));
}
inline bool exact_answer(const OrientedBox<double>& b, const Cylinder<double>& c) {
    const OrientedBox<Rational> eb = to_exact(b);
    const exact::Method m =
        exact::detail::exactly_orthonormal(eb) ? exact::Method::inequalities : exact::Method::hull;
    return exact::intersects(m, eb, to_exact(c));
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
    assert(validate(box).ok() && "boxcyl::filtered::query: invalid box (see boxcyl::validate)");
    assert(validate(cyl).ok() && "boxcyl::filtered::query: invalid cylinder (see boxcyl::validate)");
#if defined(BOXCYL_FORCE_EXACT) && BOXCYL_FORCE_EXACT
    return {exact_answer(box, cyl), true};
#else
    const std::optional<bool> fast = filter(box, cyl);
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
