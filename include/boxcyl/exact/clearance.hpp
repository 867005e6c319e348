// The exact clearance decision: does the box come within distance m of the cylinder? Exact for the
// inputs as given (each double the rational it denotes, u = D/|D| exactly), both solids closed, so a
// distance of exactly m counts. The front door (boxcyl/clearance.hpp) asks it only what its
// floating-point certificates leave open.
//
// The points within m of the cylinder (the cylinder rounded by m) are, by where their nearest point
// on the cylinder lies, the union of
//   fat   the cylinder of radius r + m and height h           (nearest point on the side),
//   tall  the cylinder of radius r and height h + 2m          (nearest point on a cap),
//   two rim tori: the points within m of a rim circle         (nearest point on a rim).
// So the box is within m ⇔ it meets fat or tall (the exact intersection test on those cylinders) or
// comes within m of a rim circle Γ. For the last, take the nearest pair (P on Γ, X on the box) when
// the box misses fat and tall (so it misses the cylinder and Γ): X lies in the relative interior of
//   a vertex  — the vertex lies in the torus: (ρ − r)² + a² ≤ m² (ρ its distance from the axis, a
//               its signed height over the rim plane), decided as q ≤ 2rρ, q = ρ² + r² + a² − m²;
//   an edge   — with both ends outside both tori, the edge enters a torus exactly when
//               N = p_top·p_bottom has a root in (0, 1), p = q² − 4r²ρ² along the edge: a root of p
//               is a point with q = ±2rρ, inside the torus, and entering from outside crosses q = 2rρ.
//               The conjugation √d ↦ −√d maps p_top to p_bottom, so N has rational coefficients
//               (degree 8); its roots are counted with Sturm sequences (number/polynomial.hpp);
//   a facet   — X is the foot of P on the facet's plane and P is critical for the distance to that
//               plane along Γ: P = rim centre ± r·n⊥/|n⊥| (n the facet normal, n⊥ its part across
//               the axis; for n⊥ = 0 the contact point is within the tall cylinder). The test is the
//               plane distance ≤ m and the foot inside the facet: signs of numbers in Q(√d, √g),
//               g = |D × n|² (number/root_sign.hpp).
// The box's interior holds no nearest point at positive distance, and a zero distance means the box
// meets Γ ⊂ fat. Each test alone is sound (it exhibits a point within m), so their union is the answer.
#pragma once

#include <array>  // vertices

#include "boxcyl/exact/paths.hpp"  // the exact intersection test on the fat and tall cylinders
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/vec3.hpp"
#include "boxcyl/number/polynomial.hpp"
#include "boxcyl/number/rational.hpp"
#include "boxcyl/number/root_sign.hpp"

