// The clearance question: boxcyl::within_distance(box, cylinder, margin) — does the box come within
// distance `margin` of the cylinder? Equivalently: does the box meet the cylinder rounded by the
// margin (every point within `margin` of it: Jolt's cylinder with a convex radius, Bullet's with a
// collision margin). margin = 0 is intersects(). EXACT for the inputs as given, both solids closed:
// a distance of exactly `margin` counts. Every box kind; float inputs are widened exactly.
// Invalid input throws std::invalid_argument naming the field (validate(); the margin must be finite
// and ≥ 0); within_distance_unchecked() skips that check. Needs the exact backend (boxcyl::exact).
//
// How: a table of stages, each answering only what it proves: three probes with the exact intersection
// query (a cylinder inside the rounded one — a hit answers yes; one that holds it — a miss answers
// no) and more cylinders inside it (the shoulders: three fixed, and one at the angle of a box point
// near the rim) in that query's first two stages, the box grown by the margin against the cylinder
// (a miss answers no), certified distance bounds from an approximate closest pair
// (filtered/separation.hpp: a quick one in running-error arithmetic, then GJK's in intervals), the
// same refined in double-double (filtered/separation_refined.hpp), the rim tori's tests in interval
// arithmetic (filtered/rim.hpp), and the exact clearance decision (exact/clearance.hpp) for what remains.
// docs/clearance.md has the method and its figures.
#pragma once

#include <algorithm>    // std::max
#include <array>        // the probe table
#include <bit>          // std::bit_cast: a sum's neighbours
#include <cmath>        // std::isfinite
#include <cstdint>      // std::uint64_t
#include <limits>       // infinity
#include <optional>     // the interval stage's "undecided"
#include <stdexcept>    // std::invalid_argument
#include <type_traits>  // std::type_identity_t

#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"
#include "boxcyl/geometry/validate.hpp"
#include "boxcyl/margin.hpp"
#include "boxcyl/query.hpp"
#if defined(BOXCYL_HAS_EXACT)
#include "boxcyl/exact/clearance.hpp"
#include "boxcyl/exact/convert.hpp"
#include "boxcyl/filtered/centre_ball.hpp"
#include "boxcyl/filtered/prepared.hpp"
#include "boxcyl/filtered/rim.hpp"
#include "boxcyl/filtered/separation.hpp"
#include "boxcyl/filtered/separation_refined.hpp"
#include "boxcyl/filtered/witness_search.hpp"
#include "boxcyl/number/interval.hpp"  // next_down, next_up: a grown box's sizes
#endif

