// The clipped edges and face cuts (docs/algorithms.md, "Clipped edges and face cuts") on enclosures: the
// rows clipped and clipped_flat. The cylinder meets B = {K + Σ λ_m·a_m : |λ_m| ≤ 1} (half-edge vectors
// a_m = e_m·A_m as given) iff the axis segment meets B, or a box edge clipped to the slab |t| ≤ H or a
// face cut by a slab plane is within r of the axis line. Every test is three-valued (yes, no, unknown
// when the enclosures cannot separate its operands); the answer is certain when one candidate is
// certainly within r, or every test certainly fails. Unlike the convex-hull method's, its tests stay
// decisive with the axis parallel to a box edge: a degeneracy that does not matter is not asked
// (docs/robustness/clipped-candidates.md).
#pragma once

#include <array>     // vertices and candidate points
#include <cstddef>   // std::size_t
#include <cstdint>   // the crossings computed
#include <optional>  // undecided

#include "boxcyl/geometry/vec3.hpp"
#include "boxcyl/number/interval.hpp"  // the uncertainty flag

namespace boxcyl::filtered::clipped {

enum class Tri { no, yes, unknown };

// The three-valued outcome of one test on enclosures: the test's own comparisons, alone, decide it.
template <class F>
Tri tri(F&& test) {
    const bool saved = detail::uncertain_flag;
    detail::uncertain_flag = false;
    const bool r = test();
    const bool unsure = detail::uncertain_flag;
    detail::uncertain_flag = saved;
    return unsure ? Tri::unknown : (r ? Tri::yes : Tri::no);
}

// The problem, every length relative to the cylinder centre: G = K − C, the half-edge vectors, the unit
// axis u (an enclosure), the radius and the half-height; which extents are exactly 0 (then a_m is exactly
// the zero vector) and whether h is (a disk: the two slab planes are one).
template <class N>
struct Problem {
    Vec3<N> G;
    std::array<Vec3<N>, 3> a;
    Vec3<N> u;
    N r, H;
    std::array<bool, 3> zero{};
    bool disk = false;
};

template <class N>
class Test {
public:
    explicit Test(const Problem<N>& p) : p_(p), r2_(p.r * p.r) {
        for (std::size_t s = 0; s < 8; ++s) {
            Vec3<N> v = p.G;
            for (std::size_t m = 0; m < 3; ++m) v = (s >> m & 1) ? Vec3<N>(v + p.a[m]) : Vec3<N>(v - p.a[m]);
            V_[s] = v;
            T_[s] = dot(p.u, v);
        }
    }

    // Which side of the slab vertex s is on (1 beyond t = H, −1 beyond t = −H, 0 in the slab), 2 when
    // uncertain. Every other test needs them certain and uses the same (exact) ones: set_sides.
    int side(int s) const {
        const N& t = T_[static_cast<std::size_t>(s)];
        if (tri([&] { return p_.H < t; }) == Tri::yes) return 1;
        if (tri([&] { return t < -p_.H; }) == Tri::yes) return -1;
        if (tri([&] { return -p_.H <= t && t <= p_.H; }) == Tri::yes) return 0;
        return 2;
    }
    void set_sides(const std::array<int, 8>& sides) { side_ = sides; }

    // Whether the non-zero half-edge vectors are certainly independent (for a solid box, det ≠ 0; a flat
    // one needs its two edges independent).
    Tri solid() {
        zeros_ = int(p_.zero[0]) + int(p_.zero[1]) + int(p_.zero[2]);
        if (zeros_ == 0) {
            det_ = dot(p_.a[0], cross(p_.a[1], p_.a[2]));
            return tri([&] { return N(0) < abs_value(det_); });
        }
        if (zeros_ == 1) {
            flat_ = p_.zero[0] ? 0 : p_.zero[1] ? 1 : 2;
            const Vec3<N> n = cross(edge(flat_ + 1), edge(flat_ + 2));
            return tri([&] { return N(0) < dot(n, n); });
        }
        return Tri::yes;  // a segment or a point is its own clipped edge
    }

