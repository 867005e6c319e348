// The exact stage for a canonical problem (aligned and canonical boxes, oriented boxes whose axes are a
// signed permutation): the linear-inequalities method evaluated in integers and Z[√d], with no rational
// anywhere (docs/algorithms.md, "The exact stage in integers"; docs/robustness/exact-stage.md). One
// power of two makes every length an integer, the axis D is scaled on its own, and every comparison,
// multiplied through by its positive denominators (√d, D_k, d), is the sign of a + b√d. The decisions are
// the method's (exact/paths.hpp), except that each candidate segment is asked first whether its line
// comes within r of the axis, which rejects most of them cheaply (box_edge, face_cut).
//
// Z is the integer type: mpz_class always works; number/fixed_integer.hpp's FixedInt (stack limbs, no
// allocation) while the values fit, the caller repeating the run in mpz_class after an overflow.
//
// Map to the generic method (algo/linear_inequalities.hpp), function by function:
//   here                                        algo/linear_inequalities.hpp
//   problem<Z>(box, cylinder)                   to_canonical, to_unit (geometry/reduce.hpp), as integers
//   intersects(Problem&), Inequalities::run     linear_inequalities: slab cull (box_outside_slab),
//                                               reflection into the first octant, the three cases
//   Inequalities::two_zero_components           two_zero_components
//   Inequalities::axis_meets_slabs              axis_meets_slabs (the early exits, eqs. 21/32)
//   Inequalities::one_zero_component,           one_zero_component, axis_meets_box_one_zero
//     square_within
//   Inequalities::no_zero_components            no_zero_components, axis_meets_box_no_zero
//   Inequalities::vertex_scaled                 ExtremeEdges' vertex projections t_v
//   Inequalities::box_edge, end_within          ExtremeEdges::box_edge (here its line first)
//   Inequalities::face_cut, cut_point,          ExtremeEdges::face_cut, cut_point
//     cut_line_far, cut_end_within
//   segment_within                              segment_within, in Z[√d]
//   abs_of                                      abs_of
#pragma once

#include <algorithm>  // std::max
#include <array>     // index triples
#include <bit>       // std::bit_cast, std::countr_zero
#include <cstddef>   // std::size_t
#include <cstdint>   // std::int64_t
#include <optional>  // not a signed permutation
#include <tuple>        // std::tuple_size_v
#include <type_traits>  // std::is_same_v, std::conditional_t

#include "boxcyl/exact/stack_room.hpp"
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/vec3.hpp"
#include "boxcyl/number/epsilon_series.hpp"
#include "boxcyl/number/fixed_integer.hpp"
#include "boxcyl/number/quadratic_integer.hpp"
#include "boxcyl/number/rational.hpp"  // mpz_class (gmpxx)

namespace boxcyl::exact::integer {

// The canonical problem in integers: the box |x_i| ≤ E_i, the cylinder with centre C, axis direction
// D (any length, not zero), radius R and half-height H — all lengths in one common unit.
template <class Z>
struct Problem {
    Vec3<Z> E, C, D;
    Z R, H;
};

// ---- Doubles as integers times a common power of two ----

// x = m·2^e with m odd (or x = 0, m = 0): exact for every finite double, subnormals included; read off
// the IEEE 754 binary64 fields.
struct Dyadic {
    std::int64_t m = 0;
    int e = 0;
};
inline Dyadic dyadic(double x) {
    const auto bits = std::bit_cast<std::uint64_t>(x);
    const int biased = static_cast<int>(bits >> 52 & 0x7ff);
    std::uint64_t mag = bits & ((std::uint64_t{1} << 52) - 1);
    int e = -1074;  // subnormals: mag·2^−1074
    if (biased != 0) {
        mag |= std::uint64_t{1} << 52;
        e = biased - 1075;
    }
    if (mag == 0) return {};
    const int tz = std::countr_zero(mag);
    mag >>= tz;
    const auto m = static_cast<std::int64_t>(mag);  // < 2^53
    return {bits >> 63 ? -m : m, e + tz};
}

// Doubles x_i as the integers x_i·2^−emin, emin the smallest exponent among the non-zero ones.
template <std::size_t K>
class Scale {
public:
    explicit Scale(const std::array<double, K>& xs) {
        bool any = false;
        for (std::size_t i = 0; i < K; ++i) {
            v_[i] = dyadic(xs[i]);
            if (v_[i].m != 0 && (!any || v_[i].e < emin_)) emin_ = v_[i].e, any = true;
        }
    }
    // Bits from the smallest exponent to the top of the largest magnitude (0 when all are zero): the
    // integers x_i·2^−emin are below 2^span.
    int span() const {
        int top = emin_;
        for (const Dyadic& v : v_)
            if (v.m != 0) {
                const auto mag = static_cast<std::uint64_t>(v.m < 0 ? -v.m : v.m);
                top = std::max(top, v.e + static_cast<int>(std::bit_width(mag)));
            }
        return top - emin_;
    }

