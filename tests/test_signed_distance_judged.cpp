// The certified signed distance, boxcyl::signed_distance, judged by independent means. Where the solids
// overlap, sd = −depth, depth = min over unit n of H(n) = n·(c − C) + Σ|n·hᵢ| + k|n·u| + r|n × u| (the
// Minkowski difference box − cylinder's support function; every direction's H is an upper bound of the
// depth). For every overlapping case:
//   (a) an independent estimate q of the depth in long double: H on a Fibonacci sphere of 20,000
//       directions, the directions where H has kinks (±u, face normals, edge × axis), the great circles
//       of its creases and the returned normal, then pattern search from the best (double, then long
//       double). q is a value H attains, so the claimed lower bound must not exceed it beyond its
//       rounding (2⁻⁵⁶·Σ, Σ = |z| + Σ|hᵢ| + k + r: relative to the lengths H is made of, not an absolute
//       tolerance, which would mean nothing for shapes of 2⁻⁶⁰⁰; still far below the stated width),
//       and it must come within 1e-9·L of the claimed upper bound (the search works; an upper bound
//       far below the depth);
//   (b) the exact intersection oracle (boxcyl/oracle/oracle.hpp) on the box moved exactly (in rationals)
//       by −(depth_upper·(1 + 2⁻⁴⁴) + 2⁻⁹⁰·L + 2⁻⁴⁸·Σ)·normal: it must no longer meet the cylinder; and
//       moved by −depth_lower·(1 − 2⁻⁴⁴)·normal: it must still meet it (the slack covers the normal's
//       and the translation's rounding, see judge(); every part is below a sixteenth of the width);
//   (c) the enclosure is at most 2⁻⁴³·L' wide (the stated bound, L' the largest of the offset c − C,
//       the half axes' components, the radius and the half height) and 0 ≥ upper ≥ lower; apart, it is
//       boxcyl::distance's answer exactly, with a unit normal;
//   (d) the witnesses: each within 1e-9·L of its solid (decided exactly by the clearance oracle,
//       tests/clearance/), and in round to nearest on_cylinder − on_box within 1e-6·L of sd·normal.
// L is the largest absolute length of the input (coordinates, half axis lengths, radius, height).
// Sets: known depths, touching and zero-size shapes, every generator profile, parallelepipeds with
// non-orthogonal axes, large offsets, float inputs and the directed rounding modes. A violation prints
// the case as C++ (hex floats) to paste into a regression test.
#include <gtest/gtest.h>

#include <algorithm>  // std::sort, std::max
#include <array>      // vectors
#include <cfenv>      // rounding modes
#include <chrono>     // timing per set
#include <cmath>      // std::sqrt, std::ldexp
#include <cstdint>    // seeds
#include <cstdio>     // std::printf
#include <cstdlib>    // std::getenv
#include <exception>  // std::exception: a non-finite answer refused by the exact conversions
#include <map>        // violations by kind
#include <random>     // fixed-seed generators
#include <string>     // messages
#include <utility>    // std::pair
#include <vector>     // candidate directions

#include "boxcyl/distance.hpp"
#include "boxcyl/oracle/oracle.hpp"
#include "boxcyl/signed_distance.hpp"
#include "clearance/clearance_oracle.hpp"
#include "clearance/exact_case.hpp"
#include "support/cases.hpp"
#include "support/fp.hpp"  // RoundingMode

