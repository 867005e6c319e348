// The SIMD filter of the batch API (batch.hpp): one cylinder, a vector of boxes per step. For each lane
// it either proves the exact answer (a certain miss or a certain hit, for the inputs as given: every
// double is the rational it denotes, u = axis/|axis| exactly, closed solids) or leaves the lane
// undecided; batch.hpp sends undecided lanes to the scalar exact default (filtered.hpp). It never
// decides wrongly; docs/robustness/batch.md derives every bound below, in short:
//
//  * Cylinder side, once per batch, in a certified enclosure type (number/bounded.hpp, sound in every
//    rounding mode): a double vector û with δ_u ≥ max_j |u_j − û_j|, the cylinder's bounding box,
//    ρ_u ≥ the cylinder's support radius along û, r_N ≥ r(1 + 2^-40), R2 ≤ r². H = h/2 must be exact.
//  * Lane side, in plain double: a margin m̂ that would be > 0 for a certain answer, and a bound β̂ on
//    its error, β̂ = K·(sum of the absolute values of the terms of m̂) + (terms for δ_u and for
//    rounded intermediate points) + τ. Decided only when m̂ > β̂. Each margin is at most a few dozen
//    operations deep, whose relative rounding error is ≤ γ_k ≤ k·2^-52/(1 − k·2^-52) in round-to-
//    nearest (and in any rounding mode: 2^-52 is one ulp), with or without FMA contraction (a fused
//    operation removes a rounding); K = 2^-46 covers k ≤ 40 with room, and every other bound term
//    carries a relative slack of 2^-40 that covers the rounding of β̂ itself.
//  * Overflow and underflow: a lane is eligible only if its coordinates relative to the cylinder's
//    centre and its sizes are ≤ 2^200 (and the cylinder's ≤ 2^200), so no operation overflows (margins
//    are at most quadratic); τ = 2^-800 covers every underflow loss (≤ 2^-1074 per rounding, amplified
//    by at most 2^406 through later products). Lanes outside the range, and margins below τ, stay
//    undecided: the scalar path answers them.
//
// Miss certificates (a separating direction n: the box lies where n·(X − C) < −(support radius of the
// cylinder along n)), hit certificates (a point of the box, exactly, inside the cylinder):
//   aligned:  the bounding boxes (exact comparisons); n = û (the slab along the axis); n = the
//             direction from a box point to the nearest axis point (radial).  Hit: the box point
//             nearest to an axis point, after one step of alternating projection box ↔ axis segment.
//   oriented: the same with n = e_x, e_y, e_z (box support Σ e_i|A_ij|), û, radial; the hit point is
//             K + Σ ξ_i A_i with |ξ_i| ≤ e_i exactly (clamped box coordinates).
// Oriented boxes are taken with their axes exactly as given (the parallelepiped they span); the
// bounds need |A_ij| ≤ 2 (checked per lane) and nothing about orthonormality.
//
// SIMD: std::experimental::simd's native ABI for double, chosen at compile time: 2 lanes with the
// default x86-64 flags (SSE2, runs on any x86-64), 4 with -mavx2, 8 with -mavx512f (-march=native).
#pragma once

#include <experimental/simd>

#include <algorithm>  // std::max
#include <cmath>      // std::fabs, std::ilogb, std::ldexp
#include <cstddef>    // std::size_t

#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/number/bounded.hpp"

// Small steps called per vector of boxes: GCC at -O2 keeps some out of line (7% of the 10M-box
// benchmark's profile in calls).

// The instruction-set namespace: everything below depends on the vector width, so each compiled
// instruction set gets its own namespace (inline, so that boxcyl::batch::detail::… names the includer's
// own): kernels for AVX2 and AVX-512 (src/batch/, boxcyl::batch_dispatch) live in one program beside
// the header's, and no symbol of one can stand in for another's at link time. The default names the
// includer's instruction set; src/batch/ sets its own.
#ifndef BOXCYL_BATCH_ISA
#if defined(__AVX512F__)
#define BOXCYL_BATCH_ISA compiled_avx512
#elif defined(__AVX__)
#define BOXCYL_BATCH_ISA compiled_avx
#elif defined(__SSE2__)
#define BOXCYL_BATCH_ISA compiled_sse2
#else
#define BOXCYL_BATCH_ISA compiled_generic
#endif
#endif