    template <class Z>
    Z integer(std::size_t i) const {
        const Dyadic& v = v_[i];
        Z z(v.m);
        if (v.m != 0 && v.e > emin_) z <<= static_cast<unsigned>(v.e - emin_);
        return z;
    }
    template <class Z>
    Vec3<Z> integers(std::size_t first) const {
        return {integer<Z>(first), integer<Z>(first + 1), integer<Z>(first + 2)};
    }

private:
    std::array<Dyadic, K> v_;
    int emin_ = 0;
};

// ---- Inputs of two far-apart scales, for runs in EpsilonSeries ----

// Doubles that fall into two groups hundreds of binary orders apart (an axis component of 1e-300
// beside 1, a box of 1e-300 beside a cylinder of 1e300): the large ones as integers in the unit
// 2^emin of the large group, the tiny ones as integers times ε = 2^−E in that unit
// (number/epsilon_series.hpp). Lengths and the axis direction are scaled apart (only the direction of
// the axis matters), so each group gets its own TwoScale; ε is common: E, set in SeriesContext by the
// caller, is the smaller of their gaps, and a group whose gap is larger has its large values
// multiplied by 2^(gap − E) (one more exact scaling) so that its tiny ones stay integers times ε.
template <std::size_t K>
class TwoScale {
public:
    static constexpr int kGroupBits = 192;  // a group spans at most this many bits
    static constexpr int kMinGap = 256;     // between the tiny group's top and the large group's bottom

    explicit TwoScale(const std::array<double, K>& xs) {
        int max_top = 0;
        bool any = false;
        for (std::size_t i = 0; i < K; ++i) {
            v_[i] = dyadic(xs[i]);
            if (v_[i].m == 0) continue;
            top_[i] = v_[i].e + static_cast<int>(std::bit_width(magnitude(v_[i])));
            max_top = any ? std::max(max_top, top_[i]) : top_[i], any = true;
        }
        if (!any) return;  // all zero: one (empty) group
        bool first_big = true, any_tiny = false;
        int tiny_top = 0;
        for (std::size_t i = 0; i < K; ++i) {
            if (v_[i].m == 0) continue;
            tiny_[i] = top_[i] < max_top - kGroupBits / 2;
            if (!tiny_[i]) {
                big_unit_ = first_big ? v_[i].e : std::min(big_unit_, v_[i].e), first_big = false;
            } else {
                tiny_unit_ = any_tiny ? std::min(tiny_unit_, v_[i].e) : v_[i].e;
                tiny_top = any_tiny ? std::max(tiny_top, top_[i]) : top_[i];
                any_tiny = true;
            }
        }
        span_ = max_top - big_unit_;
        if (any_tiny) {
            span_ = std::max(span_, tiny_top - tiny_unit_);
            if (big_unit_ - tiny_top < kMinGap) ok_ = false;
            gap_ = big_unit_ - tiny_unit_;
        }
        if (span_ > kGroupBits) ok_ = false;
    }

    // Whether the values form one group, or two groups kMinGap apart, each spanning at most kGroupBits.
    bool ok() const { return ok_; }
    // E of this group's own split (−1: one group).
    int gap() const { return gap_; }
    // Bits from a group's smallest exponent to the top of its largest magnitude, the larger of the two.
    int span() const { return span_; }

    // x_i in EpsilonSeries Z with SeriesContext's E (at most gap()).
    template <class Z>
    Z integer(std::size_t i) const {
        const Dyadic& v = v_[i];
        if (v.m == 0) return Z(0);
        typename Z::Coefficient c(v.m);
        if (tiny_[i]) {
            c <<= static_cast<unsigned>(v.e - tiny_unit_);
            return Z::term(c, 1);
        }
        const int widen = gap_ < 0 ? 0 : gap_ - SeriesContext::get().E;
        c <<= static_cast<unsigned>(v.e - big_unit_ + widen);
        return Z::term(c, 0);
    }
    template <class Z>
    Vec3<Z> integers(std::size_t first) const {
        return {integer<Z>(first), integer<Z>(first + 1), integer<Z>(first + 2)};
    }

private:
    static std::uint64_t magnitude(const Dyadic& v) { return static_cast<std::uint64_t>(v.m < 0 ? -v.m : v.m); }