namespace boxcyl {
namespace {

using namespace boxcyl::testing;

using Quad = long double;  // x86-64: 64-bit significands, 11 bits beyond double's

// ---- Cases: the generators' Case, or a parallelepiped ----

struct Shape {
    Case c;                      // its cylinder always; its box unless `parallelepiped`
    bool parallelepiped = false;
    Parallelepiped<double> pp{};
};

std::string describe(const Shape& s) {
    if (!s.parallelepiped) return testing::describe(s.c);
    const Cylinder<double>& y = s.c.cylinder;
    return "Parallelepiped<double>{" + hex(s.pp.center) + ", {Vec3<double>" + hex(s.pp.axes[0]) + ", Vec3<double>" +
           hex(s.pp.axes[1]) + ", Vec3<double>" + hex(s.pp.axes[2]) + "}, " + hex(s.pp.extents) +
           "}, Cylinder<double>{" + hex(y.center) + ", " + hex(y.axis) + ", " + hex(y.radius) + ", " + hex(y.height) + "}";
}

template <class F>
auto with_shape(const Shape& s, F&& f) {
    if (s.parallelepiped) return f(s.pp, s.c.cylinder);
    return with_box(s.c, f);
}

SignedDistance signed_distance_of(const Shape& s) {
    return with_shape(s, [](const auto& box, const Cylinder<double>& cyl) { return signed_distance(box, cyl); });
}
Distance distance_of(const Shape& s) {
    return with_shape(s, [](const auto& box, const Cylinder<double>& cyl) { return distance(box, cyl); });
}
Parallelepiped<Rational> exact_of(const Shape& s) { return s.parallelepiped ? to_exact(s.pp) : exact_box(s.c); }

Shape shape(const Case& c) { return Shape{c, false, {}}; }

// ---- The geometry in long double: H and the search for its minimum ----

using Q3 = std::array<Quad, 3>;
using D3 = std::array<double, 3>;

inline Quad abs_of(Quad x) { return x < 0 ? -x : x; }
inline double abs_of(double x) { return std::abs(x); }
inline Quad sqrt_of(Quad x) { return std::sqrt(x); }
inline double sqrt_of(double x) { return std::sqrt(x); }

template <class T>
T dot3(const std::array<T, 3>& a, const std::array<T, 3>& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class T>
std::array<T, 3> cross3(const std::array<T, 3>& a, const std::array<T, 3>& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class T>
T norm3(const std::array<T, 3>& a) {
    return sqrt_of(dot3(a, a));
}
template <class T>
std::array<T, 3> unit3(const std::array<T, 3>& a) {
    const T l = norm3(a);
    return {a[0] / l, a[1] / l, a[2] / l};
}
template <class T>
std::array<T, 3> axpy(const std::array<T, 3>& x, T s, const std::array<T, 3>& d) {
    return {x[0] + s * d[0], x[1] + s * d[1], x[2] + s * d[2]};
}

// z = c − C, the half axes hᵢ, the unit axis u, radius r, half height k.
template <class T>
struct Geometry {
    std::array<T, 3> z{};
    std::array<std::array<T, 3>, 3> h{};
    std::array<T, 3> u{};
    T r = 0, k = 0;
};

// H(n)/|n|: H at n's direction.
template <class T>
T support(const Geometry<T>& g, const std::array<T, 3>& n) {
    T s = dot3(n, g.z);
    for (const auto& h : g.h) s += abs_of(dot3(n, h));
    s += g.k * abs_of(dot3(n, g.u));
    s += g.r * norm3(cross3(n, g.u));
    return s / norm3(n);
}

Q3 quad(const Vec3<double>& v) { return {v[0], v[1], v[2]}; }

// The reference: the shape's geometry in long double, L (the largest input length) and Σ (|z| + Σ|hᵢ| + k + r,
// H's Lipschitz constant on the sphere, the scale of its rounding).
struct Reference {
    Geometry<Quad> q;
    Geometry<double> d;  // q scaled by 2^-e and rounded: for the coarse search
    int e = 0;
    Quad L = 0, lip = 0;
    Quad relative = 0;  // L': the largest |zᵢ|, half axis component, radius and half height
};

Reference reference_of(const Shape& s) {
    Reference ref;
    Q3 c{0, 0, 0};
    Quad L = 0;
    auto length = [&](Quad x) { L = std::max(L, abs_of(x)); };
    auto lengths = [&](const Vec3<double>& v) { length(v[0]), length(v[1]), length(v[2]); };
    const Case& k = s.c;
    if (s.parallelepiped || k.kind == BoxKind::oriented) {
        const Vec3<double>& center = s.parallelepiped ? s.pp.center : k.oriented.center;
        const auto& axes = s.parallelepiped ? s.pp.axes : k.oriented.axes;
        const Vec3<double>& ext = s.parallelepiped ? s.pp.extents : k.oriented.extents;
        c = quad(center);
        lengths(center);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) ref.q.h[i][j] = Quad(axes[i][j]) * Quad(ext[i]);  // exact (106 bits)
    } else if (k.kind == BoxKind::aligned) {
        lengths(k.aligned.min), lengths(k.aligned.max);
        for (int i = 0; i < 3; ++i) {
            c[i] = (Quad(k.aligned.min[i]) + Quad(k.aligned.max[i])) / 2;
            ref.q.h[i] = {0, 0, 0};
            ref.q.h[i][i] = (Quad(k.aligned.max[i]) - Quad(k.aligned.min[i])) / 2;
        }
    } else {
        for (int i = 0; i < 3; ++i) ref.q.h[i] = {0, 0, 0}, ref.q.h[i][i] = k.canonical.extents[i];
    }
    for (const Q3& h : ref.q.h) length(norm3(h));
    const Cylinder<double>& y = k.cylinder;
    lengths(y.center);
    length(y.radius), length(y.height);
    const Q3 C = quad(y.center);
    for (int i = 0; i < 3; ++i) ref.q.z[i] = c[i] - C[i];
    // u = D/|D| (long double's exponent range holds the squares of every double, subnormals included).
    ref.q.u = unit3(quad(y.axis));
    ref.q.r = y.radius;
    ref.q.k = Quad(y.height) / 2;
    ref.L = L;
    ref.relative = std::max(abs_of(ref.q.r), ref.q.k);
    for (int i = 0; i < 3; ++i) {
        ref.relative = std::max(ref.relative, abs_of(ref.q.z[i]));
        for (int j = 0; j < 3; ++j) ref.relative = std::max(ref.relative, abs_of(ref.q.h[i][j]));
    }
    ref.lip = norm3(ref.q.z) + ref.q.k + ref.q.r;
    for (const Q3& h : ref.q.h) ref.lip += norm3(h);
    ref.e = ref.lip > 0 ? std::ilogb(static_cast<double>(ref.lip)) : 0;
    auto down = [&](Quad x) { return std::ldexp(static_cast<double>(x), -ref.e); };
    for (int i = 0; i < 3; ++i) {
        ref.d.z[i] = down(ref.q.z[i]);
        ref.d.u[i] = static_cast<double>(ref.q.u[i]);
        for (int j = 0; j < 3; ++j) ref.d.h[i][j] = down(ref.q.h[i][j]);
    }
    ref.d.r = down(ref.q.r), ref.d.k = down(ref.q.k);
    return ref;
}

template <class T>
struct Best {
    T value;
    std::array<T, 3> n;
};

// A tangent basis at the unit n.
template <class T>
std::pair<std::array<T, 3>, std::array<T, 3>> tangents(const std::array<T, 3>& n) {
    int m = 0;
    for (int i = 1; i < 3; ++i)
        if (abs_of(n[i]) < abs_of(n[m])) m = i;
    std::array<T, 3> e{0, 0, 0};
    e[m] = 1;
    const std::array<T, 3> t1 = unit3(cross3(n, e));
    return {t1, cross3(n, t1)};
}

// Pattern search on the sphere from n: the tangent basis and its diagonals, the tangents of the crease
// circles through n (n ⊥ u, n ⊥ hᵢ, where H has kinks) and n snapped onto those circles; a step that
// finds no decrease is shrunk by 4, one that finds one is doubled, down to `finest`.
template <class T>
Best<T> pattern_search(const Geometry<T>& g, Best<T> at, T step, T finest, std::mt19937_64& rng) {
    std::vector<std::array<T, 3>> creases{g.u};
    for (const auto& h : g.h)
        if (dot3(h, h) > 0) creases.push_back(unit3(h));
    std::normal_distribution<double> normal(0.0, 1.0);
    int rounds = 0;
    while (step > finest && ++rounds < 2000) {
        const auto [t1, t2] = tangents(at.n);
        std::vector<std::array<T, 3>> dirs{t1, t2, unit3(axpy(t1, T(1), t2)), unit3(axpy(t1, T(-1), t2))};
        for (const auto& x : creases) {
            const std::array<T, 3> t = cross3(x, at.n);
            if (dot3(t, t) > T(1e-24)) dirs.push_back(unit3(t));
        }
        for (int i = 0; i < 4; ++i) {
            const T a = T(normal(rng)), b = T(normal(rng));
            dirs.push_back(unit3(axpy(std::array<T, 3>{a * t1[0], a * t1[1], a * t1[2]}, b, t2)));
        }
        std::vector<std::array<T, 3>> tries;
        for (const auto& d : dirs) tries.push_back(axpy(at.n, step, d)), tries.push_back(axpy(at.n, -step, d));
        for (const auto& x : creases) {  // n snapped onto the circle ⊥ x
            const T c = dot3(at.n, x);
            if (abs_of(c) < T(0.2) && c != 0) tries.push_back(axpy(at.n, -c, x));
        }
        bool improved = false;
        for (const auto& v : tries) {
            if (!(dot3(v, v) > 0)) continue;
            const std::array<T, 3> n = unit3(v);
            const T h = support(g, n);
            if (h < at.value) at = {h, n}, improved = true;
        }
        step = improved ? std::min(step * 2, T(0.1)) : step / 4;
    }
    return at;
}

// The 1-D minimum of H over the great circle ⊥ x near its best samples (zooming in on a grid).
template <class T>
void circle_minima(const Geometry<T>& g, const std::array<T, 3>& x, std::vector<Best<double>>& out) {
    const auto [a, b] = tangents(unit3(x));
    auto at = [&](double t) {
        std::array<T, 3> n;
        for (int i = 0; i < 3; ++i) n[i] = T(std::cos(t)) * a[i] + T(std::sin(t)) * b[i];
        return n;
    };
    constexpr int samples = 720;
    constexpr double pi = 3.14159265358979323846;
    std::vector<std::pair<double, double>> values;  // (H, angle)
    for (int i = 0; i < samples; ++i) {
        const double t = 2 * pi * i / samples;
        values.push_back({static_cast<double>(support(g, at(t))), t});
    }
    std::vector<std::pair<double, double>> minima;  // local minima of the samples
    for (int i = 0; i < samples; ++i) {
        const double v = values[static_cast<std::size_t>(i)].first;
        if (v <= values[static_cast<std::size_t>((i + samples - 1) % samples)].first &&
            v <= values[static_cast<std::size_t>((i + 1) % samples)].first)
            minima.push_back(values[static_cast<std::size_t>(i)]);
    }
    std::sort(minima.begin(), minima.end());
    if (minima.size() > 3) minima.resize(3);
    for (auto [v, t] : minima) {
        double w = 2 * pi / samples;
        while (w > 1e-15) {
            double best = v, bt = t;
            for (int j = -4; j <= 4; ++j) {
                const double s = t + w * j / 4;
                const double h = static_cast<double>(support(g, at(s)));
                if (h < best) best = h, bt = s;
            }
            v = best, t = bt, w /= 4;
        }
        const std::array<T, 3> n = at(t);
        out.push_back({v, {static_cast<double>(n[0]), static_cast<double>(n[1]), static_cast<double>(n[2])}});
    }
}

// q ≥ depth: the least H found (evaluated in long double at the direction `n`).
struct Estimate {
    Quad q;
    Q3 n;
};

Estimate estimate_depth(const Reference& ref, const Vec3<double>& returned_normal, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    const Geometry<double>& g = ref.d;
    std::vector<Best<double>> cands;
    auto add = [&](const D3& v) {
        if (!(dot3(v, v) > 1e-200)) return;
        const D3 n = unit3(v);
        cands.push_back({support(g, n), n});
    };
    // The Fibonacci sphere, of which the best 32 are kept.
    constexpr int N = 20000;
    const double golden = 3.14159265358979323846 * (3 - std::sqrt(5.0));
    std::vector<Best<double>> sphere;
    sphere.reserve(N);
    for (int i = 0; i < N; ++i) {
        const double zc = 1 - (2 * i + 1) / double(N), rho = std::sqrt(1 - zc * zc), phi = golden * i;
        const D3 n{rho * std::cos(phi), rho * std::sin(phi), zc};
        sphere.push_back({support(g, n), n});
    }
    std::partial_sort(sphere.begin(), sphere.begin() + 32, sphere.end(), [](const auto& a, const auto& b) { return a.value < b.value; });
    cands.insert(cands.end(), sphere.begin(), sphere.begin() + 32);
    // Where H has kinks: ±u, the box's axes and face normals, the edges × axis, the circles' crossings;
    // the returned normal and ±z.
    std::vector<D3> special{g.u};
    for (const D3& h : g.h)
        if (dot3(h, h) > 0) special.push_back(unit3(h));
    for (std::size_t i = 0; i < special.size(); ++i)
        for (std::size_t j = i + 1; j < special.size(); ++j) {
            const D3 x = cross3(special[i], special[j]);
            add(x), add(D3{-x[0], -x[1], -x[2]});
        }
    for (const D3& x : special) add(x), add(D3{-x[0], -x[1], -x[2]});
    for (int i = 0; i < 3; ++i) {
        D3 e{0, 0, 0};
        e[i] = 1, add(e), e[i] = -1, add(e);
    }
    add({returned_normal[0], returned_normal[1], returned_normal[2]});
    add(g.z), add(D3{-g.z[0], -g.z[1], -g.z[2]});
    for (const D3& x : special) circle_minima(g, x, cands);
    // Pattern search (double) from the best 16 distinct starts.
    std::sort(cands.begin(), cands.end(), [](const auto& a, const auto& b) { return a.value < b.value; });
    std::vector<Best<double>> starts;
    for (const auto& c : cands) {
        bool distinct = true;
        for (const auto& s : starts) distinct = distinct && dot3(s.n, c.n) < 0.99999;
        if (distinct) starts.push_back(c);
        if (starts.size() == 16) break;
    }
    std::vector<Best<double>> found;
    for (const auto& s : starts) found.push_back(pattern_search(g, s, 0.02, 1e-15, rng));
    std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.value < b.value; });
    // Quad: every candidate evaluated, then the best three polished.
    Estimate best{Quad(HUGE_VAL), {1, 0, 0}};  // +inf
    auto consider = [&](const Q3& n) {
        const Quad h = support(ref.q, n);
        if (h < best.q) best = {h, n};
    };
    for (const auto& c : cands) consider(Q3{c.n[0], c.n[1], c.n[2]});
    for (const auto& f : found) consider(Q3{f.n[0], f.n[1], f.n[2]});
    for (std::size_t i = 0; i < std::min<std::size_t>(3, found.size()); ++i) {
        const Q3 n{found[i].n[0], found[i].n[1], found[i].n[2]};
        const Best<Quad> p = pattern_search(ref.q, Best<Quad>{support(ref.q, n), n}, Quad(1e-7), Quad(1e-21), rng);
        if (p.value < best.q) best = {p.value, p.n};
    }
    return best;
}

std::string quad_string(Quad x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.21Lg", x);
    return buf;
}

// ---- The judge ----

// Violations printed per set: 8, or all of them with BOXCYL_TEST_PRINT_ALL set.
int print_limit() { return std::getenv("BOXCYL_TEST_PRINT_ALL") ? 1 << 30 : 8; }

struct Tally {
    bool silent = false;  // count violations without failing (the judge's own test)
    bool nearest_witnesses = true;  // round to nearest: on_cylinder − on_box is checked against sd·normal
    long checked = 0, overlapping = 0, separated = 0;
    int violations = 0;
    double worst_width = 0;       // (upper − lower)/L over overlapping cases
    double worst_relative_width = 0;  // (upper − lower)/L'
    double worst_gap = 0;         // (q − depth_upper)/L: how far above the claimed upper the search ended
    double worst_witness = 0;     // |on_cylinder − on_box − sd·normal| / L
    double closest = 1;           // min (q − depth_lower)/L: how near the reference came to the claimed lower
    std::map<std::string, int> reasons;  // each kind of violation, counted
};

Rational rational(double x) { return to_rational(x); }

// |v| without overflow or underflow: v scaled by a power of two first.
double length(Vec3<double> v) {
    const double big = std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
    if (!(big > 0) || !std::isfinite(big)) return big;
    const int e = std::ilogb(big);
    v = std::ldexp(1.0, -e) * v;
    return std::ldexp(std::sqrt(dot(v, v)), e);
}

Parallelepiped<Rational> translated(Parallelepiped<Rational> box, const Vec3<double>& t) {
    box.center = box.center + to_exact(t);
    return box;
}
Parallelepiped<Rational> point_box(const Vec3<double>& p) {
    return {to_exact(p), {Vec3<Rational>{1, 0, 0}, Vec3<Rational>{0, 1, 0}, Vec3<Rational>{0, 0, 1}}, {0, 0, 0}};
}
Cylinder<Rational> point_cylinder(const Vec3<double>& p) { return {to_exact(p), {0, 0, 1}, 0, 0}; }

// Judges one answer. `ref_seed`: the reference search's seed. Returns the reference depth (long double) for
// overlapping cases, −1 otherwise.
Quad judge_checked(const Shape& s, const SignedDistance& sd, Tally& t, const std::string& where, std::uint64_t ref_seed);

Quad judge(const Shape& s, const SignedDistance& sd, Tally& t, const std::string& where, std::uint64_t ref_seed = 1) {
    try {
        return judge_checked(s, sd, t, where, ref_seed);
    } catch (const std::exception& e) {  // a non-finite answer (to_rational refuses it), reported with the case
        ++t.reasons[std::string("exception: ") + e.what()];
        if (++t.violations <= print_limit() && !t.silent)
            ADD_FAILURE() << where << ": exception while judging: " << e.what() << "; signed distance [" << hex(sd.lower)
                          << ", " << hex(sd.upper) << "], normal " << hex(sd.normal) << ", on_box " << hex(sd.on_box)
                          << ", on_cylinder " << hex(sd.on_cylinder) << " for\n" << describe(s);
        return -1;
    }
}

Quad judge_checked(const Shape& s, const SignedDistance& sd, Tally& t, const std::string& where, std::uint64_t ref_seed) {
    ++t.checked;
    const Parallelepiped<Rational> box = exact_of(s);
    const Cylinder<Rational> cyl = to_exact(s.c.cylinder);
    const bool meet = oracle::intersects(box, cyl);
    const Reference ref = reference_of(s);
    const double L = static_cast<double>(ref.L);
    std::string why;
    const double nlen = std::sqrt(sd.normal[0] * sd.normal[0] + sd.normal[1] * sd.normal[1] + sd.normal[2] * sd.normal[2]);
    const bool unit = std::abs(nlen - 1) <= 1e-12;
    Quad q = -1;
    if (!meet) {
        ++t.separated;
        const Distance d = distance_of(s);
        if (!(sd.lower == d.lower && sd.upper == d.upper)) why += " apart, but not distance()'s enclosure;";
        if (!(sd.on_box == d.on_box && sd.on_cylinder == d.on_cylinder)) why += " apart, but not distance()'s witnesses;";
        if (!(sd.lower >= 0 && sd.upper > 0)) why += " apart, but the enclosure is not positive;";
        if (!unit) why += " normal not unit;";
        else {
            Vec3<double> w = sd.on_cylinder - sd.on_box;
            const double big = std::max({std::abs(w[0]), std::abs(w[1]), std::abs(w[2])});
            if (big > 0 && std::isfinite(big)) w = std::ldexp(1.0, -std::ilogb(big)) * w;  // |w|² in range
            const double wl = std::sqrt(dot(w, w));
            if (wl > 0 && dot(w, sd.normal) < (1 - 1e-9) * wl) why += " normal not along on_cylinder − on_box;";
        }
    } else {
        ++t.overlapping;
        const double depth_lower = -sd.upper, depth_upper = -sd.lower;
        // (c) an interval, 0 ≥ upper ≥ lower, at most 2⁻⁴³·L' wide
        if (!(sd.lower <= sd.upper)) why += " not an interval;";
        if (!(sd.upper <= 0)) why += " overlapping, but upper > 0;";
        if (!std::isfinite(sd.lower)) why += " lower not finite;";
        const Quad width = Quad(sd.upper) - Quad(sd.lower);
        // The stated bound: 2⁻⁴³·L', L' the largest of the offset c − C (each coordinate), the half axes'
        // components, the radius and the half height (offsets cancel).
        if (!(width <= Quad(std::ldexp(1.0, -43)) * ref.relative)) why += " wider than the stated 2^-43·L';";
        if (L > 0) t.worst_width = std::max(t.worst_width, static_cast<double>(width / ref.L));
        if (ref.relative > 0) t.worst_relative_width = std::max(t.worst_relative_width, static_cast<double>(width / ref.relative));
        if (!unit) why += " normal not unit;";
        // (a) the long double reference: depth_lower ≤ q (up to long double rounding) and q ≤ depth_upper + 1e-9·L.
        const Estimate est = estimate_depth(ref, sd.normal, ref_seed);
        q = est.q;
        const Quad quad_slack = Quad(std::ldexp(1.0, -56)) * ref.lip;
        if (!(Quad(depth_lower) <= q + quad_slack)) why += " depth lower bound above a value H attains (q = " + quad_string(q) + ");";
        if (!(q <= Quad(depth_upper) + Quad(1e-9) * ref.L))
            why += " the search found nothing near the claimed upper bound (q = " + quad_string(q) + ");";
        if (L > 0 && std::isfinite(depth_upper))
            t.worst_gap = std::max(t.worst_gap, static_cast<double>((q - Quad(depth_upper)) / ref.L));
        if (L > 0) t.closest = std::min(t.closest, static_cast<double>((q - Quad(depth_lower)) / ref.L));
        // (b) the exact judge along the normal. The box moved by −s·n̂ (n̂ unit) still meets the cylinder
        // iff s·n̂ lies in M = box − cylinder, i.e. iff s is at most M's radius along n̂, which lies between
        // the depth and H(n̂). So it must no longer meet once s > H(n̂), and must still meet while s < depth.
        // H(n̂) is at most the claimed upper bound for the direction whose H gave it, of which the returned
        // normal is the rounding (each component 2⁻⁵³ relative, so |Δn̂| ≤ 2⁻⁵²); that moves H by at most
        // Σ·|Δn̂|, Σ = |z| + Σ|hᵢ| + k + r being H's Lipschitz constant on the sphere: 2⁻⁴⁸·Σ covers it. The
        // moved box is the exact box translated exactly (rationals) by the double vector −s·normal, so the
        // only other roundings are those of s·normal and of |normal| (s is divided by it): a few units of
        // 2⁻⁵³, covered by the factors 1 ± 2⁻⁴⁴. (The brief's 1 ± 2⁻³⁰ would hide errors of up to 2⁻³⁰·depth,
        // far above the stated width 2⁻⁴³·L'; every slack here is below a sixteenth of the width.)
        if (unit && std::isfinite(depth_upper)) {
            const double s_up = (depth_upper * (1 + std::ldexp(1.0, -44)) + std::ldexp(L, -90) +
                                 std::ldexp(static_cast<double>(ref.lip), -48)) / nlen;
            const Vec3<double> away = -s_up * sd.normal;
            if (oracle::intersects(translated(box, away), cyl))
                why += " the box moved by (depth_upper + slack) along -normal still meets the cylinder;";
            if (depth_lower > 0x1p-1000) {  // (a subnormal depth_lower is not tried: its rounding is coarse)
                const double s_lo = depth_lower * (1 - std::ldexp(1.0, -44)) / nlen;
                if (!oracle::intersects(translated(box, -s_lo * sd.normal), cyl))
                    why += " the box moved by depth_lower along -normal no longer meets the cylinder;";
            }
        }
        // (d) the witnesses
        const double mid = 0.5 * sd.lower + 0.5 * sd.upper;
        const Vec3<double> miss = sd.on_cylinder - sd.on_box - mid * sd.normal;
        const double miss_len = length(miss);
        // (In a directed rounding mode the witnesses are the double search's, as the distance's are: near
        // their solids, their difference not checked.)
        if (t.nearest_witnesses && !(miss_len <= 1e-6 * L)) why += " on_cylinder − on_box is not sd·normal;";
        if (L > 0) t.worst_witness = std::max(t.worst_witness, miss_len / L);
        const Rational tol = rational(1e-9 * L);
        auto finite = [](const Vec3<double>& p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); };
        if (!finite(sd.on_box) || !finite(sd.on_cylinder)) why += " a witness is not finite;";
        else {
            if (!clearance_oracle::within(box, point_cylinder(sd.on_box), tol)) why += " on_box not within 1e-9·L of the box;";
            if (!clearance_oracle::within(point_box(sd.on_cylinder), cyl, tol))
                why += " on_cylinder not within 1e-9·L of the cylinder;";
        }
    }
    for (std::size_t at = 0; at < why.size();) {  // count each reason (" reason;" pieces, the text before " (")
        const std::size_t end = why.find(';', at);
        std::string reason = why.substr(at + 1, end - at - 1);
        reason = reason.substr(0, reason.find(" (q = "));
        ++t.reasons[reason];
        at = end + 1;
    }
    if (!why.empty() && ++t.violations <= print_limit() && !t.silent)
        ADD_FAILURE() << where << ":" << why << " signed distance [" << hex(sd.lower) << ", " << hex(sd.upper)
                      << "], normal " << hex(sd.normal) << ", on_box " << hex(sd.on_box) << ", on_cylinder "
                      << hex(sd.on_cylinder) << ", L " << hex(L) << ", reference q " << quad_string(q) << " for\n"
                      << describe(s);
    return q;
}

