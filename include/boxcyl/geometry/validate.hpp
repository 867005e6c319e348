// Input validation at the boundary (STYLE §13): kernels assume valid input; the CLI, the bindings and
// careful callers ask validate() first. It names the first bad field and why.
//
// The input policy (also README "What the answer means"; tests/test_validate.cpp checks it field by field):
// - NaN and ±Inf are rejected in every field ("cylinder.center[1]: is NaN").
// - cylinder.axis: any non-zero vector, only its direction counts (subnormal or near-overflow
//   components are fine); the zero vector (±0 components) is rejected.
// - radius, height, extents: negative is rejected; zero (also −0) is accepted as the exact degenerate
//   solid it denotes (segment, disk, point; flat or point box).
// - Aligned box: min > max in any component is rejected; min == max is a flat box.
// - Oriented box: axes must be non-zero and orthonormal within 1e-4 (|Ai·Aj − δij| ≤ 1e-4); the solid
//   is then exactly the parallelepiped they span (a frame orthonormal only up to rounding is fine).
//   Anything further off is almost surely a caller bug (a scaled or non-rotation matrix), so it is
//   refused with a message rather than guessed at.
// - Parallelepiped: finite fields and non-negative extents; the axes may be any vectors (zero,
//   parallel, any lengths and angles), so nothing about them is checked.
// - Magnitudes: every finite double is accepted, subnormals to ±DBL_MAX; the default query answers
//   exactly there too (no intermediate overflow turns into a wrong answer).
// For valid input, boxcyl::intersects() with default options never throws; it asserts validity in
// debug builds; in release builds invalid input gets an unspecified answer or an exception.
#pragma once

#include <cmath>    // std::isnan, std::isinf, std::fabs
#include <cstddef>  // std::size_t
#include <string>   // field names and reasons

#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/parallelepiped.hpp"

namespace boxcyl {

// Valid when `field` is empty; otherwise `field` names the first bad field ("cylinder.axis[1]") and
// `reason` says what is wrong with it ("is NaN").
struct Validity {
    std::string field;
    std::string reason;

    bool ok() const { return field.empty(); }
    explicit operator bool() const { return ok(); }
    std::string message() const { return ok() ? std::string("ok") : field + ": " + reason; }
};

inline constexpr double orthonormality_tolerance = 1e-4;

namespace detail {

template <class T>
bool check_finite(Validity& v, const std::string& field, T x) {
    if (std::isnan(x)) {
        v = {field, "is NaN"};
        return false;
    }
    if (std::isinf(x)) {
        v = {field, x > 0 ? "is +Inf" : "is -Inf"};
        return false;
    }
    return true;
}

template <class T>
bool check_finite(Validity& v, const std::string& field, const Vec3<T>& p) {
    for (std::size_t i = 0; i < 3; ++i)
        if (!check_finite(v, field + "[" + std::to_string(i) + "]", p[i])) return false;
    return true;
}

template <class T>
bool check_nonnegative(Validity& v, const std::string& field, T x) {
    if (!check_finite(v, field, x)) return false;
    if (x < T(0)) {
        v = {field, "is negative"};
        return false;
    }
    return true;
}

}  // namespace detail

// `prefix` names the object in messages ("cylinder", or "cylinders[7]" in a batch).
template <class T>
Validity validate(const Cylinder<T>& c, const std::string& prefix = "cylinder") {
    Validity v;
    if (!detail::check_finite(v, prefix + ".center", c.center)) return v;
    if (!detail::check_finite(v, prefix + ".axis", c.axis)) return v;
    if (c.axis[0] == T(0) && c.axis[1] == T(0) && c.axis[2] == T(0))
        return {prefix + ".axis", "is the zero vector"};
    if (!detail::check_nonnegative(v, prefix + ".radius", c.radius)) return v;
    if (!detail::check_nonnegative(v, prefix + ".height", c.height)) return v;
    return v;
}

template <class T>
Validity validate(const AlignedBox<T>& b, const std::string& prefix = "box") {
    Validity v;
    if (!detail::check_finite(v, prefix + ".min", b.min)) return v;
    if (!detail::check_finite(v, prefix + ".max", b.max)) return v;
    for (std::size_t i = 0; i < 3; ++i)
        if (b.max[i] < b.min[i])
            return {prefix + ".max[" + std::to_string(i) + "]",
                    "is less than " + prefix + ".min[" + std::to_string(i) + "]"};
    return v;
}

template <class T>
Validity validate(const CanonicalBox<T>& b, const std::string& prefix = "box") {
    Validity v;
    for (std::size_t i = 0; i < 3; ++i)
        if (!detail::check_nonnegative(v, prefix + ".extents[" + std::to_string(i) + "]", b.extents[i]))
            return v;
    return v;
}

template <class T>
Validity validate(const OrientedBox<T>& b, const std::string& prefix = "box") {
    Validity v;
    if (!detail::check_finite(v, prefix + ".center", b.center)) return v;
    for (std::size_t i = 0; i < 3; ++i)
        if (!detail::check_finite(v, prefix + ".axes[" + std::to_string(i) + "]", b.axes[i])) return v;
    for (std::size_t i = 0; i < 3; ++i)
        if (!detail::check_nonnegative(v, prefix + ".extents[" + std::to_string(i) + "]", b.extents[i]))
            return v;
    for (std::size_t i = 0; i < 3; ++i) {
        const Vec3<T>& a = b.axes[i];
        if (a[0] == T(0) && a[1] == T(0) && a[2] == T(0))
            return {prefix + ".axes[" + std::to_string(i) + "]", "is the zero vector"};
    }
    // Computed in long double so that the check itself cannot overflow for finite input of
    // reasonable size; values beyond ~1e2466 would, but then |Ai|² is far from 1 anyway.
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = i; j < 3; ++j) {
            long double g = 0;
            for (std::size_t k = 0; k < 3; ++k)
                g += static_cast<long double>(b.axes[i][k]) * static_cast<long double>(b.axes[j][k]);
            const long double target = (i == j) ? 1.0L : 0.0L;
            if (!(std::fabs(g - target) <= orthonormality_tolerance)) {
                std::string what = (i == j) ? "is not unit length (|axes[" + std::to_string(i) + "]|² = "
                                            : "are not orthogonal (axes[" + std::to_string(i) +
                                                  "]·axes[" + std::to_string(j) + "] = ";
                what += std::to_string(static_cast<double>(g)) + ", tolerance 1e-4)";
                return {prefix + ".axes" + (i == j ? "[" + std::to_string(i) + "]" : std::string()), what};
            }
        }
    return v;
}

// Any axes are valid: zero or parallel ones give the flat solid they span.
template <class T>
Validity validate(const Parallelepiped<T>& b, const std::string& prefix = "box") {
    Validity v;
    if (!detail::check_finite(v, prefix + ".center", b.center)) return v;
    for (std::size_t i = 0; i < 3; ++i)
        if (!detail::check_finite(v, prefix + ".axes[" + std::to_string(i) + "]", b.axes[i])) return v;
    for (std::size_t i = 0; i < 3; ++i)
        if (!detail::check_nonnegative(v, prefix + ".extents[" + std::to_string(i) + "]", b.extents[i]))
            return v;
    return v;
}

}  // namespace boxcyl