    std::array<Dyadic, K> v_{};
    std::array<int, K> top_{};
    std::array<bool, K> tiny_{};
    int big_unit_ = 0, tiny_unit_ = 0, gap_ = -1, span_ = 0;
    bool ok_ = true;
};

template <class Z>
inline constexpr bool is_epsilon_series = false;
template <class C, int M>
inline constexpr bool is_epsilon_series<EpsilonSeries<C, M>> = true;

// The scaling of K doubles to integers for the integer type Z.
template <class Z, std::size_t K>
using ScaleFor = std::conditional_t<is_epsilon_series<Z>, TwoScale<K>, Scale<K>>;

// The direction D as integers with one common power of two removed (the smallest numbers for it).
template <class Z>
Vec3<Z> integer_direction(const Vec3<double>& axis) {
    return ScaleFor<Z, 3>({axis[0], axis[1], axis[2]}).template integers<Z>(0);
}

// The lengths of each problem, in the order problem() reads them.
inline std::array<double, 11> lengths(const AlignedBox<double>& b, const Cylinder<double>& c) {
    return {b.min[0], b.min[1], b.min[2], b.max[0], b.max[1], b.max[2], c.center[0], c.center[1], c.center[2],
            c.radius, c.height};
}
inline std::array<double, 8> lengths(const CanonicalBox<double>& b, const Cylinder<double>& c) {
    return {b.extents[0], b.extents[1], b.extents[2], c.center[0], c.center[1], c.center[2], c.radius, c.height};
}
inline std::array<double, 11> lengths(const OrientedBox<double>& b, const Cylinder<double>& c) {
    return {b.center[0], b.center[1], b.center[2], b.extents[0], b.extents[1], b.extents[2], c.center[0],
            c.center[1], c.center[2], c.radius, c.height};
}

template <class Z>
Problem<Z> problem(const AlignedBox<double>& b, const Cylinder<double>& c) {
    const ScaleFor<Z, 11> s(lengths(b, c));
    Problem<Z> p;
    // Lengths ×2: E = max − min, C = 2·centre − (min + max), R = 2r, H = h.
    for (std::size_t i = 0; i < 3; ++i) {
        const Z lo = s.template integer<Z>(i), hi = s.template integer<Z>(3 + i);
        p.E[i] = hi - lo;
        p.C[i] = Z(2) * s.template integer<Z>(6 + i) - lo - hi;
    }
    p.R = Z(2) * s.template integer<Z>(9);
    p.H = s.template integer<Z>(10);
    p.D = integer_direction<Z>(c.axis);
    return p;
}

template <class Z>
Problem<Z> problem(const CanonicalBox<double>& b, const Cylinder<double>& c) {
    const ScaleFor<Z, 8> s(lengths(b, c));
    Problem<Z> p;
    for (std::size_t i = 0; i < 3; ++i) {
        p.E[i] = Z(2) * s.template integer<Z>(i);
        p.C[i] = Z(2) * s.template integer<Z>(3 + i);
    }
    p.R = Z(2) * s.template integer<Z>(6);
    p.H = s.template integer<Z>(7);
    p.D = integer_direction<Z>(c.axis);
    return p;
}

// For a signed permutation frame the canonical coordinates are x_i = s_i·(X − K)_{p_i}, exactly.
template <class Z>
std::optional<Problem<Z>> problem(const OrientedBox<double>& b, const Cylinder<double>& c) {
    const std::optional<SignedPermutation> frame = signed_permutation(b.axes);
    if (!frame) return std::nullopt;
    const std::array<int, 3>& perm = frame->perm;
    const std::array<int, 3>& sign = frame->sign;
    const ScaleFor<Z, 11> s(lengths(b, c));
    const Vec3<Z> D = integer_direction<Z>(c.axis);
    Problem<Z> p;
    for (std::size_t i = 0; i < 3; ++i) {
        const auto j = static_cast<std::size_t>(perm[i]);
        const Z delta = Z(2) * (s.template integer<Z>(6 + j) - s.template integer<Z>(j));
        p.C[i] = sign[i] > 0 ? delta : Z(-delta);
        p.D[i] = sign[i] > 0 ? D[j] : Z(-D[j]);
        p.E[i] = Z(2) * s.template integer<Z>(3 + i);
    }
    p.R = Z(2) * s.template integer<Z>(9);
    p.H = s.template integer<Z>(10);
    return p;
}

// ---- §4 in Z[√d] ----

namespace detail {

// Whether this thread's run in Z can no longer give an answer — a FixedInt value overflowed, or a
// series sign hung beyond the kept order — so that its caller will discard it: the candidates left
// are not worth computing (a series run that fails at order 2 is repeated at order 4).
template <class Z>
bool abandoned() {
    if constexpr (std::is_same_v<Z, mpz_class>) return false;
    else if constexpr (is_epsilon_series<Z>) return FixedOverflow::flag() || SeriesContext::get().undecided;
    else return FixedOverflow::flag();
}

template <class Z>
Z abs_of(const Z& x) {
    return sgn(x) < 0 ? Z(-x) : x;
}

// §4.3.3 with D unnormalised: is the segment [C + y0, C + y1] within distance r (r2 = r²) of the axis
// line {C + τD}? q = D × y is √d times the turned projection of y, so the branch tests keep their
// signs, |q|² ≤ r²·d is the point test, and (D·(y0 × δ))² ≤ r²|D × δ|² the interior one. The end
// points and r² may come scaled by one positive integer (a common denominator): no answer changes.
template <class Z>
bool segment_within(const QuadraticRing<Z>& ring, const Vec3<Z>& D, const Vec3<QuadInt<Z>>& y0,
                    const Vec3<QuadInt<Z>>& y1, const Z& r2) {
    // Two identities save products: D × y0 = D × y1 − D × δ, and D·(y0 × δ) = (D × y0)·δ.
    using Q = QuadInt<Z>;
    const Vec3<Q> delta = y1 - y0;
    const Vec3<Q> w = cross(D, delta);
    const Vec3<Q> q1 = cross(D, y1);
    const Z r2d = r2 * ring.d();
    if (!(ring.sign(ring.dot(q1, w)) > 0)) return ring.sign(ring.norm2(q1) - Q{r2d, Z(0)}) <= 0;
    const Vec3<Q> q0 = q1 - w;
    if (!(ring.sign(ring.dot(q0, w)) < 0)) return ring.sign(ring.norm2(q0) - Q{r2d, Z(0)}) <= 0;
    const Q n = ring.dot(q0, delta);
    const Q ww = ring.norm2(w);
    return ring.sign(ring.square(n) - r2 * ww) <= 0;
}

template <class Z>
class Inequalities {
public:
    using Q = QuadInt<Z>;