void report(const char* set, const Tally& t, double seconds) {
    std::printf("%s: %ld judged, %ld overlapping, %ld apart, %d violations; worst width/L %.3g (/L' %.3g), "
                "worst (q - depth_upper)/L %.3g, least (q - depth_lower)/L %.3g, worst witness miss/L %.3g; %.1f s\n",
                set, t.checked, t.overlapping, t.separated, t.violations, t.worst_width, t.worst_relative_width,
                t.worst_gap, t.closest, t.worst_witness, seconds);
    for (const auto& [reason, count] : t.reasons) std::printf("  %4d x %s\n", count, reason.c_str());
}

struct Timer {
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); }
};

// ---- Known depths ----

struct Known {
    Shape s;
    double depth;      // exact
    Vec3<double> normal;  // the unique minimising direction, or {0, 0, 0} where it is not unique
};

Shape aligned(const Vec3<double>& lo, const Vec3<double>& hi, const Cylinder<double>& cyl) {
    Case c;
    c.kind = BoxKind::aligned;
    c.aligned = {lo, hi};
    c.cylinder = cyl;
    return shape(c);
}
Shape canonical(const Vec3<double>& ext, const Cylinder<double>& cyl) {
    Case c;
    c.kind = BoxKind::canonical;
    c.canonical = {ext};
    c.cylinder = cyl;
    return shape(c);
}