    // The 25 tests: the axis segment meets B (0; after solid()), the 12 clipped edges (1–12), the
    // 12 face cuts (13–24).
    static constexpr int kTests = 25;
    Tri test(int i) const {
        if (i == 0) {
            if (zeros_ == 0) return axis_meets_box(det_);
            return zeros_ == 1 ? axis_meets_flat_box(flat_) : Tri::no;
        }
        if (i <= 12) {
            const int m = (i - 1) / 4, rest = (i - 1) % 4;  // the edges along a_m: the 4 vertices without bit m
            const int low = rest & ((1 << m) - 1), high = (rest >> m) << (m + 1);
            const int s = low | high;
            return clipped_edge_within(s, s | (1 << m));
        }
        const int f = i - 13;  // face (m, plus), plane σ
        return face_cut_within(f / 4, (f >> 1 & 1) != 0, (f & 1) ? -1 : 1);
    }

private:
    const Vec3<N>& edge(int m) const { return p_.a[static_cast<std::size_t>(m % 3)]; }

    // Cramer's rule: λ_m(t)·det = p_m + t·q_m with p_m = −n_m·G, q_m = n_m·u, n_m = a_j × a_k; the axis
    // segment meets B iff some |t| ≤ H has |p_m + t·q_m| ≤ |det| for every m. A constraint certainly
    // violated (or satisfied) on all of [−H, H] needs no sign of q_m: so an axis parallel to a face
    // (q_m = 0 in exact arithmetic, only nearly in enclosures) is still decided.
    Tri axis_meets_box(const N& det) const {
        const N adet = abs_value(det);
        std::array<N, 3> p, q;
        std::array<bool, 3> bounded{};
        bool unknown = false;
        for (std::size_t m = 0; m < 3; ++m) {
            const Vec3<N> n = cross(p_.a[(m + 1) % 3], p_.a[(m + 2) % 3]);
            N pm = -dot(n, p_.G), qm = dot(n, p_.u);
            const N ap = abs_value(pm), aq = abs_value(qm);
            if (tri([&] { return adet < ap - p_.H * aq; }) == Tri::yes) return Tri::no;
            if (tri([&] { return ap + p_.H * aq <= adet; }) == Tri::yes) continue;
            const Tri positive = tri([&] { return N(0) < qm; });
            if (positive == Tri::unknown || tri([&] { return N(0) < aq; }) != Tri::yes) {
                unknown = true;
                continue;
            }
            if (positive == Tri::no) pm = -pm, qm = -qm;  // |p + tq| = |−p − tq|: now q > 0
            p[m] = pm, q[m] = qm, bounded[m] = true;
        }
        // With q_m > 0 the constraint is lo_m = (−|det| − p_m)/q_m ≤ t ≤ hi_m = (|det| − p_m)/q_m: the
        // intervals and [−H, H] meet iff every lower end is ≤ every upper end.
        bool all_yes = !unknown;
        for (std::size_t m = 0; m < 3; ++m) {
            if (!bounded[m]) continue;
            const N lo_num = -adet - p[m], hi_num = adet - p[m];
            auto pair = [&](Tri t) {
                if (t == Tri::no) return false;
                if (t == Tri::unknown) all_yes = false;
                return true;
            };
            if (!pair(tri([&] { return lo_num <= p_.H * q[m]; }))) return Tri::no;
            if (!pair(tri([&] { return -(p_.H * q[m]) <= hi_num; }))) return Tri::no;
            for (std::size_t n = 0; n < 3; ++n) {
                if (n == m || !bounded[n]) continue;
                if (!pair(tri([&] { return lo_num * q[n] <= (adet - p[n]) * q[m]; }))) return Tri::no;
            }
        }
        return all_yes ? Tri::yes : Tri::unknown;
    }

    // A flat box (a_z = 0): the parallelogram {K + λ_i·a_i + λ_j·a_j}, n = a_i × a_j. The axis line
    // crosses its plane at t = (n·G)/(n·u); there Y = X − K with (n·u)·Y = W := (n·G)·u − (n·u)·G and
    // λ_i = Y·(a_j × n)/|n|², λ_j = Y·(n × a_i)/|n|². An axis (nearly) parallel to the plane is left to
    // the clipped edges, unless the plane is certainly beyond the segment's reach.
    Tri axis_meets_flat_box(int z) const {
        const Vec3<N>& ai = edge(z + 1);
        const Vec3<N>& aj = edge(z + 2);
        const Vec3<N> n = cross(ai, aj);
        const N nu = dot(n, p_.u), nG = dot(n, p_.G);
        const N anu = abs_value(nu);
        const Tri reach = tri([&] { return abs_value(nG) <= p_.H * anu; });
        if (reach == Tri::no) return Tri::no;
        if (tri([&] { return N(0) < anu; }) != Tri::yes) return Tri::unknown;
        const Vec3<N> W = nG * p_.u - nu * p_.G;
        const N bound = dot(n, n) * anu;
        const Tri in_i = tri([&] { return abs_value(dot(cross(aj, n), W)) <= bound; });
        const Tri in_j = tri([&] { return abs_value(dot(cross(n, ai), W)) <= bound; });
        if (in_i == Tri::no || in_j == Tri::no) return Tri::no;
        if (reach == Tri::yes && in_i == Tri::yes && in_j == Tri::yes) return Tri::yes;
        return Tri::unknown;
    }

