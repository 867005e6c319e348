// The exact stage: the one entry point into exact arithmetic for the exact default (filtered.hpp) and
// for every box kind. The answer is exact for the inputs as given (each double the rational it
// denotes, the unit axis D/|D| exactly); the oracle is not used (it stays the independent judge).
//
// Routes (docs/pipeline.md, row exact): an exact canonical frame (aligned and canonical boxes, signed
// permutation frames) takes the linear-inequalities method in integers and Z[√d] — fixed-width
// integers, else integers in powers of a tiny ε for inputs of two scales, else mpz_class; any other
// frame and any parallelepiped (dependent axes too) the clipped edges and face cuts in integers. The
// tiers let the pipeline ask one route early (Tier::fixed for narrow inputs, Tier::series for narrow
// inputs of two scales); they answer nullopt when they cannot, and Tier::full always answers.
#pragma once

#include <optional>  // the tiers' "cannot"

#include "boxcyl/exact/integer_inequalities.hpp"
#include "boxcyl/exact/integer_parallelepiped.hpp"
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"

namespace boxcyl::exact {

enum class Tier {
    fixed,   // fixed-width integers only
    series,  // integers in powers of ε only (inputs of two scales)
    full,    // every route: always answers
};

template <class Box>
std::optional<bool> answer(const Box& b, const Cylinder<double>& c, Tier tier = Tier::full);

// A parallelepiped whose axes are a signed permutation of the unit vectors is that oriented box, and the
// canonical route answers it with narrower values (and in powers of ε for inputs of two scales).
inline std::optional<bool> answer(const Parallelepiped<double>& b, const Cylinder<double>& c, Tier tier = Tier::full) {
    if (signed_permutation(b.axes)) return answer(OrientedBox<double>{b.center, b.axes, b.extents}, c, tier);
    switch (tier) {
        case Tier::fixed: return integer::parallelepiped_small(b, c);
        case Tier::series: return std::nullopt;
        case Tier::full: break;
    }
    return integer::intersects_parallelepiped(b, c);
}

// Aligned, canonical and oriented boxes.
template <class Box>
std::optional<bool> answer(const Box& b, const Cylinder<double>& c, Tier tier) {
    if constexpr (std::is_same_v<Box, OrientedBox<double>>) {
        if (!signed_permutation(b.axes)) return answer(Parallelepiped<double>{b.center, b.axes, b.extents}, c, tier);
    }
    switch (tier) {
        case Tier::fixed: return integer::answer_small(b, c);
        case Tier::series: return integer::answer_two_scale(b, c);
        case Tier::full: break;
    }
    return integer::answer(b, c);
}

}  // namespace boxcyl::exact