void check_known(const Known& k, Tally& t) {
    const SignedDistance sd = signed_distance_of(k.s);
    const Quad q = judge(k.s, sd, t, "known depth " + std::to_string(k.depth));
    EXPECT_LE(sd.lower, -k.depth) << describe(k.s);
    EXPECT_GE(sd.upper, -k.depth) << describe(k.s);
    // The reference search finds the known minimum too (a check of the judge itself).
    EXPECT_LE(static_cast<double>(abs_of(q - Quad(k.depth))), 1e-12) << describe(k.s);
    if (k.normal != Vec3<double>{0, 0, 0}) {
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(sd.normal[i], k.normal[i], 1e-9) << describe(k.s);
    }
}

TEST(SignedDistanceJudged, KnownDepths) {
    const Timer timer;
    Tally t;
    const Known known[] = {
        // The side of a vertical cylinder reaching 0.5 into the face x = 1: the box moves 0.5 along −x.
        {aligned({-1, -1, -1}, {1, 1, 1}, {{1.5, 0, 0}, {0, 0, 1}, 1, 10}), 0.5, {1, 0, 0}},
        // A cylinder wholly inside [0,2]³: 1 + 0.5 along ±x, ±y (side) and ±z (cap) alike.
        {aligned({0, 0, 0}, {2, 2, 2}, {{1, 1, 1}, {0, 0, 1}, 0.5, 1}), 1.5, {0, 0, 0}},
        // A cap 0.25 into the face z = 1 (the cylinder spans z ∈ [0.75, 1.75]): 0.25 along z.
        {aligned({-1, -1, -1}, {1, 1, 1}, {{0, 0, 1.25}, {0, 0, 1}, 0.25, 1}), 0.25, {0, 0, 1}},
        // The same with the axis given reversed and not of unit length.
        {aligned({-1, -1, -1}, {1, 1, 1}, {{0, 0, 1.25}, {0, 0, -8}, 0.25, 1}), 0.25, {0, 0, 1}},
        // A segment (radius 0) through the box at x = 0.5: 0.5 along x.
        {aligned({-1, -1, -1}, {1, 1, 1}, {{0.5, 0, 0}, {0, 0, 1}, 0, 10}), 0.5, {1, 0, 0}},
        // A disk (height 0) at z = 0.75: 0.25 along z.
        {aligned({-1, -1, -1}, {1, 1, 1}, {{0, 0, 0.75}, {0, 0, 1}, 0.5, 0}), 0.25, {0, 0, 1}},
        // A flat box (the square |x|, |y| ≤ 1 in z = 0) pierced by a cylinder of half height 1: 1 along ±z.
        {canonical({1, 1, 0}, {{0, 0, 0}, {0, 0, 1}, 0.5, 2}), 1.0, {0, 0, 0}},
        // The flat box pierced off-centre by a tall cylinder: out sideways, 1 − 0.75 + 0.5 = 0.75 along x.
        {canonical({1, 1, 0}, {{0.75, 0, 0}, {0, 0, 1}, 0.5, 4}), 0.75, {1, 0, 0}},
        // A box edge (along z) pressed 0.25 into the side of a cylinder along x: H(y) = −1.25 + 1 + 0.5 = 0.25.
        {aligned({-1, -1, -1}, {1, 1, 1}, {{0, 1.25, 0}, {1, 0, 0}, 0.5, 1}), 0.25, {0, 1, 0}},
    };
    for (const Known& k : known) check_known(k, t);

    // Touching exactly (depth 0): the side touches the face x = 1 along a line, and a cap touches z = 1.
    for (const Shape& s : {aligned({0, 0, 0}, {1, 1, 1}, {{1.5, 0.5, 0.5}, {0, 0, 1}, 0.5, 0.5}),
                           aligned({0, 0, 0}, {1, 1, 1}, {{0.5, 0.5, 1.5}, {0, 0, 1}, 0.25, 1}),
                           aligned({0, 0, 0}, {1, 1, 1}, {{4, 5, 0.5}, {0, 0, 1}, 5, 1})}) {  // a vertical edge (3-4-5)
        const SignedDistance sd = signed_distance_of(s);
        judge(s, sd, t, "touching");
        EXPECT_LE(sd.lower, 0) << describe(s);
        EXPECT_EQ(sd.upper, 0) << describe(s);
        EXPECT_GE(sd.lower, -0x1p-40 * 5) << describe(s);  // L = 5 at most here
    }
    report("known depths", t, timer.seconds());
    EXPECT_EQ(t.violations, 0);
}

