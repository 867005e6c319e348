// Stage 0 of the exact default (row semi_static): a semi-static filter in plain double.
//
// A handful of cheap geometric tests decide most queries far from touching before the
// linear-inequalities method runs at all:
//   misses: a separating axis — a box face normal E_i, the cylinder axis d, or d × E_i;
//   hits:   the cylinder centre inside the box; a witness point Q of the box inside the cylinder
//           (Q: the box point nearest to the cylinder centre, the box centre, and the box point
//           nearest to the axis point nearest to the box centre); or a witness point X of the
//           cylinder inside the box (X: that axis point itself, and the point of its cross-section
//           0.9·r towards the box centre) — the latter for segments and disks too.
// Each test is one polynomial in the inputs evaluated in plain double; it decides only when the
// computed value exceeds a bound B = (κ_ε·ε + κ_g·g)·L^k on its error (L a length scale of the query,
// k the test's degree in lengths, ε = 2^-52, g an oriented frame's distance from orthonormal), with κ_ε,
// κ_g computed at compile time by evaluating the very same template expression on StaticBound
// (number/static_bound.hpp) from the box kind's input model below. Misses are certified on a problem
// containing the exact one, hits on one contained in it; a rounded frame is widened by γ = g·|e|₁. It
// runs only for L ∈ [2^-200, 2^200]. docs/robustness/stage0.md has the derivation.
#pragma once

#include <algorithm>  // std::max, std::min
#include <array>      // the oriented frame
#include <bit>        // std::bit_cast: the unit axis's dropped components without a branch
#include <cstdint>    // std::uint64_t
#include <cmath>      // std::fabs, std::ilogb, std::scalbn, std::sqrt
#include <limits>     // infinity
#include <optional>   // undecided
#include <type_traits>  // std::is_same_v: the witnesses of each box kind
#include <utility>    // std::swap

#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/number/static_bound.hpp"
#include "boxcyl/number/traits.hpp"  // abs_value

// problem() and the unit axis inlined into the query: GCC at -O2 kept them as calls, whose results went
// through memory to the tests that wait for them (3–5% of the default query on bench_stages' random set).
// The same for the small certificates and projections that stage 0b's searches call at every step
// (witness_search.hpp): as calls, stage 0b took ≈10% longer on bench_batch's near-surface boxes.

// The unit axis's dropped components as SSE2 masks where the target has SSE2 (every x86-64): GCC
// compiles the portable form (an integer mask from a comparison) through general registers and back,
// on the path from the axis to every test (stage 0 ≈2 ns slower on bench_query's random set).
#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#define BOXCYL_STAGE0_SSE2 1
#else
#define BOXCYL_STAGE0_SSE2 0
#endif

