// libFuzzer target: metamorphic checks of the exact default query, with no oracle in the loop. The
// bytes are decoded (fuzz/decode.hpp) into a query — an aligned, oriented or canonical box, or any
// parallelepiped, and a cylinder — and then into up to six steps, each an exact symmetry of the question
// or another way of writing the same solids:
//   geometry   permute the coordinates, reflect some of them, scale every length by 2^k, translate
//              everything by one vector;
//   cylinder   axis → −axis, axis → 2^k·axis (only its direction counts);
//   box        aligned ⇄ oriented or parallelepiped with a signed-permutation frame (centre (min+max)/2,
//              extents (max−min)/2), oriented ⇄ parallelepiped, canonical ⇄ aligned {−e, e}; reorder
//              the axes of an oriented box or parallelepiped with their extents, negate some of its
//              axes; scale a parallelepiped's axis by 2^k and its extent by 2^−k, fold extents into
//              the axes (axis·extent, extent 1);
//   float      ask the float query instead, when every field is a float.
// A step is applied only where every value it computes is exact (checked by computing back: a sum by
// TwoSum's error term, a power-of-two scaling by scaling back, a product by FMA) and the new query is
// valid; otherwise it is skipped. The exact answer depends only on the rationals the inputs denote and
// the solids they describe, so boxcyl::intersects() must answer the query after the steps as it answers
// the decoded one; a difference is a bug: the steps are replayed to find the first that changes the
// answer, the case is printed as C++ (hex floats) and the run aborts.
//
// Throughput is the point (fuzz_query spends ~90% of its time in the oracle): the steps compose into
// one query, so an input costs two default queries; and seven inputs in eight take their values near
// one scale (Decoder::narrow), where the exact stage is cheap, the eighth mixes the whole double range
// as fuzz_query does. BOXCYL_FUZZ_STATS=1 prints at exit how many inputs were valid and how many steps
// ran.
#include <array>    // frames
#include <cmath>    // std::ldexp, std::fma, std::fabs, std::isfinite
#include <cstddef>  // std::size_t
#include <cstdint>  // std::uint8_t, std::int8_t
#include <cstdio>   // std::fprintf
#include <cstdlib>  // std::abort, std::getenv
#include <limits>   // float's range
#include <string>   // failure messages

#include "boxcyl/query.hpp"
#include "decode.hpp"

