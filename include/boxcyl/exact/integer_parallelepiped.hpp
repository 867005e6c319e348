// The exact stage for any parallelepiped (an oriented box whose frame is only nearly orthonormal is
// one): the clipped edges and face cuts (docs/algorithms.md, "Clipped edges and face cuts") in integers
// and Z[√d], as exact/integer_inequalities.hpp. B = {K + Σ λ_m·a_m : |λ_m| ≤ 1} with the half-edge
// vectors a_m = e_m·A_m exactly as given; the axis test solves for λ by Cramer's rule, and the
// candidates' end points (box vertices, points where a box edge crosses a slab plane t = ±H) have
// positive integer denominators, so every test is the sign of a + b√d with integers a, b.
//
// Dependent half-edge vectors are answered the same way. B is then a zonogon (rank 2), a segment or a
// point, and the argument for the solid carries over: the distance to the axis line is convex on the
// convex B ∩ slab, so its least value is 0 where the axis crosses B inside the slab, or lies on the
// relative boundary of B ∩ slab. That boundary is covered by the cube's edges mapped into B (the
// boundary of a linear image of the cube is the image of some of its edges; for a segment, the images
// of its connected edge graph cover it) clipped to the slab, and by the chords B ∩ {t = ±H}, which the
// face cuts cover (every point of B is the image of a point on the cube's surface, since the kernel
// line through any point of the cube leaves it there).
#pragma once

#include <array>     // vertices, candidate points
#include <cstddef>   // std::size_t
#include <cstdint>   // std::int64_t
#include <optional>  // nullopt: a value outgrew the fixed-width integers
#include <type_traits>  // std::is_same_v

#include "boxcyl/exact/integer_inequalities.hpp"
#include "boxcyl/exact/stack_room.hpp"
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"

namespace boxcyl::exact::integer {

// All lengths in one unit, relative to the cylinder centre C: G = K − C, the half-edge vectors a_m,
// the radius R and the half-height H; the axis direction D.
template <class Z>
struct ParallelepipedProblem {
    Vec3<Z> G;
    std::array<Vec3<Z>, 3> a;
    Vec3<Z> D;
    Z R, H;
};

// The exact products e_m·A_mj are dyadic too: m1·m2·2^(e1 + e2).
template <class Z>
ParallelepipedProblem<Z> problem_turned(const Parallelepiped<double>& b, const Cylinder<double>& c) {
    struct Item {
        std::int64_t m1 = 0, m2 = 1;
        int e = 0;
    };
    std::array<Item, 17> items;  // K (3), C (3), r, h, e_m·A_mj (9)
    auto single = [](double x) {
        const Dyadic v = dyadic(x);
        return Item{v.m, 1, v.e};
    };
    for (std::size_t i = 0; i < 3; ++i) items[i] = single(b.center[i]), items[3 + i] = single(c.center[i]);
    items[6] = single(c.radius);
    items[7] = single(c.height);
    for (std::size_t m = 0; m < 3; ++m)
        for (std::size_t j = 0; j < 3; ++j) {
            const Dyadic e = dyadic(b.extents[m]), a = dyadic(b.axes[m][j]);
            items[8 + 3 * m + j] = e.m == 0 || a.m == 0 ? Item{} : Item{e.m, a.m, e.e + a.e};
        }
    bool any = false;
    int emin = 0;
    for (const Item& it : items)
        if (it.m1 != 0 && (!any || it.e < emin)) emin = it.e, any = true;
    auto integer = [&](std::size_t i) {
        const Item& it = items[i];
        if (it.m1 == 0) return Z(0);
        Z z = Z(it.m1) * Z(it.m2);
        if (it.e > emin) z <<= static_cast<unsigned>(it.e - emin);
        return z;
    };
    // Lengths ×2: G = 2(K − C), a_m = 2·e_m·A_m, R = 2r, H = h.
    ParallelepipedProblem<Z> p;
    for (std::size_t i = 0; i < 3; ++i) p.G[i] = Z(2) * (integer(i) - integer(3 + i));
    for (std::size_t m = 0; m < 3; ++m)
        for (std::size_t j = 0; j < 3; ++j) p.a[m][j] = Z(2) * integer(8 + 3 * m + j);
    p.R = Z(2) * integer(6);
    p.H = integer(7);
    p.D = integer_direction<Z>(c.axis);
    return p;
}

namespace detail {

template <class Z>
class ClippedTest {
public:
    using Q = QuadInt<Z>;