namespace boxcyl::filtered::semi_static {

inline constexpr double eps = 0x1p-52;  // one rounding, relative, in every rounding mode
inline constexpr double min_scale = 0x1p-200, max_scale = 0x1p200;

// x clamped to [lo, hi] (lo ≤ hi), as std::clamp but without a branch: max then min compile to
// maxsd/minsd, where GCC 12 compiles std::clamp's nested comparison for double to branches, which
// mispredict on random data. Same value for every input, NaN included.
inline double clamp_to(double x, double lo, double hi) { return std::min(std::max(x, lo), hi); }

// ---- The tests, written once over T: double evaluates them, StaticBound bounds their error. ----

// A box face normal E_i separates when the box's gap s = |c_i| − e_i − H|d_i| exceeds the cylinder's
// cross-section half-width r·√(1 − d_i²) = r·√(d_j² + d_k²) (|d| = 1): s > 0 and s² > r²(d_j² + d_k²).
template <class T>
constexpr T face_gap(const T& ci, const T& ei, const T& h, const T& di) {
    return abs_value(ci) - ei - h * abs_value(di);
}
template <class T>
constexpr T face_gap_squared(const T& s, const T& r, const T& dj, const T& dk) {
    return s * s - r * r * (dj * dj + dk * dk);
}
// The cylinder axis d separates when |d·c| > H + Σ e_k|d_k| (the box's extent along d).
template <class T>
constexpr T axis_gap(const Vec3<T>& c, const Vec3<T>& d, const Vec3<T>& e, const T& h) {
    return abs_value(dot(d, c)) - h - (e[0] * abs_value(d[0]) + e[1] * abs_value(d[1]) + e[2] * abs_value(d[2]));
}
// n = d × E_i = (0, d_k, −d_j) in (i, j, k) order, ⊥ d: the axis segment projects to a point, the
// cross-section to r|n|, the box to e_j|d_k| + e_k|d_j|; it separates when s = |n·c| − (that) > 0 and
// s² > r²|n|² = r²(d_j² + d_k²).
template <class T>
constexpr T edge_gap(const T& cj, const T& ck, const T& dj, const T& dk, const T& ej, const T& ek) {
    return abs_value(T(dk * cj - dj * ck)) - (ej * abs_value(dk) + ek * abs_value(dj));
}
// Any direction n (a double vector with |n_i| ≤ 1, exact as given; stage 0b takes it from a nearest-
// point search, filtered/witness_search.hpp): the cylinder's extent along n is H|n·d| + r·|n × d|, the
// box's Σ e_k|n_k|, so n separates when s = |n·c| − H|n·d| − Σ e_k|n_k| > 0 and
// s² > r²|n × d|² = r²(n·n − (n·d)²) (|d| = 1). The face and edge tests are its special cases.
template <class T>
constexpr T direction_gap(const Vec3<T>& n, const Vec3<T>& c, const Vec3<T>& d, const Vec3<T>& e, const T& h) {
    return abs_value(dot(n, c)) - h * abs_value(dot(n, d)) -
           (e[0] * abs_value(n[0]) + e[1] * abs_value(n[1]) + e[2] * abs_value(n[2]));
}
template <class T>
constexpr T direction_gap_squared(const T& s, const Vec3<T>& n, const Vec3<T>& d, const T& r) {
    const T nd = dot(n, d);
    return s * s - r * r * (dot(n, n) - nd * nd);
}
// The cylinder centre inside the box: e_i − |c_i| ≥ 0 for every i.
template <class T>
constexpr T inside_margin(const T& ci, const T& ei) {
    return ei - abs_value(ci);
}
// A box point Q = C + v inside the cylinder: H − |d·v| ≥ 0 and r² − (|v|² − (d·v)²) ≥ 0 (|d| = 1).
template <class T>
constexpr T witness_height_margin(const Vec3<T>& v, const Vec3<T>& d, const T& h) {
    return h - abs_value(dot(d, v));
}
template <class T>
constexpr T witness_radial_margin(const Vec3<T>& v, const Vec3<T>& d, const T& r) {
    const T t = dot(d, v);
    return r * r - (dot(v, v) - t * t);
}
// Signed forms for the two-point certificates below: d·v ≤ H (below the top), d·v ≥ −H (above the
// bottom), and a cylinder point's box coordinate x_i ≤ e_i, x_i ≥ −e_i. Their κ come out equal to the
// absolute forms' (|·| and a sign change round nothing), but are computed from these expressions.
template <class T>
constexpr T witness_top_margin(const Vec3<T>& v, const Vec3<T>& d, const T& h) {
    return h - dot(d, v);
}
template <class T>
constexpr T witness_bottom_margin(const Vec3<T>& v, const Vec3<T>& d, const T& h) {
    return h + dot(d, v);
}
template <class T>
constexpr T chord_upper_margin(const T& ci, const T& ei, const T& t, const T& di, const T& zi, const T& dz) {
    return ei - T(ci + t * di + zi - dz * di);
}
template <class T>
constexpr T chord_lower_margin(const T& ci, const T& ei, const T& t, const T& di, const T& zi, const T& dz) {
    return ei + T(ci + t * di + zi - dz * di);
}
// A point of an oriented box as given, P = K + Σ_m x_m·A_m for doubles x with |x_m| ≤ e_m (exactly a
// point of the parallelepiped its axes span: no polar factor, no γ), relative to C in world
// coordinates; kc = K − C. Stage 0b tests such points against the cylinder in world coordinates.
template <class T>
constexpr Vec3<T> world_offset(const Vec3<T>& kc, const std::array<Vec3<T>, 3>& a, const Vec3<T>& x) {
    Vec3<T> v;
    for (int j = 0; j < 3; ++j) v[j] = kc[j] + ((x[0] * a[0][j] + x[1] * a[1][j]) + x[2] * a[2][j]);
    return v;
}
// A cylinder point X = C + t·d + (z − (d·z)·d) for doubles t, z with |t| ≤ H exactly and
// |z − (d·z)d| ≤ r (that is witness_radial_margin(z, d, r) ≥ 0; nothing to check for z = 0) inside
// the box: e_i − |c_i + t·d_i + z_i − (d·z)·d_i| ≥ 0 for every i (dz = d·z, computed once).
template <class T>
constexpr T chord_box_margin(const T& ci, const T& ei, const T& t, const T& di, const T& zi, const T& dz) {
    return ei - abs_value(T(ci + t * di + zi - dz * di));
}

// ---- Input models: magnitude (units of L) and error (units of ε·L and g·L) of the computed data. ----
// L = 2·max|input length|. docs/robustness/stage0.md derives each entry (the unit axis's 3.6ε, the
// aligned centre's rounding, an oriented frame's 7ε + g, the witnesses' |t| ≤ 0.26L and |z_i| ≤ 2L,
// a separating direction scaled to |n_i| ≤ 1).
struct InputModel {
    StaticBound c, d, e, r, h, v;
    StaticBound t{0.26, 0}, z{2, 0}, n{1, 0};
};
inline constexpr InputModel canonical_model{{0.5, 0}, {1, 4}, {0.5, 0}, {0.5, 0}, {0.25, 0}, {1, 1}};
inline constexpr InputModel aligned_model{{1, 2}, {1, 4}, {0.5, 1}, {0.5, 0}, {0.25, 0}, {1, 1}};
inline constexpr InputModel oriented_model{{1.7321, 7, 1.7321}, {1, 7, 1},  {0.5, 1},
                                           {0.51, 1},           {0.26, 1}, {2.2321, 10, 1.7321}};

// κ of each test for a model: the StaticBound evaluation inflated by 1% (the constant evaluation's own
// rounding and the rounding of the bound at run time), plus one unit of ε (the subnormal slack).
struct Kappa {
    double eps = 0, g = 0;
};
struct Kappas {
    Kappa face, face_sq, axis, edge, edge_sq, inside, height, radial, chord_box, chord_radial, direction, direction_sq;
    Kappa height_signed, chord_signed;  // the two-point certificates' signed margins
};
constexpr Kappa kappa(const StaticBound& b) { return {b.eps * 1.01 + 1, b.g * 1.01}; }
constexpr Kappa larger(const Kappa& a, const Kappa& b) {
    return {a.eps > b.eps ? a.eps : b.eps, a.g > b.g ? a.g : b.g};
}
constexpr Kappas kappas_for(const InputModel& m) {
    const Vec3<StaticBound> c{m.c, m.c, m.c}, d{m.d, m.d, m.d}, e{m.e, m.e, m.e}, v{m.v, m.v, m.v}, z{m.z, m.z, m.z},
        n{m.n, m.n, m.n};
    const StaticBound face = face_gap(m.c, m.e, m.h, m.d);
    const StaticBound edge = edge_gap(m.c, m.c, m.d, m.d, m.e, m.e);
    const StaticBound direction = direction_gap(n, c, d, e, m.h);
    return {kappa(face),
            kappa(face_gap_squared(face, m.r, m.d, m.d)),
            kappa(axis_gap(c, d, e, m.h)),
            kappa(edge),
            kappa(face_gap_squared(edge, m.r, m.d, m.d)),
            kappa(inside_margin(m.c, m.e)),
            kappa(witness_height_margin(v, d, m.h)),
            kappa(witness_radial_margin(v, d, m.r)),
            kappa(chord_box_margin(m.c, m.e, m.t, m.d, m.z, dot(d, z))),
            kappa(witness_radial_margin(z, d, m.r)),
            kappa(direction),
            kappa(direction_gap_squared(direction, n, d, m.r)),
            larger(kappa(witness_top_margin(v, d, m.h)), kappa(witness_bottom_margin(v, d, m.h))),
            larger(kappa(chord_upper_margin(m.c, m.e, m.t, m.d, m.z, dot(d, z))),
                   kappa(chord_lower_margin(m.c, m.e, m.t, m.d, m.z, dot(d, z))))};
}
inline constexpr Kappas canonical_kappas = kappas_for(canonical_model);
inline constexpr Kappas aligned_kappas = kappas_for(aligned_model);
inline constexpr Kappas oriented_kappas = kappas_for(oriented_model);

// World box points of an oriented box (world_offset): K, C exact with |K_j|, |C_j| ≤ L/2, x exact with
// |x_m| ≤ e_m ≤ L/2, A exact with |A_mj| ≤ 1.0005 (g ≤ 2^-10), u the world unit axis (3.6ε, as d in
// the canonical model), r and H exact. No input error but u's and no g: the point is the box's own.
struct WorldKappas {
    Kappa height, radial, height_signed;
};
constexpr WorldKappas world_kappas_for() {
    const StaticBound k{0.5, 0}, c{0.5, 0}, a{1.0005, 0}, x{0.5, 0}, u{1, 4}, r{0.5, 0}, h{0.25, 0};
    const Vec3<StaticBound> kc{k - c, k - c, k - c}, xs{x, x, x}, us{u, u, u};
    const std::array<Vec3<StaticBound>, 3> axes{Vec3<StaticBound>{a, a, a}, Vec3<StaticBound>{a, a, a},
                                                Vec3<StaticBound>{a, a, a}};
    const Vec3<StaticBound> v = world_offset(kc, axes, xs);
    return {kappa(witness_height_margin(v, us, h)), kappa(witness_radial_margin(v, us, r)),
            larger(kappa(witness_top_margin(v, us, h)), kappa(witness_bottom_margin(v, us, h)))};
}
inline constexpr WorldKappas world_kappas = world_kappas_for();

// ---- The computed problem and the decision. ----

// The canonical problem as computed (box frame): miss tests use (r_out, h_out), hit tests with box
// points (r_in, h_in) when has_inner, hit tests with cylinder points the cylinder as given (r, h) and
// the box shrunk to e_in (they all differ by γ for rounded oriented frames only: the ideal box shrunk
// by γ lies inside the true parallelepiped, whose support function differs from the ideal one's by at
// most γ in every direction).
//
// Every field is written by problem() (below) before any is read, so none has an initialiser:
// value-initialising the struct (≈300 bytes, `rep stos`) cost a fifth of problem()'s time on random
// data. A Problem is only read after problem() returned true.
struct Problem {
    Vec3<double> c{uninitialized}, d{uninitialized}, e{uninitialized};
    double r_out, h_out, r_in, h_in, r, h;
    Vec3<double> e_in{uninitialized};
    bool has_inner;
    bool exact_inside;  // aligned and canonical boxes: "C in the box" decided exactly
    double l;           // the length scale L
    double e1, e2;      // ε·L and ε·L²: the rounding units of degree 1 and 2
    double g1, g2;      // g·L and g·L²
    double g, gamma;    // oriented boxes: g ≥ ‖AᵀA − I‖₂ and γ ≥ g·|e|₁
    Vec3<double> k{uninitialized};  // aligned boxes: the computed centre (min + max)/2, a box point
    Vec3<double> u{uninitialized};  // the world unit axis (for world box points of oriented boxes)
};

// The unit axis. When the largest component m is within 2^±250, nothing below overflows or
// underflows; otherwise the axis is first scaled by a power of two to m ∈ [1, 2) (a libm call).
// A component below 2^-250·m is dropped (set to 0): then |u_j| < 2^-250, far inside the model's error
// of u_j, and |a|² changes by a relative 3·2^-500, far inside the model's error of the others. Kept
// tiny, such a component (an axis like (1e-300, 0.6, 0.8), or a subnormal one) makes every product
// with it subnormal, which x86 runs in microcode: stage 0 took twice as long on such queries (100 vs
// 52 ns; a third of the benchmark's random axes have one).
BOXCYL_FORCE_INLINE inline Vec3<double> unit_axis(const Vec3<double>& a) {
    double x = a[0], y = a[1], z = a[2];
    double m = std::max(std::max(std::fabs(x), std::fabs(y)), std::fabs(z));
    if (!(m >= 0x1p-250 && m <= 0x1p250)) {
        const int k = std::ilogb(m);  // m > 0: the caller checked
        x = std::scalbn(x, -k), y = std::scalbn(y, -k), z = std::scalbn(z, -k);
        m = std::scalbn(m, -k);
    }
    // Scalars, not a loop over a Vec3: the loop went through memory, and reloading the three stores as
    // one vector stalled store forwarding.
    const double floor = m * 0x1p-250;  // exact: m·2^-250 ≥ 2^-500 is normal
    // As masks, not `|x| < floor ? 0 : x`: GCC made those three branches, and a third of random axes
    // have such a component (they mispredicted about once a query). Dropped, a component is +0.
    auto keep = [floor](double v) {
#if BOXCYL_STAGE0_SSE2
        const __m128d x = _mm_set_sd(v), magnitude = _mm_andnot_pd(_mm_set_sd(-0.0), x);
        return _mm_cvtsd_f64(_mm_and_pd(x, _mm_cmpge_sd(magnitude, _mm_set_sd(floor))));
#else
        const std::uint64_t mask = 0 - static_cast<std::uint64_t>(std::fabs(v) >= floor);
        return std::bit_cast<double>(std::bit_cast<std::uint64_t>(v) & mask);
#endif
    };
    x = keep(x);
    y = keep(y);
    z = keep(z);
    const double len = std::sqrt(x * x + y * y + z * z);
    return {x / len, y / len, z / len};
}

inline bool in_range(double l) { return l >= min_scale && l <= max_scale; }
BOXCYL_FORCE_INLINE inline double largest(const Vec3<double>& v) {
    return std::max(std::max(std::fabs(v[0]), std::fabs(v[1])), std::fabs(v[2]));
}
// The largest of several doubles, the first of equals as std::max({...}) takes it, by nested std::max:
// the initializer-list form compiled to a loop with a branch per element, a fifth of stage 0's setup.
template <class... T>
BOXCYL_FORCE_INLINE inline double max_of(double a, T... rest) {
    ((a = std::max(a, static_cast<double>(rest))), ...);
    return a;
}
inline bool usable_axis(const Vec3<double>& a) {
    const double m = largest(a);
    return m > 0 && m <= 0x1p1000;  // finite and non-zero (validated input is)
}

// The decision on a computed problem; `witness(k)` returns the offset v = Q_k − C of the k-th witness
// box point (k = 0, 1, 2) in the box frame.
// The cylinder-side witnesses' axial parameter t: the axis point nearest to the box centre, clamped to
// |t| ≤ H' where H' < H for sure (H·(1 − 2^-40) with H = fl(h/2) normal, or 0 for a disk); nullopt
// when H is subnormal (no safe H').
BOXCYL_FORCE_INLINE inline std::optional<double> axial_parameter(const Problem& p) {
    if (p.h != 0 && !(p.h >= 0x1p-1000)) return std::nullopt;
    const double h = p.h * (1 - 0x1p-40);
    return clamp_to(-dot(p.d, p.c), -h, h);
}
// The middle of the axis segment's part inside the box (Liang–Barsky clipping of c + t·d, |t| ≤ H',
// against |x_i| ≤ e_i), when that part is not empty; H' as in axial_parameter (call it first: it
// rejects a subnormal H).
BOXCYL_FORCE_INLINE inline std::optional<double> chord_middle(const Problem& p) {
    const double h = p.h * (1 - 0x1p-40);
    double lo = -h, hi = h;
    for (int i = 0; i < 3; ++i) {
        if (p.d[i] == 0) continue;
        double a = (-p.e_in[i] - p.c[i]) / p.d[i], b = (p.e_in[i] - p.c[i]) / p.d[i];
        if (a > b) std::swap(a, b);
        lo = std::max(lo, a);
        hi = std::min(hi, b);
    }
    if (!(lo <= hi)) return std::nullopt;
    return clamp_to(lo * 0.5 + hi * 0.5, -h, h);
}
// z = s·y, y = −c − t·d (from the axis point to the box centre), s ≤ 1 such that the radial part of z
// is about 0.9·r: any double vector would do, the radial margin is checked.
inline Vec3<double> towards_centre(const Problem& p, double t) {
    const Vec3<double> y = -(p.c + t * p.d);
    const double a = dot(p.d, y);
    const double perp = std::sqrt(std::max(0.0, dot(y, y) - a * a));
    const double s = perp > 0.9 * p.r ? 0.9 * p.r / perp : 1.0;
    return s * y;
}

// ---- Certificates on a computed problem, shared by stage 0 and the searches of stage 0b. ----

inline double bound1(const Problem& p, const Kappa& k) { return k.eps * p.e1 + k.g * p.g1; }
inline double bound2(const Problem& p, const Kappa& k) { return k.eps * p.e2 + k.g * p.g2; }

// A miss: the direction n (any double vector; scaled here to |n_i| ≤ 1, which keeps it a double
// vector, now exact as given) separates the outer problem.
BOXCYL_FORCE_INLINE inline bool separated_along(const Problem& p, const Kappas& k, Vec3<double> n) {
    const double m = largest(n);
    if (!(m > 0) || !(m < std::numeric_limits<double>::infinity())) return false;  // also NaN
    n = {n[0] / m, n[1] / m, n[2] / m};  // |n_i / m| ≤ 1 survives rounding (monotone)
    const double s = direction_gap(n, p.c, p.d, p.e, p.h_out);
    return s > bound1(p, k.direction) && direction_gap_squared(s, n, p.d, p.r_out) > bound2(p, k.direction_sq);
}
// A hit: the box point Q = C + v (exactly a box point: the caller's clamp) lies in the inner cylinder.
// The test on a cylinder given by axis a, radius r and half-height h in the offsets' frame (the inner
// cylinder in the box frame here; the cylinder as given in world coordinates for world_point_inside).
BOXCYL_FORCE_INLINE inline bool point_in_cylinder(const Problem& p, const Vec3<double>& a, double r, double h,
                                            const Kappa& k_height, const Kappa& k_radial, const Vec3<double>& v) {
    return witness_height_margin(v, a, h) > bound1(p, k_height) && witness_radial_margin(v, a, r) > bound2(p, k_radial);
}
inline bool box_point_inside(const Problem& p, const Kappas& k, const Vec3<double>& v) {
    return p.has_inner && point_in_cylinder(p, p.d, p.r_in, p.h_in, k.height, k.radial, v);
}
// A hit: the cylinder point X = C + t·d + (z − (d·z)d) lies in the box shrunk to e_in. The caller
// guarantees |t| ≤ H exactly (axial_parameter's H'), |t| ≤ 0.26L and |z_i| ≤ 2L (the model); z = 0
// needs no radial check.
BOXCYL_FORCE_INLINE inline bool cylinder_point_inside(const Problem& p, const Kappas& k, double t, const Vec3<double>& z,
                                                bool radial = true) {
    if (radial && !(witness_radial_margin(z, p.d, p.r) > bound2(p, k.chord_radial))) return false;
    const double dz = dot(p.d, z), b = bound1(p, k.chord_box);
    for (int i = 0; i < 3; ++i)
        if (!(chord_box_margin(p.c[i], p.e_in[i], t, p.d[i], z[i], dz) > b)) return false;
    return true;
}

// Two-point certificates: hits where no single point has a margin to spare — a disk (H = 0) crossing
// a box, a segment (r = 0) or a cylinder crossing a flat box (a side 0), thin overlaps. A segment
// between two points of a convex set lies in it; a distance to the axis line is convex along it, and
// an axial or box coordinate is affine along it, so it takes every value between its ends.
//
// Box points Q1 = C + v1, Q2 = C + v2 (exactly in the box, as for box_point_inside), both radially
// inside the inner cylinder, with d·v ≤ H at one of them and d·v ≥ −H at one of them: the segment
// Q1Q2 is in the box and radially inside, and d·v takes a value in [−H, H] on it — that point is in
// the inner cylinder.
BOXCYL_FORCE_INLINE inline bool pair_in_cylinder(const Problem& p, const Vec3<double>& a, double r, double h,
                                           const Kappa& k_signed, const Kappa& k_radial, const Vec3<double>& v1,
                                           const Vec3<double>& v2) {
    const double b_radial = bound2(p, k_radial), b = bound1(p, k_signed);
    if (!(witness_radial_margin(v1, a, r) > b_radial && witness_radial_margin(v2, a, r) > b_radial)) return false;
    const bool below_top = witness_top_margin(v1, a, h) > b || witness_top_margin(v2, a, h) > b;
    const bool above_bottom = witness_bottom_margin(v1, a, h) > b || witness_bottom_margin(v2, a, h) > b;
    return below_top && above_bottom;
}
inline bool box_segment_inside(const Problem& p, const Kappas& k, const Vec3<double>& v1, const Vec3<double>& v2) {
    return p.has_inner && pair_in_cylinder(p, p.d, p.r_in, p.h_in, k.height_signed, k.radial, v1, v2);
}
// The same two certificates for world box points of an oriented box (world_offset): tested against
// the cylinder as given (u, r, H), so a rounded frame costs nothing — no inner cylinder, which a disk
// or a segment does not have, and no g in the bounds.
inline bool world_point_inside(const Problem& p, const WorldKappas& k, const Vec3<double>& v) {
    return point_in_cylinder(p, p.u, p.r, p.h, k.height, k.radial, v);
}
inline bool world_segment_inside(const Problem& p, const WorldKappas& k, const Vec3<double>& v1, const Vec3<double>& v2) {
    return pair_in_cylinder(p, p.u, p.r, p.h, k.height_signed, k.radial, v1, v2);
}
// Cylinder points X1 = (t1, z1), X2 = (t2, z2) (exactly in the cylinder, as for cylinder_point_inside,
// whose conditions on t and z the caller guarantees for both): the segment X1X2 is in the cylinder.
// If in every box coordinate but at most one both points are strictly inside the box shrunk to e_in,
// and in that one (with e ≥ 0) x ≤ e at one of them and x ≥ −e at one of them, a point of the
// segment is in it.
inline bool cylinder_segment_inside(const Problem& p, const Kappas& k, double t1, const Vec3<double>& z1, double t2,
                                    const Vec3<double>& z2, bool radial) {
    if (radial) {
        const double b_radial = bound2(p, k.chord_radial);
        if (!(witness_radial_margin(z1, p.d, p.r) > b_radial && witness_radial_margin(z2, p.d, p.r) > b_radial))
            return false;
    }
    const double dz1 = dot(p.d, z1), dz2 = dot(p.d, z2), b = bound1(p, k.chord_signed);
    int crossing = 0;
    for (int i = 0; i < 3; ++i) {
        const bool upper1 = chord_upper_margin(p.c[i], p.e_in[i], t1, p.d[i], z1[i], dz1) > b;
        const bool lower1 = chord_lower_margin(p.c[i], p.e_in[i], t1, p.d[i], z1[i], dz1) > b;
        const bool upper2 = chord_upper_margin(p.c[i], p.e_in[i], t2, p.d[i], z2[i], dz2) > b;
        const bool lower2 = chord_lower_margin(p.c[i], p.e_in[i], t2, p.d[i], z2[i], dz2) > b;
        if (upper1 && lower1 && upper2 && lower2) continue;
        // [−e, e] must not be empty: e_in = fl(e − γ) has the exact difference's sign (no FTZ).
        if (++crossing > 1 || !(p.e_in[i] >= 0) || !((upper1 || upper2) && (lower1 || lower2))) return false;
    }
    return true;
}

// Always inlined into the per-kind overloads below: as a call, its first tests waited for the problem's
// fields through memory (stage 0 ≈2 ns slower on bench_query's random set).
// Misses along the box faces' normals and the cylinder axis, the most common certificates: all four
// evaluated and combined without branches (on random data a branch per test mispredicts).
BOXCYL_FORCE_INLINE inline bool faces_or_axis_separate(const Problem& p, const Kappas& k) {
    const Vec3<double>& c = p.c;
    const Vec3<double>& d = p.d;
    const Vec3<double>& e = p.e;
    const double b_face = bound1(p, k.face), b_face_sq = bound2(p, k.face_sq);
    bool apart = axis_gap(c, d, e, p.h_out) > bound1(p, k.axis);
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, l = (i + 2) % 3;
        const double s = face_gap(c[i], e[i], p.h_out, d[i]);
        apart |= (s > b_face) & (face_gap_squared(s, p.r_out, d[j], d[l]) > b_face_sq);
    }
    return apart;
}
// Misses along d × E_i.
BOXCYL_FORCE_INLINE inline bool edges_separate(const Problem& p, const Kappas& k) {
    const Vec3<double>& c = p.c;
    const Vec3<double>& d = p.d;
    const Vec3<double>& e = p.e;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, l = (i + 2) % 3;
        const double s = edge_gap(c[j], c[l], d[j], d[l], e[j], e[l]);
        if (s > bound1(p, k.edge) && face_gap_squared(s, p.r_out, d[j], d[l]) > bound2(p, k.edge_sq)) return true;
    }
    return false;
}