namespace boxcyl::batch {

namespace stdx = std::experimental;

inline namespace BOXCYL_BATCH_ISA {

// One vector of lanes: the widest the compile flags allow.
using Lanes = stdx::native_simd<double>;
using LaneMask = Lanes::mask_type;
inline constexpr std::size_t lane_count = Lanes::size();
static_assert(64 % lane_count == 0, "a vector of lanes must not straddle a 64-bit mask word");

namespace detail {

inline constexpr double kRel = 0x1p-46;     // K: relative rounding allowance of one margin
inline constexpr double kAbs = 0x1p-800;    // τ: absolute underflow allowance
inline constexpr double kLimit = 0x1p200;   // eligibility: magnitudes ≤ 2^200
inline constexpr double kSlack = 1 + 0x1p-40;
inline constexpr int kSteps = 8;  // alternating-projection steps towards a hit point (measured: 3 → 8 halves the undecided hits)

// The constants of aligned_ball_lanes, broadcast once per batch (GCC re-broadcasts a double in every
// vector step otherwise: a fifth of that pass's instructions).
struct BallConstants {
    Lanes c[3], u[3];
    Lanes box_lo[3], box_hi[3];
    Lanes two_h, two_r, four_r2, kappa;
};

// The cylinder's quantities, computed once (certified enclosures) and broadcast to every lane.
struct CylinderFilter {
    bool usable = false;            // false: every lane is left undecided (and the bounding-box test off)
    double c[3]{};                  // C
    double u[3]{};                  // û ≈ u = axis/|axis|
    bool u_nonneg[3]{};             // û_j ≥ 0: which box bound is the far one along û
    double du = 0;                  // δ_u(1 + 2^-40) rounded up, δ_u ≥ max_j |u_j − û_j|
    double h = 0;                   // H = height/2, exact
    double rho_u = 0;               // ≥ H|u·û| + r·√(|û|² − (u·û)²): the support radius along û
    double r_n = 0;                 // ≥ r(1 + 2^-40): the support radius r|n| for |n| ≤ 1 + 2^-42, with slack
    double r = 0;                   // r
    double r2 = 0;                  // ≤ r²
    double w[3]{};                  // ≥ the cylinder's half-width along e_j: H|u_j| + r√(1 − u_j²)
    double box_lo[3]{}, box_hi[3]{};  // the cylinder's bounding box, outward (±∞: test off)
    double kappa = 0;               // κ = 2^-44 + 2δ_u: the first pass's relative error allowance
    double aim = 0;                 // min(H, r)/8: how deep inside the surface the hit search aims
    BallConstants ball{};           // the first pass's constants as vectors (2H, 2r, 4·R2: exact)
};

inline bool eligible(double x) { return std::fabs(x) <= kLimit; }  // false for NaN and ±∞

// The cylinder's quantities are certified in an enclosure type N (number/bounded.hpp's Bounded: a
// double and a running error bound, branch-free; Interval gives the same guarantees and was five
// times slower here, ≈550 ns per batch, because its products branch on the signs of their bounds).
// N provides N(x) (exact), N::range(lo, hi), + − × ÷, sqrt, enclosure_abs and certain bounds lo(), hi().

// √x for an enclosure of a quantity known to be ≥ 0 (a sum of squares may get a lower bound just
// below 0 from outward rounding).
template <class N>
N sqrt_nonneg(const N& x) {
    return sqrt(N::range(std::max(0.0, x.lo()), std::max(0.0, x.hi())));
}

// An enclosure of u = a/|a|: exact ±1 for a single non-zero component; otherwise a itself when its
// largest component m is within 2^±250, else a prescaled to m ∈ [1, 2) by a power of two (exact
// unless a component lands below the normal range: then widened by one double each way), normalised
// in N. A component below 2^-250 of the largest is left out of |a| and enclosed as ±2^-250 (then
// |u_j| < 2^-250, and |a| is enclosed once widened by one double up): kept, its square would be
// subnormal, which x86 runs in microcode (a third of prepare's time on such an axis).
template <class N>
void unit_axis(const Vec3<double>& a, N out[3]) {
    int nonzero = 0, which = 0;
    double m = 0;
    for (int j = 0; j < 3; ++j) {
        if (a[j] != 0) ++nonzero, which = j;
        m = std::max(m, std::fabs(a[j]));
    }
    if (nonzero == 1) {
        for (int j = 0; j < 3; ++j) out[j] = N(j == which ? (a[j] > 0 ? 1.0 : -1.0) : 0.0);
        return;
    }
    double y[3] = {a[0], a[1], a[2]};
    bool inexact[3] = {false, false, false};
    if (!(m >= 0x1p-250 && m <= 0x1p250)) {
        const int e = std::ilogb(m);  // m > 0: two non-zero components
        for (int j = 0; j < 3; ++j) {
            y[j] = std::ldexp(a[j], -e);
            inexact[j] = std::ldexp(y[j], e) != a[j];
        }
        m = std::ldexp(m, -e);
    }
    const double floor = m * 0x1p-250;  // exact: m·2^-250 ≥ 2^-500 is normal
    N v[3];
    bool dropped[3], any_dropped = false;
    for (int j = 0; j < 3; ++j) {
        dropped[j] = std::fabs(y[j]) < floor;
        any_dropped |= dropped[j];
        v[j] = dropped[j] ? N(0.0)
               : inexact[j] ? N::range(boxcyl::detail::next_down(y[j]), boxcyl::detail::next_up(y[j]))
                            : N(y[j]);
    }
    N len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (any_dropped) len = N::range(len.lo(), boxcyl::detail::next_up(len.hi()));  // + ≤ 3·2^-500 relative in |a|²
    for (int j = 0; j < 3; ++j) out[j] = dropped[j] ? N::range(-0x1p-250, 0x1p-250) : v[j] / len;
}

template <class N>
CylinderFilter prepare_scalars(const Cylinder<double>& cyl) {
    CylinderFilter f;
    const double inf = std::numeric_limits<double>::infinity();
    for (int j = 0; j < 3; ++j) f.box_lo[j] = -inf, f.box_hi[j] = inf;
    for (int j = 0; j < 3; ++j)
        if (!eligible(cyl.center[j])) return f;
    if (!eligible(cyl.radius) || !eligible(cyl.height) || !(cyl.radius >= 0) || !(cyl.height >= 0)) return f;
    if (!(cyl.axis[0] != 0 || cyl.axis[1] != 0 || cyl.axis[2] != 0)) return f;
    const double half = cyl.height * 0.5;
    if (half * 2 != cyl.height) return f;  // h/2 rounded (h subnormal): leave it to the scalar path
    N u[3];
    unit_axis(cyl.axis, u);
    const N H(half), r(cyl.radius);
    double du = 0;
    for (int j = 0; j < 3; ++j) {
        f.c[j] = cyl.center[j];
        f.u[j] = u[j].lo() * 0.5 + u[j].hi() * 0.5;  // any double: δ_u measures it
        // A tiny component (an axis like (1e-322, −0.66, 0)) becomes 0, which δ_u then covers: a
        // subnormal û_j would make every product with it subnormal, and subnormal arithmetic is
        // microcoded on x86 (≈100 cycles): it made the filter about twice as slow on such a cylinder.
        if (std::fabs(f.u[j]) < 0x1p-400) f.u[j] = 0;
        f.u_nonneg[j] = f.u[j] >= 0;
        du = std::max({du, (N(u[j].hi()) - N(f.u[j])).hi(), (N(f.u[j]) - N(u[j].lo())).hi()});
    }
    if (!(du <= 0x1p-20)) return f;  // the oriented bounds use δ_u ≤ 1/4; a sane axis gives ~2^-52
    f.du = (N(du) * N(kSlack)).hi();
    f.h = half;
    // Half-widths along e_j: H|u_j| + r√(u_k² + u_l²) (√(1 − u_j²) without cancellation).
    for (int j = 0; j < 3; ++j) {
        const N& uk = u[(j + 1) % 3];
        const N& ul = u[(j + 2) % 3];
        const N w = H * enclosure_abs(u[j]) + r * sqrt_nonneg(uk * uk + ul * ul);
        f.w[j] = w.hi();
        f.box_lo[j] = (N(cyl.center[j]) - w).lo();
        f.box_hi[j] = (N(cyl.center[j]) + w).hi();
    }
    // Support radius along û: H|u·û| + r√(|û|² − (u·û)²).
    const N uu = u[0] * N(f.u[0]) + u[1] * N(f.u[1]) + u[2] * N(f.u[2]);
    const N nn = N(f.u[0]) * N(f.u[0]) + N(f.u[1]) * N(f.u[1]) + N(f.u[2]) * N(f.u[2]);
    const N perp2 = nn - uu * uu;
    const N perp = sqrt_nonneg(perp2);
    f.rho_u = (H * enclosure_abs(uu) + r * perp).hi();
    f.r_n = (r * N(kSlack)).hi();
    f.r = cyl.radius;
    f.r2 = std::max(0.0, (r * r).lo());
    f.kappa = 0x1p-44 + 2 * f.du;
    // The same depth along and across the axis. Shrunk by a factor instead (to 7/8 of r and of H), a
    // flat disk (r ≫ H) lost more radial room than most overlaps at its rim have (a needle the same
    // axially): 10–17% fewer lanes go to the scalar query on bench_batch's near-surface sets.
    f.aim = 0.125 * std::min(f.h, f.r);
    f.usable = eligible(f.rho_u) && eligible(f.r_n) && eligible(f.w[0]) && eligible(f.w[1]) && eligible(f.w[2]);
    return f;
}

// prepare_scalars, and its vectors for the first pass — on every path, the early returns included (an
// unusable cylinder keeps its bounding box at ±∞, so that nothing is decided from it).
inline CylinderFilter prepare(const Cylinder<double>& cyl) {
    CylinderFilter f = prepare_scalars<Bounded>(cyl);
    for (int j = 0; j < 3; ++j) {
        f.ball.c[j] = f.c[j], f.ball.u[j] = f.u[j];
        f.ball.box_lo[j] = f.box_lo[j], f.ball.box_hi[j] = f.box_hi[j];
    }
    f.ball.two_h = 2 * f.h, f.ball.two_r = 2 * f.r, f.ball.four_r2 = 4 * f.r2, f.ball.kappa = f.kappa;
    return f;
}

// What the filter proved for each lane: decided lanes answer `hit`; the others are undecided.
struct LaneResult {
    LaneMask decided;
    LaneMask hit;
};

BOXCYL_FORCE_INLINE inline Lanes clamp(const Lanes& x, const Lanes& lo, const Lanes& hi) { return stdx::min(stdx::max(x, lo), hi); }

// The certified tests at a box point w, given as v (relative to C) exact up to `ev` per component
// (ev = 0 when v_j is within 2^-52|v_j| of w_j): with a = u·w,
//   e_a ≥ |â − a|: K·Σ|û_j||v_j| (products, sums, and v's own rounding) + δ_u·Σ|v_j| + 2.5·ev + τ
//   inside radially (|w|² − a² ≤ r²): (R2 − q̂) + â² > K(R2 + q̂ + â²) + e_a(2|â| + e_a) + ev(2Σ|v_j| + 3ev) + τ
//   below the top (a ≤ H):      H − â > e_a + K(H + |â|);   above the bottom (a ≥ −H): H + â > the same
// (|â² − a²| ≤ e_a(2|â| + e_a); |q̂ − |w|²| ≤ K·q̂ + Σ_j ev(2|v_j| + ev); Σ|û_j| ≤ √3(1 + 2^-40) and
// δ_u ≤ 2^-20 give the 2.5).
struct PointTests {
    LaneMask radial, below_top, above_bottom;
};
// The terms of the tests that depend on the point and the axis alone (û, δ_u), not on the radius or
// the height: cylinders that share the axis (the clearance form's probes) share them, and each further
// cylinder's tests cost a few operations (point_tests below: the same values, summed in the same order).
struct PointTerms {
    Lanes a, aa, ea, q, a2, t1, t2;
};
BOXCYL_FORCE_INLINE inline PointTerms point_terms(const CylinderFilter& f, const Lanes v[3], const Lanes& ev) {
    PointTerms t;
    t.a = f.u[0] * v[0] + f.u[1] * v[1] + f.u[2] * v[2];
    const Lanes sa = std::fabs(f.u[0]) * stdx::abs(v[0]) + std::fabs(f.u[1]) * stdx::abs(v[1]) +
                     std::fabs(f.u[2]) * stdx::abs(v[2]);
    const Lanes sv = stdx::abs(v[0]) + stdx::abs(v[1]) + stdx::abs(v[2]);
    t.ea = kRel * sa + f.du * sv + 2.5 * ev + kAbs;
    t.aa = stdx::abs(t.a);
    t.q = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    t.a2 = t.a * t.a;
    t.t1 = t.ea * (2 * t.aa + t.ea);
    t.t2 = ev * (2 * sv + 3 * ev);
    return t;
}
BOXCYL_FORCE_INLINE inline PointTests point_tests(const CylinderFilter& f, const PointTerms& t) {
    const Lanes axial_bound = t.ea + kRel * (f.h + t.aa);
    const Lanes m = (f.r2 - t.q) + t.a2;
    const Lanes bound = kRel * (f.r2 + t.q + t.a2) + t.t1 + t.t2 + kAbs;
    return {m > bound, (f.h - t.a) > axial_bound, (f.h + t.a) > axial_bound};
}
BOXCYL_FORCE_INLINE inline PointTests point_tests(const CylinderFilter& f, const Lanes v[3], const Lanes& ev) {
    return point_tests(f, point_terms(f, v, ev));
}

// A certain hit from box points P_k (each exactly in the box): if the points that are radially inside
// include one with a ≤ H and one with a ≥ −H, the segment between those two lies in the box (convex)
// and radially inside (the distance to the axis line is convex), and a is affine along it, so one of
// its points has |a| ≤ H: it lies in the cylinder. (One point with both is the plain case; two points
// on either side of the end planes certify the hits of disks, h = 0, and of boxes over an end.)
BOXCYL_FORCE_INLINE inline LaneMask certain_hit(const PointTests* p, int count) {
    LaneMask low(false), high(false);
    for (int k = 0; k < count; ++k) {
        low = low || (p[k].radial && p[k].below_top);
        high = high || (p[k].radial && p[k].above_bottom);
    }
    return low && high;
}

// Normalises n in place (n/|n|, rounded: any double vector is a valid direction) and reports the lanes
// where that worked and |n| ≤ 1 + 2^-42 is certain: Σ n̂_j² computed ≤ 1 + 2^-42 gives
// |n̂|² ≤ (1 + 2^-42)(1 + 2^-49) + 3·2^-1074 < (1 + 2^-42)² (r_n carries 1 + 2^-40).
BOXCYL_FORCE_INLINE inline LaneMask normalise(Lanes n[3]) {
    const Lanes nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    LaneMask ok = nn >= 0x1p-600 && nn <= 0x1p600;
    Lanes s = 1;
    stdx::where(ok, s) = stdx::sqrt(nn);
    for (int j = 0; j < 3; ++j) n[j] = n[j] / s;
    const Lanes n2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    return ok && n2 <= 1 + 0x1p-42;
}

// The radial miss test along a lane direction n̂ (|n̂| ≤ 1 + 2^-42, `dir_ok`): the box's support along
// n̂ relative to C is Ŝ⁺ with error ≤ K·err_s, and the cylinder's is H|u·n̂| + r√(|n̂|² − (u·n̂)²).
// p̂ = û·n̂ is within e_p = K·Σ|û_j||n̂_j| + δ_u·Σ|n̂_j| + τ of u·n̂; with p_lo = max(0, |p̂| − e_p)
// (rounded down: (·)(1 − 2^-50)), √(|n̂|² − (u·n̂)²) ≤ √(1 + 2^-40 − p_lo²) ≤ s_up, computed with the
// factors (1 − 2^-50) on p_lo² and (1 + 2^-50) on the root that cover its four roundings. Miss if
// −(Ŝ⁺ + H(|p̂| + e_p) + r·s_up) > K(err_s + H(|p̂| + e_p) + r·s_up) + τ.
BOXCYL_FORCE_INLINE inline LaneMask radial_miss(const CylinderFilter& f, const Lanes n[3], const Lanes& s_plus, const Lanes& err_s) {
    Lanes p = 0, tpu = 0, sn = 0;
    for (int j = 0; j < 3; ++j) {
        p += f.u[j] * n[j];
        tpu += std::fabs(f.u[j]) * stdx::abs(n[j]);
        sn += stdx::abs(n[j]);
    }
    const Lanes ap = stdx::abs(p);
    const Lanes ep = kRel * tpu + f.du * sn + kAbs;
    const Lanes p_lo = stdx::max(Lanes(0), (ap - ep) * (1 - 0x1p-50));
    const Lanes s_up = stdx::sqrt(stdx::max(Lanes(0), (1 + 0x1p-40) - (p_lo * p_lo) * (1 - 0x1p-50))) * (1 + 0x1p-50);
    const Lanes axial = f.h * (ap + ep);
    const Lanes across = f.r * s_up;
    const Lanes m = -(s_plus + axial + across);
    return m > kRel * (err_s + axial + across) + kAbs;
}

// Moves w (relative to C) to the nearest point of the cylinder shrunk by the depth f.aim (radius and
// half-height each less by it), in plain double: only a choice of the next target, nothing is
// concluded from it.
BOXCYL_FORCE_INLINE inline void into_cylinder(const CylinderFilter& f, const Lanes w[3], Lanes y[3]) {
    const Lanes a = f.u[0] * w[0] + f.u[1] * w[1] + f.u[2] * w[2];
    const double h7 = f.h - f.aim;
    const Lanes ac = clamp(a, -h7, h7);
    Lanes rho[3];
    for (int j = 0; j < 3; ++j) rho[j] = w[j] - a * f.u[j];
    const Lanes rr = rho[0] * rho[0] + rho[1] * rho[1] + rho[2] * rho[2];
    const double r7 = f.r - f.aim;
    Lanes scale = 1;
    const LaneMask outside = rr > r7 * r7;
    stdx::where(outside, scale) = r7 / stdx::sqrt(stdx::max(rr, Lanes(0x1p-1000)));
    for (int j = 0; j < 3; ++j) y[j] = ac * f.u[j] + scale * rho[j];
}

// The hit search that ends both filters: from the box point w0, alternate between the box (`to_box`:
// the nearest box point, exactly a box point) and the cylinder shrunk by f.aim (into_cylinder, a mere
// target), testing the box point after steps 2, 4 and 8 alone and with the start points pt[0..2] (the
// two-point certificate); ev as in point_tests. The hits it proves; it stops early once every lane is
// a hit or in `done` (decided before). For oriented boxes it is a pass of its own over the lanes their
// filter leaves, gathered into full vectors (kernel.hpp): run on the filter's own vectors, each vector
// with one open lane spent the eight steps' square roots and divisions on all its lanes (gathered,
// bench_batch's near-surface oriented sets ran ≈20% faster with AVX-512, ≈10% with SSE2). Aligned
// boxes reach it in their second pass, whose vectors are gathered already: a pass of its own gained
// nothing there.
template <class ToBox>
BOXCYL_FORCE_INLINE inline LaneMask search_hits(const CylinderFilter& f, const LaneMask& ok, const LaneMask& done,
                                         PointTests pt[4], const Lanes w0[3], const Lanes& ev, ToBox&& to_box) {
    Lanes w[3] = {w0[0], w0[1], w0[2]};
    LaneMask hit(false);
    for (int it = 1; it <= kSteps; ++it) {
        Lanes z[3];
        into_cylinder(f, w, z);
        to_box(z, w);
        if (it != 2 && it != 4 && it != kSteps) continue;
        pt[3] = point_tests(f, w, ev);
        hit = hit || (ok && certain_hit(pt, 4));
        if (stdx::all_of(done || hit)) break;
    }
    return hit && !done;
}

// ---- Aligned boxes: lo ≤ X ≤ hi. ----
//
// First pass (every box, no branches): the box's centre and a ball around it. With d̂lo, d̂hi = fl(lo − C),
// fl(hi − C), in doubled coordinates (no halvings, which could round): ŝ = fl(d̂lo + d̂hi) (twice the centre,
// relative to C; ŝ_j/2 lies in [d̂lo_j, d̂hi_j] since rounding is monotone), t̂ = fl(d̂hi − d̂lo) (twice the
// half-extents). docs/robustness/batch.md derives, with u = 2^-52, ε_A = 3.01u + 1.74δ_u:
//   * the box lies in the ball around C + ŝ/2 of radius ρ, 2ρ ≤ |t̂|(1 + 2^-49) + 2^-49|ŝ|;
//   * a point W/2 of the box (exactly) has |W − ŝ| ≤ 2u|ŝ|;
//   * Q̂ = fl(Σŝ_j²), Â = fl(Σû_jŝ_j) (|Â − u·ŝ| ≤ ε_A|ŝ|), Ŝ1 = fl(Σ|ŝ_j|) ≥ |ŝ|(1 − 2.01u),
//     T̂ = fl(t̂_x + t̂_y + t̂_z) ≥ |t̂|(1 − 2.01u) (the 1-norm: no square root, whose latency would cost
//     more than the slightly bigger ball; t̂_j ≥ 0 by monotone rounding), R̂ = fl(2r + T̂).
// With κ = 2^-44 + 2δ_u (every term below is at least twice what it must cover) and τ = 2^-800:
//   miss, radially (the ball is further than r from the axis line):  (Q̂ − Â²) − R̂² > κ(Q̂ + Â² + R̂²) + τ
//   miss, axially (the ball lies beyond an end plane):               |Â| − 2H − T̂ > κ(|Â| + 2H + T̂ + Ŝ1) + τ
//   hit (the box point W/2 is in the cylinder):                      (4R2 − Q̂) + Â² > κ(4R2 + Q̂ + Â²) + τ
//                                                               and 2H − |Â| > κ(2H + |Â| + Ŝ1) + τ.
// Eligible: Ŝ1, T̂ ≤ 2^200 (false for NaN and ∞), so nothing overflows. Lanes that none of these decide
// (boxes near the surface, big boxes) go on to aligned_lanes.
// The ball's terms (doubled coordinates relative to C): Q̂, Â, Ŝ1 and T̂. They depend on C and û
// alone, so that cylinders sharing them (the clearance form's probes) share the terms.
struct BallTerms {
    Lanes q, a, s1, t;
};
BOXCYL_FORCE_INLINE inline BallTerms ball_terms(const BallConstants& b, const Lanes lo[3], const Lanes hi[3]) {
    BallTerms x{0, 0, 0, 0};
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC unroll 3
#endif
    for (int j = 0; j < 3; ++j) {
        const Lanes dlo = lo[j] - b.c[j], dhi = hi[j] - b.c[j];
        const Lanes s = dlo + dhi;
        x.q += s * s;
        x.a += b.u[j] * s;
        x.s1 += stdx::abs(s);
        x.t += dhi - dlo;
    }
    return x;
}
// The ball's verdict against the cylinder of `b` (a usable filter's), without the bounding boxes.
BOXCYL_FORCE_INLINE inline LaneResult ball_verdict(const BallConstants& b, const BallTerms& x) {
    const Lanes aa = stdx::abs(x.a), a2 = x.a * x.a;
    const Lanes rr = b.two_r + x.t, r2 = rr * rr;
    const LaneMask ok = x.s1 <= kLimit && x.t <= kLimit;
    const LaneMask miss = ((x.q - a2) - r2 > b.kappa * (x.q + a2 + r2) + kAbs) ||
                          (aa - b.two_h - x.t > b.kappa * (aa + b.two_h + x.t + x.s1) + kAbs);
    const LaneMask hit = ((b.four_r2 - x.q) + a2 > b.kappa * (b.four_r2 + x.q + a2) + kAbs) &&
                         (b.two_h - aa > b.kappa * (b.two_h + aa + x.s1) + kAbs);
    const LaneMask dec = ok && (miss || hit);
    return {dec, dec && !miss};
}
// The hit half of ball_verdict alone: the lanes whose ball certainly lies in the cylinder of `b` (a
// ball cannot also be proved to miss it).
BOXCYL_FORCE_INLINE inline LaneMask ball_inside(const BallConstants& b, const BallTerms& x) {
    const Lanes aa = stdx::abs(x.a), a2 = x.a * x.a;
    return x.s1 <= kLimit && x.t <= kLimit && ((b.four_r2 - x.q) + a2 > b.kappa * (b.four_r2 + x.q + a2) + kAbs) &&
           (b.two_h - aa > b.kappa * (b.two_h + aa + x.s1) + kAbs);
}
// The box point nearest to C, relative to C: w_j = clamp(0, d̂lo_j, d̂hi_j). As for every clamped point
// (aligned_lanes' hit point, y = 0), w is within 2^-52|w_j| per component of a point of the box, exactly:
// point_tests applies with ev = 0.
BOXCYL_FORCE_INLINE inline void nearest_to_centre(const BallConstants& b, const Lanes lo[3], const Lanes hi[3], Lanes w[3]) {
    for (int j = 0; j < 3; ++j) w[j] = clamp(Lanes(0), lo[j] - b.c[j], hi[j] - b.c[j]);
}
// The lanes whose box point w (nearest_to_centre) certainly lies in the cylinder of f (a usable
// filter's); eligible where |w_j| ≤ 2^200, point_tests' range.
BOXCYL_FORCE_INLINE inline LaneMask point_inside(const CylinderFilter& f, const PointTerms& t, const LaneMask& in_range) {
    const PointTests p = point_tests(f, t);
    return in_range && p.radial && p.below_top && p.above_bottom;
}
BOXCYL_FORCE_INLINE inline LaneMask point_in_range(const Lanes w[3]) {
    return stdx::max(stdx::max(stdx::abs(w[0]), stdx::abs(w[1])), stdx::abs(w[2])) <= kLimit;
}

// What the first pass computed for a vector, for the clearance form's later probes (kernel.hpp's
// LaterBalls), which share C and û: the ball's terms where `computed`, and where `tried` the box point
// nearest to C and the lanes it proved to be hits (`by_point`).
struct FirstPassTerms {
    BallTerms x;
    PointTerms w;       // the point's terms (point_terms, ev = 0), which probes sharing û and δ_u share
    LaneMask w_ok;      // the point within point_tests' range
    LaneMask by_point;  // no initialiser: the constructor would not inline into a kernel's `#pragma GCC target`
    bool computed = false, tried = false;
};

// `terms`, when given, receives what was computed (FirstPassTerms; nothing where every lane was decided
// by the bounding boxes, or the filter is unusable).
// Where the ball leaves lanes, the box point nearest to C is tried as a hit: a box that holds C, or
// reaches past it towards the axis, has it in the cylinder, while its ball, as big as the box, fails
// the ball's hit test (on bench_batch's 10M random boxes it leaves 1.6% to the second pass, the ball
// alone 16%).
BOXCYL_FORCE_INLINE inline LaneResult aligned_ball_lanes(const CylinderFilter& f, const Lanes lo[3], const Lanes hi[3],
                                                         FirstPassTerms* terms = nullptr) {
    // The bounding boxes first: on voxel-like data most vectors end here, and the branch saves the
    // rest of the pass. Exact: for doubles x, y (±∞ included, never NaN here) fl(x − y) > 0 iff x > y,
    // and one comparison of the largest difference costs fewer instructions than six of mask logic.
    const BallConstants& b = f.ball;
    const Lanes gap = stdx::max(stdx::max(stdx::max(lo[0] - b.box_hi[0], b.box_lo[0] - hi[0]),
                                          stdx::max(lo[1] - b.box_hi[1], b.box_lo[1] - hi[1])),
                                stdx::max(lo[2] - b.box_hi[2], b.box_lo[2] - hi[2]));
    const LaneMask out = gap > 0;
    if (stdx::all_of(out)) return {out, LaneMask(false)};
    if (!f.usable) return {out, LaneMask(false)};
    const BallTerms x = ball_terms(b, lo, hi);
    const LaneResult v = ball_verdict(b, x);
    LaneMask decided = out || v.decided, hit = v.hit && !out;
    if (terms != nullptr) terms->x = x, terms->computed = true;
    if (!stdx::all_of(decided)) {
        Lanes w[3];
        nearest_to_centre(b, lo, hi, w);
        const PointTerms pt = point_terms(f, w, Lanes(0));
        const LaneMask w_ok = point_in_range(w);
        const LaneMask by_point = point_inside(f, pt, w_ok) && !out;
        decided = decided || by_point, hit = hit || by_point;
        if (terms != nullptr) {
            terms->w = pt, terms->w_ok = w_ok;
            terms->by_point = by_point, terms->tried = true;
        }
    }
    return {decided, hit};
}

//
// d = lo − C, hi − C rounded: |d̂ − d| ≤ 2^-52|d̂| (a subnormal difference is exact).
// Bounding boxes: exact comparisons of the inputs with the outward cylinder bounding box.
// Slab along û: S⁺ = Σ û_j far_j = max over the box of û·(X − C) (far_j: hi_j − C_j where û_j ≥ 0),
//   S⁻ = Σ û_j near_j; the cylinder lies in |û·(X − C)| ≤ ρ_u. Miss if −(Ŝ⁺ + ρ_u) > K(Σ|û_j||far_j| + ρ_u) + τ,
//   or Ŝ⁻ − ρ_u > K(Σ|û_j||near_j| + ρ_u) + τ.
// Hit point: v_j = clamp(y_j, d̂lo_j, d̂hi_j) for any double y_j. Rounding is monotone and fixes doubles,
//   so d̂lo_j < y_j < d̂hi_j implies lo_j ≤ C_j + y_j ≤ hi_j: then v_j = y_j is exact; otherwise v_j is
//   d̂lo_j or d̂hi_j, within 2^-52|v_j| of lo_j − C_j or hi_j − C_j. Either way v is within 2^-52|v_j| per
//   component of P − C for a point P of the box, exactly: the hit test applies with ev = 0.
// Radial miss: n = y − v (from the box point towards the axis point), normalised; the box's support
//   along n̂ is S⁺ = Σ n̂_j far_j (far_j by the sign of n̂_j, per lane), the cylinder's at most
//   H|u·n̂| + r|n̂| ≤ H(|û·n̂| + γΣ|û_j||n̂_j| + δ_uΣ|n̂_j|) + r_n. Miss if
//   −(Ŝ⁺ + H|p̂| + r_n) > K(Σ|n̂_j||far_j| + H(|p̂| + Σ|û_j||n̂_j|) + r_n) + H·δ_u·Σ|n̂_j| + τ, p̂ = û·n̂.
inline LaneResult aligned_lanes(const CylinderFilter& f, const Lanes lo[3], const Lanes hi[3]) {
    LaneMask miss = (lo[0] > f.box_hi[0]) || (hi[0] < f.box_lo[0]) || (lo[1] > f.box_hi[1]) ||
                    (hi[1] < f.box_lo[1]) || (lo[2] > f.box_hi[2]) || (hi[2] < f.box_lo[2]);
    if (stdx::all_of(miss) || !f.usable) return {miss, LaneMask(false)};
    Lanes dlo[3], dhi[3];
    for (int j = 0; j < 3; ++j) dlo[j] = lo[j] - f.c[j], dhi[j] = hi[j] - f.c[j];
    const Lanes big = stdx::max(stdx::max(stdx::max(stdx::abs(dlo[0]), stdx::abs(dhi[0])),
                                          stdx::max(stdx::abs(dlo[1]), stdx::abs(dhi[1]))),
                                stdx::max(stdx::abs(dlo[2]), stdx::abs(dhi[2])));
    const LaneMask ok = big <= kLimit;

    // Slab along û.
    Lanes smax_c = 0, smin_c = 0;
    {
        Lanes smax = 0, smin = 0, tmax = 0, tmin = 0;
        for (int j = 0; j < 3; ++j) {
            const Lanes& far = f.u_nonneg[j] ? dhi[j] : dlo[j];
            const Lanes& near = f.u_nonneg[j] ? dlo[j] : dhi[j];
            const double au = std::fabs(f.u[j]);
            smax += f.u[j] * far, smin += f.u[j] * near;
            tmax += au * stdx::abs(far), tmin += au * stdx::abs(near);
        }
        miss = miss || (ok && (-(smax + f.rho_u) > kRel * (tmax + f.rho_u) + kAbs)) ||
               (ok && (smin - f.rho_u > kRel * (tmin + f.rho_u) + kAbs));
        smax_c = smax, smin_c = smin;
    }
    if (stdx::all_of(miss)) return {miss, LaneMask(false)};

    // Box points nearest to three axis points: the one nearest to the box centre (t_c), and t_c ± λ
    // with λ a quarter of the box's extent along û.
    Lanes t = 0;
    for (int j = 0; j < 3; ++j) t += f.u[j] * ((dlo[j] + dhi[j]) * 0.5);
    t = clamp(t, -f.h, f.h);
    const Lanes lambda = (smax_c - smin_c) * 0.25;
    Lanes v[3], y[3], w[3];
    PointTests pt[4];
    for (int k = 1; k < 3; ++k) {
        const Lanes tk = k == 1 ? t - lambda : t + lambda;
        for (int j = 0; j < 3; ++j) w[j] = clamp(tk * f.u[j], dlo[j], dhi[j]);
        pt[k] = point_tests(f, w, Lanes(0));
    }
    for (int j = 0; j < 3; ++j) y[j] = t * f.u[j], v[j] = clamp(y[j], dlo[j], dhi[j]);
    pt[0] = point_tests(f, v, Lanes(0));
    LaneMask hit = ok && !miss && certain_hit(pt, 3);
    if (stdx::all_of(miss || hit)) return {miss || hit, hit};
    // The ball around the box, for the small boxes inside the bounding box but away from the axis,
    // after the three point tests (they decide most lanes that reach this pass: 92% on the benchmark's
    // random boxes, where the ball decides 2%; ahead of them it cost 8% of that run):
    // the box lies in the ball around C + p̂, p̂ the computed centre (any double vector), of radius
    // δ̂ ≥ the largest corner distance: per axis g_j = max|d̂_j − p̂_j| plus 2^-51(|d̂lo_j| + |d̂hi_j|) for
    // the rounding of d̂ and g_j, then √ of the sum of squares (≤ 6 roundings) times (1 + 2^-48), plus
    // 2^-500 for squares lost to underflow. The box misses if the ball's centre is further than r + δ
    // from the axis line: with a = û·p̂ (error e_a as in point_tests) and R̂ = r_n + δ̂ (≥ r + δ for sure:
    // r_n and δ̂ carry ≥ 2^-48 of slack against R̂'s rounding), miss if
    // (q̂ − â²) − R̂² > K(q̂ + â² + R̂²) + e_a(2|â| + e_a) + τ, q̂ = |p̂|².
    {
        Lanes p[3], sq = 0, sa = 0, sv = 0;
        for (int j = 0; j < 3; ++j) {
            p[j] = (dlo[j] + dhi[j]) * 0.5;
            const Lanes g = stdx::max(stdx::abs(dhi[j] - p[j]), stdx::abs(dlo[j] - p[j])) +
                            0x1p-51 * (stdx::abs(dlo[j]) + stdx::abs(dhi[j]));
            sq += g * g;
            sa += std::fabs(f.u[j]) * stdx::abs(p[j]);
            sv += stdx::abs(p[j]);
        }
        const Lanes delta = stdx::sqrt(sq) * (1 + 0x1p-48) + 0x1p-500;
        const Lanes a = f.u[0] * p[0] + f.u[1] * p[1] + f.u[2] * p[2];
        const Lanes ea = kRel * sa + f.du * sv + kAbs;
        const Lanes q = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
        const Lanes rr = f.r_n + delta;
        const Lanes a2 = a * a, r2 = rr * rr;
        const Lanes bound = kRel * (q + a2 + r2) + ea * (2 * stdx::abs(a) + ea) + kAbs;
        miss = miss || (ok && ((q - a2) - r2 > bound));
    }
    hit = hit && !miss;
    if (stdx::all_of(miss || hit)) return {miss || hit, hit};

    // Radial separation along the direction from the box point nearest to an axis point to that
    // axis point, after one more step of alternating projection (v, then the axis point nearest to it).
    t = clamp(f.u[0] * v[0] + f.u[1] * v[1] + f.u[2] * v[2], -f.h, f.h);
    for (int j = 0; j < 3; ++j) y[j] = t * f.u[j], v[j] = clamp(y[j], dlo[j], dhi[j]);
    Lanes n[3] = {y[0] - v[0], y[1] - v[1], y[2] - v[2]};
    const LaneMask dir_ok = normalise(n);
    Lanes sp = 0, tp = 0;
    for (int j = 0; j < 3; ++j) {
        Lanes far = dlo[j];
        stdx::where(n[j] >= 0, far) = dhi[j];
        sp += n[j] * far;
        tp += stdx::abs(n[j]) * stdx::abs(far);
    }
    miss = miss || (ok && dir_ok && radial_miss(f, n, sp, tp));
    if (stdx::all_of(miss || hit)) return {miss || hit, hit};
    // Still undecided: the hit search, on these vectors (see `search_hits`).
    const auto to_box = [&dlo, &dhi](const Lanes z[3], Lanes x[3]) BOXCYL_FORCE_INLINE {
        for (int j = 0; j < 3; ++j) x[j] = clamp(z[j], dlo[j], dhi[j]);
    };
    hit = hit || search_hits(f, ok, miss || hit, pt, v, Lanes(0), to_box);
    return {miss || hit, hit};
}

// ---- Oriented boxes: {K + Σ ξ_i A_i : |ξ_i| ≤ e_i}, the axes A_i exactly as given. ----
//
// d = K − C rounded (|d̂ − d| ≤ 2^-52|d̂|). Eligible: |d̂_j|, e_i ≤ 2^200, |A_ij| ≤ 2; E = Σ e_i.
// Along e_j: the box spans d_j ± Σ_i e_i|A_ij|, the cylinder ±w_j. Miss if
//   |d̂_j| − hw_j − w_j > K(|d̂_j| + hw_j + w_j) + τ, hw_j = Σ_i e_i|A_ij| computed.
// Along û: the box spans û·d ± Σ_i e_i|û·A_i|. With Σ_j|û_j||A_ij| ≤ 2·√3(1 + 2^-40) < 4, every rounding
//   of p_i = û·A_i and of Σ e_i|p_i| is within K·4E: miss if −(û·d + ext + ρ_u) or (û·d − ext − ρ_u)
//   exceeds K(Σ|û_j||d̂_j| + 4E + ρ_u) + τ.
// Hit point: ξ_i = clamp(A_i·(y − d̂), −e_i, e_i) (exactly within ±e_i), v = d̂ + Σ ξ_i A_i rounded; the
//   box point w = K − C + Σ ξ_i A_i is within ev = K(max_j|d̂_j| + 2E) of v per component.
// Radial miss: as for aligned boxes, with the box's support along n̂ = n̂·d + Σ_i e_i|n̂·A_i|, within
//   K(Σ|n̂_j||d̂_j| + 4E) (Σ_j|n̂_j||A_ij| ≤ 2√3(1 + 2^-42) < 4).
// The lanes' box centre relative to C, d̂ = fl(K − C), the bound ev on a box point's rounding, and
// the eligibility.
struct OrientedFrame {
    Lanes d[3], E, ev;
    LaneMask ok;
};
BOXCYL_FORCE_INLINE inline OrientedFrame oriented_frame(const CylinderFilter& f, const Lanes k[3], const Lanes A[3][3],
                                                 const Lanes e[3]) {
    OrientedFrame o;
    for (int j = 0; j < 3; ++j) o.d[j] = k[j] - f.c[j];
    const Lanes dmax = stdx::max(stdx::max(stdx::abs(o.d[0]), stdx::abs(o.d[1])), stdx::abs(o.d[2]));
    Lanes amax = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) amax = stdx::max(amax, stdx::abs(A[i][j]));
    o.E = e[0] + e[1] + e[2];
    o.ok = dmax <= kLimit && o.E <= kLimit && amax <= 2;
    o.ev = kRel * (dmax + 2 * o.E);
    return o;
}
// The box's half-extent along û, Σ e_i|û·A_i|.
BOXCYL_FORCE_INLINE inline Lanes oriented_extent(const CylinderFilter& f, const Lanes A[3][3], const Lanes e[3]) {
    Lanes ext = 0;
    for (int i = 0; i < 3; ++i) ext += e[i] * stdx::abs(f.u[0] * A[i][0] + f.u[1] * A[i][1] + f.u[2] * A[i][2]);
    return ext;
}
// The box point nearest (in box coordinates) to y: ξ clamped to ±e, v = d̂ + Σ ξ_i A_i.
BOXCYL_FORCE_INLINE inline void oriented_point(const OrientedFrame& o, const Lanes A[3][3], const Lanes e[3], const Lanes y[3],
                                        Lanes v[3]) {
    Lanes xi[3];
    for (int i = 0; i < 3; ++i)
        xi[i] = clamp(A[i][0] * (y[0] - o.d[0]) + A[i][1] * (y[1] - o.d[1]) + A[i][2] * (y[2] - o.d[2]), -e[i], e[i]);
    for (int j = 0; j < 3; ++j) v[j] = o.d[j] + xi[0] * A[0][j] + xi[1] * A[1][j] + xi[2] * A[2][j];
}
// Box points nearest to three axis points, as for aligned boxes (λ half the extent along û): v the
// one nearest to the axis point nearest to the centre; their tests in pt[0], pt[1], pt[2].
BOXCYL_FORCE_INLINE inline void oriented_start(const CylinderFilter& f, const OrientedFrame& o, const Lanes A[3][3],
                                        const Lanes e[3], const Lanes& ext, Lanes v[3], PointTests pt[3]) {
    const Lanes t = clamp(f.u[0] * o.d[0] + f.u[1] * o.d[1] + f.u[2] * o.d[2], -f.h, f.h);
    const Lanes lambda = ext * 0.5;
    Lanes y[3], w[3];
    for (int k = 1; k < 3; ++k) {
        const Lanes tk = k == 1 ? t - lambda : t + lambda;
        for (int j = 0; j < 3; ++j) y[j] = tk * f.u[j];
        oriented_point(o, A, e, y, w);
        pt[k] = point_tests(f, w, o.ev);
    }
    for (int j = 0; j < 3; ++j) y[j] = t * f.u[j];
    oriented_point(o, A, e, y, v);
    pt[0] = point_tests(f, v, o.ev);
}
// One more step of alternating projection: the axis point y nearest to v, then v the box point nearest to y.
BOXCYL_FORCE_INLINE inline void oriented_step(const CylinderFilter& f, const OrientedFrame& o, const Lanes A[3][3],
                                       const Lanes e[3], Lanes v[3], Lanes y[3]) {
    const Lanes t = clamp(f.u[0] * v[0] + f.u[1] * v[1] + f.u[2] * v[2], -f.h, f.h);
    for (int j = 0; j < 3; ++j) y[j] = t * f.u[j];
    oriented_point(o, A, e, y, v);
}

inline LaneResult oriented_lanes(const CylinderFilter& f, const Lanes k[3], const Lanes A[3][3], const Lanes e[3]) {
    if (!f.usable) return {LaneMask(false), LaneMask(false)};
    const OrientedFrame o = oriented_frame(f, k, A, e);
    const Lanes(&d)[3] = o.d;
    const Lanes& E = o.E;
    const LaneMask& ok = o.ok;

    LaneMask miss(false);
    for (int j = 0; j < 3; ++j) {
        const Lanes hw = e[0] * stdx::abs(A[0][j]) + e[1] * stdx::abs(A[1][j]) + e[2] * stdx::abs(A[2][j]);
        const Lanes ad = stdx::abs(d[j]);
        miss = miss || (ad - hw - f.w[j] > kRel * (ad + hw + f.w[j]) + kAbs);
    }
    miss = miss && ok;
    if (stdx::all_of(miss)) return {miss, LaneMask(false)};

    // Slab along û.
    const Lanes ext = oriented_extent(f, A, e);
    {
        Lanes ud = 0, sud = 0;
        for (int j = 0; j < 3; ++j) ud += f.u[j] * d[j], sud += std::fabs(f.u[j]) * stdx::abs(d[j]);
        const Lanes bound = kRel * (sud + 4 * E + f.rho_u) + kAbs;
        miss = miss || (ok && (-(ud + ext + f.rho_u) > bound || (ud - ext - f.rho_u) > bound));
    }
    if (stdx::all_of(miss)) return {miss, LaneMask(false)};

    Lanes v[3], y[3];
    PointTests pt[3];
    oriented_start(f, o, A, e, ext, v, pt);
    const LaneMask hit = ok && !miss && certain_hit(pt, 3);
    if (stdx::all_of(miss || hit)) return {miss || hit, hit};
    // Radial separation, after one more step of alternating projection.
    oriented_step(f, o, A, e, v, y);
    Lanes n[3] = {y[0] - v[0], y[1] - v[1], y[2] - v[2]};
    const LaneMask dir_ok = normalise(n);
    Lanes sp = 0, tp = 0;
    for (int j = 0; j < 3; ++j) {
        sp += n[j] * d[j];
        tp += stdx::abs(n[j]) * stdx::abs(d[j]);
    }
    for (int i = 0; i < 3; ++i) sp += e[i] * stdx::abs(n[0] * A[i][0] + n[1] * A[i][1] + n[2] * A[i][2]);
    miss = miss || (ok && dir_ok && radial_miss(f, n, sp, tp + 4 * E));
    return {miss || hit, hit};  // still undecided: oriented_search_lanes
}

// The hit search for the lanes oriented_lanes left (gathered), as aligned_search_lanes.
inline LaneResult oriented_search_lanes(const CylinderFilter& f, const Lanes k[3], const Lanes A[3][3], const Lanes e[3]) {
    if (!f.usable) return {LaneMask(false), LaneMask(false)};
    const OrientedFrame o = oriented_frame(f, k, A, e);
    Lanes v[3], y[3];
    PointTests pt[4];
    oriented_start(f, o, A, e, oriented_extent(f, A, e), v, pt);
    oriented_step(f, o, A, e, v, y);
    const auto to_box = [&](const Lanes z[3], Lanes w[3]) BOXCYL_FORCE_INLINE { oriented_point(o, A, e, z, w); };
    const LaneMask hit = search_hits(f, o.ok, LaneMask(false), pt, v, o.ev, to_box);
    return {hit, hit};
}

}  // namespace detail
}  // namespace BOXCYL_BATCH_ISA
}  // namespace boxcyl::batch