    explicit ClippedTest(const ParallelepipedProblem<Z>& p) : p_(p), ring_(dot(p.D, p.D)) {
        for (int s = 0; s < 8; ++s) {
            Vec3<Z> v = p.G;
            for (int m = 0; m < 3; ++m) v = (s >> m & 1) ? Vec3<Z>(v + p.a[m]) : Vec3<Z>(v - p.a[m]);
            T_[s] = dot(p.D, v);
            V_[s] = v;
        }
    }

    // Any half-edge vectors: independent ones span a solid, dependent ones a flat zonogon (rank 2), a
    // segment (rank 1) or a point.
    bool run() const {
        const Z det = dot(p_.a[0], cross(p_.a[1], p_.a[2]));
        // The box outside the slab: every vertex beyond the same plane.
        int above = 0, below = 0;
        for (int s = 0; s < 8; ++s) {
            const int side = side_of(T_[s]);
            above += side > 0, below += side < 0;
        }
        if (above == 8 || below == 8) return false;
        // The axis segment meets B. A segment or point (rank ≤ 1) needs no such test: the union of its
        // clipped edges is B ∩ slab, and each is tested whole. A cylinder of radius 0 is its axis
        // segment, so where that test covers the whole segment (a solid B, or a flat one the axis
        // crosses at one point) its answer is the answer, without the edges' wide values.
        const bool segment = sgn(p_.R) == 0;
        if (sgn(det) != 0) {
            if (axis_meets_box(det)) return true;
            if (segment) return false;
        } else if (const std::optional<Vec3<Z>> n = plane_normal()) {
            if (axis_meets_flat_box(*n)) return true;
            if (segment && sgn(dot(*n, p_.D)) != 0) return false;
        }
        // The ends of the clipped edges and the face cuts' end points are box vertices in the slab and
        // crossings of box edges with t = ±H: tested once each, below, so that the edges and the cuts
        // need test only their interiors.
        for (int s = 0; s < 8; ++s)
            if (side_of(T_[s]) == 0 && point_within(V_[s])) return true;
        for (int m = 0; m < 3; ++m)
            for (int s = 0; s < 8; ++s)
                if (!(s >> m & 1) && clipped_edge_within(s, s | (1 << m))) return true;
        for (int m = 0; m < 3; ++m)
            for (int plus = 0; plus < 2; ++plus)
                for (int sigma : {1, -1}) {
                    if (sigma < 0 && sgn(p_.H) == 0) continue;  // one plane
                    if (face_cut_within(m, plus != 0, sigma)) return true;
                }
        return false;
    }

private:
    // A crossing of a box edge with t = σH: its position relative to C times den.
    struct Point {
        Vec3<Q> num;
        Z den;  // > 0
    };

    // +1 beyond t = H, −1 beyond t = −H, 0 in the slab (T = √d·t).
    int side_of(const Z& T) const {
        if (ring_.sign(T, Z(-p_.H)) > 0) return 1;
        if (ring_.sign(T, p_.H) < 0) return -1;
        return 0;
    }
    // Within R of the axis line: |D × Y|² ≤ R²·d for a point Y relative to C.
    bool point_within(const Vec3<Z>& Y) const {
        const Vec3<Z> q = cross(p_.D, Y);
        return sgn(Z(dot(q, q) - Z(p_.R * p_.R) * ring_.d())) <= 0;
    }
    // Where the edge s → s' (T_s ≠ T_s') crosses t = σH: V_s + λ·δ with δ = V_s' − V_s and
    // λ = (σH√d − T_s)/Δ, Δ = T_s' − T_s. Times Δ that is V_s·T_s' − T_s·V_s' + σH·δ·√d: no quotient, and
    // values of about 2L + M bits for lengths of L bits and an axis of M.
    Point crossing(int s, int s1, int sigma) const {
        Z delta = T_[s1] - T_[s];
        const Z h = sigma > 0 ? p_.H : Z(-p_.H);
        Point x;
        for (int j = 0; j < 3; ++j)
            x.num[j] = Q{Z(V_[s][j] * T_[s1] - T_[s] * V_[s1][j]), Z(h * Z(V_[s1][j] - V_[s][j]))};
        if (sgn(delta) < 0) delta = -delta, x.num = Vec3<Q>{-x.num[0], -x.num[1], -x.num[2]};
        x.den = delta;
        return x;
    }
    bool point_within(const Point& x) const {
        return ring_.sign(ring_.norm2(cross(p_.D, x.num)) - Q{Z(Z(p_.R * p_.R) * ring_.d() * Z(x.den * x.den)), Z(0)}) <= 0;
    }