// The hit tests, in two parts: the cylinder centre in the box and the first witness box point; the
// other witnesses and the cylinder points in the box. (The clearance query's stage 0 runs them
// interleaved across its probe cylinders, clearance.hpp.)
template <class Witness>
BOXCYL_FORCE_INLINE inline bool first_hits(const Problem& p, const Kappas& k, Witness&& witness) {
    if (!p.has_inner) return false;
    if (p.exact_inside) return true;
    const Vec3<double>& c = p.c;
    const Vec3<double>& e = p.e;
    const double inside = bound1(p, k.inside);
    if (inside_margin(c[0], e[0]) > inside && inside_margin(c[1], e[1]) > inside && inside_margin(c[2], e[2]) > inside)
        return true;
    return box_point_inside(p, k, witness(0));
}
template <class Witness>
BOXCYL_FORCE_INLINE inline bool other_hits(const Problem& p, const Kappas& k, Witness&& witness) {
    if (p.has_inner)
        for (int w = 1; w < 3; ++w)
            if (box_point_inside(p, k, witness(w))) return true;
    // Cylinder points X of the cylinder as given, inside the box shrunk by γ (e_in = e − γ: for a
    // rounded frame, the ideal box shrunk by γ lies inside the true one; see `Problem`).
    if (const std::optional<double> t = axial_parameter(p)) {
        const Vec3<double> zero{0, 0, 0};
        if (cylinder_point_inside(p, k, *t, zero, false)) return true;
        if (const std::optional<double> mid = chord_middle(p); mid && cylinder_point_inside(p, k, *mid, zero, false))
            return true;
        if (cylinder_point_inside(p, k, *t, towards_centre(p, *t))) return true;
    }
    return false;
}