    explicit Inequalities(Problem<Z>& p) : p_(p), ring_(dot(p.D, p.D)) {}

    bool run() {
        Vec3<Z>& C = p_.C;
        Vec3<Z>& D = p_.D;
        const Vec3<Z>& E = p_.E;
        // §1.6 cull: the box is outside the slab iff |u·C| > Σ|u_i|E_i + H, i.e. with
        // A = |D·C| − Σ|D_i|E_i: A > H√d (A > 0 and A² > H²d).
        const Z A = Z(abs_of(Z(dot(D, C))) - abs_of(D[0]) * E[0] - abs_of(D[1]) * E[1] - abs_of(D[2]) * E[2]);
        if (ring_.sign(A, Z(-p_.H)) > 0) return false;
        // §4.4: reflect into the first octant (the box is symmetric in every coordinate plane).
        for (int n = 0; n < 3; ++n)
            if (sgn(D[n]) < 0) {
                C[n] = -C[n];
                D[n] = -D[n];
            }
        const bool p0 = sgn(D[0]) > 0, p1 = sgn(D[1]) > 0, p2 = sgn(D[2]) > 0;
        if (p0) {
            if (p1) {
                if (p2) return no_zero_components();
                return one_zero_component({0, 1, 2});
            }
            if (p2) return one_zero_component({2, 0, 1});
            return two_zero_components({0, 1, 2});
        }
        if (p1) {
            if (p2) return one_zero_component({1, 2, 0});
            return two_zero_components({1, 2, 0});
        }
        return two_zero_components({2, 0, 1});  // D ≠ 0: the only component left
    }

private:
    // §4.1: D ∥ x_{i0}. The squared distance from (c1, c2) to the rectangle |x1| ≤ e1, |x2| ≤ e2.
    bool two_zero_components(const std::array<int, 3>& i) const {
        Z dist2(0);
        for (int n = 1; n < 3; ++n) {
            const Z out = Z(abs_of(p_.C[i[n]]) - p_.E[i[n]]);
            if (sgn(out) > 0) dist2 += out * out;
        }
        return dist2 <= p_.R * p_.R;
    }

    // §4.2.1 / §4.3.1: the axis segment stays in the slabs |x_a| ≤ e_a (a in idx, D_a > 0) for a
    // common t. u_a·H < lo ⇔ D_a·H − lo·√d < 0; hi < −u_a·H ⇔ D_a·H + hi·√d < 0; the pairwise
    // comparison lo_a/u_a ≤ hi_b/u_b is D_a·hi_b ≥ D_b·lo_a (√d cancels).
    template <std::size_t N>
    bool axis_meets_slabs(const std::array<int, N>& idx) const {
        const Vec3<Z>& C = p_.C;
        const Vec3<Z>& D = p_.D;
        const Vec3<Z>& E = p_.E;
        for (int a : idx) {
            const Z lo = Z(-E[a] - C[a]);
            const Z hi = Z(E[a] - C[a]);
            const Z DH = D[a] * p_.H;
            if (ring_.sign(DH, Z(-lo)) < 0 || ring_.sign(DH, hi) < 0) return false;
            for (int b : idx) {
                if (b == a) continue;
                if (D[a] * Z(E[b] - C[b]) < D[b] * lo) return false;
            }
        }
        return true;
    }

    // Is S²/(d·k²) + rest_neg ≤ R², i.e. S² ≤ d·k²·rest with rest = R² − (the other squared part)?
    // (a + b√d)² = a² + b²d + 2ab√d.
    bool square_within(const Q& S, const Z& k, const Z& rest) const {
        const Z a = Z(S.a * S.a + Z(S.b * S.b) * ring_.d() - Z(ring_.d() * k * k) * rest);
        const Z b = Z(Z(2) * S.a * S.b);
        return ring_.sign(a, b) <= 0;
    }

