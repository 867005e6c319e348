// The clearance oracle: a test-only, exact judge of "is dist(B, cyl) ≤ m ?" for a parallelepiped B, a
// finite cylinder and a margin m ≥ 0 (both solids closed, every input the exact rational it denotes).
//
// Method. F(X) = dist(X, cyl)² = max(|t| − H, 0)² + max(ρ − r, 0)², t = u·(X − C), H = h/2, ρ the distance
// of X to the axis line, is the squared distance to a compact convex set: convex, C¹, coercive. Write
// B = { P(s) = K + Σ sᵢaᵢ : s ∈ [−1, 1]³ }, aᵢ = eᵢAᵢ (axes exactly as given, possibly dependent or zero).
//  (a) If the m = 0 oracle (boxcyl/oracle/oracle.hpp) says B meets the cylinder, dist = 0.
//  (b) Otherwise d* = min_B F > 0. Take a cube face φ (vertex, edge or facet; not the cube itself: there
//      F would have an interior minimum 0) of least dimension whose image P(φ) holds a minimiser of F
//      over B. Then P restricted to aff φ is injective (if not, some kernel direction moves every point
//      of φ to ∂φ with the same image, so a smaller face would do), the minimiser lies in P(relint φ),
//      and by convexity it minimises F over the affine subspace L = P(aff φ). Moreover the whole set M
//      of minimisers of F over L lies in P(φ) (M is convex; leaving P(φ) it would cross P(∂φ), where no
//      minimiser lies). So it suffices to produce, for every face with P injective on it, a finite set
//      of points of L containing at least one point of M whenever min_L F > 0, and to keep those in
//      P(φ): each kept point is a point of B (its F is ≥ d*), and the right face gives one with F = d*.
//  (c) Such a set, by where a point X* of M lies (δ² = F(X*) > 0; ∇F(X*) = 2(X* − nearest cylinder point)
//      is orthogonal to L):
//      - X* in a cap region (ρ ≤ r, |t| > H): ∇F ∥ u, so L ⊥ u, t is constant on L and every point of L
//        with ρ ≤ r has the same F: the point of L nearest the axis line (rational) is in M.
//      - else X* in a rim region (ρ > r, |t| ≥ H): X* is a stationary point of the squared distance to
//        the rim circle on L. On a line X(λ), with q(λ) = ρ², T(λ) = D·(X − C), d = D·D,
//        W± = (X − C)·a ∓ H·T′/√d, stationarity gives ρ·W± = r·q′/2, squared q·W±² − r²(q′/2)² = 0: a
//        quartic over Q(√d); the product of both signs (both rims) is a degree-8 rational polynomial,
//        identically zero only when L is the axis line (then min_L F = 0). Only its real roots in
//        [−1, 1] matter (see "Roots" below). On a plane with normal n (n⊥ = n − (n·D/d)D ≠ 0) the nearest circle
//        point is centre ± r·n⊥/|n⊥| and X* is its orthogonal projection onto L (coordinates in
//        Q(√d, √|n⊥|²), handled as a biquadratic field); n⊥ = 0 (L ⊥ u) makes ρ > r stationary points
//        impossible. r = 0 is the same with the circle a point.
//      - else X* in the side region (ρ > r, |t| < H): u is not along L (else M would reach |t| = H, a rim
//        point), F = (ρ − r)² depends on the projection ⊥ u only, which is injective on L; on a plane no
//        such stationary point exists, on a line it is the point nearest the axis line (rational).
//  (d) At each kept candidate, sign(F − m²) is decided exactly from T² and q alone: which region (two
//      rational-coefficient sign tests), then a chain of "a − √b" sign tests by squaring with the signs
//      checked first. Candidates are rational, biquadratic (a + b√d + c√N + e√(dN), signs by nested
//      squaring), or polynomials in a real algebraic root λ of the edge equation (see "Roots").
//  (e) Shortcuts: an edge whose points all have F > m² (exact rational bounds on min ρ and min |t| over
//      it) skips its root finding; it could not change the answer. For m = 0 a disjoint pair is answered
//      at once (dist > 0).
// Roots. The edge equation P is split by FLINT (fmpz_poly_factor) into distinct irreducible factors f; a
// linear one gives a rational root, kept if in [−1, 1], whose signs are exact. For deg f ≥ 2 (no rational
// root, so none at ±1), Arb's certified bisection (arb_calc_isolate_roots on [−1, 1], f enclosed on a ball
// by its Taylor form at the midpoint) returns blocks that it could not exclude: each either certified to
// hold exactly one root (sign change at the ends, f′ ≠ 0 on it) or a run of undecided blocks (a cluster,
// or too little precision), kept as one "group". A candidate's sign chain (d) is then run once per group:
// each sign of a polynomial g at λ is 0 iff f divides g (then g = 0 at every root of f, f being
// irreducible); otherwise g ≠ 0 at every root of f, and g mod f evaluated on the group's interval in ball
// arithmetic (Taylor form) either has a certain sign — the same for every root in the group — or the
// group is refined (an isolated root narrowed by arb_calc_refine_root_bisect, anything else re-isolated
// deeper) with more precision, and the chain runs again; this ends, since the signs asked are non-zero
// at the roots and the enclosures shrink to them. A group whose sign is > 0 is dropped whether or not it
// holds a root (it could not lower the verdict); a sign ≤ 0 counts only once the group is shown to hold
// a root: isolated, a sign change of f at its ends, or (after a few refinements) a FLINT Sturm count
// (_fmpz_poly_num_real_roots_sturm after the Möbius map of its interval onto (0, ∞)); a group shown
// empty is dropped. Why not all complex roots: the edge equations of inputs of mixed magnitudes have
// integer coefficients of thousands of bits and pairs of real roots as close as the cylinder's height
// (2^−1000 for a subnormal one); isolating every complex root (qqbar_roots_fmpz_poly, Durand–Kerner)
// took minutes there, while a group usually decides its signs long before such a pair is split.
// Nothing is rounded: the only floating point is Arb's rigorous ball arithmetic, used only to read the
// sign of a quantity already proven non-zero. It shares no code with the production query and is
// different in kind from its decomposition (fat cylinder, tall cylinder, rim tori).
//
// Library choice: FLINT 2.9 (factoring, Sturm counts) and Arb 2.23 (arb_calc's certified isolation and
// bisection, ball arithmetic), Debian's libflint-dev and libflint-arb-dev, rather than Calcium's exact
// algebraic numbers (qqbar: exact too, but isolating every complex root was slow on the inputs above).
// Nothing hand-rolled isolates roots: the shim only encloses f on a ball (Taylor form) and chooses
// depths and precisions. The calls live in a small C file, clearance_roots.c (C headers that are not
// all valid C++). These files sit in tests/clearance/, not tests/support/, so that they are not among
// the sources the recorded long runs depend on.
#pragma once

#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/number/rational.hpp"

namespace boxcyl::clearance_oracle {

// sign(dist(B, cyl)² − v), exactly, for a rational v ≥ 0: −1, 0 or +1. Certifies the distance against any
// rational (bisection gives it to any precision; 0 means the squared distance is exactly v).
// Preconditions (std::invalid_argument): D ≠ 0; r, h, extents ≥ 0; v ≥ 0. Axes may be dependent or zero.
int compare_squared_distance(const Parallelepiped<Rational>& box, const Cylinder<Rational>& cyl,
                             const Rational& v);

// dist(B, cyl) ≤ m, exactly (m ≥ 0; std::invalid_argument otherwise).
bool within(const Parallelepiped<Rational>& box, const Cylinder<Rational>& cyl, const Rational& m);

}  // namespace boxcyl::clearance_oracle