template <class Witness>
BOXCYL_FORCE_INLINE inline std::optional<bool> decide(const Problem& p, const Kappas& k, Witness&& witness) {
    if (faces_or_axis_separate(p, k)) return false;
    if (first_hits(p, k, witness)) return true;
    // The d × E_i misses before the remaining hit tests: those cost divisions and a square root, and on
    // bench_query's random set the edge tests decide more queries (6%) than all of them together (4%).
    if (edges_separate(p, k)) return false;
    if (other_hits(p, k, witness)) return true;
    return std::nullopt;
}

// Whether one of stage 0's separating-axis tests (a box face's normal, the cylinder axis, d × E_i) is
// within 2^20 of its error bound: the solids are then within about 2^-32 of the problem's scale of
// touching along that direction. Only a hint for the order of the later stages (near touching, stage
// 1's double precision cannot decide and the middle stage runs first; elsewhere stage 1 decides at a
// third of the middle stage's cost), never for an answer.
BOXCYL_FORCE_INLINE inline bool near_touching(const Problem& p, const Kappas& k) {
    constexpr double wide = 0x1p20;
    const Vec3<double>& c = p.c;
    const Vec3<double>& d = p.d;
    const Vec3<double>& e = p.e;
    auto near = [](double gap, double bound) { return std::fabs(gap) <= bound; };
    if (near(axis_gap(c, d, e, p.h_out), wide * bound1(p, k.axis))) return true;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, l = (i + 2) % 3;
        const double s = face_gap(c[i], e[i], p.h_out, d[i]);
        if (near(s, wide * bound1(p, k.face))) return true;
        if (s > 0 && near(face_gap_squared(s, p.r_out, d[j], d[l]), wide * bound2(p, k.face_sq))) return true;
        const double t = edge_gap(c[j], c[l], d[j], d[l], e[j], e[l]);
        if (t > 0 && near(face_gap_squared(t, p.r_out, d[j], d[l]), wide * bound2(p, k.edge_sq))) return true;
    }
    return false;
}