namespace boxcyl {

namespace detail::clearance {

// Doubles lo ≤ a + b ≤ hi (a, b ≥ 0 finite), equal when the sum is exact; hi = +∞ past the range.
// Holds in every rounding mode: the sum is within one ulp of a + b, and s − max(a, b) is exact by
// Sterbenz's lemma (max ≤ s ≤ 2·max), so it equals min(a, b) exactly when s is exact.
struct Bounds {
    double lo, hi;
};
// The neighbours of an inexact s > 0 are its bit pattern ∓ 1 (the pattern after DBL_MAX is +∞): no
// libm call, which was a tenth of the query's time on random pairs.
inline Bounds sum_bounds(double a, double b) {
    const double s = a + b;
    if (!std::isfinite(s)) return {std::numeric_limits<double>::max(), std::numeric_limits<double>::infinity()};
    if (s - std::max(a, b) == std::min(a, b)) return {s, s};
    const auto bits = std::bit_cast<std::uint64_t>(s);  // s > 0: an exact sum 0 + 0 returned above
    return {std::bit_cast<double>(bits - 1), std::bit_cast<double>(bits + 1)};
}

// A double ≤ m·f (m, f ≥ 0 finite): the computed product's neighbour below, or 0. The exact product
// lies between the computed one and a neighbour of it, in every rounding mode.
inline double product_below(double m, double f) {
    const double p = m * f;
    if (!(p > 0)) return 0;
    if (!std::isfinite(p)) return std::numeric_limits<double>::max();
    return std::bit_cast<double>(std::bit_cast<std::uint64_t>(p) - 1);
}

// The rounded cylinder's shoulders: it holds every cylinder of radius r + m·cos θ and half height
// h/2 + m·sin θ (a point within both is at most √((m cos θ)² + (m sin θ)²) = m from the cylinder). These
// factors (cos θ, sin θ) for θ of 30°, 45° and 60°, rounded so that cos² + sin² ≤ 1 exactly, give three
// cylinders between fat and tall: a box that cuts the rounded cylinder's rim region meets one of them.
inline constexpr std::array<std::array<double, 2>, 3> kShoulders{{{0.866, 0.4999}, {0.7071, 0.7071}, {0.4999, 0.866}}};
static_assert(0.866 * 0.866 + 0.4999 * 0.4999 < 1 && 2 * 0.7071 * 0.7071 < 1);

// The cylinders the probes ask, sharing the cylinder's centre and axis: `outer` holds the rounded
// cylinder (radius ≥ r + m, height ≥ h + 2m: a miss is a miss; left out, `outer_valid` false, when
// those sizes overflow), `fat` and `tall` lie inside it (radius ≤ r + m; height ≤ h + 2m: a hit is a
// hit).
struct Grown {
    Cylinder<double> outer, fat, tall;
    bool outer_valid;
    double m;
};
inline Grown grown(const Cylinder<double>& c, double m) {
    const Bounds r = sum_bounds(c.radius, m);
    const Bounds h = sum_bounds(c.height, 2 * m);  // 2m is exact, or +∞ (then h.hi = ∞)
    return {{c.center, c.axis, r.hi, h.hi}, {c.center, c.axis, r.lo, c.height}, {c.center, c.axis, c.radius, h.lo},
            std::isfinite(r.hi) && std::isfinite(h.hi), m};
}
// The shoulder of factors (c, s), c² + s² ≤ 1 exactly, inside the rounded cylinder: radius r + m·c and
// height h + 2m·s, rounded down (g.tall has the radius as given, g.fat the height). Shoulder k has
// kShoulders[k]'s factors.
inline Cylinder<double> shoulder(const Grown& g, double c, double s) {
    return {g.fat.center, g.fat.axis, sum_bounds(g.tall.radius, product_below(g.m, c)).lo,
            sum_bounds(g.fat.height, 2 * product_below(g.m, s)).lo};
}
inline Cylinder<double> shoulder(const Grown& g, std::size_t k) { return shoulder(g, kShoulders[k][0], kShoulders[k][1]); }

// Factors (c, s) ≥ 0 with c² + s² ≤ 1 exactly, nearly proportional to (a, b) (a point's distances
// beyond the side and beyond a cap): the shoulder through the rim at that point's angle. Any
// computation of them would do; the check makes them safe: the computed c² + s² is within a relative
// 3·2^-52 (and 2^-1073 below the normal range) of the exact one in every rounding mode, so a computed
// value ≤ 1 − 2^-40 proves the exact one below 1. nullopt when the check fails (or a NaN came in).
inline std::optional<std::array<double, 2>> shoulder_factors(double a, double b) {
    a = std::max(a, 0.0), b = std::max(b, 0.0);
    const double n = std::sqrt(a * a + b * b);
    const double c = n > 0 ? a / n * (1 - 0x1p-30) : 0, s = n > 0 ? b / n * (1 - 0x1p-30) : 0;
    if (!(c * c + s * s <= 1 - 0x1p-40)) return std::nullopt;
    return std::array<double, 2>{c, s};
}

// One probe: the exact intersection query on a cylinder (one of a Grown's, which must outlive it: the
// probes are formed twice a query, and copying the cylinders was 2% of its instructions on random pairs);
// when its answer is `decides_when`, that is the answer. `valid` is false for the outer cylinder whose
// sizes overflow (left out).
struct Probe {
    const Cylinder<double>* cylinder;
    bool decides_when;
    bool valid;
};
// The probes in the order the query asks them (the batch filter asks the same, in the same order): fat
// (a hit is a hit), outer (a miss is a miss), tall (a hit is a hit).
inline std::array<Probe, 3> probes(const Grown& g) {
    return {{{&g.fat, true, true}, {&g.outer, false, g.outer_valid}, {&g.tall, true, true}}};
}

// Stage 0's cylinders: the three probes, then the shoulders (a hit is a hit). The shoulders get stage
// 0 and its search, no whole query: what those leave in the rim region, the distance bounds answer.
inline constexpr std::size_t kStage0Cylinders = 3 + kShoulders.size();

#if defined(BOXCYL_HAS_EXACT)
// A box that holds every point within m of `b` (b ⊕ ball(m)): if it misses the cylinder, the box is
// farther than m from it. Its sizes are rounded outwards; nullopt when they overflow. An oriented box's
// axes are orthonormal within 1e-4 (validate.hpp), so a displacement of length m has coordinates of at
// most m/σ_min ≤ 1.00015·m along them: its extents grow by a double above m·(1 + 2^-11).
// Parallelepipeds are left out (nullopt): their axes may be far from orthogonal. The exact result of
// a rounded operation lies between the computed one's neighbours (number/interval.hpp's next_down,
// next_up), in every rounding mode.
inline std::optional<AlignedBox<double>> grown_box(const AlignedBox<double>& b, double m) {
    AlignedBox<double> g = b;
    for (int i = 0; i < 3; ++i) {
        g.min[i] = next_down(b.min[i] - m);
        g.max[i] = next_up(b.max[i] + m);
        if (!std::isfinite(g.min[i]) || !std::isfinite(g.max[i])) return std::nullopt;
    }
    return g;
}
template <class Box>  // CanonicalBox, OrientedBox: centre and axes kept, extents grown
std::optional<Box> grown_box(const Box& b, double m) {
    if constexpr (std::is_same_v<Box, Parallelepiped<double>>) {
        return std::nullopt;
    } else {
        // The computed product's neighbour above is at least the exact product, m·(1 + 2^-11), in every
        // rounding mode and below the normal range too.
        const double grow = std::is_same_v<Box, OrientedBox<double>> ? next_up(m * (1 + 0x1p-11)) : m;
        if (!std::isfinite(grow)) return std::nullopt;
        Box g = b;
        for (int i = 0; i < 3; ++i) {
            g.extents[i] = sum_bounds(b.extents[i], grow).hi;
            if (!std::isfinite(g.extents[i])) return std::nullopt;
        }
        return g;
    }
}

// How close (relatively) the quick bounds' pair must lie to the margin for the refined bounds to start
// from it, skipping the grown box, the shoulders and GJK's bounds. Those decide hardly any pair this
// close (intervals resolve about 2^-45 of it, and the quick bounds, which resolve as much, have just
// failed), and the refined stage's Newton steps still converge from such a start: on bench_clearance's
// at-margin set, 2^-10 answers the same pairs in the same stages as 2^-20 did, for about 5% less work;
// from 2^-4, two pairs fell through to the exact stage.
inline constexpr double kNearMargin = 0x1p-10;

// One query on its way through the stages, with what earlier stages proved for later ones.
template <class Box>
struct Pair {
    // A constructor, not an aggregate: aggregate initialisation cleared the whole Pair first (half a
    // kilobyte, `rep stos`), a tenth of a query's time on random pairs.
    Pair(const Box& b, const Cylinder<double>& c, double margin) : box(b), cyl(c), m(margin), g(grown(c, margin)) {}