    // The segment x → y (relative to C) within r of the axis line. With q = u × x, the projections on
    // the plane ⊥ u, w = q_y − q_x: an end point within r, or the nearest point interior
    // (q_y·w > 0 > q_x·w) and the line through the segment within r: (u·(x × (y − x)))² ≤ r²|w|².
    Tri within(const Vec3<N>& x, const Vec3<N>& y) const {
        const Vec3<N> qx = cross(p_.u, x), qy = cross(p_.u, y);
        const N ax = dot(qx, qx), ay = dot(qy, qy);
        const Tri in_x = tri([&] { return ax <= r2_; }), in_y = tri([&] { return ay <= r2_; });
        if (in_x == Tri::yes || in_y == Tri::yes) return Tri::yes;
        const bool both_out = in_x == Tri::no && in_y == Tri::no;
        const Vec3<N> w = qy - qx;
        const Tri toward_y = tri([&] { return N(0) < dot(qy, w); });  // the nearest point is not y
        const Tri from_x = tri([&] { return dot(qx, w) < N(0); });    // ... and not x
        // Both end points farther than r, and the nearest point one of them (most far candidates).
        if (both_out && (toward_y == Tri::no || from_x == Tri::no)) return Tri::no;
        const N ww = dot(w, w);
        const N n = dot(p_.u, cross(x, Vec3<N>(y - x)));
        const Tri line_within = tri([&] { return n * n <= r2_ * ww; });
        if (toward_y == Tri::yes && from_x == Tri::yes && line_within == Tri::yes) return Tri::yes;
        if (!both_out) return Tri::unknown;
        // The line through the segment is farther than r, or the segment is shorter (projected) than
        // the end points' margin.
        if (line_within == Tri::no) return Tri::no;
        const N reach = p_.r + abs_value(w[0]) + abs_value(w[1]) + abs_value(w[2]);  // ≥ r + |w|
        if (tri([&] { return reach * reach < ax; }) == Tri::yes) return Tri::no;
        return Tri::unknown;
    }

    // Where the edge s → s' crosses t = σH (the two ends certainly on either side of it).
    // Each is computed once: an edge's crossing serves its clipped edge and the cuts of its two faces.
    const Vec3<N>& crossing(int s, int s1, int sigma) const {
        const int lo = s < s1 ? s : s1, hi = s ^ s1 ^ lo;
        const int m = (hi ^ lo) == 1 ? 0 : (hi ^ lo) == 2 ? 1 : 2;  // the edge runs along a_m from lo
        const int along = (lo & ((1 << m) - 1)) | ((lo >> (m + 1)) << m);  // lo's other two bits
        const int slot_index = (4 * m + along) * 2 + (sigma > 0 ? 1 : 0);  // < 24
        const auto slot = static_cast<std::size_t>(slot_index);
        if (!(known_ >> slot & 1u)) {
            const std::size_t i = static_cast<std::size_t>(lo), j = static_cast<std::size_t>(hi);
            const N lambda = (N(sigma) * p_.H - T_[i]) / (T_[j] - T_[i]);
            crossings_[slot] = V_[i] + lambda * Vec3<N>(V_[j] - V_[i]);
            known_ |= 1u << slot;
        }
        return crossings_[slot];
    }

    // The box edge s → s' clipped to the slab.
    Tri clipped_edge_within(int s, int s1) const {
        const int a = side_[static_cast<std::size_t>(s)], b = side_[static_cast<std::size_t>(s1)];
        if (a != 0 && a == b) return Tri::no;
        const Vec3<N> x = a == 0 ? V_[static_cast<std::size_t>(s)] : crossing(s, s1, a);
        if (p_.disk && b == -a) return within(x, x);  // one plane: both crossings are one point
        const Vec3<N> y = b == 0 ? V_[static_cast<std::size_t>(s1)] : crossing(s, s1, b);
        return within(x, y);
    }