// The axis point nearest to the box centre (canonical origin), clamped to the slab: c + t·d with
// t = clamp(−d·c, −H, H). Any point will do for a witness; this one is often deep inside.
inline Vec3<double> axis_point_near_centre(const Vec3<double>& c, const Vec3<double>& d, double h) {
    const double t = clamp_to(-dot(d, c), -h, h);
    return {c[0] + t * d[0], c[1] + t * d[1], c[2] + t * d[2]};
}

// ---- The computed problem of each box kind (false: out of range, stage 1 decides). ----

// Each fills in every field of p (false: out of range, stage 1 decides). Assigned field by field into
// the caller's Problem: value-initialising it again first (`p = Problem{}`, which GCC does with
// `rep stos`) was a third of problem()'s time on random data, and building it as a returned
// std::optional<Problem> costs a copy of the whole struct.

// The error units of degree 1 and 2 for the scale l and an oriented frame's g (0 otherwise).
inline void set_units(Problem& p, double l, double g) {
    p.l = l;
    p.e1 = eps * l;
    p.e2 = p.e1 * l;
    p.g1 = g * l;
    p.g2 = p.g1 * l;
    p.g = g;
}

// The cylinder's sizes in the problem (γ: an oriented frame's widening, set before; 0 for the other
// kinds, which take the sizes as they are): the outer cylinder grown by γ, the inner one shrunk by it.
// The clearance query's stage 0 (clearance.hpp) sets the sizes of each of its probe cylinders on one
// problem computed for the largest, whose L bounds them all.
template <bool Rounded>
BOXCYL_FORCE_INLINE inline void set_sizes(Problem& p, double radius, double height) {
    const double h = height * 0.5;
    if constexpr (Rounded) {
        p.r_out = radius + p.gamma;
        p.h_out = h + p.gamma;
        p.has_inner = radius >= p.gamma && height >= 2 * p.gamma;
        p.r_in = radius - p.gamma;
        p.h_in = h - p.gamma;
    } else {
        p.r_out = p.r_in = radius;
        p.h_out = p.h_in = h;
        p.has_inner = true;
    }
    p.r = radius;
    p.h = h;
}