// ---- Random sets ----

TEST(SignedDistanceJudged, RandomPairsEveryProfile) {
    const Timer timer;
    Tally all;
    for (Profile p : {Profile::mixed, Profile::degenerate, Profile::uniform, Profile::georeferenced, Profile::magnitudes}) {
        const Timer one;
        Tally t;
        CaseGenerator gen(0x5d150100 + static_cast<std::uint64_t>(p), p);
        // 200 cases, and more where fewer than 40 of them overlap (the degenerate and magnitudes profiles).
        for (int i = 0; i < 2000 && (i < 200 || t.overlapping < 40); ++i) {
            const Shape s = shape(gen.next());
            judge(s, signed_distance_of(s), t, "profile " + std::to_string(static_cast<int>(p)), 0x5d15 + i);
        }
        const std::string name = "profile " + std::to_string(static_cast<int>(p));
        report(name.c_str(), t, one.seconds());
        EXPECT_EQ(t.violations, 0);
        EXPECT_GE(t.overlapping, 40) << name;
        all.violations += t.violations;
    }
    std::printf("every profile: %.1f s\n", timer.seconds());
}

// Perturbed frames (a component off by up to 2e-6: far from orthonormal against rounding).
TEST(SignedDistanceJudged, PerturbedFrames) {
    const Timer timer;
    Tally t;
    CaseGenerator gen(0x5d150200, Profile::mixed);
    for (int i = 0; i < 60; ++i) {
        const Shape s = shape(perturbed_frame(gen));
        judge(s, signed_distance_of(s), t, "perturbed frame", 0x5d16 + i);
    }
    report("perturbed frames", t, timer.seconds());
    EXPECT_EQ(t.violations, 0);
}

