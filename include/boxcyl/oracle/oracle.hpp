// The exact oracle: an independent, deliberately plain decision procedure that judges the three methods.
//
// It is none of the published algorithms. It works in world coordinates (no canonical frame,
// so it also judges the reductions to the canonical frame) on the box as the parallelepiped
//     B = { K + Σ ξᵢ Aᵢ : |ξᵢ| ≤ eᵢ }   (axes exactly as given, linearly independent),
// and the closed cylinder with centre C, axis direction D (any length; u = D/|D|), radius r, height h.
//
// Facts it rests on, each elementary:
//  (1) Cylinder ∩ B ≠ ∅  ⇔  some X ∈ P := B ∩ slab has distance ≤ r from the axis line, where
//      slab = { X : |D·(X − C)| ≤ σ }, σ = (h/2)·√d, d = D·D. (Inside the slab, the nearest axis point
//      lies on the axis segment.) So: dist(O, π(P)) ≤ r, π the projection along D, O = π(C).
//  (2) P is a polytope whose vertices are box vertices inside the slab or points where a box edge
//      crosses a slab plane. S = all of those (duplicates and non-vertices do no harm: S ⊂ P and
//      S ⊇ vert P). P = ∅ ⇔ S = ∅.
//  (3) O ∈ π(P) ⇔ the axis segment meets B: a 1-D interval intersection in the axis parameter.
//  (4) Otherwise dist(O, π(P)) is attained on ∂π(P) ⊂ π(edges of P). Every edge of P joins two points
//      of S that share at least two tight constraints (of the 6 box faces and 2 slab planes), and
//      every such segment lies in P. So dist(O, π(P)) = min over those segments (and points).
// Everything is computed in Q(√d): rationals (every double taken as the exact rational it denotes)
// and numbers a + b√d. No rounding, no sqrt, no division by an irrational. Touching intersects.
#pragma once

#include <array>      // fixed-size point lists
#include <bit>        // std::popcount
#include <cstddef>    // std::size_t
#include <stdexcept>  // std::invalid_argument on violated preconditions
#include <vector>     // the point set S

#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/vec3.hpp"
#include "boxcyl/exact/convert.hpp"  // to_exact: the rationals the doubles denote
#include "boxcyl/number/qfield.hpp"
#include "boxcyl/number/rational.hpp"