// Canonical box: the box is canonical, the cylinder already in its frame: nothing rounds but the unit axis.
BOXCYL_FORCE_INLINE inline bool problem(const CanonicalBox<double>& b, const Cylinder<double>& cyl, Problem& p) {
    const double l = 2 * max_of(largest(b.extents), largest(cyl.center), cyl.radius, cyl.height);
    if (!in_range(l) || !usable_axis(cyl.axis)) return false;
    p.c = cyl.center;
    p.d = unit_axis(cyl.axis);
    p.e = b.extents;
    set_sizes<false>(p, cyl.radius, cyl.height);
    p.e_in = p.e;
    // As ints combined by &: no branch to mispredict (and no clang -Wbitwise-instead-of-logical).
    const int in0 = std::fabs(p.c[0]) <= p.e[0], in1 = std::fabs(p.c[1]) <= p.e[1], in2 = std::fabs(p.c[2]) <= p.e[2];
    p.exact_inside = (in0 & in1 & in2) != 0;
    p.gamma = 0;
    p.k = {0, 0, 0};
    p.u = p.d;  // the box's frame is the world's here
    set_units(p, l, 0);
    return true;
}

// Aligned box: centre K and extents E rounded (in the model); "C in the box" is decided exactly.
BOXCYL_FORCE_INLINE inline bool problem(const AlignedBox<double>& b, const Cylinder<double>& cyl, Problem& p) {
    const double l = 2 * max_of(largest(b.min), largest(b.max), largest(cyl.center), cyl.radius, cyl.height);
    if (!in_range(l) || !usable_axis(cyl.axis)) return false;
    int inside = 1;
    for (int i = 0; i < 3; ++i) {
        p.k[i] = b.min[i] * 0.5 + b.max[i] * 0.5;  // in [min, max]: rounding is monotone
        p.c[i] = cyl.center[i] - p.k[i];
        p.e[i] = b.max[i] * 0.5 - b.min[i] * 0.5;
        const int above = b.min[i] <= cyl.center[i], below = cyl.center[i] <= b.max[i];
        inside &= above & below;  // ints and &: no branch to mispredict
    }
    p.d = unit_axis(cyl.axis);
    set_sizes<false>(p, cyl.radius, cyl.height);
    p.e_in = p.e;
    p.exact_inside = inside != 0;
    p.gamma = 0;
    p.u = p.d;
    set_units(p, l, 0);
    return true;
}