namespace boxcyl::exact::clearance {

namespace detail {

using root_sign::Quadratic;

// The cylinder and margin, with the numbers every rim test shares.
struct Rim {
    Rim(const Cylinder<Rational>& c, const Rational& margin)
        : C(c.center), D(c.axis), d(dot(D, D)), r(c.radius), h(c.height), m(margin),
          offset(r * r + h * h / 4 - m * m) {}
    Vec3<Rational> C, D;
    Rational d, r, h, m;
    Rational offset;  // r² + h²/4 − m²
};

// Whether V lies within m of the rim circle on side eps (+1: centre + (h/2)·u, −1: centre − (h/2)·u).
// With Z = V − C, w = D·Z: ρ² = |Z|² − w²/d, a = w/√d − eps·h/2, so q = |Z|² + offset − eps·(h·w/d)·√d.
inline bool in_rim_torus(const Rim& f, const Vec3<Rational>& V, int eps) {
    const Vec3<Rational> Z = V - f.C;
    const Rational w = dot(f.D, Z);
    const Rational zz = dot(Z, Z);
    const Rational rho2 = zz - w * w / f.d;
    const Rational alpha = zz + f.offset;
    const Rational beta = f.h * w / f.d;
    // 2r·ρ − q ≥ 0 with ρ = √ρ².
    return root_sign::sign(Quadratic{-alpha, eps * beta}, Quadratic{2 * f.r, 0}, f.d, rho2) >= 0;
}

// Whether the open edge V0 + s·E, 0 < s < 1, meets either rim torus. Precondition: both ends lie
// outside both tori (then N(0), N(1) > 0) and E ≠ 0.
inline bool edge_meets_rim_tori(const Rim& f, const Vec3<Rational>& V0, const Vec3<Rational>& E) {
    const Vec3<Rational> Z0 = V0 - f.C;
    const RationalPolynomial zz{dot(Z0, Z0), 2 * dot(Z0, E), dot(E, E)};
    const RationalPolynomial w{dot(f.D, Z0), dot(f.D, E)};
    const RationalPolynomial alpha = zz + RationalPolynomial{f.offset};
    const RationalPolynomial beta = Rational(f.h / f.d) * w;
    const RationalPolynomial rho2 = zz - Rational(1 / f.d) * (w * w);
    // p_top·p_bottom with q = α ∓ β√d: (α² − dβ²)² − 8r²ρ²(α² + dβ²) + 16r⁴ρ⁴.
    const RationalPolynomial a2 = alpha * alpha;
    const RationalPolynomial db2 = f.d * (beta * beta);
    const Rational r2 = f.r * f.r;
    const RationalPolynomial n = (a2 - db2) * (a2 - db2) - Rational(8 * r2) * (rho2 * (a2 + db2)) +
                                 Rational(16 * r2 * r2) * (rho2 * rho2);
    return roots_in_unit_interval(n) > 0;
}

// Whether a rim point critical for the distance to the facet { X_F + μj·Aj + μk·Ak : |μ| ≤ e } is
// within m of the facet with its foot inside it.
inline bool facet_near_rim(const Rim& f, const Vec3<Rational>& XF, const Vec3<Rational>& Aj, const Rational& ej,
                           const Vec3<Rational>& Ak, const Rational& ek) {
    const Vec3<Rational> n = cross(Aj, Ak);
    const Rational nn = dot(n, n);
    if (sgn(nn) == 0) return false;  // a degenerate facet: its points lie on edges
    const Vec3<Rational> Dn = cross(f.D, n);
    const Rational g = dot(Dn, Dn);  // d·|n⊥|²
    if (sgn(g) == 0) return false;   // facet across the axis: within the tall cylinder
    const Rational nD = dot(n, f.D);
    const Vec3<Rational> nps = f.d * n - nD * f.D;  // d·n⊥, of length √(d·g)
    const Vec3<Rational> CX = f.C - XF;
    const Rational A = dot(n, CX);
    const std::array<Vec3<Rational>, 2> lambda{cross(Ak, n), cross(n, Aj)};  // λ·(X − X_F) = μ·|n|²
    const std::array<Rational, 2> bound{ej * nn, ek * nn};
    for (int eps : {1, -1}) {
        const Rational B = eps * f.h / 2 * nD;
        for (int tau : {1, -1}) {
            // P = C + eps·(h/2)(D/d)√d + tau·r·nps/√(dg). Plane distance ≤ m: |L|·√d ≤ m·√(d|n|²) with
            // L√d = A√d + B + tau·r√g; squared: m²d|n|² − (A√d + B + tau·r√g)² ≥ 0.
            const Quadratic x{f.m * f.m * f.d * nn - A * A * f.d - B * B - f.r * f.r * g, -2 * A * B};
            const Quadratic y{-2 * B * tau * f.r, -2 * A * tau * f.r};
            if (root_sign::sign(x, y, f.d, g) < 0) continue;
            // The foot inside: |λ·(P − X_F)| ≤ e·|n|², λ·(P − X_F) = λ·CX + eps(h/2)(λ·D)/d·√d
            // + tau·r(λ·nps)/(dg)·√d·√g.
            bool inside = true;
            for (int k = 0; k < 2 && inside; ++k) {
                const Rational c0 = dot(lambda[k], CX);
                const Rational c1 = eps * f.h / 2 * dot(lambda[k], f.D) / f.d;
                const Quadratic yk{0, tau * f.r * dot(lambda[k], nps) / (f.d * g)};
                inside = root_sign::sign(Quadratic{c0 - bound[k], c1}, yk, f.d, g) <= 0 &&
                         root_sign::sign(Quadratic{c0 + bound[k], c1}, yk, f.d, g) >= 0;
            }
            if (inside) return true;
        }
    }
    return false;
}

}  // namespace detail

// What a caller has already proved (filtered/rim.hpp), so that the decision skips those tests: the box
// misses the fat and tall cylinders; edge (axis i, start vertex bits) is farther than m from both rim
// circles (index 8i + bits); facet (axis i, side σ) has no contact within m (index 2i + (σ > 0)).
struct Known {
    bool misses_fat_and_tall = false;
    std::array<bool, 24> edge_far{};
    std::array<bool, 6> facet_far{};
};

// Preconditions: a valid cylinder (D ≠ 0, r, h ≥ 0), extents ≥ 0, m ≥ 0.
inline bool within(const Parallelepiped<Rational>& box, const Cylinder<Rational>& cyl, const Rational& m,
                   const Known& known = {}) {
    if (!known.misses_fat_and_tall) {
        Cylinder<Rational> fat = cyl;
        fat.radius += m;
        if (intersects(Method::hull, box, fat)) return true;
        if (sgn(m) == 0) return false;
        Cylinder<Rational> tall = cyl;
        tall.height += 2 * m;
        if (intersects(Method::hull, box, tall)) return true;
    }
    if (sgn(m) == 0) return false;

    const detail::Rim rim(cyl, m);
    std::array<Vec3<Rational>, 3> half;  // eᵢ·Aᵢ
    for (int i = 0; i < 3; ++i) half[i] = box.extents[i] * box.axes[i];
    auto vertex = [&](int bits) {
        Vec3<Rational> v = box.center;
        for (int i = 0; i < 3; ++i) v = (bits >> i & 1) ? Vec3<Rational>(v + half[i]) : Vec3<Rational>(v - half[i]);
        return v;
    };
    for (int bits = 0; bits < 8; ++bits) {
        const Vec3<Rational> v = vertex(bits);
        if (detail::in_rim_torus(rim, v, 1) || detail::in_rim_torus(rim, v, -1)) return true;
    }
    for (int i = 0; i < 3; ++i) {
        if (sgn(box.extents[i]) == 0 || box.axes[i] == Vec3<Rational>{0, 0, 0}) continue;  // no edge interior
        const Vec3<Rational> E = Rational(2) * half[i];
        for (int bits = 0; bits < 8; ++bits)
            if (!(bits >> i & 1) && !known.edge_far[8 * static_cast<std::size_t>(i) + static_cast<std::size_t>(bits)] &&
                detail::edge_meets_rim_tori(rim, vertex(bits), E))
                return true;
    }
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        const int k = (i + 2) % 3;
        for (int sigma : {1, -1}) {
            if (known.facet_far[2 * static_cast<std::size_t>(i) + (sigma > 0 ? 1U : 0U)]) continue;
            const Vec3<Rational> XF = sigma > 0 ? Vec3<Rational>(box.center + half[i]) : Vec3<Rational>(box.center - half[i]);
            if (detail::facet_near_rim(rim, XF, box.axes[j], box.extents[j], box.axes[k], box.extents[k])) return true;
        }
    }
    return false;
}

// The other box kinds as the parallelepipeds they are, exactly.
inline Parallelepiped<Rational> as_parallelepiped(const AlignedBox<Rational>& b) {
    Parallelepiped<Rational> p;
    for (int i = 0; i < 3; ++i) {
        p.center[i] = (b.min[i] + b.max[i]) / 2;
        p.extents[i] = (b.max[i] - b.min[i]) / 2;
        p.axes[i] = {Rational(i == 0), Rational(i == 1), Rational(i == 2)};
    }
    return p;
}
inline Parallelepiped<Rational> as_parallelepiped(const CanonicalBox<Rational>& b) {
    return {{0, 0, 0}, {Vec3<Rational>{1, 0, 0}, Vec3<Rational>{0, 1, 0}, Vec3<Rational>{0, 0, 1}}, b.extents};
}
inline Parallelepiped<Rational> as_parallelepiped(const OrientedBox<Rational>& b) {
    return {b.center, b.axes, b.extents};
}
inline Parallelepiped<Rational> as_parallelepiped(const Parallelepiped<Rational>& b) { return b; }

}  // namespace boxcyl::exact::clearance
