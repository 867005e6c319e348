// The exact default's pipeline as data: for each box kind a table of rows — name, rounding modes, when
// it applies, certifier — walked in order until one decides; the last row is the exact stage, which
// always does. docs/pipeline.md describes every row by these names.
//
// A certifier is one function of the prepared query (filtered/prepared.hpp) with one signature,
// returning a hit, a miss or nothing; it knows nothing of the order. Every certificate it accepts is
// proved for the inputs as given, in the rounding modes its row lists. "When" is either a fact that a
// certifier needs (stage 0's range, a flat shape) or a speed hint, marked `hint`: a hint only orders
// the rows — whatever it says, some later row (at worst the exact stage) answers exactly.
#pragma once

#include <chrono>     // Stats' timing
#include <cstdint>    // std::uint8_t
#include <optional>   // the verdicts
#include <tuple>      // the tables
#include <type_traits>  // std::is_same_v
#include <utility>    // std::index_sequence

#include "boxcyl/exact/answer.hpp"
#include "boxcyl/exact/point.hpp"
#include "boxcyl/filtered/enclosed.hpp"
#include "boxcyl/filtered/parallelepiped.hpp"
#include "boxcyl/filtered/prepared.hpp"
#include "boxcyl/filtered/sandwich.hpp"
#include "boxcyl/filtered/semi_static.hpp"
#include "boxcyl/filtered/slabs.hpp"
#include "boxcyl/filtered/stats.hpp"
#include "boxcyl/filtered/witness_search.hpp"
#include "boxcyl/number/bounded.hpp"
#include "boxcyl/number/double_double.hpp"
#include "boxcyl/number/interval.hpp"