// Parallelepipeds: a random rotation sheared (non-orthogonal, unequal axis lengths), and a few flat ones
// (two parallel axes, a zero axis).
Shape random_parallelepiped(CaseGenerator& gen, int i) {
    std::mt19937_64& rng = gen.rng();
    Shape s;
    s.parallelepiped = true;
    const double scale = std::ldexp(1.0, static_cast<int>(gen.uniform(-6, 6)));
    auto axes = random_rotation(rng);
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            if (a != b) axes[a] = axes[a] + gen.uniform(-0.6, 0.6) * axes[b];
    for (auto& a : axes) a = gen.uniform(0.3, 3) * a;
    if (i % 10 == 7) axes[2] = gen.uniform(-2, 2) * axes[0];  // dependent axes: a hexagonal prism's flat cousin
    if (i % 10 == 9) axes[1] = {0, 0, 0};
    s.pp.axes = axes;
    s.pp.center = {scale * gen.uniform(-4, 4), scale * gen.uniform(-4, 4), scale * gen.uniform(-4, 4)};
    double reach = 0;
    for (int a = 0; a < 3; ++a) {
        s.pp.extents[a] = scale * gen.uniform(0.05, 1.5);
        reach += s.pp.extents[a] * std::sqrt(dot(axes[a], axes[a]));
    }
    Cylinder<double>& y = s.c.cylinder;
    y.axis = {gen.uniform(-1, 1), gen.uniform(-1, 1), gen.uniform(-1, 1)};
    if (y.axis == Vec3<double>{0, 0, 0}) y.axis = {0, 0, 1};
    y.radius = scale * gen.uniform(0.05, 1.5);
    y.height = scale * gen.uniform(0.1, 3);
    reach += y.radius + 0.5 * y.height;
    for (int a = 0; a < 3; ++a) y.center[a] = s.pp.center[a] + reach * gen.uniform(-0.45, 0.45);
    return s;
}