    // Cramer's rule: λ_m·det = n_m·(X − K), n_m = a_j × a_k, X = C + t·D/√d, |t| ≤ H. With s = sgn(det),
    // p_m = −s·n_m·G, q_m = s·n_m·D: −|det| − p_m ≤ t·q_m/√d ≤ |det| − p_m. Each bound on t is
    // A·√d/Q with Q > 0; the bounds are compatible iff every lower one is ≤ every upper one, pairwise
    // (√d cancels between two of them; against ±H it is a sign in Z[√d]).
    bool axis_meets_box(const Z& det) const {
        const int s = sgn(det);
        const Z adet = s < 0 ? Z(-det) : det;
        std::array<Z, 3> lo, hi, q;
        std::array<bool, 3> bounded{};
        for (int m = 0; m < 3; ++m) {
            const Vec3<Z> n = cross(p_.a[(m + 1) % 3], p_.a[(m + 2) % 3]);
            Z pm = dot(n, p_.G), qm = dot(n, p_.D);
            if (s > 0) pm = -pm;
            else qm = -qm;
            if (sgn(qm) == 0) {
                if (adet < abs_of(pm)) return false;
                continue;
            }
            bounded[m] = true;
            if (sgn(qm) > 0) {
                lo[m] = Z(-adet - pm), hi[m] = Z(adet - pm), q[m] = qm;
            } else {
                lo[m] = Z(pm - adet), hi[m] = Z(pm + adet), q[m] = Z(-qm);
            }
        }
        for (int m = 0; m < 3; ++m) {
            if (!bounded[m]) continue;
            if (ring_.sign(Z(p_.H * q[m]), Z(-lo[m])) < 0) return false;  // lo_m ≤ H
            if (ring_.sign(Z(p_.H * q[m]), hi[m]) < 0) return false;       // −H ≤ hi_m
            for (int n = 0; n < 3; ++n)
                if (n != m && bounded[n] && Z(hi[n] * q[m]) < Z(lo[m] * q[n])) return false;  // lo_m ≤ hi_n
        }
        return true;
    }

    // A flat box (rank 2): a normal of its plane, a_i × a_j for a pair that is not parallel; none for
    // rank ≤ 1.
    std::optional<Vec3<Z>> plane_normal() const {
        for (int m = 0; m < 3; ++m) {
            Vec3<Z> n = cross(p_.a[m], p_.a[(m + 1) % 3]);
            if (sgn(n[0]) != 0 || sgn(n[1]) != 0 || sgn(n[2]) != 0) return n;
        }
        return std::nullopt;
    }

    // A flat box: the zonogon P = {K + Σ λ_m·a_m : |λ_m| ≤ 1} in the plane through K with normal n. The
    // axis line crosses that plane at t = (n·G)·√d/(n·D) (G = K − C), where Y = X − K satisfies
    // (n·D)·Y = W := (n·G)·D − (n·D)·G. P is the intersection of the strips across its edges, which are
    // parallel to the non-zero a_m: with ν_m = n × a_m, Y ∈ P iff |ν_m·Y| ≤ Σ_k |ν_m·a_k| (the support
    // of P in direction ν_m) for each m. An axis parallel to the plane (n·D = 0) meets P only inside
    // its plane, and a line in the plane that meets the bounded P crosses its boundary, or ends inside
    // it at t = ±H: the clipped edges or face cuts then find distance 0.
    bool axis_meets_flat_box(const Vec3<Z>& n) const {
        const Z nD = dot(n, p_.D);
        if (sgn(nD) == 0) return false;
        const Z nG = dot(n, p_.G);
        const Z abs_nD = abs_of(nD);
        if (ring_.sign(Z(p_.H * abs_nD), Z(-abs_of(nG))) < 0) return false;  // |t| ≤ H
        const Vec3<Z> W = nG * p_.D - nD * p_.G;
        for (int m = 0; m < 3; ++m) {
            const Vec3<Z> nu = cross(n, p_.a[m]);
            Z support = abs_of(Z(dot(nu, p_.a[0])));
            support += abs_of(Z(dot(nu, p_.a[1])));
            support += abs_of(Z(dot(nu, p_.a[2])));
            if (Z(abs_nD * support) < abs_of(Z(dot(nu, W)))) return false;
        }
        return true;
    }