namespace boxcyl::filtered {

// A certifier's verdict: true (the solids meet), false (they do not), nullopt (not certified).
using Verdict = std::optional<bool>;

// The rounding modes a row runs in. Double-double arithmetic is exact only in round to nearest; the
// rows on it are replaced by rows on outward-rounded intervals in the other modes.
enum class Modes : std::uint8_t { any, nearest, directed };

template <class When, class Certify>
struct Row {
    RowId id;
    Modes modes;
    When when;         // bool(Prepared&): the row applies
    Certify certify;   // Verdict(Prepared&)
};
template <class When, class Certify>
Row(RowId, Modes, When, Certify) -> Row<When, Certify>;

// ---- Conditions ----

inline constexpr auto always = [](auto&) { return true; };
inline constexpr auto in_range = [](auto& q) { return q.in_range; };
inline constexpr auto flat_two_scale_axis = [](auto& q) { return q.facts().flat && q.facts().two_scale_axis; };
inline constexpr auto flat_in_range = [](auto& q) { return q.facts().flat && q.in_range; };
// The box kind of a prepared query.
template <class Q>
using box_of = typename std::remove_cvref_t<Q>::box_type;

inline constexpr auto turned = [](auto& q) {
    if constexpr (is_oriented<box_of<decltype(q)>>) return q.facts().turned;
    return false;
};
// A flat shape whose axis is of one scale (what the linear inequalities leave there hangs on the tiny
// components, docs/robustness/enclosures.md), not a turned frame (its clipped row ran already).
inline constexpr auto flat_one_scale_axis = [](auto& q) {
    const auto& f = q.facts();
    return f.flat && !f.two_scale_axis && !turned(q);
};
// The tiny sizes' row, unless it ran right after the clipped row (a turned frame in round to nearest).
inline constexpr auto not_asked_early = [](auto& q) { return !(turned(q) && q.nearest()); };
// Hints.
inline constexpr auto hint_narrow = [](auto& q) { return exact::integer::narrow(q.box, q.cyl); };
inline constexpr auto hint_narrow_two_scale = [](auto& q) { return exact::integer::narrow_two_scale(q.box, q.cyl); };
// Near touching, stage 0b's searched certificates need a margin that is not there.
inline constexpr auto hint_search = [](auto& q) { return q.in_range && !q.near(); };
// Linear inequalities on Bounded decide most queries that are not near touching at a third of the
// middle stage's cost; near touching, and for turned frames (whose widened problem fails there at
// several µs), they are left out.
inline constexpr auto hint_not_near = [](auto& q) { return !q.near() && !turned(q) && !q.looks_near(); };

// ---- Certifiers ----

// Each certifier checks what it needs (stage 0's range), so that every row can be tested alone.
inline constexpr auto semi_static_tests = [](auto& q) BOXCYL_FORCE_INLINE -> Verdict {  // the hot path
    if (!q.in_range) return std::nullopt;
    return semi_static::decide(q.p, q.box, q.cyl);
};
inline constexpr auto searched = [](auto& q) -> Verdict {
    if (!q.in_range) return std::nullopt;
    return witness_search::decide(q.p, q.box, q.cyl);
};
inline constexpr auto thorough = [](auto& q) -> Verdict {
    if (q.in_range && witness_search::certain_hit(q.p, q.box, q.cyl)) return true;
    return std::nullopt;
};
template <class N>
inline constexpr auto inequalities = [](auto& q) -> Verdict { return enclosed::inequalities<N>(q); };
inline constexpr auto clipped_dd = [](auto& q) -> Verdict {
    return enclosed::clipped_candidates(q.box, q.cyl, q.facts().k);
};
// A pair asked of the pipeline without its last row, the exact stage (which the given query would
// reach next at no more cost), as a call (defined below the runner): its answer, nullopt where only
// the exact stage would give it, and whether one of the exact tiers for narrow inputs gave it.
struct PairAnswer {
    Verdict intersect;
    bool exact_used;
};
template <class Box>
PairAnswer sub_query(const Box& box, const Cylinder<double>& cyl);
// Tiny sizes: the answers of the pairs with them shrunk to 0 and grown to τ (filtered/sandwich.hpp).
// The query counts as answered by the exact stage when a pair was.
inline constexpr auto sandwiched = [](auto& q) -> Verdict {
    using Box = box_of<decltype(q)>;
    return sandwich::decide(
        q.box, q.cyl, q.facts().scale, [&q] { return plain_answer(q.box, q.cyl); },
        [&q](const Box& b, const Cylinder<double>& c) {
            const PairAnswer a = sub_query(b, c);
            q.exact_in_pairs |= a.exact_used;
            return a.intersect;
        });
};
template <exact::Tier tier>
inline constexpr auto exact_stage = [](auto& q) -> Verdict { return exact::answer(q.box, q.cyl, tier); };
// Narrow inputs: exact decisions in plain double first (exact/point.hpp: a few dozen operations) — a
// cylinder along a coordinate axis beside an aligned box decided whole, else one box point tested, where
// such shapes mostly touch exactly on a cap, a side or a rim — then the exact stage in fixed-width
// integers.
inline constexpr auto exact_narrow_stage = [](auto& q) -> Verdict {
    if (const Verdict v = exact::decide_along_an_axis(q.box, q.cyl)) return v;
    if (exact::hit_at_a_point(q.box, q.cyl)) return true;
    return exact::answer(q.box, q.cyl, exact::Tier::fixed);
};

// Parallelepipeds.
inline constexpr auto pp_candidates = [](auto& q) -> Verdict {
    return parallelepiped::certify(q.bounded(), q.plain, q.fixed);
};
template <class N>
inline constexpr auto pp_frame = [](auto& q) -> Verdict {
    if constexpr (std::is_same_v<N, Bounded>) return parallelepiped::frame_stage(q.bounded(), q.scale());
    else return parallelepiped::frame_stage(q.interval(), q.scale());
};
inline constexpr auto pp_search = [](auto& q) -> Verdict {
    for (const auto& [shrink, steps] : parallelepiped::search_phases) {
        parallelepiped::Candidates phase;
        parallelepiped::searched_candidates(q.approx, shrink, phase, steps);
        if (const Verdict r = parallelepiped::certify(q.bounded(), q.plain, phase)) return r;
        q.searched.append(phase);
    }
    return std::nullopt;
};
inline constexpr auto pp_candidates_interval = [](auto& q) -> Verdict {
    if (const Verdict r = parallelepiped::certify(q.interval(), q.plain, q.fixed)) return r;
    return parallelepiped::certify(q.interval(), q.plain, q.searched);
};
inline constexpr auto pp_clipped = [](auto& q) -> Verdict {
    return enclosed::clipped_candidates(q.box, q.cyl, scale_exponent(q.scale()));
};

// ---- The tables ----

using R = RowId;
using M = Modes;

// The query as given, before anything costly is prepared: the rows whose certifiers read the caller's
// box and cylinder alone, so that the queries they decide pay for nothing else. They run where the
// prepared query would cost more than stage 0 itself — off stage 0's direct path (Prepared: shapes far
// from the origin for their size, moved exactly first; beyond stage 0's range of scales, rescaled
// first; an axis it cannot use) — and for every parallelepiped, whose rows all cost more. On the
// direct path stage 0's own tests decide the same queries at about the same cost.
template <class Box>
struct Given {
    using box_type = Box;
    const Box& box;
    const Cylinder<double>& cyl;
    bool nearest() const { return boxcyl::detail::round_to_nearest(); }
};
inline constexpr auto slab_tests = [](const auto& q) -> Verdict { return slabs::decide(q.box, q.cyl); };
inline constexpr std::tuple given_schedule{
    Row{R::slabs, M::any, always, slab_tests},
};

// Aligned, canonical and oriented boxes. Tiny sizes come last before the exact stage: earlier, their
// pairs cost more than the rows after them on the queries those decide (the narrow two-scale inputs of
// exact_series_narrow among them). Turned frames are the exception: where the clipped row fails on
// them, a tiny size is what it failed on; the double-double rows after it fail there too, at 20 to
// 30 µs, and the pairs decide (on the magnitudes boundary set, all 42 such queries, in about 10 µs
// each all told). The convex-hull method on double-double enclosures, once the next row for turned
// frames, decided none of 263,400 queries of every generator's sets there, at 13 to 100 µs a try.
inline constexpr std::tuple box_schedule{
    Row{R::semi_static, M::any, always, semi_static_tests},
    Row{R::exact_narrow, M::any, hint_narrow, exact_narrow_stage},
    Row{R::search, M::nearest, hint_search, searched},
    Row{R::search, M::directed, in_range, searched},
    Row{R::inequalities_bounded, M::nearest, hint_not_near, inequalities<Bounded>},
    Row{R::exact_series_narrow, M::nearest, hint_narrow_two_scale, exact_stage<exact::Tier::series>},
    Row{R::clipped, M::nearest, turned, clipped_dd},
    Row{R::tiny_sizes, M::nearest, turned, sandwiched},
    Row{R::inequalities_dd, M::nearest, always, inequalities<DoubleDouble>},
    Row{R::clipped_flat, M::nearest, flat_one_scale_axis, clipped_dd},
    Row{R::exact_series, M::nearest, flat_two_scale_axis, exact_stage<exact::Tier::series>},
    Row{R::inequalities_bounded_late, M::nearest, flat_two_scale_axis, inequalities<Bounded>},
    Row{R::inequalities_bounded, M::directed, always, inequalities<Bounded>},
    Row{R::inequalities_interval, M::nearest, flat_two_scale_axis, inequalities<Interval>},
    Row{R::inequalities_interval, M::directed, always, inequalities<Interval>},
    Row{R::thorough_search, M::nearest, flat_in_range, thorough},
    Row{R::thorough_search, M::directed, in_range, thorough},
    Row{R::tiny_sizes, M::any, not_asked_early, sandwiched},
    Row{R::exact, M::any, always, exact_stage<exact::Tier::full>},
};

// Any parallelepiped.
inline constexpr std::tuple parallelepiped_schedule{
    Row{R::pp_fixed, M::any, always, pp_candidates},
    Row{R::pp_frame, M::any, always, pp_frame<Bounded>},
    Row{R::pp_search, M::any, always, pp_search},
    Row{R::pp_frame_interval, M::any, always, pp_frame<Interval>},
    Row{R::pp_candidates_interval, M::any, always, pp_candidates_interval},
    Row{R::clipped, M::nearest, always, pp_clipped},
    Row{R::exact, M::any, always, exact_stage<exact::Tier::full>},
};

template <class Box>
BOXCYL_FORCE_INLINE constexpr const auto& schedule() {
    if constexpr (std::is_same_v<Box, Parallelepiped<double>>)
        return parallelepiped_schedule;
    else
        return box_schedule;
}

// ---- The runner ----

// No statistics: every hook is empty and inlines away.
struct NoStats {
    static constexpr bool enabled = false;
};

// The runner is inlined into the query (BOXCYL_FORCE_INLINE): as calls, the first rows — the ones that
// decide nearly every query — waited for the prepared problem through memory (about 15% more
// instructions on the random benchmark set than one hand-written function).

// Whether the row runs in the query's rounding mode (probed once, on the first row that asks).
template <class Q>
BOXCYL_FORCE_INLINE inline bool runs_in(Modes modes, Q& q) {
    return modes == Modes::any || (modes == Modes::nearest) == q.nearest();
}

// Runs one row on a query (Given or Prepared); true when it decided (verdict set, `by` the row).
template <class Q, class R, class Recorder>
BOXCYL_FORCE_INLINE inline bool try_row(const R& row, Q& q, Recorder& stats, Verdict& verdict, RowId& by) {
    if (!runs_in(row.modes, q) || !row.when(q)) return false;
    if constexpr (Recorder::enabled) {
        const auto start = std::chrono::steady_clock::now();
        verdict = row.certify(q);
        const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start);
        Stats::Row& s = stats[row.id];
        ++s.tried;
        s.nanoseconds += static_cast<std::uint64_t>(ns.count());
        if (verdict) ++(*verdict ? s.hits : s.misses);
    } else {
        verdict = row.certify(q);
    }
    if (!verdict) return false;
    by = row.id;
    return true;
}