TEST(SignedDistanceJudged, Parallelepipeds) {
    const Timer timer;
    Tally t;
    CaseGenerator gen(0x5d150300, Profile::uniform);
    for (int i = 0; i < 150; ++i) {
        const Shape s = random_parallelepiped(gen, i);
        judge(s, signed_distance_of(s), t, "parallelepiped", 0x5d17 + i);
    }
    report("parallelepipeds", t, timer.seconds());
    EXPECT_EQ(t.violations, 0);
    EXPECT_GT(t.overlapping, 40);
}

// Zero sizes in random positions: flat boxes, segments (radius 0) and disks (height 0).
TEST(SignedDistanceJudged, ZeroSizes) {
    const Timer timer;
    Tally t;
    CaseGenerator gen(0x5d150400, Profile::uniform);
    for (int i = 0; i < 120; ++i) {
        Case c = gen.next();
        switch (i % 4) {
            case 0: c.cylinder.radius = 0; break;
            case 1: c.cylinder.height = 0; break;
            case 2:  // a flat box
                if (c.kind == BoxKind::aligned) c.aligned.max[i % 3] = c.aligned.min[i % 3];
                else if (c.kind == BoxKind::oriented) c.oriented.extents[i % 3] = 0;
                else c.canonical.extents[i % 3] = 0;
                break;
            default:  // a flat box and a disk
                if (c.kind == BoxKind::oriented) c.oriented.extents[0] = 0;
                else if (c.kind == BoxKind::canonical) c.canonical.extents[2] = 0;
                else c.aligned.max[1] = c.aligned.min[1];
                c.cylinder.height = 0;
                break;
        }
        const Shape s = shape(c);
        judge(s, signed_distance_of(s), t, "zero sizes", 0x5d18 + i);
    }
    report("zero sizes", t, timer.seconds());
    EXPECT_EQ(t.violations, 0);
    EXPECT_GT(t.overlapping, 20);
}

// Large offsets: a case on the 2^-30 grid moved by 2^20 along every axis, which is exact, so the depth
// is the same: both enclosures hold it, so they overlap, and each is at most 2^-43·L' wide.
TEST(SignedDistanceJudged, LargeOffsets) {
    const Timer timer;
    Tally t;
    CaseGenerator gen(0x5d150500, Profile::uniform);
    const double offset = 0x1p20;
    auto snap = [](double x) { return std::ldexp(std::nearbyint(std::ldexp(x, 30)), -30); };
    int compared = 0;
    for (int i = 0; i < 120 && compared < 40; ++i) {
        Case c = gen.next();
        if (c.kind == BoxKind::canonical) continue;
        for (int k = 0; k < 3; ++k) {
            c.cylinder.center[k] = snap(c.cylinder.center[k]);
            c.aligned.min[k] = snap(c.aligned.min[k]), c.aligned.max[k] = snap(c.aligned.max[k]);
            c.oriented.center[k] = snap(c.oriented.center[k]);
        }
        Case far = c;
        for (int k = 0; k < 3; ++k) {
            far.cylinder.center[k] += offset;
            far.aligned.min[k] += offset, far.aligned.max[k] += offset;
            far.oriented.center[k] += offset;
            // exact: multiples of 2^-30 below 2^22 in magnitude
            EXPECT_EQ(far.cylinder.center[k] - offset, c.cylinder.center[k]);
        }
        const Shape near_shape = shape(c), far_shape = shape(far);
        if (!oracle_answer(c)) continue;
        const SignedDistance a = signed_distance_of(near_shape), b = signed_distance_of(far_shape);
        judge(near_shape, a, t, "offset: at the origin", 0x5d19 + i);
        judge(far_shape, b, t, "offset: moved by 2^20", 0x5d19 + i);
        ++compared;
        const double L = static_cast<double>(reference_of(far_shape).L);
        EXPECT_LE(std::max(a.lower, b.lower), std::min(a.upper, b.upper)) << describe(c) << "\nand\n" << describe(far);
        EXPECT_LE(std::abs((0.5 * a.lower + 0.5 * a.upper) - (0.5 * b.lower + 0.5 * b.upper)), std::ldexp(L, -40))
            << describe(c) << "\nand\n" << describe(far);
    }
    report("large offsets", t, timer.seconds());
    EXPECT_EQ(t.violations, 0);
    EXPECT_GE(compared, 20);
}

// Narrowed out of line (as in test_distance_judged: GCC's SLP vectorizer otherwise forwards the
// unrounded double).
[[gnu::noinline]] float narrow(double x) { return static_cast<float>(x); }
Vec3<float> narrow(const Vec3<double>& v) { return {narrow(v[0]), narrow(v[1]), narrow(v[2])}; }
Vec3<double> widen(const Vec3<float>& v) { return {v[0], v[1], v[2]}; }

TEST(SignedDistanceJudged, FloatInputs) {
    const Timer timer;
    Tally t;
    CaseGenerator gen(0x5d150600, Profile::uniform);
    for (int i = 0; i < 100; ++i) {
        const Case c = gen.next();
        Cylinder<float> fc{narrow(c.cylinder.center), narrow(c.cylinder.axis), narrow(c.cylinder.radius), narrow(c.cylinder.height)};
        if (fc.axis == Vec3<float>{0, 0, 0}) fc.axis = {0, 0, 1};
        Case w;  // the float inputs, judged as the doubles they equal
        w.cylinder = {widen(fc.center), widen(fc.axis), fc.radius, fc.height};
        SignedDistance sd;
        if (c.kind == BoxKind::oriented) {
            OrientedBox<float> fb{narrow(c.oriented.center), {narrow(c.oriented.axes[0]), narrow(c.oriented.axes[1]), narrow(c.oriented.axes[2])},
                                  narrow(c.oriented.extents)};
            if (!validate(fb).ok()) continue;
            w.kind = BoxKind::oriented;
            w.oriented = {widen(fb.center), {widen(fb.axes[0]), widen(fb.axes[1]), widen(fb.axes[2])}, widen(fb.extents)};
            sd = signed_distance(fb, fc);
        } else if (c.kind == BoxKind::aligned) {
            AlignedBox<float> fb{narrow(c.aligned.min), narrow(c.aligned.max)};
            for (int k = 0; k < 3; ++k) fb.max[k] = std::max(fb.min[k], fb.max[k]);
            w.kind = BoxKind::aligned;
            w.aligned = {widen(fb.min), widen(fb.max)};
            sd = signed_distance(fb, fc);
        } else {
            const CanonicalBox<float> fb{narrow(c.canonical.extents)};
            w.kind = BoxKind::canonical;
            w.canonical = {widen(fb.extents)};
            sd = signed_distance(fb, fc);
        }
        judge(shape(w), sd, t, "float", 0x5d1a + i);
    }
    report("float inputs", t, timer.seconds());
    EXPECT_EQ(t.violations, 0);
    EXPECT_GT(t.overlapping, 20);
}