    // §4.2: D_{i0}, D_{i1} > 0, D_{i2} = 0 (write 0, 1, 2). In the plane of x0, x1: t = T/√d, s = S/√d
    // with T = D0(x0 − c0) + D1(x1 − c1), S = D1(x0 − c0) − D0(x1 − c1), so D0·S = D1·T − d(x1 − c1)
    // and D1·S = d(x0 − c0) − D0·T. Where §4 clips a vertex to the slab plane t = ±H the point has
    // T = ±H√d and one known coordinate: S = (integer + integer·√d)/k with k = D0 or D1.
    bool one_zero_component(const std::array<int, 3>& i) const {
        const Z& c0 = p_.C[i[0]];
        const Z& c1 = p_.C[i[1]];
        const Z& d0 = p_.D[i[0]];
        const Z& d1 = p_.D[i[1]];
        const Z& e0 = p_.E[i[0]];
        const Z& e1 = p_.E[i[1]];
        const Z& e2 = p_.E[i[2]];
        const Z& H = p_.H;
        const Z& d = ring_.d();
        const Z abs_c2 = abs_of(p_.C[i[2]]);
        if (!(e2 < abs_c2) && axis_meets_slabs(std::array<int, 2>{i[0], i[1]})) return true;  // §4.2.1

        const Z me0_c0 = Z(-e0 - c0), e0_c0 = Z(e0 - c0), e1_c1 = Z(e1 - c1), me1_c1 = Z(-e1 - c1);
        Q s_min, s_max;
        Z k_min(1), k_max(1);
        const Z t_hat = Z(d0 * me0_c0 + d1 * e1_c1);  // vertex (−e0, +e1)
        if (ring_.sign(t_hat, H) < 0) {               // t̂ < −H: on x1 = e1 where t = −H
            s_min = {Z(-d * e1_c1), Z(-d1 * H)};
            k_min = d0;
        } else if (ring_.sign(t_hat, Z(-H)) > 0) {    // t̂ > H: on x0 = −e0 where t = H
            s_min = {Z(d * me0_c0), Z(-d0 * H)};
            k_min = d1;
        } else {
            s_min = {Z(d1 * me0_c0 - d0 * e1_c1), Z(0)};
        }
        const Z t_bar = Z(d0 * e0_c0 + d1 * me1_c1);  // vertex (+e0, −e1)
        if (ring_.sign(t_bar, H) < 0) {               // t̄ < −H: on x0 = e0 where t = −H
            s_max = {Z(d * e0_c0), Z(d0 * H)};
            k_max = d1;
        } else if (ring_.sign(t_bar, Z(-H)) > 0) {    // t̄ > H: on x1 = −e1 where t = H
            s_max = {Z(-d * me1_c1), Z(d1 * H)};
            k_max = d0;
        } else {
            s_max = {Z(d1 * e0_c0 - d0 * me1_c1), Z(0)};
        }
        Z rest = p_.R * p_.R;
        if (e2 < abs_c2) {
            const Z out = Z(abs_c2 - e2);
            rest -= out * out;
        }
        if (ring_.sign(s_min) > 0) return square_within(s_min, k_min, rest);
        if (ring_.sign(s_max) < 0) return square_within(s_max, k_max, rest);
        return sgn(rest) >= 0;
    }

    Vec3<Q> vertex_scaled(int v, const Z& k) const {
        Vec3<Q> p;
        for (int n = 0; n < 3; ++n) {
            p[n] = {Z(k * p_.E[n]), Z(0)};
            if (!(v >> n & 1)) p[n].a = -p[n].a;
        }
        return p;
    }

    // §4.3 (every D_i > 0). T_v = D·(V_v − C), the vertex projections times √d.
    bool no_zero_components() {
        if (axis_meets_slabs(std::array<int, 3>{0, 1, 2})) return true;  // §4.3.1
        const Vec3<Z>& D = p_.D;
        const Vec3<Z>& E = p_.E;
        const Z dc = dot(D, p_.C);
        const Z de[3] = {Z(D[0] * E[0]), Z(D[1] * E[1]), Z(D[2] * E[2])};
        for (int v = 0; v < 8; ++v) {
            Z t = -dc;
            for (int n = 0; n < 3; ++n) {
                if (v >> n & 1) t += de[n];
                else t -= de[n];
            }
            T_[v] = t;
        }
        // Six box edges, then the six face cuts; a disk has the face cuts only (they contain every
        // clipped box edge: algo/linear_inequalities.hpp). A run that can no longer answer stops.
        static constexpr int kEdge[6][2] = {{0, 2}, {1, 2}, {0, 1}, {2, 1}, {1, 0}, {2, 0}};
        for (int n = sgn(p_.H) == 0 ? 6 : 0; n < 12; ++n) {
            if (n < 6 ? box_edge(kEdge[n][0], kEdge[n][1]) : face_cut((n - 6) / 2, n % 2 == 0)) return true;
            if (abandoned<Z>()) return false;
        }
        return false;
    }