    // The box edge s → s' clipped to the slab [λ0, λ1] ⊂ [0, 1]: its ends (vertices in the slab, tested in
    // run(), or crossings of t = ±H), and its interior where the edge line comes nearest the axis line
    // strictly between them. With A = D × V_s and B = D × δ, |D × (V_s + λδ)|² is least at
    // λ* = −A·B/|B|², where it is d·(D·(V_s × δ))²/|B|² (|A × B| = √d·|D·(V_s × δ)|). Every value stays
    // within about 4L + 4M bits, and the signs in Z[√d] within 3L + 3M before their squares: a segment
    // between two clipped ends as quotient points would take about 12L + 12M.
    bool clipped_edge_within(int s, int s1) const {
        const int a = side_of(T_[s]), b = side_of(T_[s1]);
        if (a != 0 && a == b) return false;
        if (a != 0 && point_within(crossing(s, s1, a))) return true;
        if (b != 0 && point_within(crossing(s, s1, b))) return true;
        const Vec3<Z> delta = V_[s1] - V_[s];
        const Vec3<Z> B = cross(p_.D, delta);
        const Z BB = dot(B, B);
        if (sgn(BB) == 0) return false;  // parallel to the axis: the distance is the ends'
        const Z AB = dot(cross(p_.D, V_[s]), B);
        const Z Delta = T_[s1] - T_[s];
        const int sd = sgn(Delta);
        const Z abs_delta = sd < 0 ? Z(-Delta) : Delta;
        // λ* > λ0: −A·B > 0 at a vertex; at a crossing, −A·B·|Δ| > (σH√d − T_s)·sgn(Δ)·|B|².
        if (a == 0) {
            if (!(sgn(AB) < 0)) return false;
        } else {
            Z lhs = Z(T_[s] * BB) * Z(sd) - AB * abs_delta;
            Z root = Z(p_.H * BB) * Z(-a * sd);
            if (!(ring_.sign(lhs, root) > 0)) return false;
        }
        // λ* < λ1: −A·B < |B|² at a vertex; at a crossing, −A·B·|Δ| < (σH√d − T_s)·sgn(Δ)·|B|².
        if (b == 0) {
            if (!(sgn(Z(AB + BB)) > 0)) return false;
        } else {
            Z lhs = AB * abs_delta - Z(T_[s] * BB) * Z(sd);
            Z root = Z(p_.H * BB) * Z(b * sd);
            if (!(ring_.sign(lhs, root) > 0)) return false;
        }
        const Z n = dot(p_.D, cross(V_[s], V_[s1]));  // V_s × δ = V_s × V_s'
        return sgn(Z(n * n - Z(p_.R * p_.R) * BB)) <= 0;
    }