    const Box& box;
    const Cylinder<double>& cyl;
    double m;
    Grown g;
    // The distance bounds' search, for the refined stage (constructed there: it is most of a Pair).
    std::optional<filtered::separation::Approximate> search;
    filtered::rim::Proved proved{};
    std::array<std::optional<bool>, kStage0Cylinders> stage0{};  // each answer stage 0 or the search gave
    // The quick bounds' pair is within kNearMargin of the margin: the pair is most likely at it, where
    // the grown box, the shoulders and GJK's bounds cost more than they decide (they are skipped).
    bool near_margin = false;
};

// A stage answers (true: within, false: not) or passes (nullopt) to the next.
template <class Box>
using Stage = std::optional<bool> (*)(Pair<Box>&);

// The shoulders' verdicts (after the probes': few queries get here), on the probes' problem. Not
// inlined: as part of the probes' loop, it made the common path slower.
template <bool all, class Box>
[[gnu::noinline]] bool shoulder_verdicts(filtered::Prepared<Box>& prep, const Grown& g,
                                         std::array<std::optional<bool>, kStage0Cylinders>& verdicts) {
    bool hit = false;
    for (std::size_t k = 0; k < kShoulders.size(); ++k) {
        const Cylinder<double> s = shoulder(g, k);
        const Cylinder<double> c{prep.cyl.center, prep.cyl.axis, s.radius, s.height};
        filtered::semi_static::set_sizes_of<Box>(prep.p, c.radius, c.height);
        verdicts[3 + k] = filtered::semi_static::decide(prep.p, prep.box, c);
        hit |= verdicts[3 + k] == true;
        if (!all && hit) return true;
    }
    return hit;
}

// The rim witnesses, for a box that cuts the rounded cylinder's rim region where no fixed shoulder
// shows it: Q1, the box point nearest the rim point nearest the box centre, and Q2, the box point
// nearest the cylinder point nearest Q1 (a step of alternating projections). Each is tested against
// the shoulder at its own angle from the rim (shoulder_factors), which holds it when it is within m of
// the cylinder with a little to spare. Box points exactly, as stage 0's witnesses are: clamped in the
// box's coordinates, an aligned box's in world coordinates (filtered/semi_static.hpp, witness_offset);
// the search itself is approximate, its test is stage 0's. The shoulder that holds one, or nullopt.
template <class Box>
std::optional<Cylinder<double>> rim_witness_shoulder(filtered::Prepared<Box>& prep, const Grown& g) {
    filtered::semi_static::Problem& p = prep.p;
    const Vec3<double>& d = p.d;
    const double r = g.tall.radius, h = 0.5 * g.fat.height;
    // The box point nearest C + z, as its offset from C.
    auto box_offset = [&](const Vec3<double>& z) {
        Vec3<double> v;
        for (int i = 0; i < 3; ++i) {
            if constexpr (std::is_same_v<Box, AlignedBox<double>>)
                v[i] = filtered::semi_static::clamp_to(prep.cyl.center[i] + z[i], prep.box.min[i], prep.box.max[i]) -
                       prep.cyl.center[i];
            else
                v[i] = filtered::semi_static::clamp_to(p.c[i] + z[i], -p.e[i], p.e[i]) - p.c[i];
        }
        return v;
    };
    // An offset w's height along the axis and its part across it.
    auto split = [&d](const Vec3<double>& w) {
        const double t = dot(d, w);
        const Vec3<double> across{w[0] - t * d[0], w[1] - t * d[1], w[2] - t * d[2]};
        return std::pair{t, across};
    };
    // Whether box point C + v lies in the shoulder at its angle: the shoulder when it does.
    auto holds = [&](const Vec3<double>& v) -> std::optional<Cylinder<double>> {
        const auto [t, across] = split(v);
        const std::optional<std::array<double, 2>> f =
            shoulder_factors(std::sqrt(dot(across, across)) - r, std::abs(t) - h);
        if (!f) return std::nullopt;
        const Cylinder<double> sh = shoulder(g, (*f)[0], (*f)[1]);
        filtered::semi_static::set_sizes_of<Box>(p, sh.radius, sh.height);
        if (!filtered::semi_static::box_point_inside(p, filtered::semi_static::kappas_of<Box>, v)) return std::nullopt;
        return sh;
    };
    const auto [t0, across0] = split(Vec3<double>{-p.c[0], -p.c[1], -p.c[2]});  // the box centre
    const double l0 = std::sqrt(dot(across0, across0));
    if (!(l0 > 0)) return std::nullopt;  // on the axis (or a NaN): no nearest rim point
    const double to_rim = r / l0, to_cap = t0 >= 0 ? h : -h;
    const Vec3<double> v1 = box_offset({to_cap * d[0] + to_rim * across0[0], to_cap * d[1] + to_rim * across0[1],
                                        to_cap * d[2] + to_rim * across0[2]});
    if (std::optional<Cylinder<double>> sh = holds(v1)) return sh;
    const auto [t1, across1] = split(v1);
    const double l1 = std::sqrt(dot(across1, across1)), inward = l1 > r ? r / l1 : 1.0;
    const double t = filtered::semi_static::clamp_to(t1, -h, h);
    return holds(box_offset({t * d[0] + inward * across1[0], t * d[1] + inward * across1[1],
                             t * d[2] + inward * across1[2]}));
}

// Stage 0 of the exact intersection query (filtered/semi_static.hpp) on stage 0's cylinders at once:
// one problem, computed for the outer cylinder — the largest, so its length scale bounds the others —
// with each cylinder's sizes set in turn (the reduction to the box's frame, most of stage 0's cost, is
// shared). Each cylinder's verdict, probes() then, with `shoulders`, the fixed shoulders (nullopt:
// undecided, or not asked: the outer one left out, a query that stage 0 takes only rescaled, a
// parallelepiped), then the rim witnesses' shoulder when one holds a witness (a hit); unless `all`, the
// probes' tests run interleaved (probes_interleaved, below) and stop at the first answer, and the outer
// probe, whose hit decides nothing, gets stage 0's misses alone (its hit tests would only cost). The
// query asks the fixed shoulders later (shoulders()): the quick bounds answer most pairs they would, and
// the others for less than their three tests cost.
struct Stage0Verdicts {
    std::array<std::optional<bool>, kStage0Cylinders> cylinders{};
    std::optional<Cylinder<double>> rim_shoulder;
};

// Stage 0 of the three probes interleaved, cheapest certificate first, where the probes' own order
// would run one probe's whole test before the next's: the outer probe's misses along the face normals
// and the axis; the fat and tall probes' hits at the cylinder centre and the first witness; the outer
// probe's misses along d × E_i; then for the fat and the tall probe, its misses and its remaining hits.
// A pair farther than the margin then costs one miss test, not the fat probe's tests first; a pair
// within it one or two hit tests. Each test is stage 0's own for its probe's sizes, so each answer is
// that probe's (sound in every rounding mode), and the verdicts left are those of stage 0 on each probe
// (semi_static::decide finds a miss or a hit, never both). Returns the verdicts' answer: false (outer
// misses), true (fat or tall holds a box point), or nullopt.
template <class Box>
std::optional<bool> probes_interleaved(filtered::Prepared<Box>& prep, const Grown& g,
                                       std::array<std::optional<bool>, kStage0Cylinders>& verdicts) {
    namespace ss = filtered::semi_static;
    ss::Problem& p = prep.p;
    const ss::Kappas& k = ss::kappas_of<Box>;
    auto sizes = [&](const Cylinder<double>& c) { ss::set_sizes_of<Box>(p, c.radius, c.height); };
    // semi_static::decide's hit tests in its two parts, on a probe's sizes (the witnesses hang on the
    // centre alone, which the probes share).
    auto first_hits = [&](const Cylinder<double>& c) {
        sizes(c);
        return ss::first_hits(p, prep.box, prep.cyl);
    };
    auto other_hits = [&](const Cylinder<double>& c) {
        sizes(c);
        return ss::other_hits(p, prep.box, prep.cyl);
    };
    constexpr std::size_t fat = 0, outer = 1, tall = 2;
    auto answer = [&](std::size_t probe, bool v) {
        verdicts[probe] = v;
        return std::optional<bool>(v);
    };
    sizes(g.outer);
    if (ss::faces_or_axis_separate(p, k)) return answer(outer, false);
    if (first_hits(g.fat)) return answer(fat, true);
    if (first_hits(g.tall)) return answer(tall, true);
    sizes(g.outer);
    if (ss::edges_separate(p, k)) return answer(outer, false);
    // The fat and tall probes' misses before their remaining hit tests (divisions and a square root),
    // as in semi_static::decide: a proved miss skips them (most pairs at the margin miss one of them).
    for (const std::size_t probe : {fat, tall}) {
        const Cylinder<double>& c = probe == fat ? g.fat : g.tall;
        sizes(c);
        verdicts[probe] = ss::decide_miss<Box>(p);
        if (!verdicts[probe] && other_hits(c)) return answer(probe, true);
    }
    return std::nullopt;
}

template <bool all, class Box>
Stage0Verdicts stage0_verdicts(const Box& box, const Grown& g, bool shoulders = true) {
    Stage0Verdicts verdicts;
#if !(defined(BOXCYL_FORCE_EXACT) && BOXCYL_FORCE_EXACT)
    if constexpr (!std::is_same_v<Box, Parallelepiped<double>>) {  // a parallelepiped's query has no stage 0
        const std::array<Probe, 3> ps = probes(g);
        if (!ps[1].valid) return verdicts;
        filtered::Prepared<Box> prep(box, *ps[1].cylinder);
        if (!prep.in_range || prep.rescaled()) return verdicts;
        if constexpr (!all) {
            if (probes_interleaved(prep, g, verdicts.cylinders)) return verdicts;
        } else {
            for (std::size_t k = 0; k < ps.size(); ++k) {
                const Cylinder<double> c{prep.cyl.center, prep.cyl.axis, ps[k].cylinder->radius, ps[k].cylinder->height};
                filtered::semi_static::set_sizes_of<Box>(prep.p, c.radius, c.height);
                verdicts.cylinders[k] = filtered::semi_static::decide(prep.p, prep.box, c);
            }
        }
        if (shoulders && shoulder_verdicts<all>(prep, g, verdicts.cylinders) && !all) return verdicts;
        verdicts.rim_shoulder = rim_witness_shoulder(prep, g);
    }
#endif
    return verdicts;
}
// A cylinder that stage 0 answered with its deciding answer is the answer; a probe answered otherwise
// is skipped below; one left undecided asks the whole query.
template <class Box>
std::optional<bool> probes_stage0(Pair<Box>& q) {
    const Stage0Verdicts v = stage0_verdicts<false>(q.box, q.g, false);
    q.stage0 = v.cylinders;
    const std::array<Probe, 3> ps = probes(q.g);
    for (std::size_t k = 0; k < ps.size(); ++k)
        if (q.stage0[k] == ps[k].decides_when) return ps[k].decides_when;
    if (v.rim_shoulder) return true;
    return std::nullopt;
}
// The fixed shoulders, on the probes' problem again: stage 0 of the exact intersection query on each,
// then stage 0b (filtered/witness_search.hpp: a search in double for a point or a direction that stage
// 0's certificates then prove) on each it leaves undecided: hits in the rim region that no fixed
// witness shows. Sound in every rounding mode, as in the intersection query. (The probes' own whole
// queries search too.)
template <class Box>
std::optional<bool> shoulders(Pair<Box>& q) {
#if !(defined(BOXCYL_FORCE_EXACT) && BOXCYL_FORCE_EXACT)
    if constexpr (!std::is_same_v<Box, Parallelepiped<double>>) {
        if (!q.g.outer_valid || q.near_margin) return std::nullopt;
        filtered::Prepared<Box> prep(q.box, q.g.outer);
        if (!prep.in_range || prep.rescaled()) return std::nullopt;
        if (shoulder_verdicts<false>(prep, q.g, q.stage0)) return true;
        for (std::size_t k = 0; k < kShoulders.size(); ++k) {
            std::optional<bool>& verdict = q.stage0[3 + k];
            if (verdict) continue;
            const Cylinder<double> s = shoulder(q.g, k);
            const Cylinder<double> c{prep.cyl.center, prep.cyl.axis, s.radius, s.height};
            filtered::semi_static::set_sizes_of<Box>(prep.p, c.radius, c.height);
            verdict = filtered::witness_search::decide(prep.p, prep.box, c);
            if (verdict == true) return true;
        }
    }
#endif
    return std::nullopt;
}
// The box grown by the margin (grown_box) against the cylinder as given, in stage 0 of the exact
// intersection query: a miss is a miss. Its face tests are the rounded cylinder's own (the support of
// box ⊕ ball(m) along a unit normal is the box's plus m), where the outer probe's corners reach up to
// m·(√2 − 1) beyond the rim: the misses of a box face near the rim that the probes leave. (Its
// witness search as well decided a few more on random pairs, and cost more at the margin than it saved.)
template <class Box>
std::optional<bool> grown_box_misses(Pair<Box>& q) {
#if !(defined(BOXCYL_FORCE_EXACT) && BOXCYL_FORCE_EXACT)
    if constexpr (!std::is_same_v<Box, Parallelepiped<double>>) {
        if (q.near_margin) return std::nullopt;
        const std::optional<Box> g = grown_box(q.box, q.m);
        if (!g) return std::nullopt;
        filtered::Prepared<Box> prep(*g, q.cyl);
        if (!prep.in_range || prep.rescaled()) return std::nullopt;
        const std::optional<bool> hit = filtered::semi_static::decide(prep.p, prep.box, prep.cyl);
        if (hit == false) return false;
    }
#endif
    return std::nullopt;
}
// The doubles a search in double starts from: the box's centre and half axes and the unit axis,
// rounded, without the interval enclosures that the distance bounds are proved on (the search needs no
// proof; the refined bounds prove what it finds). The axis is scaled exactly by a power of two first, so
// that |D|² neither overflows nor underflows.
template <class Box>
filtered::separation::Approximate search_start(const Box& box, const Cylinder<double>& cyl) {
    namespace sep = filtered::separation;
    const sep::BoundedBox b = sep::bounded_box(box);
    sep::Approximate a;
    a.box.c = {b.center[0].value(), b.center[1].value(), b.center[2].value()};
    for (std::size_t i = 0; i < 3; ++i) a.box.half[i] = {b.half[i][0].value(), b.half[i][1].value(), b.half[i][2].value()};
    const Vec3<double> D = filtered::rim::scaled_axis(cyl.axis);
    const double len = std::sqrt(dot(D, D));
    a.u = sep::without_tiny_components({D[0] / len, D[1] / len, D[2] / len});
    return a;
}
// An approximate closest pair from doubles (distance.hpp's start, signed_distance.hpp's witnesses): GJK
// from search_start. `decide_at` and `rel_gap` are GJK's (algo/gjk.hpp).
template <class Box>
filtered::separation::Approximate search_in_double(const Box& box, const Cylinder<double>& cyl, double decide_at,
                                                   double rel_gap) {
    filtered::separation::Approximate a = search_start(box, cyl);
    a.closest = algo::gjk::closest(a.box, {cyl.center, a.u, cyl.radius, 0.5 * cyl.height}, decide_at, 48, rel_gap);
    filtered::separation::detail::complete(a, cyl);
    return a;
}
// The same from alternating projections (separation.hpp's projected(): a third of GJK's cost), for a
// separated pair.
template <class Box>
filtered::separation::Approximate projected_search(const Box& box, const Cylinder<double>& cyl) {
    filtered::separation::Approximate a = search_start(box, cyl);
    filtered::separation::projected(a, cyl);
    return a;
}
// Probe k of probes(), unless stage 0 or the search answered it.
template <class Box, std::size_t k>
std::optional<bool> probe(Pair<Box>& q) {
    const Probe p = probes(q.g)[k];
    if (q.stage0[k] || !p.valid) return std::nullopt;
    if (intersects_unchecked(q.box, *p.cylinder) == p.decides_when) return p.decides_when;
    return std::nullopt;
}
// Certified distance bounds from an approximate closest pair (filtered/separation.hpp). Where the quick
// bounds' pair lies within kNearMargin of the margin, the refined bounds start from that pair
// (quick_separation keeps it) and this stage is skipped.
template <class Box>
std::optional<bool> separation(Pair<Box>& q) {
    if (q.near_margin) return std::nullopt;
    const filtered::separation::Bounds b = filtered::separation::bounds(q.box, q.cyl, q.m, &q.search.emplace());
    if (b.upper <= q.m) return true;
    if (b.lower > q.m) return false;
    return std::nullopt;
}
// Certified distance bounds (filtered/separation.hpp) from a quick search near the rim, in running-error
// arithmetic (projected_bounds): most boxes in the rim region that stage 0 leaves, at a fraction of the
// cost of GJK's bounds below.
template <class Box>
std::optional<bool> quick_separation(Pair<Box>& q) {
    filtered::separation::Approximate a;
    const filtered::separation::Bounds b = filtered::separation::projected_bounds(q.box, q.cyl, q.m, &a);
    if (b.upper <= q.m) return true;
    if (b.lower > q.m) return false;
    q.near_margin = std::abs(a.upper - q.m) <= kNearMargin * q.m;
    if (q.near_margin) {
        // The refined bounds' start, with the best of the common directions for the lower bound: Newton's
        // steps from it do as well as from GJK's pair, which cost 0.7 µs more on the at-margin pairs.
        filtered::separation::detail::complete(a, q.cyl);
        q.search = a;
    }
    return std::nullopt;
}
// The box's centre and a ball about it (filtered/centre_ball.hpp): a box near the rim tori that stage
// 0's cylinders leave often has its centre within the margin, or lies beyond it as a whole ball, which
// a few dozen flops prove where the quick bounds' search costs most of a microsecond.
template <class Box>
std::optional<bool> centre_ball(Pair<Box>& q) {
    return filtered::centre_ball::decide(q.box, q.cyl, q.m);
}
// The same bounds after Newton refinement, in double-double (filtered/separation_refined.hpp): the
// pairs within rounding of the margin.
template <class Box>
std::optional<bool> refined_separation(Pair<Box>& q) {
    if (!q.search) return std::nullopt;
    return filtered::separation::refined_within(q.box, q.cyl, q.m, *q.search);
}
// Whether the box misses the exact fat and tall cylinders, proved by missing them with their sizes
// rounded up.
template <class Box>
bool misses_fat_and_tall(const Pair<Box>& q) {
    const Bounds r = sum_bounds(q.cyl.radius, q.m);
    const Bounds h = sum_bounds(q.cyl.height, 2 * q.m);
    return std::isfinite(r.hi) && std::isfinite(h.hi) &&
           !intersects_unchecked(q.box, Cylinder<double>{q.cyl.center, q.cyl.axis, r.hi, q.cyl.height}) &&
           !intersects_unchecked(q.box, Cylinder<double>{q.cyl.center, q.cyl.axis, q.cyl.radius, h.hi});
}
// The rim tori in intervals (filtered/rim.hpp). Its "no" needs the box to miss the exact fat and tall
// cylinders: proved by missing them with their sizes rounded up. What it proves far, the exact stage
// skips.
template <class Box>
std::optional<bool> rim(Pair<Box>& q) {
    const std::optional<bool> r = filtered::rim::decide(q.box, q.cyl, q.m, &q.proved);
    if (r == true) return true;
    if (r == false && misses_fat_and_tall(q)) return false;
    return std::nullopt;
}
// The exact decision (exact/clearance.hpp): always answers. Without a proof that the box misses fat
// and tall it asks them itself, and skips only the edges and facets proved far.
template <class Box>
std::optional<bool> exact_stage(Pair<Box>& q) {
    const exact::clearance::Known known{misses_fat_and_tall(q), q.proved.edge_far, q.proved.facet_far};
    return exact::clearance::within(exact::clearance::as_parallelepiped(to_exact(q.box)), to_exact(q.cyl),
                                    to_rational(q.m), known);
}

// The order is policy: on random pairs most are decided by the probes' stage 0 (the fat cylinder's hit
// or the outer one's miss, certified in plain double, or a rim witness's hit); of the rest, near the
// rim, the centre ball decides many for a few dozen flops and the quick bounds nearly all others, a
// fraction of the cost of the grown box, the shoulders and GJK's bounds that follow. A pair whose quick
// search lands within kNearMargin of the margin skips the grown box, the shoulders and GJK
// (near_margin): the refined bounds start from its pair. They come before the
// probes' whole queries: at the margin they decide the pairs whose distance is within rounding of it
// but not equal (most contacts with the side or a cap among them), where the probes' queries, on
// shapes within rounding of touching, cost as much and decide fewer. The probes then decide the
// side and cap contacts at exactly the margin; the rim tests and the exact decision what is left:
// rim contacts at exactly the margin, and queries in a directed rounding mode that the earlier stages
// leave (docs/clearance.md gives the measured shares).
template <class Box>
inline constexpr std::array<Stage<Box>, 12> stages{
    &probes_stage0<Box>, &centre_ball<Box>,        &quick_separation<Box>, &grown_box_misses<Box>,
    &shoulders<Box>,     &separation<Box>,         &refined_separation<Box>, &probe<Box, 0>,
    &probe<Box, 1>,      &probe<Box, 2>,           &rim<Box>,              &exact_stage<Box>};
inline constexpr std::array<const char*, 12> stage_names{
    "probes' stage 0", "centre ball", "quick bounds", "grown box",   "shoulders",     "distance bounds",
    "refined bounds",  "fat probe",   "outer probe",  "tall probe",  "rim intervals", "exact"};

// The index of the stage that answers, for the benchmark's per-stage shares (margin > 0).
template <class Box>
std::size_t answering_stage(const Box& box, const Cylinder<double>& cyl, double m) {
    Pair<Box> q(box, cyl, m);
    for (std::size_t i = 0; i < stages<Box>.size(); ++i)
        if (stages<Box>[i](q)) return i;
    return stages<Box>.size();
}

template <class Box>
bool within(const Box& box, const Cylinder<double>& cyl, double m) {
    if (m == 0) return intersects_unchecked(box, cyl);
    Pair<Box> q(box, cyl, m);
    for (const Stage<Box> stage : stages<Box>)
        if (const std::optional<bool> answer = stage(q)) return *answer;
    return false;  // not reached: the exact stage always answers
}
#endif

}  // namespace detail::clearance

// Whether dist(box, cyl) ≤ margin, exactly. Preconditions: valid box and cylinder, margin finite ≥ 0.
template <class Box, class T>
bool within_distance_unchecked(const Box& box, const Cylinder<T>& cyl, std::type_identity_t<T> margin) {
#if defined(BOXCYL_HAS_EXACT)
    if constexpr (std::is_same_v<T, double>)
        return detail::clearance::within(box, cyl, margin);
    else
        return detail::clearance::within(detail::cast<double>(box), detail::cast<double>(cyl),
                                         static_cast<double>(margin));
#else
    static_assert(detail::dependent_false<T>, "boxcyl::within_distance is exact and needs the exact backend: "
                                              "link boxcyl::exact (GMP, FLINT)");
    return false;
#endif
}

template <class Box, class T>
bool within_distance(const Box& box, const Cylinder<T>& cyl, std::type_identity_t<T> margin) {
    detail::require_valid(box, cyl);
    if (!is_valid_margin(margin)) [[unlikely]]
        throw std::invalid_argument(validate_margin(margin).message());
    return within_distance_unchecked(box, cyl, margin);
}

}  // namespace boxcyl