// Whether a row is the exact stage (in one of its tiers).
constexpr bool is_exact_row(RowId r) {
    return r == RowId::exact || r == RowId::exact_narrow || r == RowId::exact_series_narrow || r == RowId::exact_series;
}

// Walks a table: the first row that decides answers (`by` says which).
template <class Q, class Table, class Recorder, std::size_t... I>
BOXCYL_FORCE_INLINE inline Verdict walk(const Table& table, Q& q, Recorder& stats, RowId& by, std::index_sequence<I...>) {
    Verdict verdict;
    (try_row(std::get<I>(table), q, stats, verdict, by) || ...);
    return verdict;
}
template <class Q, class Table, class Recorder>
BOXCYL_FORCE_INLINE inline Verdict walk(const Table& table, Q& q, Recorder& stats, RowId& by) {
    return walk(table, q, stats, by, std::make_index_sequence<std::tuple_size_v<Table>>{});
}
// The given query's rows, then the prepared query's (the box kind's table).
template <class Box, class Recorder>
BOXCYL_FORCE_INLINE inline Verdict walk(Given<Box>& q, Recorder& stats, RowId& by) {
    return walk(given_schedule, q, stats, by);
}
template <class Box, class Recorder>
BOXCYL_FORCE_INLINE inline Verdict walk(Prepared<Box>& q, Recorder& stats, RowId& by) {
    return walk(schedule<Box>(), q, stats, by);
}

// The sandwich's pairs: none has a tiny size (sandwich.hpp), so this recursion is one level deep. Not
// inlined: the runner is, and the walk it holds would otherwise hold itself.
template <class Box, std::size_t... I>
Verdict walk_before_exact(Prepared<Box>& q, RowId& by, std::index_sequence<I...>) {
    NoStats none;
    Verdict verdict;
    ((std::get<I>(schedule<Box>()).id != RowId::exact && try_row(std::get<I>(schedule<Box>()), q, none, verdict, by)) ||
     ...);
    return verdict;
}
template <class Box>
[[gnu::noinline]] PairAnswer sub_query(const Box& box, const Cylinder<double>& cyl) {
    constexpr std::size_t rows = std::tuple_size_v<std::remove_cvref_t<decltype(schedule<Box>())>>;
    Prepared<Box> q(box, cyl);
    RowId by = RowId::exact;
    const Verdict v = walk_before_exact(q, by, std::make_index_sequence<rows>{});
    return {v, v && is_exact_row(by)};
}

}  // namespace boxcyl::filtered
