// The clearance query's margin (boxcyl/clearance.hpp: is the box within distance `margin` of the
// cylinder?) and its validation, beside validate()'s for the shapes: a finite number ≥ 0 (−0 is 0).
#pragma once

#include <cmath>        // std::isfinite
#include <string>       // the field name
#include <string_view>  // the field name

#include "boxcyl/geometry/validate.hpp"

namespace boxcyl {

template <class T>
bool is_valid_margin(T m) noexcept {
    return std::isfinite(m) && m >= T(0);
}

// Names the margin and why it is refused ("margin: is negative"), or ok().
template <class T>
Validity validate_margin(T m, std::string_view name = "margin") {
    Validity v;
    if (!is_valid_margin(m)) detail::check_nonnegative(v, std::string(name), m);
    return v;
}

}  // namespace boxcyl