    // The box edge x_i = +e_i, x_j = −e_j along x_k from vertex a to b, clipped to |t| ≤ H; in D_k·x_k
    // its ends are L0 = −E_k·D_k, or −E_k·D_k − T_a − H√d where t_a < −H, and L1 = E_k·D_k, or
    // E_k·D_k − T_b + H√d where t_b > H. Its distance to the axis line is the distance of its line
    // where the line's nearest point lies between the ends, else the nearer end's: the line's test is
    // in integers (the edge runs along a box axis) and decides most edges alone.
    bool box_edge(int i, int k) const {
        const int a = 1 << i, b = a | (1 << k);
        const Z& H = p_.H;
        if (ring_.sign(T_[a], Z(-H)) > 0 || ring_.sign(T_[b], H) < 0) return false;  // t_a > H or t_b < −H
        const int j = 3 - i - k;
        const Vec3<Z>& D = p_.D;
        const Z& Dk = D[k];
        // y = (the edge's point) − C in x_i, x_j. The line is within r of the axis line iff
        // (D_i·y_j − D_j·y_i)² ≤ R²·g, g = |D × e_k|² = D_i² + D_j².
        const Z yi = Z(p_.E[i] - p_.C[i]), yj = Z(-p_.E[j] - p_.C[j]);
        const Z n = Z(D[i] * yj - D[j] * yi);
        const Z g = Z(D[i] * D[i] + D[j] * D[j]);
        if (sgn(Z(n * n - Z(p_.R * p_.R) * g)) > 0) return false;
        // The line's nearest point has D_k·x_k = K/g, K = D_k·(C_k·g + D_k·(D_i·y_i + D_j·y_j)).
        const Z K = Z(Dk * Z(p_.C[k] * g + Dk * Z(D[i] * yi + D[j] * yj)));
        const Z EkDk = Z(p_.E[k] * Dk);
        const Q L0 = ring_.sign(T_[a], H) < 0 ? Q{Z(-EkDk - T_[a]), Z(-H)} : Q{Z(-EkDk), Z(0)};
        if (ring_.sign(Z(K - g * L0.a), Z(-g * L0.b)) < 0) return end_within(i, j, k, yi, yj, g, L0);
        const Q L1 = ring_.sign(T_[b], Z(-H)) > 0 ? Q{Z(EkDk - T_[b]), H} : Q{EkDk, Z(0)};
        if (ring_.sign(Z(g * L1.a - K), Z(g * L1.b)) < 0) return end_within(i, j, k, yi, yj, g, L1);
        return true;
    }

    // Whether the edge's end with D_k·x_k = L = α' + β√d (and y_i, y_j as above) is within r of the
    // axis line: with Y = D_k·(end − C), Y_k = α + β√d, d·|Y|² − (D·Y)² ≤ R²·d·D_k², where
    // D·Y = γ + D_k·β√d and d − D_k² = g.
    bool end_within(int i, int j, int k, const Z& yi, const Z& yj, const Z& g, const Q& L) const {
        const Vec3<Z>& D = p_.D;
        const Z& Dk = D[k];
        const Z& d = ring_.d();
        const Z Yi = Z(Dk * yi), Yj = Z(Dk * yj);
        const Z alpha = Z(L.a - Dk * p_.C[k]);
        const Z& beta = L.b;
        const Z gamma = Z(D[i] * Yi + D[j] * Yj + Dk * alpha);
        const Z a = Z(d * Z(Yi * Yi + Yj * Yj + alpha * alpha - Z(p_.R * p_.R) * Z(Dk * Dk)) + Z(beta * beta) * Z(d * g) -
                      gamma * gamma);
        const Z b = Z(Z(2) * beta * Z(d * alpha - gamma * Dk));
        return ring_.sign(a, b) <= 0;
    }

    // Whether the line where the face x_i = s (s = ±E_i) meets the slab plane t = τ (τ = ±H) is farther
    // than r from the axis point A = C + τu of that plane. Within the plane, the face's normal has length
    // √(1 − u_i²) and A lies (s − A_i) from the face along e_i, so the distance is
    // |s − A_i|/√(1 − u_i²); times √d, with g = s − C_i: (g·√d − τ·D_i)² > R²·(d − D_i²).
    bool cut_line_far(int i, const Z& s, const Z& tau) const {
        const Z g = Z(s - p_.C[i]);
        const Z& Di = p_.D[i];
        const Z DiDi = Di * Di;
        const Z a = Z(g * g * ring_.d() + tau * tau * DiDi - Z(p_.R * p_.R) * Z(ring_.d() - DiDi));
        const Z b = Z(Z(-2) * g * tau * Di);
        return ring_.sign(a, b) > 0;
    }

    // Where t = τ = σH crosses the path m → mid = m + 2e_j·U_j → M: a point times its denominator
    // (D_j on the first edge, D_k on the second).
    void cut_point(int m, int j, int k, int sigma, Vec3<Q>& point, Z& den) const {
        const int mid = m | (1 << j);
        const Z sH = sigma > 0 ? p_.H : Z(-p_.H);
        if (ring_.sign(T_[mid], Z(-sH)) >= 0) {  // t_mid ≥ τ: on the first edge
            den = p_.D[j];
            point = vertex_scaled(m, den);
            point[j] = {Z(-p_.E[j] * den - T_[m]), sH};
        } else {
            den = p_.D[k];
            point = vertex_scaled(mid, den);
            point[k] = {Z(-p_.E[k] * den - T_[mid]), sH};
        }
    }