namespace boxcyl {

// An aligned box is the parallelepiped with the standard axes, centre (min+max)/2, extents
// (max−min)/2 — exact in rationals.
inline OrientedBox<Rational> as_oriented_box(const AlignedBox<Rational>& b) {
    OrientedBox<Rational> p;
    for (int i = 0; i < 3; ++i) {
        p.center[i] = (b.min[i] + b.max[i]) / 2;
        p.extents[i] = (b.max[i] - b.min[i]) / 2;
        p.axes[i] = {Rational(i == 0), Rational(i == 1), Rational(i == 2)};
    }
    return p;
}
inline OrientedBox<Rational> as_oriented_box(const CanonicalBox<Rational>& b) {
    return {{0, 0, 0}, {Vec3<Rational>{1, 0, 0}, Vec3<Rational>{0, 1, 0}, Vec3<Rational>{0, 0, 1}}, b.extents};
}

namespace oracle {

namespace detail {

using Q = QFRational;

// Constraint tags: bit 2k for face ξₖ = +eₖ, bit 2k+1 for ξₖ = −eₖ, bit 6/7 for the upper/lower slab
// plane D·(X − C) = ±σ.
constexpr unsigned face_bit(int k, int sign) { return 1u << (2 * k + (sign > 0 ? 0 : 1)); }
constexpr unsigned upper_bit = 1u << 6;
constexpr unsigned lower_bit = 1u << 7;

struct Point {
    Vec3<Q> y;  // X − C
    unsigned tags;
};

inline Vec3<Q> lift(const Vec3<Rational>& v) { return {Q(v[0]), Q(v[1]), Q(v[2])}; }

}  // namespace detail

// Preconditions (checked, std::invalid_argument): D ≠ 0; r, h, eᵢ ≥ 0; axes linearly independent.
inline bool intersects(const OrientedBox<Rational>& box, const Cylinder<Rational>& cyl) {
    using detail::Q;
    using detail::Point;
    const Vec3<Rational>& D = cyl.axis;
    const Rational d = dot(D, D);
    if (sgn(d) == 0) throw std::invalid_argument("oracle: cylinder axis is the zero vector");
    if (sgn(cyl.radius) < 0 || sgn(cyl.height) < 0) throw std::invalid_argument("oracle: negative r or h");
    for (int i = 0; i < 3; ++i)
        if (sgn(box.extents[i]) < 0) throw std::invalid_argument("oracle: negative extent");
    const Rational det = dot(box.axes[0], cross(box.axes[1], box.axes[2]));
    if (sgn(det) == 0) throw std::invalid_argument("oracle: box axes are linearly dependent");

    const QuadraticField<Rational> field(d);
    const Rational half_h = cyl.height / 2;
    const Q sigma(Rational(0), half_h, field);      // slab half-width in units of D·(X − C)
    const Rational sigma2 = half_h * half_h * d;    // σ²

    std::array<Vec3<Rational>, 3> a;                // half-edge vectors eᵢAᵢ
    for (int i = 0; i < 3; ++i) a[i] = box.extents[i] * box.axes[i];
    const Vec3<Rational> g = box.center - cyl.center;

    // (2) Box vertices Y(x) = g + Σ xᵢaᵢ for x ∈ {±1}³ (vertex index bit i ⇔ xᵢ = +1), and t = D·Y.
    std::array<Vec3<Rational>, 8> vy;
    std::array<Rational, 8> vt;
    for (int s = 0; s < 8; ++s) {
        Vec3<Rational> y = g;
        for (int i = 0; i < 3; ++i) y = (s >> i & 1) ? y + a[i] : y - a[i];
        vt[s] = dot(D, y);
        vy[s] = std::move(y);
    }
    auto face_tags = [&](int s) {
        unsigned t = 0;
        for (int i = 0; i < 3; ++i) {
            if (sgn(box.extents[i]) == 0) t |= detail::face_bit(i, +1) | detail::face_bit(i, -1);
            else t |= detail::face_bit(i, (s >> i & 1) ? +1 : -1);
        }
        return t;
    };
    auto plane_tags_of = [&](const Rational& t) {
        unsigned tags = 0;
        if (t * t == sigma2) {
            if (sgn(t) >= 0) tags |= detail::upper_bit;
            if (sgn(t) <= 0) tags |= detail::lower_bit;
        }
        return tags;
    };

    // (2a) P = ∅ ⇔ all vertex projections lie on one side outside the slab (the box's projection onto
    // the axis is the interval spanned by its vertices). Cheap, rational, and decides most misses.
    {
        const Rational* tmin = &vt[0];
        const Rational* tmax = &vt[0];
        for (int s = 1; s < 8; ++s) {
            if (vt[s] < *tmin) tmin = &vt[s];
            if (vt[s] > *tmax) tmax = &vt[s];
        }
        // t > σ ⇔ t > 0 and t² > σ² (σ ≥ 0).
        if (sgn(*tmin) > 0 && *tmin * *tmin > sigma2) return false;
        if (sgn(*tmax) < 0 && *tmax * *tmax > sigma2) return false;
    }

    // (3) Axis segment X = C + τD, |τ| ≤ σ/d, against |ξᵢ| ≤ eᵢ with ξ = A⁻¹(X − K) = −A⁻¹g + τA⁻¹D.
    // Rows of A⁻¹ (A = [A0 A1 A2]) are (A1×A2)/det, (A2×A0)/det, (A0×A1)/det.
    {
        const Q tau_max(Rational(0), Rational(half_h / d), field);
        Q lo = -tau_max, hi = tau_max;
        bool empty = false;
        for (int i = 0; i < 3 && !empty; ++i) {
            const Vec3<Rational> row = cross(box.axes[(i + 1) % 3], box.axes[(i + 2) % 3]);
            const Rational w = dot(row, D) / det;
            const Rational c0 = -dot(row, g) / det;  // ξᵢ at τ = 0
            const Rational& e = box.extents[i];
            if (sgn(w) == 0) {
                empty = abs(c0) > e;
                continue;
            }
            Rational b1 = (-e - c0) / w, b2 = (e - c0) / w;
            if (sgn(w) < 0) swap(b1, b2);
            if (Q(b1) > lo) lo = Q(b1);
            if (Q(b2) < hi) hi = Q(b2);
        }
        if (!empty && lo <= hi) return true;
    }

    // (2b) The point set S with its tight constraints.
    std::vector<Point> S;
    S.reserve(32);
    for (int s = 0; s < 8; ++s)
        if (vt[s] * vt[s] <= sigma2) S.push_back({detail::lift(vy[s]), face_tags(s) | plane_tags_of(vt[s])});

    // Edge-plane crossings: the edge along axis k from vertex s (xₖ = −1) to s' (xₖ = +1) is
    // Y = vy[s] + μ·aₖ, μ ∈ [0, 2], and crosses D·Y = p·σ at μ = (p·σ − t)/(D·aₖ). It does so iff p·σ
    // lies between the endpoint values t, t' — checked in rationals first: (p·σ − t)(p·σ − t') ≤ 0.
    auto between = [&](const Rational& t0, const Rational& t1, int p) {
        // sign of (pσ − t0)(pσ − t1) = σ² − pσ(t0 + t1) + t0·t1, with σ irrational in general:
        // compare σ² + t0·t1 with pσ(t0 + t1) by squaring (signs first).
        const Rational lhs = sigma2 + t0 * t1;
        const Rational sum = p * (t0 + t1);  // rhs = σ·sum
        const int sl = sgn(lhs), sr = sgn(sum) * (sgn(half_h) == 0 ? 0 : 1);
        if (sl <= 0 && sr >= 0) return true;   // lhs ≤ 0 ≤ rhs
        if (sl > 0 && sr <= 0) return false;   // lhs > 0 ≥ rhs
        const Rational l2 = lhs * lhs, r2 = sigma2 * sum * sum;
        return sl > 0 ? l2 <= r2 : l2 >= r2;    // both positive: lhs ≤ rhs ⇔ l² ≤ r²; both negative: ⇔ l² ≥ r²
    };
    for (int k = 0; k < 3; ++k) {
        const Rational dak = dot(D, a[k]);
        if (sgn(dak) == 0) continue;  // parallel to the slab planes: endpoints already cover it
        for (int s = 0; s < 8; ++s) {
            if (s >> k & 1) continue;
            const int s1 = s | (1 << k);
            for (int p : {+1, -1}) {
                if (!between(vt[s], vt[s1], p)) continue;
                const Q m = ((p > 0 ? sigma : Q(-sigma)) - Q(vt[s])) / Q(dak);
                Vec3<Q> y = detail::lift(vy[s]);
                for (int i = 0; i < 3; ++i) y[i] += m * Q(a[k][i]);
                unsigned tags = face_tags(s) & ~(detail::face_bit(k, +1) | detail::face_bit(k, -1));
                if (m == Q(0)) tags |= detail::face_bit(k, -1);
                if (m == Q(2)) tags |= detail::face_bit(k, +1);
                tags |= (p > 0) ? detail::upper_bit : detail::lower_bit;
                if (sgn(half_h) == 0) tags |= detail::upper_bit | detail::lower_bit;
                S.push_back({std::move(y), tags});
            }
        }
    }
    if (S.empty()) return false;  // unreachable after (2a) and (3), kept as the plain statement of (2)

    // (4) Distances in the plane orthogonal to D, scaled by d to stay division-free:
    // p(Y) = d·Y − (D·Y)·D, so |p|² = d²·dist²(Y, axis line); compare with R² = r²d².
    const Q qd(d);
    const Vec3<Q> Dq = detail::lift(D);
    const Q R2(cyl.radius * cyl.radius * d * d);
    std::vector<Vec3<Q>> proj;
    std::vector<Q> norm2;
    proj.reserve(S.size());
    norm2.reserve(S.size());
    for (const Point& pt : S) {
        const Q t = dot(Dq, pt.y);
        Vec3<Q> p{qd * pt.y[0] - t * Dq[0], qd * pt.y[1] - t * Dq[1], qd * pt.y[2] - t * Dq[2]};
        Q n2 = dot(p, p);
        if (n2 <= R2) return true;
        proj.push_back(std::move(p));
        norm2.push_back(std::move(n2));
    }
    for (std::size_t i = 0; i < S.size(); ++i)
        for (std::size_t j = i + 1; j < S.size(); ++j) {
            if (std::popcount(S[i].tags & S[j].tags) < 2) continue;
            const Vec3<Q> ab = proj[j] - proj[i];
            const Q len2 = dot(ab, ab);
            if (len2 == Q(0)) continue;
            const Q along = -dot(proj[i], ab);  // λ*·|ab|² for the foot of O on the line
            if (along <= Q(0) || along >= len2) continue;  // foot outside: an endpoint is nearest
            // dist² = |pᵢ|² − (pᵢ·ab)²/|ab|² ≤ R²
            if (norm2[i] * len2 - along * along <= R2 * len2) return true;
        }
    return false;
}

// Any parallelepiped { K + Σ ξᵢWᵢ : |ξᵢ| ≤ eᵢ }, the Wᵢ exactly as given. Linearly independent axes
// are the solid above. Dependent ones (a zero or parallel axis, or three coplanar axes) span a flat
// solid; for it the same facts (1), (2) hold — P = B ∩ slab is the image of the cube ∩ (the slab pulled
// back to ξ-space), so S is built as above — while (3) and (4) are done without the frame:
//  (3') the axis segment meets B ⇔ 0 ∈ Z = {(K − C) + Σ ξᵢaᵢ − τD : |ξᵢ| ≤ 1, |τ| ≤ σ/d}, a zonotope
//       with generators a₀, a₁, a₂, D. 0 ∉ Z ⇔ some direction n has |n·(K − C)| > Σ|n·aᵢ| + (σ/d)|n·D|,
//       and one such n is among the facet normals of Z whatever its dimension: gᵢ × gⱼ (3-D),
//       (gᵢ × gⱼ) × gₖ (edge normals within a plane), gᵢ × Eₖ and gᵢ (a segment), Eₖ (a point).
//  (4') π(P) is the hull of π(S), so its boundary is covered by segments between points of S, each
//       lying in P: every pair is tested (no tags needed).
inline bool intersects(const Parallelepiped<Rational>& box, const Cylinder<Rational>& cyl) {
    using detail::Q;
    const Rational det = dot(box.axes[0], cross(box.axes[1], box.axes[2]));
    if (sgn(det) != 0) return intersects(OrientedBox<Rational>{box.center, box.axes, box.extents}, cyl);

    const Vec3<Rational>& D = cyl.axis;
    const Rational d = dot(D, D);
    if (sgn(d) == 0) throw std::invalid_argument("oracle: cylinder axis is the zero vector");
    if (sgn(cyl.radius) < 0 || sgn(cyl.height) < 0) throw std::invalid_argument("oracle: negative r or h");
    for (int i = 0; i < 3; ++i)
        if (sgn(box.extents[i]) < 0) throw std::invalid_argument("oracle: negative extent");
    const QuadraticField<Rational> field(d);
    const Rational half_h = cyl.height / 2;
    const Q sigma(Rational(0), half_h, field);
    const Rational sigma2 = half_h * half_h * d;
    std::array<Vec3<Rational>, 3> a;
    for (int i = 0; i < 3; ++i) a[i] = box.extents[i] * box.axes[i];
    const Vec3<Rational> g = box.center - cyl.center;

    // (3')
    {
        const std::array<Vec3<Rational>, 4> gen{a[0], a[1], a[2], D};
        std::vector<Vec3<Rational>> normals;
        for (int k = 0; k < 3; ++k) {
            Vec3<Rational> unit{0, 0, 0};
            unit[k] = 1;
            normals.push_back(unit);
            for (const Vec3<Rational>& gi : gen) normals.push_back(cross(gi, unit));
        }
        for (std::size_t i = 0; i < gen.size(); ++i) {
            normals.push_back(gen[i]);
            for (std::size_t j = i + 1; j < gen.size(); ++j) {
                const Vec3<Rational> m = cross(gen[i], gen[j]);
                normals.push_back(m);
                for (const Vec3<Rational>& gk : gen) normals.push_back(cross(m, gk));
            }
        }
        bool separated = false;
        for (const Vec3<Rational>& n : normals) {
            const Rational reach = abs(dot(n, a[0])) + abs(dot(n, a[1])) + abs(dot(n, a[2]));
            const Q lhs(Rational(abs(dot(n, g)) - reach));
            const Q rhs(Rational(0), Rational(half_h * abs(dot(n, D)) / d), field);  // (σ/d)|n·D|
            if (lhs > rhs) {
                separated = true;
                break;
            }
        }
        if (!separated) return true;
    }

    // (2) the point set S (no tags): vertices in the slab, edge-plane crossings.
    std::array<Vec3<Rational>, 8> vy;
    std::array<Rational, 8> vt;
    for (int s = 0; s < 8; ++s) {
        Vec3<Rational> y = g;
        for (int i = 0; i < 3; ++i) y = (s >> i & 1) ? y + a[i] : y - a[i];
        vt[s] = dot(D, y);
        vy[s] = std::move(y);
    }
    std::vector<Vec3<Q>> S;
    for (int s = 0; s < 8; ++s)
        if (vt[s] * vt[s] <= sigma2) S.push_back(detail::lift(vy[s]));
    for (int k = 0; k < 3; ++k) {
        const Rational dak = dot(D, a[k]);
        if (sgn(dak) == 0) continue;
        for (int s = 0; s < 8; ++s) {
            if (s >> k & 1) continue;
            for (int p : {+1, -1}) {
                // the crossing μ ∈ [0, 2] of D·Y = pσ along Y = vy[s] + μ·aₖ
                const Q m = ((p > 0 ? sigma : Q(-sigma)) - Q(vt[s])) / Q(dak);
                if (m < Q(0) || m > Q(2)) continue;
                Vec3<Q> y = detail::lift(vy[s]);
                for (int i = 0; i < 3; ++i) y[i] += m * Q(a[k][i]);
                S.push_back(std::move(y));
            }
        }
    }
    if (S.empty()) return false;

    // (4') distances in the plane ⊥ D, scaled by d as above.
    const Q qd(d);
    const Vec3<Q> Dq = detail::lift(D);
    const Q R2(cyl.radius * cyl.radius * d * d);
    std::vector<Vec3<Q>> proj;
    for (const Vec3<Q>& y : S) {
        const Q t = dot(Dq, y);
        Vec3<Q> p{qd * y[0] - t * Dq[0], qd * y[1] - t * Dq[1], qd * y[2] - t * Dq[2]};
        if (dot(p, p) <= R2) return true;
        proj.push_back(std::move(p));
    }
    for (std::size_t i = 0; i < proj.size(); ++i)
        for (std::size_t j = i + 1; j < proj.size(); ++j) {
            const Vec3<Q> ab = proj[j] - proj[i];
            const Q len2 = dot(ab, ab);
            if (len2 == Q(0)) continue;
            const Q along = -dot(proj[i], ab);
            if (along <= Q(0) || along >= len2) continue;
            if (dot(proj[i], proj[i]) * len2 - along * along <= R2 * len2) return true;
        }
    return false;
}

inline bool intersects(const AlignedBox<Rational>& box, const Cylinder<Rational>& cyl) {
    return intersects(as_oriented_box(box), cyl);
}
inline bool intersects(const CanonicalBox<Rational>& box, const Cylinder<Rational>& cyl) {
    return intersects(as_oriented_box(box), cyl);
}
template <class Box>
bool intersects(const Box& box, const Cylinder<double>& cyl) {
    return intersects(to_exact(box), to_exact(cyl));
}

}  // namespace oracle
}  // namespace boxcyl
