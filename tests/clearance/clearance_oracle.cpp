// The clearance oracle (see clearance_oracle.hpp for the method and why it is exact).
#include "clearance/clearance_oracle.hpp"

#include "clearance/clearance_roots.h"  // real roots and signs at them (FLINT and Arb, behind a C shim)

#include <array>      // face vectors
#include <stdexcept>  // std::invalid_argument
#include <utility>    // std::move
#include <vector>     // polynomials, roots

#include "boxcyl/geometry/vec3.hpp"
#include "boxcyl/oracle/oracle.hpp"  // the m = 0 answer

namespace boxcyl::clearance_oracle {
namespace {

using V = Vec3<Rational>;

int sign(const Rational& x) { return sgn(x); }

// ---- Polynomials in one variable over Q (coefficient i of λ^i) ------------------------------------
using Poly = std::vector<Rational>;

Poly padd(const Poly& a, const Poly& b) {
    Poly r(a.size() > b.size() ? a.size() : b.size());
    for (std::size_t i = 0; i < a.size(); ++i) r[i] += a[i];
    for (std::size_t i = 0; i < b.size(); ++i) r[i] += b[i];
    return r;
}
Poly pmul(const Poly& a, const Poly& b) {
    if (a.empty() || b.empty()) return {};
    Poly r(a.size() + b.size() - 1);
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
    return r;
}
Poly pscale(const Poly& a, const Rational& s) {
    Poly r(a);
    for (Rational& c : r) c *= s;
    return r;
}
Poly pderiv(const Poly& a) {
    Poly r;
    for (std::size_t i = 1; i < a.size(); ++i) r.push_back(a[i] * Rational(static_cast<long>(i)));
    return r;
}

std::vector<mpq_srcptr> coeff_ptrs(const Poly& p) {
    std::vector<mpq_srcptr> c;
    for (const Rational& x : p) c.push_back(x.get_mpq_t());
    return c;
}

// The real roots in [−1, 1] of a rational polynomial, in groups (see clearance_roots.h): a sign asked of a group
// holds for every root in it, or the group is too coarse yet (Undecided: refine it and ask again).
struct Undecided {};

class RealRoots {
public:
    explicit RealRoots(const Poly& p) {
        const std::vector<mpq_srcptr> c = coeff_ptrs(p);
        roots_ = boxcyl_real_roots_new(c.data(), static_cast<long>(c.size()));
    }
    ~RealRoots() { boxcyl_real_roots_free(roots_); }
    RealRoots(const RealRoots&) = delete;
    RealRoots& operator=(const RealRoots&) = delete;
    long size() const { return boxcyl_real_roots_count(roots_); }
    int sign_at(long i, const Poly& g) const {
        const std::vector<mpq_srcptr> c = coeff_ptrs(g);
        const int s = boxcyl_real_roots_sign_at(roots_, i, c.data(), static_cast<long>(c.size()));
        if (s == BOXCYL_UNDECIDED) throw Undecided{};
        return s;
    }
    int nonempty(long i) const { return boxcyl_real_roots_nonempty(roots_, i); }
    bool empty(long i) const { return boxcyl_real_roots_empty(roots_, i) != 0; }
    void refine(long i) { boxcyl_real_roots_refine(roots_, i); }

private:
    boxcyl_real_roots* roots_;
};

struct Root {
    const RealRoots* roots;
    long i;
};

// A polynomial in a fixed algebraic root: the ring the edge candidates' quantities live in.
struct AtRoot {
    Poly p;
    const Root* root;
};
AtRoot operator+(const AtRoot& a, const AtRoot& b) { return {padd(a.p, b.p), a.root}; }
AtRoot operator*(const AtRoot& a, const AtRoot& b) { return {pmul(a.p, b.p), a.root}; }
AtRoot operator+(const AtRoot& a, const Rational& c) { return {padd(a.p, Poly{c}), a.root}; }
AtRoot operator*(const AtRoot& a, const Rational& c) { return {pscale(a.p, c), a.root}; }
int sign(const AtRoot& a) { return a.root->roots->sign_at(a.root->i, a.p); }

// ---- Q(√d, √N) with d, N > 0: a + b√d + c√N + e√(dN) ----------------------------------------------
struct Biq {
    Rational a, b, c, e;
    const Rational* d;
    const Rational* n;
};
Biq operator+(const Biq& x, const Biq& y) { return {x.a + y.a, x.b + y.b, x.c + y.c, x.e + y.e, x.d, x.n}; }
Biq operator*(const Biq& x, const Biq& y) {
    const Rational& d = *x.d;
    const Rational& n = *x.n;
    return {x.a * y.a + d * x.b * y.b + n * x.c * y.c + d * n * x.e * y.e,
            x.a * y.b + x.b * y.a + n * (x.c * y.e + x.e * y.c),
            x.a * y.c + x.c * y.a + d * (x.b * y.e + x.e * y.b),
            x.a * y.e + x.e * y.a + x.b * y.c + x.c * y.b, x.d, x.n};
}
Biq operator+(const Biq& x, const Rational& s) { return {x.a + s, x.b, x.c, x.e, x.d, x.n}; }
Biq operator*(const Biq& x, const Rational& s) { return {x.a * s, x.b * s, x.c * s, x.e * s, x.d, x.n}; }

// sign(p + q√k), k > 0.
int sign_root(const Rational& p, const Rational& q, const Rational& k) {
    const int sp = sgn(p), sq = sgn(q);
    if (sq == 0) return sp;
    if (sp == 0 || sp == sq) return sq;
    const int s = sgn(p * p - q * q * k);  // |p| vs |q|√k
    return s > 0 ? sp : (s < 0 ? sq : 0);
}
int sign(const Biq& x) {
    // (a + b√d) + √N(c + e√d) = X + √N·Y
    const Rational& d = *x.d;
    const Rational& n = *x.n;
    const int sx = sign_root(x.a, x.b, d), sy = sign_root(x.c, x.e, d);
    if (sy == 0) return sx;
    if (sx == 0 || sx == sy) return sy;
    // sign(X² − N·Y²), X² − N·Y² = (a² + b²d − N(c² + e²d)) + (2ab − 2Nce)√d
    const int s = sign_root(x.a * x.a + x.b * x.b * d - n * (x.c * x.c + x.e * x.e * d),
                            2 * (x.a * x.b - n * x.c * x.e), d);
    return s > 0 ? sx : (s < 0 ? sy : 0);
}

// ---- sign(F − v) from S = (D·y)² and q = ρ² ------------------------------------------------------
struct Consts {
    Rational d, r, H, v;
};

// sign(a − √b2c), b2c ≥ 0.
template <class R>
int sign_minus_sqrt(const R& a, const R& b2c) {
    const int sa = sign(a);
    if (sign(b2c) == 0) return sa;
    if (sa <= 0) return -1;
    return sign(a * a + b2c * Rational(-1));
}

template <class R>
int sign_f_minus_v(const R& S, const R& q, const Consts& k) {
    const Rational inv_d = 1 / k.d;
    const R t2 = S * inv_d;  // t²
    const bool in_t = sign(t2 + Rational(-(k.H * k.H))) <= 0;
    const bool in_r = sign(q + Rational(-(k.r * k.r))) <= 0;
    if (in_t && in_r) return sgn(k.v) > 0 ? -1 : 0;  // inside: F = 0
    if (in_t)  // side: (ρ − r)² − v = (q + r² − v) − √(4r²q)
        return sign_minus_sqrt<R>(q + Rational(k.r * k.r - k.v), q * Rational(4 * k.r * k.r));
    if (in_r)  // cap: (|t| − H)² − v = (t² + H² − v) − √(4H²t²)
        return sign_minus_sqrt<R>(t2 + Rational(k.H * k.H - k.v), t2 * Rational(4 * k.H * k.H));
    // rim: F − v = L0 − (√α + √β), L0 = q + r² + t² + H² − v, α = 4r²q, β = 4H²t²
    const R L0 = q + t2 + Rational(k.r * k.r + k.H * k.H - k.v);
    const R alpha = q * Rational(4 * k.r * k.r);
    const R beta = t2 * Rational(4 * k.H * k.H);
    const int sl = sign(L0);
    if (sl < 0) return -1;
    if (sl == 0) return sign(alpha + beta) > 0 ? -1 : 0;
    return sign_minus_sqrt<R>(L0 * L0 + alpha * Rational(-1) + beta * Rational(-1), alpha * beta * Rational(4));
}

// The quantities at y = y0 + Σ λⱼaⱼ (X − C) in ring R, λⱼ given in R.
template <class R>
int sign_at_point(const V& y0, const std::vector<V>& a, const std::vector<R>& lambda, const R& one, const V& D,
                  const Consts& k) {
    R T = one * dot(D, y0);
    R Y2 = one * dot(y0, y0);
    for (std::size_t j = 0; j < a.size(); ++j) {
        T = T + lambda[j] * dot(D, a[j]);
        Y2 = Y2 + lambda[j] * Rational(2 * dot(y0, a[j]));
        for (std::size_t l = 0; l < a.size(); ++l) Y2 = Y2 + lambda[j] * lambda[l] * dot(a[j], a[l]);
    }
    const R S = T * T;
    const R q = Y2 + S * Rational(-1 / k.d);
    return sign_f_minus_v(S, q, k);
}

// |λ| ≤ 1 in ring R.
template <class R>
bool in_unit(const R& lambda) {
    return sign(lambda + Rational(-1)) <= 0 && sign(lambda + Rational(1)) >= 0;
}

V project_perp(const V& w, const V& D, const Rational& d) { return w - Rational(dot(D, w) / d) * D; }

// The accumulated answer: −1 as soon as a candidate has F < v, else 0 once one has F = v, else +1.
struct Verdict {
    int best = 1;
    void add(int s) {
        if (s < best) best = s;
    }
    bool done() const { return best < 0; }
};

void edge_candidates(const V& y0, const V& a, const V& D, const Consts& k, Verdict& out) {
    const std::vector<V> av{a};
    // The point nearest the axis line (side region, and cap region when the edge is ⊥ u).
    const V p0 = project_perp(y0, D, k.d), p1 = project_perp(a, D, k.d);
    const Rational pp = dot(p1, p1);
    Rational lam_near = 0;  // the parameter in [−1, 1] of the edge point nearest the axis line
    if (sgn(pp) != 0) {
        const Rational lam = -dot(p0, p1) / pp;
        if (abs(lam) <= 1) out.add(sign_at_point<Rational>(y0, av, {lam}, Rational(1), D, k));
        if (out.done()) return;
        lam_near = lam > 1 ? Rational(1) : (lam < -1 ? Rational(-1) : lam);
    }
    const Rational T0 = dot(D, y0), T1 = dot(D, a);
    // Pruning (exact, a shortcut only): the root finding is skipped when every point of the edge has F > v,
    // shown by ρ ≥ ρ_min > r + √v or by |t| ≥ t_min > H + √v (F ≥ max(ρ − r, 0)², F ≥ max(|t| − H, 0)²).
    {
        const V pn = p0 + lam_near * p1;
        const Rational q_min = dot(pn, pn);  // min ρ² over the edge
        if (sign_minus_sqrt<Rational>(q_min - k.r * k.r - k.v, 4 * k.r * k.r * k.v) > 0) return;
        const Rational T1abs = abs(T1);
        const Rational Tabs = sgn(T0) > 0 ? Rational(T0 - T1abs) : Rational(-T0 - T1abs);  // min |T| if > 0
        if (sgn(Tabs) > 0 && Tabs * Tabs > k.H * k.H * k.d &&
            sign_minus_sqrt<Rational>(Tabs * Tabs / k.d + k.H * k.H - k.v, 4 * k.H * k.H * Tabs * Tabs / k.d) > 0)
            return;
    }
    // Rim-stationary points: real roots of A² − d·B² (both rims), see the header.
    const Poly T{T0, T1};
    const Poly Y2{dot(y0, y0), 2 * dot(y0, a), dot(a, a)};
    const Poly q = padd(Y2, pscale(pmul(T, T), -1 / k.d));
    const Poly W0{dot(y0, a), dot(a, a)};
    const Rational w = k.H * T1;
    const Poly half_dq = pscale(pderiv(q), Rational(1, 2));
    const Poly A = padd(pmul(q, padd(pmul(W0, W0), Poly{w * w / k.d})), pscale(pmul(half_dq, half_dq), -(k.r * k.r)));
    const Poly B = pscale(pmul(q, W0), 2 * w / k.d);
    const Poly P = padd(pmul(A, A), pscale(pmul(B, B), -k.d));
    bool nonconstant = false;  // P ≡ 0 only on the axis line itself (min F = 0 there); a constant has no roots
    for (std::size_t i = 1; i < P.size(); ++i) nonconstant = nonconstant || sgn(P[i]) != 0;
    if (!nonconstant) return;
    // Every real root in [−1, 1], group by group. A group's sign chain holds for all its roots; a chain that a
    // group cannot decide yet refines it (narrower, split, or found empty) and runs again. A candidate sign
    // ≤ 0 counts only once the group is known to hold a root; a sign > 0 changes nothing.
    RealRoots roots(P);
    for (long i = 0; i < roots.size() && !out.done(); ++i) {
        const Root root{&roots, i};
        const AtRoot lam{Poly{0, 1}, &root};
        while (!roots.empty(i)) {
            int s;
            try {
                s = sign_at_point<AtRoot>(y0, av, {lam}, AtRoot{Poly{1}, &root}, D, k);
            } catch (const Undecided&) {
                roots.refine(i);
                continue;
            }
            if (s <= 0) {
                const int n = roots.nonempty(i);
                if (n < 0) {  // not known yet: refine and decide again
                    roots.refine(i);
                    continue;
                }
                if (n > 0) out.add(s);
            }
            break;
        }
    }
}

void facet_candidates(const V& y0, const V& a1, const V& a2, const V& D, const Consts& k, Verdict& out) {
    const std::vector<V> av{a1, a2};
    // The point nearest the axis line (cap region when the facet is ⊥ u).
    {
        const V p0 = project_perp(y0, D, k.d), p1 = project_perp(a1, D, k.d), p2 = project_perp(a2, D, k.d);
        const Rational g11 = dot(p1, p1), g12 = dot(p1, p2), g22 = dot(p2, p2);
        const Rational det = g11 * g22 - g12 * g12;
        if (sgn(det) != 0) {
            const Rational r1 = -dot(p0, p1), r2 = -dot(p0, p2);
            const Rational l1 = (g22 * r1 - g12 * r2) / det, l2 = (g11 * r2 - g12 * r1) / det;
            if (abs(l1) <= 1 && abs(l2) <= 1) out.add(sign_at_point<Rational>(y0, av, {l1, l2}, Rational(1), D, k));
            if (out.done()) return;
        }
    }
    // Rim: the projections onto the plane of the circle points centre ± r·n⊥/|n⊥| (both rims).
    const V nperp = project_perp(cross(a1, a2), D, k.d);
    Rational N = dot(nperp, nperp);
    const bool point_rim = sgn(k.r) == 0;
    if (!point_rim && sgn(N) == 0) return;  // plane ⊥ u: no rim-stationary point with ρ > r
    if (point_rim) N = 1;                   // unused: the circle is a point
    const Rational g11 = dot(a1, a1), g12 = dot(a1, a2), g22 = dot(a2, a2);
    const Rational det = g11 * g22 - g12 * g12;  // > 0: P is injective on this face
    const Biq one{1, 0, 0, 0, &k.d, &N};
    for (int s1 : {1, -1})
        for (int s2 : {1, -1}) {
            if (point_rim && s2 < 0) continue;
            // c − C = s1·(H/d)·D·√d + s2·(r/N)·n⊥·√N; rhsⱼ = aⱼ·(c − C − y0)
            std::array<Biq, 2> rhs;
            for (int j = 0; j < 2; ++j) {
                const V& aj = j == 0 ? a1 : a2;
                rhs[j] = Biq{-dot(aj, y0), s1 * k.H * dot(aj, D) / k.d,
                             point_rim ? Rational(0) : Rational(s2 * k.r * dot(aj, nperp) / N), 0, &k.d, &N};
            }
            const Biq l1 = rhs[0] * (g22 / det) + rhs[1] * (-g12 / det);
            const Biq l2 = rhs[1] * (g11 / det) + rhs[0] * (-g12 / det);
            if (!in_unit(l1) || !in_unit(l2)) continue;
            out.add(sign_at_point<Biq>(y0, av, {l1, l2}, one, D, k));
            if (out.done()) return;
        }
}

}  // namespace

int compare_squared_distance(const Parallelepiped<Rational>& box, const Cylinder<Rational>& cyl, const Rational& v) {
    if (sgn(v) < 0) throw std::invalid_argument("clearance_oracle: negative squared margin");
    // Checks D ≠ 0 and r, h, extents ≥ 0; B ∩ cylinder ≠ ∅ ⇔ dist = 0.
    if (oracle::intersects(box, cyl)) return sgn(v) > 0 ? -1 : 0;
    if (sgn(v) == 0) return 1;  // disjoint compact sets: dist > 0

    const V& D = cyl.axis;
    const Consts k{dot(D, D), cyl.radius, cyl.height / 2, v};
    std::array<V, 3> a;
    for (int i = 0; i < 3; ++i) a[i] = box.extents[i] * box.axes[i];
    const V g = box.center - cyl.center;  // K − C
    Verdict out;

    // Faces of the cube: free coordinates J (|J| ≤ 2), the others fixed at ±1 (bit i of s ⇔ +1).
    for (int mask = 0; mask < 8 && !out.done(); ++mask) {
        std::vector<int> J;
        for (int i = 0; i < 3; ++i)
            if (mask >> i & 1) J.push_back(i);
        if (J.size() == 3) continue;  // B's interior: min F there would be 0, already answered
        for (int s = 0; s < 8 && !out.done(); ++s) {
            if (s & mask) continue;  // each fixed-sign pattern once
            V y0 = g;
            for (int i = 0; i < 3; ++i)
                if (!(mask >> i & 1)) y0 = (s >> i & 1) ? y0 + a[i] : y0 - a[i];
            if (J.empty()) {
                out.add(sign_at_point<Rational>(y0, {}, {}, Rational(1), D, k));
            } else if (J.size() == 1) {
                const V& e = a[J[0]];
                if (sgn(dot(e, e)) == 0) continue;  // not injective: its image is its end points'
                edge_candidates(y0, e, D, k, out);
            } else {
                const V& e1 = a[J[0]];
                const V& e2 = a[J[1]];
                const V n = cross(e1, e2);
                if (sgn(dot(n, n)) == 0) continue;  // not injective: its image is its edges'
                facet_candidates(y0, e1, e2, D, k, out);
            }
        }
    }
    return out.best;
}

bool within(const Parallelepiped<Rational>& box, const Cylinder<Rational>& cyl, const Rational& m) {
    if (sgn(m) < 0) throw std::invalid_argument("clearance_oracle: negative margin");
    return compare_squared_distance(box, cyl, m * m) <= 0;
}

}  // namespace boxcyl::clearance_oracle