    // The face x_i = s = ±e_i cut by the slab plane t = τ = ∓H: the segment from P0 (on the path
    // m → m + 2e_j·U_j → M) to P1 (the path through m + 2e_k·U_k). Both lie on the line L where the two
    // planes meet; in the slab plane a point's distance to the axis line is its distance to
    // A = C + τu, so the segment is within r iff L is (cut_line_far) and A's foot on L lies between the
    // ends, or else the nearer end is. Along L, σ(x) = D_k·x_j − D_j·x_k grows from P1 to P0, and
    // σ(A) = D_k·C_j − D_j·C_k (u's part cancels), an integer.
    bool face_cut(int i, bool plus_face) const {
        const int m = plus_face ? (1 << i) : 0;
        const int M = plus_face ? 7 : (7 & ~(1 << i));
        const int sigma = plus_face ? -1 : 1;
        const Z sH = sigma > 0 ? p_.H : Z(-p_.H);
        // τ < t_m ⇔ T_m − τ√d > 0; t_M < τ ⇔ T_M − τ√d < 0.
        if (ring_.sign(T_[m], Z(-sH)) > 0 || ring_.sign(T_[M], Z(-sH)) < 0) return false;
        if (cut_line_far(i, plus_face ? p_.E[i] : Z(-p_.E[i]), sH)) return false;
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        const Vec3<Z>& D = p_.D;
        const Z sigma_A = Z(D[k] * p_.C[j] - D[j] * p_.C[k]);
        Vec3<Q> P;
        Z den;
        // σ(P0)·k0 as a + b√d (P = P0·k0 has one coordinate in Z[√d]).
        cut_point(m, j, k, sigma, P, den);
        if (ring_.sign(Z(sigma_A * den - D[k] * P[j].a + D[j] * P[k].a), Z(D[j] * P[k].b - D[k] * P[j].b)) > 0)
            return cut_end_within(P, den, sH);  // A's foot beyond P0
        cut_point(m, k, j, sigma, P, den);
        if (ring_.sign(Z(sigma_A * den - D[k] * P[j].a + D[j] * P[k].a), Z(D[j] * P[k].b - D[k] * P[j].b)) < 0)
            return cut_end_within(P, den, sH);  // beyond P1
        return true;
    }

    // Whether the cut point P/den (in the slab plane t = τ) is within r of the axis line:
    // |P/den − C|² − τ² ≤ r², i.e. |P − den·C|² ≤ den²·(R² + τ²).
    bool cut_end_within(const Vec3<Q>& P, const Z& den, const Z& tau) const {
        Vec3<Q> y = P;
        for (int n = 0; n < 3; ++n) y[n].a -= den * p_.C[n];
        const Q n2 = ring_.norm2(y);
        return ring_.sign(Z(n2.a - Z(den * den) * Z(p_.R * p_.R + tau * tau)), n2.b) <= 0;
    }

    Problem<Z>& p_;
    QuadraticRing<Z> ring_;
    std::array<Z, 8> T_;
};

}  // namespace detail

// The exact §4 answer for the canonical integer problem (p is modified: reflected into the first octant).
template <class Z>
bool intersects(Problem<Z>& p) {
    return detail::Inequalities<Z>(p).run();
}

}  // namespace boxcyl::exact::integer