// The directed rounding modes: the query runs in the mode, every judge (the long double reference included)
// in round to nearest.
TEST(SignedDistanceJudged, EveryRoundingMode) {
    const Timer timer;
    Tally t;
    t.nearest_witnesses = false;
    std::vector<Shape> cases;
    for (Profile p : {Profile::mixed, Profile::uniform, Profile::georeferenced, Profile::degenerate}) {
        CaseGenerator gen(0x5d150700 + static_cast<std::uint64_t>(p), p);
        for (int found = 0; found < 11;) {
            const Case c = gen.next();
            if (!oracle_answer(c)) continue;
            cases.push_back(shape(c));
            ++found;
        }
    }
    CaseGenerator pgen(0x5d150800, Profile::uniform);
    for (int i = 0; cases.size() < 50; ++i) {
        const Shape s = random_parallelepiped(pgen, i);
        if (oracle::intersects(to_exact(s.pp), to_exact(s.c.cylinder))) cases.push_back(s);
    }
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const SignedDistance nearest = signed_distance_of(cases[i]);
        for (const int mode : {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
            SignedDistance sd;
            {
                const RoundingMode scope(mode);
                sd = signed_distance_of(cases[i]);
            }
            judge(cases[i], sd, t, mode_name(mode), 0x5d1b + i);
            // Both enclosures hold the same depth.
            EXPECT_LE(std::max(sd.lower, nearest.lower), std::min(sd.upper, nearest.upper)) << mode_name(mode) << " " << describe(cases[i]);
        }
    }
    report("rounding modes", t, timer.seconds());
    EXPECT_EQ(t.violations, 0);
}

// The judge itself: answers made wrong by a little (far less than the depth, a few times the stated
// width) are caught, each by the check meant for it.
TEST(SignedDistanceJudged, JudgeRejectsWrongAnswers) {
    CaseGenerator gen(0x5d150900, Profile::uniform);
    int cases = 0;
    std::map<std::string, int> caught, tried;
    while (cases < 20) {
        const Shape s = shape(gen.next());
        if (!oracle_answer(s.c)) continue;
        ++cases;
        const SignedDistance sd = signed_distance_of(s);
        const double L = static_cast<double>(reference_of(s).L), w = std::ldexp(L, -36);  // ≥ 64 × the stated width
        auto wrong = [&](SignedDistance bad, const char* expected) {
            Tally t;
            t.silent = true;
            judge(s, bad, t, "wrong", 7);
            caught[expected] += t.reasons.count(expected) ? 1 : 0;
            ++tried[expected];
            std::string seen;
            for (const auto& r : t.reasons) seen += " [" + r.first + "]";
            EXPECT_EQ(t.reasons.count(expected), 1u) << expected << " not caught (caught:" << seen << ") in the answer ["
                                                     << hex(bad.lower) << ", " << hex(bad.upper) << "] for [" << hex(sd.lower)
                                                     << ", " << hex(sd.upper) << "], normal " << hex(sd.normal) << ", for\n"
                                                     << describe(s);
        };
        SignedDistance deeper = sd;  // the depth's lower bound above the depth
        deeper.upper = sd.lower - w, deeper.lower = sd.lower - 2 * w;
        wrong(deeper, "depth lower bound above a value H attains");
        SignedDistance shallower = sd;  // the depth's upper bound below the depth
        shallower.lower = sd.upper + w, shallower.upper = sd.upper + 2 * w;
        wrong(shallower, "the box moved by (depth_upper + slack) along -normal still meets the cylinder");
        SignedDistance low = sd;  // the depth's upper bound far below the depth
        low.lower = sd.upper + 1e-6 * L, low.upper = low.lower;
        wrong(low, "the search found nothing near the claimed upper bound");
        wrong(low, "the box moved by (depth_upper + slack) along -normal still meets the cylinder");
        SignedDistance loose = sd;  // an upper bound above the depth by 64 × the stated width or more
        loose.lower = sd.lower - w;
        wrong(loose, "wider than the stated 2^-43·L'");
        SignedDistance turned = sd;  // the normal turned by 0.1 rad: H there is above the depth (the
        const auto [t1, t2] = tangents(D3{sd.normal[0], sd.normal[1], sd.normal[2]});  // minimum is strict here)
        for (int i = 0; i < 3; ++i) turned.normal[i] = std::cos(0.1) * sd.normal[i] + std::sin(0.1) * t1[i];
        Tally t;
        t.silent = true;
        judge(s, turned, t, "turned", 7);
        caught["turned normal"] += t.violations > 0 ? 1 : 0;
        ++tried["turned normal"];
        SignedDistance moved = sd;  // the box's witness moved out of its face (the box's normal there is sd.normal)
        moved.on_box = sd.on_box + 1e-3 * L * sd.normal;
        wrong(moved, "on_box not within 1e-9·L of the box");
        wrong(moved, "on_cylinder − on_box is not sd·normal");
        moved = sd;  // and the cylinder's, out of the cylinder (along −normal)
        moved.on_cylinder = sd.on_cylinder - 1e-3 * L * sd.normal;
        wrong(moved, "on_cylinder not within 1e-9·L of the cylinder");
    }
    for (const auto& [check, count] : caught) std::printf("  caught %2d of %d: %s\n", count, tried[check], check.c_str());
    EXPECT_GE(caught["turned normal"], 15);
}

TEST(SignedDistanceJudged, InvalidInputIsRefused) {
    const Cylinder<double> zero_axis{{0, 0, 0}, {0, 0, 0}, 1, 1};
    EXPECT_THROW((void)signed_distance(AlignedBox<double>{{0, 0, 0}, {1, 1, 1}}, zero_axis), std::invalid_argument);
    const Cylinder<double> ok{{0, 0, 0}, {0, 0, 1}, 1, 1};
    EXPECT_THROW((void)signed_distance(AlignedBox<double>{{0, 0, 0}, {std::nan(""), 1, 1}}, ok), std::invalid_argument);
    EXPECT_THROW((void)signed_distance(AlignedBox<double>{{0, 0, 0}, {1, 1, 1}}, Cylinder<double>{{0, 0, 0}, {0, 0, 1}, -1, 1}),
                 std::invalid_argument);
}

}  // namespace
}  // namespace boxcyl