namespace {

using boxcyl::AlignedBox;
using boxcyl::CanonicalBox;
using boxcyl::Cylinder;
using boxcyl::OrientedBox;
using boxcyl::Parallelepiped;
using V = boxcyl::Vec3<double>;
using Frame = std::array<V, 3>;

enum class Kind : std::uint8_t { aligned, oriented, parallelepiped, canonical };

// One query; only the box of its kind counts.
struct Query {
    Kind kind = Kind::aligned;
    AlignedBox<double> aligned{};
    OrientedBox<double> oriented{};
    Parallelepiped<double> pp{};
    CanonicalBox<double> canonical{};
    Cylinder<double> cyl{};
};

bool valid(const Query& q) {
    if (!boxcyl::is_valid(q.cyl)) return false;
    switch (q.kind) {
        case Kind::aligned: return boxcyl::is_valid(q.aligned);
        case Kind::oriented: return boxcyl::is_valid(q.oriented);
        case Kind::parallelepiped: return boxcyl::is_valid(q.pp);
        case Kind::canonical: return boxcyl::is_valid(q.canonical);
    }
    return false;
}

bool answer(const Query& q) {
    switch (q.kind) {
        case Kind::aligned: return boxcyl::intersects(q.aligned, q.cyl);
        case Kind::oriented: return boxcyl::intersects(q.oriented, q.cyl);
        case Kind::parallelepiped: return boxcyl::intersects(q.pp, q.cyl);
        case Kind::canonical: return boxcyl::intersects(q.canonical, q.cyl);
    }
    return false;
}

// ---- exact arithmetic: each returns whether its result is exact (and finite) ----

// s = a + b: TwoSum's error term is zero. An overflow anywhere gives Inf or NaN there, never a zero term.
bool add(double a, double b, double& s) {
    s = a + b;
    const double bb = s - a;
    return std::isfinite(s) && (a - (s - bb)) + (b - bb) == 0;
}
bool add(const V& a, const V& b, V& s) { return add(a[0], b[0], s[0]) && add(a[1], b[1], s[1]) && add(a[2], b[2], s[2]); }
// y = x·2^k: scaled back it is x again (an overflow gives Inf; an underflow that rounded does not come back).
bool scale(double x, int k, double& y) {
    y = std::ldexp(x, k);
    return std::isfinite(y) && std::ldexp(y, -k) == x;
}
bool scale(const V& x, int k, V& y) { return scale(x[0], k, y[0]) && scale(x[1], k, y[1]) && scale(x[2], k, y[2]); }
// p = a·b: the FMA's error term is zero, with the product far enough above the subnormal range
// (|p| ≥ 2^−969) for that term to be representable; 0 only from a zero factor.
bool mul(double a, double b, double& p) {
    p = a * b;
    if (!std::isfinite(p)) return false;
    if (p == 0) return a == 0 || b == 0;
    return std::fabs(p) >= 0x1p-969 && std::fma(a, b, -p) == 0;
}

constexpr int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

V permuted(const V& v, const int* p) { return {v[p[0]], v[p[1]], v[p[2]]}; }
V reflected(V v, unsigned mask) {
    for (std::size_t j = 0; j < 3; ++j)
        if (mask >> j & 1u) v[j] = -v[j];
    return v;
}

// The signed-permutation frame a byte names: axes[i] = ±e_{perm[i]}, signs from bits 3..5.
Frame signed_frame(std::uint8_t b, const int*& p) {
    p = perms[b % 6];
    Frame a{};
    for (std::size_t i = 0; i < 3; ++i) a[i][static_cast<std::size_t>(p[i])] = (b >> (3 + i) & 1) ? -1.0 : 1.0;
    return a;
}

// The aligned box a centre, axes and extents span, when it is one: every axis with a non-zero extent
// has at most one non-zero component (any value: zero or parallel axes give flat boxes), and the half
// widths and bounds are exact.
bool to_aligned(const V& c, const Frame& axes, const V& e, AlignedBox<double>& out) {
    V h{0, 0, 0};
    for (std::size_t i = 0; i < 3; ++i) {
        if (e[i] == 0) continue;
        int nonzero = 0;
        std::size_t p = 0;
        for (std::size_t j = 0; j < 3; ++j)
            if (axes[i][j] != 0) ++nonzero, p = j;
        if (nonzero == 0) continue;
        double hi = 0;
        if (nonzero > 1 || !mul(e[i], std::fabs(axes[i][p]), hi) || !add(h[p], hi, h[p])) return false;
    }
    return add(c, -h, out.min) && add(c, h, out.max);
}

// The centre and a signed-permutation frame's extents of an aligned box: (min+max)/2, (max−min)/2.
bool centre_extents(const AlignedBox<double>& b, const int* p, V& c, V& e) {
    V s, w;
    if (!add(b.min, b.max, s) || !scale(s, -1, c) || !add(b.max, -b.min, w) || !scale(w, -1, w)) return false;
    e = {w[static_cast<std::size_t>(p[0])], w[static_cast<std::size_t>(p[1])], w[static_cast<std::size_t>(p[2])]};
    return true;
}

// ---- the steps ----

enum class Op : std::uint8_t {
    permute,          // a: permutation
    reflect,          // a: mask of coordinates
    scale_lengths,    // a: k; b: for a parallelepiped, scale its axes instead of its extents
    translate,        // t
    flip_axis,        // cylinder axis → −axis
    scale_axis,       // a: k
    convert,          // a: target kind; b: frame byte
    reorder_axes,     // a: permutation
    negate_box_axes,  // a: mask
    rescale_edge,     // a: axis; b: k
    fold_extents,     // a: mask
    as_float,         // the last answer from the float query, if every field is then a float
    count
};

struct Step {
    Op op = Op::permute;
    int a = 0, b = 0;
    V t{};
};

std::string describe(const Step& s) {
    char buf[256];
    const char* kinds[] = {"aligned", "oriented", "parallelepiped", "canonical"};
    switch (s.op) {
        case Op::permute:
            std::snprintf(buf, sizeof buf, "permute coordinates (x'[i] = x[p[i]], p = {%d, %d, %d})", perms[s.a][0],
                          perms[s.a][1], perms[s.a][2]);
            break;
        case Op::reflect: std::snprintf(buf, sizeof buf, "reflect coordinates (mask %d)", s.a); break;
        case Op::scale_lengths:
            std::snprintf(buf, sizeof buf, "scale every length by 2^%d%s", s.a, s.b ? " (parallelepiped: its axes)" : "");
            break;
        case Op::translate:
            std::snprintf(buf, sizeof buf, "translate by {%a, %a, %a}", s.t[0], s.t[1], s.t[2]);
            break;
        case Op::flip_axis: std::snprintf(buf, sizeof buf, "cylinder axis -> -axis"); break;
        case Op::scale_axis: std::snprintf(buf, sizeof buf, "cylinder axis -> 2^%d axis", s.a); break;
        case Op::convert:
            std::snprintf(buf, sizeof buf, "the same box as %s (frame byte %d)", kinds[s.a], s.b);
            break;
        case Op::reorder_axes:
            std::snprintf(buf, sizeof buf, "reorder the box axes with their extents (p = {%d, %d, %d})", perms[s.a][0],
                          perms[s.a][1], perms[s.a][2]);
            break;
        case Op::negate_box_axes: std::snprintf(buf, sizeof buf, "negate box axes (mask %d)", s.a); break;
        case Op::rescale_edge:
            std::snprintf(buf, sizeof buf, "parallelepiped axis %d times 2^%d, its extent times 2^%d", s.a, s.b, -s.b);
            break;
        case Op::fold_extents:
            std::snprintf(buf, sizeof buf, "fold extents into parallelepiped axes (mask %d)", s.a);
            break;
        case Op::as_float: std::snprintf(buf, sizeof buf, "the same query in float"); break;
        case Op::count: std::snprintf(buf, sizeof buf, "?"); break;
    }
    return buf;
}

// A power of two's exponent: mostly small, sometimes across the whole range (and beyond, then rarely exact).
int exponent(boxcyl::fuzz::Decoder& d) {
    const std::uint8_t b = d.byte();
    if (b & 1) return d.i16() % 2100;
    return static_cast<std::int8_t>(b) >> 1;
}

Step decode_step(boxcyl::fuzz::Decoder& d, const Query& q) {
    Step s;
    s.op = static_cast<Op>(d.byte() % static_cast<int>(Op::count));
    switch (s.op) {
        case Op::permute:
        case Op::reorder_axes: s.a = d.byte() % 6; break;
        case Op::reflect:
        case Op::negate_box_axes:
        case Op::fold_extents: s.a = d.byte() % 7 + 1; break;
        case Op::scale_lengths: s.b = d.byte() & 1, s.a = exponent(d); break;
        case Op::scale_axis: s.a = exponent(d); break;
        case Op::translate: {
            // Most translations of arbitrary coordinates round; these are the ones that often do not.
            switch (d.byte() % 4) {
                case 0: s.t = d.vec(); break;
                case 1: s.t = -q.cyl.center; break;  // the cylinder's centre to the origin
                case 2:                              // the box's centre to the origin
                    if (q.kind == Kind::oriented) s.t = -q.oriented.center;
                    else if (q.kind == Kind::parallelepiped) s.t = -q.pp.center;
                    else if (q.kind == Kind::aligned && add(q.aligned.min, q.aligned.max, s.t) && scale(s.t, -1, s.t))
                        s.t = -s.t;
                    else s.t = {0, 0, 0};
                    break;
                default: {  // along one coordinate
                    const std::size_t j = d.byte() % 3;
                    s.t[j] = d.value();
                    break;
                }
            }
            break;
        }
        case Op::flip_axis:
        case Op::as_float:
        case Op::count: break;
        case Op::convert: s.a = d.byte() % 4, s.b = d.byte(); break;
        case Op::rescale_edge: s.a = d.byte() % 3, s.b = exponent(d); break;
    }
    return s;
}

// The query as a parallelepiped (an oriented box is one); false for the other kinds.
bool as_parallelepiped(Query& r) {
    if (r.kind == Kind::oriented) {
        r.pp = {r.oriented.center, r.oriented.axes, r.oriented.extents};
        r.kind = Kind::parallelepiped;
    }
    return r.kind == Kind::parallelepiped;
}

// The new query, when the step is exact on q; false when it would round or does not apply.
bool apply(const Step& s, const Query& q, Query& r) {
    r = q;
    Cylinder<double>& cyl = r.cyl;
    switch (s.op) {
        case Op::permute: {
            const int* p = perms[s.a];
            cyl.center = permuted(cyl.center, p), cyl.axis = permuted(cyl.axis, p);
            r.aligned.min = permuted(r.aligned.min, p), r.aligned.max = permuted(r.aligned.max, p);
            r.canonical.extents = permuted(r.canonical.extents, p);
            r.oriented.center = permuted(r.oriented.center, p);
            r.pp.center = permuted(r.pp.center, p);
            for (std::size_t i = 0; i < 3; ++i)
                r.oriented.axes[i] = permuted(r.oriented.axes[i], p), r.pp.axes[i] = permuted(r.pp.axes[i], p);
            return true;
        }
        case Op::reflect: {
            const unsigned m = static_cast<unsigned>(s.a);
            cyl.center = reflected(cyl.center, m), cyl.axis = reflected(cyl.axis, m);
            r.aligned.min = reflected(q.aligned.max, m), r.aligned.max = reflected(q.aligned.min, m);
            for (std::size_t j = 0; j < 3; ++j)
                if (!(m >> j & 1u)) r.aligned.min[j] = q.aligned.min[j], r.aligned.max[j] = q.aligned.max[j];
            r.oriented.center = reflected(r.oriented.center, m);
            r.pp.center = reflected(r.pp.center, m);
            for (std::size_t i = 0; i < 3; ++i)
                r.oriented.axes[i] = reflected(r.oriented.axes[i], m), r.pp.axes[i] = reflected(r.pp.axes[i], m);
            return true;
        }
        case Op::scale_lengths: {
            const int k = s.a;
            if (!scale(cyl.center, k, cyl.center) || !scale(cyl.radius, k, cyl.radius) || !scale(cyl.height, k, cyl.height))
                return false;
            switch (r.kind) {
                case Kind::aligned: return scale(r.aligned.min, k, r.aligned.min) && scale(r.aligned.max, k, r.aligned.max);
                case Kind::canonical: return scale(r.canonical.extents, k, r.canonical.extents);
                case Kind::oriented:
                    return scale(r.oriented.center, k, r.oriented.center) && scale(r.oriented.extents, k, r.oriented.extents);
                case Kind::parallelepiped:
                    if (!scale(r.pp.center, k, r.pp.center)) return false;
                    if (!s.b) return scale(r.pp.extents, k, r.pp.extents);
                    for (V& a : r.pp.axes)
                        if (!scale(a, k, a)) return false;
                    return true;
            }
            return false;
        }
        case Op::translate:
            if (r.kind == Kind::canonical) {
                r.aligned = {-r.canonical.extents, r.canonical.extents};
                r.kind = Kind::aligned;
            }
            if (!add(cyl.center, s.t, cyl.center)) return false;
            switch (r.kind) {
                case Kind::aligned: return add(r.aligned.min, s.t, r.aligned.min) && add(r.aligned.max, s.t, r.aligned.max);
                case Kind::oriented: return add(r.oriented.center, s.t, r.oriented.center);
                case Kind::parallelepiped: return add(r.pp.center, s.t, r.pp.center);
                case Kind::canonical: break;
            }
            return false;
        case Op::flip_axis: cyl.axis = -cyl.axis; return true;
        case Op::scale_axis: return scale(cyl.axis, s.a, cyl.axis);
        case Op::convert: {
            const Kind to = static_cast<Kind>(s.a);
            if (to == q.kind) return false;
            const int* p = nullptr;
            const Frame frame = signed_frame(static_cast<std::uint8_t>(s.b), p);
            // First as an aligned box where the target needs one.
            if (to == Kind::aligned || to == Kind::canonical) {
                if (q.kind == Kind::oriented && !to_aligned(q.oriented.center, q.oriented.axes, q.oriented.extents, r.aligned))
                    return false;
                if (q.kind == Kind::parallelepiped && !to_aligned(q.pp.center, q.pp.axes, q.pp.extents, r.aligned))
                    return false;
                if (q.kind == Kind::canonical) r.aligned = {-q.canonical.extents, q.canonical.extents};
                r.kind = Kind::aligned;
                if (to == Kind::aligned) return true;
                if (!(r.aligned.min == -r.aligned.max)) return false;
                r.canonical.extents = r.aligned.max;
                r.kind = Kind::canonical;
                return true;
            }
            // To an oriented box or a parallelepiped.
            V c, e;
            Frame axes = frame;
            if (q.kind == Kind::aligned) {
                if (!centre_extents(q.aligned, p, c, e)) return false;
            } else if (q.kind == Kind::canonical) {
                c = {0, 0, 0};
                e = permuted(q.canonical.extents, p);
            } else if (q.kind == Kind::oriented) {
                c = q.oriented.center, axes = q.oriented.axes, e = q.oriented.extents;
            } else {
                c = q.pp.center, axes = q.pp.axes, e = q.pp.extents;
            }
            if (to == Kind::oriented) r.oriented = {c, axes, e};
            else r.pp = {c, axes, e};
            r.kind = to;
            return true;
        }
        case Op::reorder_axes: {
            const int* p = perms[s.a];
            auto reorder = [p](auto& box) {
                const auto old = box;
                for (std::size_t i = 0; i < 3; ++i) {
                    const auto j = static_cast<std::size_t>(p[i]);
                    box.axes[i] = old.axes[j], box.extents[i] = old.extents[j];
                }
            };
            if (r.kind == Kind::oriented) reorder(r.oriented);
            else if (r.kind == Kind::parallelepiped) reorder(r.pp);
            else return false;
            return true;
        }
        case Op::negate_box_axes: {
            const unsigned m = static_cast<unsigned>(s.a);
            for (std::size_t i = 0; i < 3; ++i)
                if (m >> i & 1u) r.oriented.axes[i] = -r.oriented.axes[i], r.pp.axes[i] = -r.pp.axes[i];
            return r.kind == Kind::oriented || r.kind == Kind::parallelepiped;
        }
        case Op::rescale_edge: {
            if (!as_parallelepiped(r)) return false;
            const auto i = static_cast<std::size_t>(s.a);
            return scale(r.pp.axes[i], s.b, r.pp.axes[i]) && scale(r.pp.extents[i], -s.b, r.pp.extents[i]);
        }
        case Op::fold_extents: {
            if (!as_parallelepiped(r)) return false;
            for (std::size_t i = 0; i < 3; ++i) {
                if (!(static_cast<unsigned>(s.a) >> i & 1u)) continue;
                for (std::size_t j = 0; j < 3; ++j)
                    if (!mul(r.pp.extents[i], r.pp.axes[i][j], r.pp.axes[i][j])) return false;
                r.pp.extents[i] = 1;
            }
            return true;
        }
        case Op::as_float: return true;  // the query is unchanged; answer() asks it in float where it can
        case Op::count: break;
    }
    return false;
}

// ---- float ----

bool fits_float(double x) {
    return std::fabs(x) <= std::numeric_limits<float>::max() && static_cast<double>(static_cast<float>(x)) == x;
}
bool fits_float(const V& v) { return fits_float(v[0]) && fits_float(v[1]) && fits_float(v[2]); }
boxcyl::Vec3<float> to_float(const V& v) {
    return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

// The float query's answer, when every field of q is a float (then it is the same question).
bool float_answer(const Query& q, bool& got) {
    const Cylinder<double>& c = q.cyl;
    if (!fits_float(c.center) || !fits_float(c.axis) || !fits_float(c.radius) || !fits_float(c.height)) return false;
    const Cylinder<float> cyl{to_float(c.center), to_float(c.axis), static_cast<float>(c.radius), static_cast<float>(c.height)};
    auto framed = [&](const auto& b, auto box) {
        if (!fits_float(b.center) || !fits_float(b.extents) || !fits_float(b.axes[0]) || !fits_float(b.axes[1]) ||
            !fits_float(b.axes[2]))
            return false;
        box.center = to_float(b.center), box.extents = to_float(b.extents);
        for (std::size_t i = 0; i < 3; ++i) box.axes[i] = to_float(b.axes[i]);
        got = boxcyl::intersects(box, cyl);
        return true;
    };
    switch (q.kind) {
        case Kind::aligned:
            if (!fits_float(q.aligned.min) || !fits_float(q.aligned.max)) return false;
            got = boxcyl::intersects(AlignedBox<float>{to_float(q.aligned.min), to_float(q.aligned.max)}, cyl);
            return true;
        case Kind::canonical:
            if (!fits_float(q.canonical.extents)) return false;
            got = boxcyl::intersects(CanonicalBox<float>{to_float(q.canonical.extents)}, cyl);
            return true;
        case Kind::oriented: return framed(q.oriented, OrientedBox<float>{});
        case Kind::parallelepiped: return framed(q.pp, Parallelepiped<float>{});
    }
    return false;
}

// ---- reporting ----

std::string cpp(const Query& q, const char* box, const char* cyl) {
    using boxcyl::fuzz::cpp;
    std::string b;
    switch (q.kind) {
        case Kind::aligned: b = cpp(q.aligned); break;
        case Kind::oriented: b = cpp(q.oriented); break;
        case Kind::parallelepiped: b = cpp(q.pp); break;
        case Kind::canonical: b = cpp(q.canonical); break;
    }
    return std::string("    const auto ") + box + " = " + b + ";\n    const auto " + cyl + " = " + cpp(q.cyl) + ";\n";
}

// The answer after the steps: in float (then as_float is set) when a step asked for it and every
// field is a float.
bool answer_after(const Query& q, bool in_float, bool& as_float) {
    bool got = false;
    as_float = in_float && float_answer(q, got);
    return as_float ? got : answer(q);
}

// The final answer differs from the first: find the first step after which it does (the steps are
// replayed, asking after each) and print the case from the decoded query to there.
[[noreturn]] void mismatch(const Query& first, bool want, const Step* steps, int n) {
    Query q = first, next;
    bool in_float = false, as_float = false, got = want;
    int i = 0;
    while (i < n && got == want) {
        apply(steps[i], q, next);
        q = next;
        in_float |= steps[i].op == Op::as_float;
        got = answer_after(q, in_float, as_float);
        ++i;
    }
    const std::string what = got == want ? "the steps gave a different answer once and the same when replayed"
                                         : "step " + std::to_string(i) + " (" + describe(steps[i - 1]) + ")";
    std::string text = "fuzz_symmetry: " + what + " changed the exact answer from " + (want ? "true" : "false") +
                       " to " + (got ? "true" : "false") + "\n    // boxcyl::intersects(box, cyl) == " +
                       (want ? "true" : "false") + "\n" + cpp(first, "box", "cyl");
    for (int k = 0; k < i; ++k) text += "    // step " + std::to_string(k + 1) + ": " + describe(steps[k]) + "\n";
    text += std::string("    // boxcyl::intersects(box2, cyl2) == ") + (got ? "true" : "false") +
            (as_float ? " (box2, cyl2 as float)" : "") + ", must equal the above\n" + cpp(q, "box2", "cyl2");
    std::fputs(text.c_str(), stderr);
    std::abort();
}

// Totals printed at exit with BOXCYL_FUZZ_STATS=1: what the inputs/s of a run amount to.
struct Totals {
    unsigned long long inputs = 0, valid = 0, steps = 0, applied = 0, compared = 0, floats = 0;
    ~Totals() {
        if (!std::getenv("BOXCYL_FUZZ_STATS")) return;
        std::fprintf(stderr,
                     "fuzz_symmetry: %llu inputs, %llu valid; %llu steps decoded, %llu applied; %llu answers "
                     "compared with the first (%llu of them in float)\n",
                     inputs, valid, steps, applied, compared, floats);
    }
} totals;

constexpr int max_steps = 6;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace boxcyl::fuzz;
    ++totals.inputs;
    Decoder d(data, size);
    const std::uint8_t head = d.byte();
    // Mostly values of one scale (cheap exact stages); one input in eight mixes the whole double range
    // as fuzz_query's do.
    switch (head >> 2 & 7) {
        case 0: break;
        case 6: d.narrow(static_cast<std::int8_t>(d.byte())); break;
        case 7: d.narrow(d.i16() % 1100); break;
        default: d.narrow(0); break;
    }
    Query first;
    first.kind = static_cast<Kind>(head % 4);
    first.cyl = cylinder(d);
    switch (first.kind) {
        case Kind::aligned: first.aligned = aligned_box(d); break;
        case Kind::oriented: first.oriented = oriented_box(d); break;
        case Kind::parallelepiped: first.pp = parallelepiped(d); break;
        case Kind::canonical: first.canonical = canonical_box(d); break;
    }
    if (!valid(first)) return 0;
    ++totals.valid;

    // The steps compose into one query, asked once: two queries per input, whatever the steps.
    Step steps[max_steps];
    int n = 0;
    bool in_float = false;
    Query q = first, next;
    for (int decoded = 0; n < max_steps && decoded < 2 * max_steps && d.remaining(); ++decoded) {
        const Step s = decode_step(d, q);
        ++totals.steps;
        if (!apply(s, q, next) || !valid(next)) continue;
        steps[n++] = s;
        q = next;
        in_float |= s.op == Op::as_float;
    }
    if (n == 0) return 0;
    totals.applied += static_cast<unsigned>(n), ++totals.compared;
    bool as_float = false;
    const bool got = answer_after(q, in_float, as_float);
    totals.floats += as_float;
    const bool want = answer(first);
    if (got != want) mismatch(first, want, steps, n);
    return 0;
}