namespace boxcyl::exact::integer {

// The integer types tried in turn: FixedInt (stack limbs) while every value fits, else mpz_class.
// §4's largest values (the sign tests of a clipped end's distance and of §4.2's extremes square
// numbers of Z[√d]) have about 4·L + 8·M + 64 bits for lengths below 2^L and axis components below 2^M
// (after the scalings), so kFixedLimbs·64 bits hold them for integer and binary-fraction coordinates,
// also with full-precision axis directions; wider inputs overflow it and the stage reruns in mpz.
inline constexpr int kFixedLimbs = 16;
using Small = FixedInt<kFixedLimbs>;

// The stage in the integer type F (FixedInt<N>, or EpsilonSeries over FixedInt): the answer, or
// nullopt when a value outgrew F (or, for an oriented box, when its frame is not a signed permutation).
template <class F, class Box>
std::optional<bool> answer_in(const Box& b, const Cylinder<double>& c) {
    FixedOverflow::flag() = false;
    auto p = problem<F>(b, c);
    bool r = false;
    if constexpr (std::is_same_v<decltype(p), Problem<F>>) {
        if (FixedOverflow::flag()) return std::nullopt;
        r = intersects(p);
    } else {
        if (!p || FixedOverflow::flag()) return std::nullopt;
        r = intersects(*p);
    }
    if (FixedOverflow::flag()) return std::nullopt;
    return r;
}
template <class Box>
std::optional<bool> answer_small(const Box& b, const Cylinder<double>& c) {
    return answer_in<Small>(b, c);
}

// Inputs whose range is wide only because some values are tiny beside the others (TwoScale: the
// lengths, the axis, or both, in two groups hundreds of binary orders apart): the stage in
// EpsilonSeries over FixedInt — order 2, then order 4 when a sign hung on a higher power of the tiny
// values (the orders count from each value's own lowest power of ε). nullopt when neither decides (the
// caller runs plain mpz_class) or the inputs are not of two scales. The coefficients get kSeriesLimbs
// limbs: a group may span 192 bits, and the widest values (about 4·L + 8·M + 64 bits, as for
// kFixedLimbs above) then outgrow 16 limbs; FixedInt's arithmetic costs what the limbs in use cost,
// so the wider type costs little where the values are narrower.
inline constexpr int kSeriesLimbs = 32;
// The series runs keep every value on the stack, M + 1 coefficients of kSeriesLimbs limbs each: the
// query's deepest path, through the order-4 run, takes about 115 KB at -O2 (test
// ExactStage.StackHighWaterMark). With less room than this left on the thread's stack they are
// skipped, and the stage answers in mpz_class.
inline constexpr std::size_t kSeriesStackRoom = std::size_t{512} << 10;

template <int Limbs, int Order, class Box>
std::optional<bool> answer_series(const Box& b, const Cylinder<double>& c, int E, bool& overflow) {
    SeriesContext& ctx = SeriesContext::get();
    ctx.E = E;
    ctx.order = Order;
    ctx.undecided = false;
    const std::optional<bool> r = answer_in<EpsilonSeries<FixedInt<Limbs>, Order>>(b, c);
    overflow = FixedOverflow::flag();
    if (!r || overflow || ctx.undecided) return std::nullopt;
    return r;
}

template <class Box>
std::optional<bool> answer_two_scale(const Box& b, const Cylinder<double>& c) {
    const TwoScale<std::tuple_size_v<decltype(lengths(b, c))>> L(lengths(b, c));
    const TwoScale<3> D({c.axis[0], c.axis[1], c.axis[2]});
    if (!L.ok() || !D.ok() || (L.gap() < 0 && D.gap() < 0)) return std::nullopt;
    if (stack_room() < kSeriesStackRoom) return std::nullopt;
    const int E = L.gap() < 0 ? D.gap() : D.gap() < 0 ? L.gap() : std::min(L.gap(), D.gap());
    bool overflow = false;
    if (const std::optional<bool> r = answer_series<kSeriesLimbs, 2>(b, c, E, overflow)) return r;
    if (overflow) return std::nullopt;
    return answer_series<kSeriesLimbs, 4>(b, c, E, overflow);
}

// FixedInt first, mpz_class when a value outgrew it. (A second, wider FixedInt tier measured no
// faster: the inputs that outgrow 16 limbs mostly span hundreds of binary orders — an axis component
// of 1e-300 beside 1 — and outgrow any fixed width.)
template <class Box>
auto answer(const Box& b, const Cylinder<double>& c) {
    const std::optional<bool> fixed = answer_small(b, c);
    if constexpr (std::is_same_v<decltype(problem<mpz_class>(b, c)), Problem<mpz_class>>) {
        if (fixed) return *fixed;
        if (const std::optional<bool> r = answer_two_scale(b, c)) return *r;
        Problem<mpz_class> big = problem<mpz_class>(b, c);
        return intersects(big);
    } else {
        if (fixed) return fixed;
        if (const std::optional<bool> r = answer_two_scale(b, c)) return r;
        std::optional<Problem<mpz_class>> big = problem<mpz_class>(b, c);
        if (!big) return std::optional<bool>();
        return std::optional<bool>(intersects(*big));
    }
}

// Narrow inputs — every length an integer below 2^kNarrowLengthBits times one power of two, the axis
// likewise below 2^kNarrowAxisBits: integer and binary-fraction coordinates, axes along box axes or
// with small integer directions — keep every value of §4 within FixedInt (its largest has about
// 4·(length bits) + 8·(axis bits) + 64 bits), so the exact stage costs less than the searched
// certificates and the certified filter; the pipeline asks it right after stage 0. An overflow all the
// same only gives nullopt. The axis is checked first: on random data it is almost never narrow, and
// the check then costs three doubles.
inline constexpr int kNarrowLengthBits = 48;
inline constexpr int kNarrowAxisBits = 16;

template <class Box>
bool narrow(const Box& b, const Cylinder<double>& c) {
    const Scale<3> axis({c.axis[0], c.axis[1], c.axis[2]});
    if (axis.span() > kNarrowAxisBits) return false;
    int emin = 0, top = 0;
    bool any = false;
    for (double x : lengths(b, c)) {
        const Dyadic v = dyadic(x);
        if (v.m == 0) continue;
        const auto mag = static_cast<std::uint64_t>(v.m < 0 ? -v.m : v.m);
        const int t = v.e + static_cast<int>(std::bit_width(mag));
        if (!any) emin = v.e, top = t, any = true;
        emin = std::min(emin, v.e), top = std::max(top, t);
    }
    return top - emin <= kNarrowLengthBits;
}
// Narrow inputs of two scales: each group of the lengths within 64 bits (narrow()'s 48, and room for
// 1 ± ulp beside 1), the axis' groups within kNarrowAxisBits. The series run then costs about a
// narrow run (about a µs), less than the middle stage spends failing on such queries near touching — a
// subnormal tilt of an exactly touching shape, a box of 2^−1000 at a cylinder of 2^1000 — whose
// answers hang on values no double-double enclosure resolves; the pipeline asks it before the middle
// stage.
inline constexpr int kNarrowTwoScaleLengthBits = 64;
template <class Box>
bool narrow_two_scale(const Box& b, const Cylinder<double>& c) {
    const TwoScale<3> D({c.axis[0], c.axis[1], c.axis[2]});
    if (!D.ok() || D.span() > kNarrowAxisBits) return false;
    const TwoScale<std::tuple_size_v<decltype(lengths(b, c))>> L(lengths(b, c));
    return L.ok() && L.span() <= kNarrowTwoScaleLengthBits && (L.gap() >= 0 || D.gap() >= 0);
}

}  // namespace boxcyl::exact::integer