// Oriented box, with the frame as given: g bounds ‖AᵀA − I‖₂ (max row sum of |G|). The computed Gram entries
// are within γ3·|A_i||A_j| ≤ 3.0003ε of the exact ones (the diagonal's "− 1" is exact by Sterbenz's
// lemma, as |A_i|² ∈ [0.5, 2]), a row sum of three rounds twice: so g ≤ row + 10ε, and
// g = fl(row + 32ε) is an upper bound.
BOXCYL_FORCE_INLINE inline bool problem(const OrientedBox<double>& b, const Cylinder<double>& cyl, Problem& p) {
    const double l = 2 * max_of(largest(b.center), largest(b.extents), largest(cyl.center), cyl.radius, cyl.height);
    if (!in_range(l) || !usable_axis(cyl.axis)) return false;
    const std::array<Vec3<double>, 3>& a = b.axes;
    // G is symmetric: six dot products; the rows summed in the same order as the three-term sum.
    const double g00 = std::fabs(dot(a[0], a[0]) - 1), g11 = std::fabs(dot(a[1], a[1]) - 1),
                 g22 = std::fabs(dot(a[2], a[2]) - 1);
    const double g01 = std::fabs(dot(a[0], a[1])), g02 = std::fabs(dot(a[0], a[2])), g12 = std::fabs(dot(a[1], a[2]));
    const double row_max = std::max(std::max(g00 + g01 + g02, g01 + g11 + g12), g02 + g12 + g22);
    const double g = row_max + 32 * eps;
    if (!(g <= 0x1p-10)) return false;  // also the validated bound on |G_ij| and a NaN
    const Vec3<double> delta = cyl.center - b.center;
    const Vec3<double> u = unit_axis(cyl.axis);
    for (int i = 0; i < 3; ++i) {
        p.c[i] = dot(a[i], delta);
        p.d[i] = dot(a[i], u);
    }
    p.u = u;
    p.e = b.extents;
    // γ ≥ g·|e|₁ as a double (the product rounded, then inflated by 8ε: ≥ the exact product).
    p.gamma = g * (b.extents[0] + b.extents[1] + b.extents[2]) * (1 + 0x1p-49);
    set_sizes<true>(p, cyl.radius, cyl.height);
    p.exact_inside = false;
    for (int i = 0; i < 3; ++i) p.e_in[i] = b.extents[i] - p.gamma;
    p.k = {0, 0, 0};
    set_units(p, l, g);
    return true;
}

