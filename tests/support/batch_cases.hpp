// Inputs for the batch API (tests/test_batch.cpp, bench/bench_batch.cpp): one cylinder and
// many boxes around it, built from the tests' generators (cases.hpp: CaseGenerator's cylinders and
// random distributions, random_rotation, random_signed_permutation), so that about half the boxes
// hit; flat, thin and point boxes included. Also boxes one ulp from touching (bisection over adjacent
// doubles of a box shift, judged by the scalar exact default).
#pragma once

#include <algorithm>  // std::max
#include <cmath>      // std::ldexp
#include <cstdint>    // std::uint64_t
#include <vector>     // the sets

#include "boxcyl/filtered.hpp"
#include "support/cases.hpp"

namespace boxcyl::testing {

struct BatchSet {
    Cylinder<double> cylinder;
    std::vector<AlignedBox<double>> aligned;
    std::vector<OrientedBox<double>> oriented;
};

// Box sizes as CaseGenerator draws them: flat, thin, or ordinary (relative to `size`).
inline double box_extent(CaseGenerator& gen, double size) {
    switch (static_cast<int>(gen.uniform(0, 10))) {
        case 0: return 0.0;
        case 1: return size * std::ldexp(1.0, -30);
        default: return size * gen.uniform(0.05, 1.5);
    }
}

// n aligned and n oriented boxes (unless !oriented) around the cylinder of one CaseGenerator case.
inline BatchSet random_batch(std::uint64_t seed, std::size_t n, Profile profile = Profile::mixed, bool oriented = true) {
    CaseGenerator gen(seed, profile);
    BatchSet s;
    s.cylinder = gen.next().cylinder;
    const Cylinder<double>& c = s.cylinder;
    // The cylinder's reach; a segment-and-disk (r = h = 0) point gets the scale of its centre.
    double reach = c.radius + c.height * 0.5;
    if (!(reach > 0)) reach = std::max({std::fabs(c.center[0]), std::fabs(c.center[1]), std::fabs(c.center[2]), 1e-3});
    auto position = [&](int j, double ext) { return c.center[j] + (reach + ext) * gen.uniform(-1.1, 1.1); };
    for (std::size_t i = 0; i < n; ++i) {
        const double size = reach * std::ldexp(1.0, static_cast<int>(gen.uniform(-3, 1)));
        AlignedBox<double> a;
        for (int j = 0; j < 3; ++j) {
            const double e = box_extent(gen, size);
            const double k = position(j, e);
            a.min[j] = k - e;
            a.max[j] = k + e;
        }
        s.aligned.push_back(a);
        if (!oriented) continue;
        OrientedBox<double> o;
        o.axes = gen.uniform(0, 1) < 0.25 ? random_signed_permutation(gen.rng()) : random_rotation(gen.rng());
        for (int j = 0; j < 3; ++j) {
            o.extents[j] = box_extent(gen, size);
            o.center[j] = position(j, o.extents[j]);
        }
        s.oriented.push_back(o);
    }
    return s;
}

// The box moved to x-position v: the aligned box's min_x (its width kept), the oriented box's centre.
inline AlignedBox<double> shifted(AlignedBox<double> b, double v) {
    const double w = b.max[0] - b.min[0];
    b.min[0] = v;
    b.max[0] = v + w;
    return b;
}
inline OrientedBox<double> shifted(OrientedBox<double> b, double v) {
    b.center[0] = v;
    return b;
}
inline double position_x(const AlignedBox<double>& b) { return b.min[0]; }
inline double position_x(const OrientedBox<double>& b) { return b.center[0]; }

// Appends the two boxes one ulp apart (in their x position) between which the exact answer flips,
// for `pairs` boxes of `from` that have such a flip within ±8·(reach + |C|) of where they are.
template <class Box>
void append_boundary(const Cylinder<double>& c, const std::vector<Box>& from, std::size_t pairs, std::vector<Box>& out) {
    const double span = 8 * (c.radius + c.height + std::fabs(c.center[0]) + std::fabs(c.center[1]) +
                             std::fabs(c.center[2]) + 1e-300);
    std::size_t made = 0;
    for (std::size_t i = 0; i < from.size() && made < pairs; ++i) {
        const Box& b = from[i];
        auto answer = [&](double v) { return filtered::intersects(shifted(b, v), c); };
        double lo = position_x(b) - span, hi = position_x(b) + span;
        if (answer(lo) == answer(hi)) {
            const double mid = position_x(b);
            if (answer(mid) == answer(lo)) continue;
            hi = mid;
        }
        const auto [x, y] = bisect_ulp(lo, hi, answer);
        out.push_back(shifted(b, x));
        out.push_back(shifted(b, y));
        ++made;
    }
}

}  // namespace boxcyl::testing