    // The face λ_m = ±1 cut by the plane t = σH: a chord of the cap's plane, whose end points (vertices
    // on the plane, crossings of the face's edges) run() and the clipped edges test. What is left is
    // its interior: whether the cap's centre P = C + σH·D/√d has its foot on the chord's line strictly
    // between two of those points, and lies within R of that line. The line is the face's plane
    // (normal ν = a_j × a_k, through G_f = G ± a_m) within the cap's plane; P's distance to it is
    // |σH·(ν·D) − √d·(ν·G_f)| / |ν × D|.
    bool face_cut_within(int m, bool plus, int sigma) const {
        const int j = (m + 1) % 3, k = (m + 2) % 3;
        const Vec3<Z> nu = cross(p_.a[j], p_.a[k]);
        const Vec3<Z> nuD = cross(nu, p_.D);
        const Z nuD2 = dot(nuD, nuD);
        // ν × D = 0: a face parallel to the cap's plane (in it, or not cutting it) or a degenerate face
        // (a segment or a point), whose cut is at most its end points.
        if (sgn(nuD2) == 0) return false;
        const int base = plus ? (1 << m) : 0;
        const std::array<int, 4> corner{base, base | (1 << j), base | (1 << j) | (1 << k), base | (1 << k)};
        const Z tau_b = sigma > 0 ? Z(-p_.H) : p_.H;  // T − σH√d = T + tau_b·√d
        std::array<int, 4> sign{};
        for (std::size_t c = 0; c < 4; ++c) sign[c] = ring_.sign(T_[corner[c]], tau_b);
        std::array<Point, 4> pts;
        int n = 0;
        for (std::size_t c = 0; c < 4; ++c) {
            const std::size_t c1 = (c + 1) % 4;
            if (sign[c] == 0) pts[static_cast<std::size_t>(n++)] = vertex(corner[c]);
            else if (sign[c] * sign[c1] < 0) pts[static_cast<std::size_t>(n++)] = crossing(corner[c], corner[c1], sigma);
        }
        if (n < 2) return false;
        // The distance to the line first: one test for the face, where a foot test is one per pair.
        const Vec3<Z> Gf = plus ? Vec3<Z>(p_.G + p_.a[m]) : Vec3<Z>(p_.G - p_.a[m]);
        const Z u = Z(sigma > 0 ? p_.H : Z(-p_.H)) * dot(nu, p_.D);
        const Z v = dot(nu, Gf);
        // (u − v√d)² ≤ R²·|ν × D|²
        const Z alpha = Z(u * u) + Z(Z(v * v) * ring_.d()) - Z(Z(p_.R * p_.R) * nuD2);
        if (!(ring_.sign(alpha, Z(Z(-2) * Z(u * v))) <= 0)) return false;
        for (int x = 0; x < n; ++x)
            for (int y = x + 1; y < n; ++y)
                if (foot_between(pts[static_cast<std::size_t>(x)], pts[static_cast<std::size_t>(y)])) return true;
        return false;
    }
    // Two points Y0, Y1 of the cap's plane (relative to C): P's foot on their line lies strictly between
    // them. P − C is along D, which is normal to Y1 − Y0, so (P − Y0)·(Y1 − Y0) = Y0·(Y0 − Y1): the tests
    // are Y0·(Y0 − Y1) > 0 and Y1·(Y1 − Y0) > 0, with W = den1·num0 − den0·num1 for the difference.
    bool foot_between(const Point& x, const Point& y) const {
        Vec3<Q> W;
        for (int j = 0; j < 3; ++j) W[j] = y.den * x.num[j] - x.den * y.num[j];
        return ring_.sign(ring_.dot(x.num, W)) > 0 && ring_.sign(ring_.dot(y.num, W)) < 0;
    }
    Point vertex(int s) const {
        return {{Q{V_[s][0], Z(0)}, Q{V_[s][1], Z(0)}, Q{V_[s][2], Z(0)}}, Z(1)};
    }

    const ParallelepipedProblem<Z>& p_;
    QuadraticRing<Z> ring_;
    std::array<Vec3<Z>, 8> V_;
    std::array<Z, 8> T_;
};

template <class Z>
bool run_turned(const Parallelepiped<double>& b, const Cylinder<double>& c) {
    const ParallelepipedProblem<Z> p = problem_turned<Z>(b, c);
    return ClippedTest<Z>(p).run();
}

}  // namespace detail

// The widest values here are wider than §4's: about 6·L + 4·M bits for lengths below 2^L and axis
// components below 2^M (the face cuts' tests; twice that where a sign in Z[√d] must square them), where
// §4 needs 4·L + 8·M. Random rounded rotations
// (L ≈ 110, M ≈ 53) fit in 16 limbs; 64 hold lengths that span about 600 bits (a unit box beside a
// cylinder of 2^349), and cost what 16 do where 16 suffice (FixedInt's arithmetic runs on the limbs in
// use). On random rounded rotations (bench_exact_stage's "turned" set) that is about 10 µs per query,
// against 24 µs in mpz_class alone.
inline constexpr int kParallelepipedLimbs = 64;
using Wide = FixedInt<kParallelepipedLimbs>;
// The 64-limb run keeps its values on the stack (test ExactStage.ParallelepipedStack prints how much);
// with less room than this left it runs in 16 limbs.
inline constexpr std::size_t kParallelepipedStackRoom = std::size_t{512} << 10;

// The answer in fixed-width integers (64 limbs where the stack has room, else 16); nullopt when a value
// outgrew them.
inline std::optional<bool> parallelepiped_small(const Parallelepiped<double>& b, const Cylinder<double>& c) {
    FixedOverflow::flag() = false;
    const bool r = stack_room() >= kParallelepipedStackRoom ? detail::run_turned<Wide>(b, c) : detail::run_turned<Small>(b, c);
    if (FixedOverflow::flag()) return std::nullopt;
    return r;
}

// The exact answer for any parallelepiped: fixed-width integers, mpz_class when a value outgrew them.
inline bool intersects_parallelepiped(const Parallelepiped<double>& b, const Cylinder<double>& c) {
    if (const std::optional<bool> r = parallelepiped_small(b, c)) return *r;
    return detail::run_turned<mpz_class>(b, c);
}

}  // namespace boxcyl::exact::integer