// The witness offsets v = Q − C (box frame) of the three witness box points Q, w = 0, 1, 2: the box
// point nearest to the cylinder centre, the box centre, the box point nearest to the axis point
// nearest to the box centre. Q is exactly a box point: clamped in world coordinates for aligned boxes,
// box coordinates x with |x_m| ≤ e_m otherwise.
inline Vec3<double> witness_offset(const Problem& p, int w) {
    const Vec3<double> target = w == 0 ? p.c : w == 1 ? Vec3<double>{0, 0, 0} : axis_point_near_centre(p.c, p.d, p.h_in);
    Vec3<double> v;
    for (int i = 0; i < 3; ++i) v[i] = clamp_to(target[i], -p.e[i], p.e[i]) - p.c[i];
    return v;
}
inline Vec3<double> witness_offset(const Problem& p, int w, const AlignedBox<double>& b, const Cylinder<double>& cyl) {
    Vec3<double> target = cyl.center;
    if (w == 1) target = p.k;
    if (w == 2) target = p.k + axis_point_near_centre(p.c, p.d, p.h_in);
    Vec3<double> v;
    for (int i = 0; i < 3; ++i) v[i] = clamp_to(target[i], b.min[i], b.max[i]) - cyl.center[i];
    return v;
}
// witness(w): the box kind's witness offsets (by reference: the caller keeps p, b and cyl alive).
template <class Box>
BOXCYL_FORCE_INLINE inline auto witnesses_of(const Problem& p, const Box& b, const Cylinder<double>& cyl) {
    if constexpr (std::is_same_v<Box, AlignedBox<double>>)
        return [&p, &b, &cyl](int w) { return witness_offset(p, w, b, cyl); };
    else
        return [&p](int w) { return witness_offset(p, w); };
}

// ---- Stage 0: the answer, or nullopt when undecided. ----

// The κ of each box kind.
template <class Box>
inline constexpr const Kappas& kappas_of = canonical_kappas;
template <>
inline constexpr const Kappas& kappas_of<AlignedBox<double>> = aligned_kappas;
template <>
inline constexpr const Kappas& kappas_of<OrientedBox<double>> = oriented_kappas;

// set_sizes for the box kind's problem (only an oriented frame widens the cylinder by γ).
template <class Box>
BOXCYL_FORCE_INLINE inline void set_sizes_of(Problem& p, double radius, double height) {
    set_sizes<std::is_same_v<Box, OrientedBox<double>>>(p, radius, height);
}

// On a problem computed by problem() for the same box and cylinder (the query builds it once and hands
// it on to the witness search). The tests pass other κ (zero: the computed values alone, unsound)
// through the generic decide() above.
template <class Box>
BOXCYL_FORCE_INLINE inline std::optional<bool> decide(const Problem& p, const Box& b, const Cylinder<double>& cyl) {
    return decide(p, kappas_of<Box>, witnesses_of(p, b, cyl));
}
// The two parts of the hit tests alone, for the box kind.
template <class Box>
BOXCYL_FORCE_INLINE inline bool first_hits(const Problem& p, const Box& b, const Cylinder<double>& cyl) {
    return first_hits(p, kappas_of<Box>, witnesses_of(p, b, cyl));
}
template <class Box>
BOXCYL_FORCE_INLINE inline bool other_hits(const Problem& p, const Box& b, const Cylinder<double>& cyl) {
    return other_hits(p, kappas_of<Box>, witnesses_of(p, b, cyl));
}
// Stage 0's misses alone (false, or nullopt: undecided), for a cylinder whose hit would decide nothing:
// a cylinder that holds another (clearance.hpp's outer probe), whose hit tests are skipped.
template <class Box>
BOXCYL_FORCE_INLINE inline std::optional<bool> decide_miss(const Problem& p) {
    if (faces_or_axis_separate(p, kappas_of<Box>) || edges_separate(p, kappas_of<Box>)) return false;
    return std::nullopt;
}

}  // namespace boxcyl::filtered::semi_static