    // The face λ_m = ±1 cut by the plane t = σH: its corners' sides of the plane must be certain.
    Tri face_cut_within(int m, bool plus, int sigma) const {
        if (p_.disk && sigma < 0) return Tri::no;  // one plane
        const int j = (m + 1) % 3, k = (m + 2) % 3;
        const int base = plus ? (1 << m) : 0;
        const std::array<int, 4> corner{base, base | (1 << j), base | (1 << j) | (1 << k), base | (1 << k)};
        const N plane = N(sigma) * p_.H;
        std::array<int, 4> sign{};
        int pos = 0, neg = 0;
        for (std::size_t c = 0; c < 4; ++c) {
            const N& t = T_[static_cast<std::size_t>(corner[c])];
            if (tri([&] { return plane < t; }) == Tri::yes) sign[c] = 1, ++pos;
            else if (tri([&] { return t < plane; }) == Tri::yes) sign[c] = -1, ++neg;
            else return Tri::unknown;
        }
        if (pos == 0 || neg == 0) return Tri::no;  // the plane misses the face
        std::array<Vec3<N>, 4> pts;
        std::size_t n = 0;
        for (std::size_t c = 0; c < 4; ++c) {
            const std::size_t c1 = (c + 1) % 4;
            if (sign[c] * sign[c1] < 0) pts[n++] = crossing(corner[c], corner[c1], sigma);
        }
        // A plane through a parallelogram with no corner on it crosses exactly two of its edges.
        Tri result = Tri::no;
        for (std::size_t x = 0; x < n; ++x)
            for (std::size_t y = x + 1; y < n; ++y) {
                const Tri t = within(pts[x], pts[y]);
                if (t == Tri::yes) return t;
                if (t == Tri::unknown) result = t;
            }
        return result;
    }

    const Problem<N>& p_;
    N r2_;
    std::array<Vec3<N>, 8> V_;
    std::array<N, 8> T_;
    std::array<int, 8> side_{};
    N det_{};
    int zeros_ = 0, flat_ = 0;
    mutable std::array<Vec3<N>, 24> crossings_;  // by edge (12) and plane (2)
    mutable std::uint32_t known_ = 0;
};

// The three-valued parallelepiped test: true or false when certain, nullopt otherwise. Each test runs
// on the fast enclosures first (Bounded: most candidates are far from the axis), and on the tight ones
// (double-double, built by `tight()` on first need) only when the fast ones left it undecided.
template <class Fast, class Tight, class MakeTight>
std::optional<bool> decide(const Problem<Fast>& fast, MakeTight&& tight) {
    Test<Fast> f(fast);
    std::optional<Problem<Tight>> tp;
    std::optional<Test<Tight>> t;
    auto second = [&]() -> Test<Tight>& {
        if (!t) {
            tp.emplace(tight());
            t.emplace(*tp);
        }
        return *t;
    };
    std::array<int, 8> sides{};
    int above = 0, below = 0;
    for (int s = 0; s < 8; ++s) {
        int side = f.side(s);
        if (side == 2) side = second().side(s);
        if (side == 2) return std::nullopt;  // a vertex within rounding of a slab plane
        sides[static_cast<std::size_t>(s)] = side;
        above += side > 0, below += side < 0;
    }
    if (above == 8 || below == 8) return false;
    f.set_sides(sides);
    const Tri solid = f.solid();
    if (solid == Tri::no) return std::nullopt;  // flat, or dependent axes: other methods
    bool tight_ready = false;
    auto tight_test = [&]() -> Test<Tight>* {
        Test<Tight>& s = second();
        if (!tight_ready) {
            s.set_sides(sides);
            if (s.solid() != Tri::yes) return nullptr;
            tight_ready = true;
        }
        return &s;
    };
    if (solid == Tri::unknown && !tight_test()) return std::nullopt;
    bool unknown = false;
    for (int i = 0; i < Test<Fast>::kTests; ++i) {
        Tri r = solid == Tri::yes ? f.test(i) : Tri::unknown;
        if (r == Tri::unknown) {
            Test<Tight>* s = tight_test();
            if (!s) return std::nullopt;
            r = s->test(i);
        }
        if (r == Tri::yes) return true;
        if (r == Tri::unknown) unknown = true;
    }
    if (unknown) return std::nullopt;
    return false;
}

}  // namespace boxcyl::filtered::clipped
