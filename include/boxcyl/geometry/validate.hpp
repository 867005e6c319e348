// Input validation at the boundary: kernels assume valid input; the CLI, the bindings and
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
// boxcyl::intersects() refuses invalid input in every build type: std::invalid_argument whose message is
// validate()'s; for valid input with default options it never throws. intersects_unchecked() skips the
// check (it asserts validity in debug builds).
//
// Cost: is_valid() is a few comparisons (no allocation, never throws), and validate() on valid input
// is is_valid() plus an empty Validity; the strings naming the field are built only when something
// is wrong (bench/bench_validate.cpp measures both).
#pragma once

#include <array>        // OrientedBox::axes
#include <bit>          // std::bit_cast
#include <cmath>        // std::fabs, std::isnan, std::isinf
#include <cstddef>      // std::size_t
#include <cstdint>      // the bits of a float or double
#include <cstdio>       // std::snprintf
#include <limits>       // std::numeric_limits
#include <string>       // field names and reasons
#include <string_view>  // prefixes
#include <type_traits>  // std::is_floating_point_v

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

// --- the checks themselves: no strings; truth values as ints (0 or 1) combined with & rather than &&,
// so that valid input (the common case) takes no branch per field (ints: & on bools draws clang's
// -Wbitwise-instead-of-logical) ---

template <class T>
int finite(T x) noexcept {
    return static_cast<int>(std::fabs(x) <= std::numeric_limits<T>::max());  // 0 for NaN and ±Inf
}

// finite(x) read off the bits for float and double: the exponent field is all ones only for ±Inf and
// NaN. Integer operations cost the same for every value; floating-point ones need not (a product with a
// subnormal operand takes a slow path on some processors: x·0 over a query's fields, the way this was
// done before, doubled the front door's check on inputs with subnormal sizes).
template <class T>
int finite_bits(T x) noexcept {
    if constexpr (std::is_same_v<T, double>) {
        constexpr std::uint64_t exponent = 0x7ffULL << 52;
        return static_cast<int>((std::bit_cast<std::uint64_t>(x) & exponent) != exponent);
    } else if constexpr (std::is_same_v<T, float>) {
        constexpr std::uint32_t exponent = 0xffU << 23;
        return static_cast<int>((std::bit_cast<std::uint32_t>(x) & exponent) != exponent);
    } else {
        return finite(x);
    }
}

template <class T>
int finite3(const Vec3<T>& p) noexcept {
    return finite_bits(p[0]) & finite_bits(p[1]) & finite_bits(p[2]);
}

template <class T>
int size_ok(T x) noexcept {
    return finite(x) & static_cast<int>(!(x < T(0)));
}

template <class T>
int is_zero3(const Vec3<T>& p) noexcept {
    return static_cast<int>(p[0] == T(0)) & static_cast<int>(p[1] == T(0)) & static_cast<int>(p[2] == T(0));
}

// min ≤ max, or not comparable (NaN: caught by finite3)
template <class T>
int ordered(T lo, T hi) noexcept {
    return static_cast<int>(!(hi < lo));
}

// The Gram entry Ai·Aj in long double, so that the check itself cannot overflow for finite input of
// reasonable size; values beyond ~1e2466 would, but then |Ai|² is far from 1 anyway.
template <class T>
long double gram(const std::array<Vec3<T>, 3>& a, std::size_t i, std::size_t j) noexcept {
    long double g = 0;
    for (std::size_t k = 0; k < 3; ++k) g += static_cast<long double>(a[i][k]) * static_cast<long double>(a[j][k]);
    return g;
}

template <class T>
bool gram_entry_ok(const std::array<Vec3<T>, 3>& a, std::size_t i, std::size_t j) noexcept {
    const long double target = (i == j) ? 1.0L : 0.0L;
    return std::fabs(gram(a, i, j) - target) <= orthonormality_tolerance;
}

// |Ai·Aj − δij| ≤ 1e-4 for all i ≤ j, as gram_entry_ok() decides it.
template <class T>
bool gram_ok(const std::array<Vec3<T>, 3>& a) noexcept {
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = i; j < 3; ++j)
            if (!gram_entry_ok(a, i, j)) return false;
    return true;
}

// A sufficient condition for gram_ok(), cheap for float and double: the six entries in double each
// within 0.9e-4 of their targets. The rows then have length ≤ 1.0001, so the double and the long
// double entries differ by less than 1e-15 and the latter are within 1e-4 too. When this fails (near
// the tolerance, overflow, a bad frame), gram_ok() decides.
template <class T>
bool gram_clearly_ok(const std::array<Vec3<T>, 3>& a) noexcept {
    if constexpr (std::is_floating_point_v<T> && sizeof(T) <= sizeof(double)) {
        // The six entries written out and combined without branches: as a loop GCC kept them serial
        // (the front door runs this on every oriented query).
        const auto entry = [&a](int i, int j, double target) {
            const double g = static_cast<double>(a[i][0]) * static_cast<double>(a[j][0]) +
                             static_cast<double>(a[i][1]) * static_cast<double>(a[j][1]) +
                             static_cast<double>(a[i][2]) * static_cast<double>(a[j][2]);
            return static_cast<int>(std::fabs(g - target) <= 0.9 * orthonormality_tolerance);
        };
        return (entry(0, 0, 1) & entry(1, 1, 1) & entry(2, 2, 1) & entry(0, 1, 0) & entry(0, 2, 0) & entry(1, 2, 0)) != 0;
    } else {
        return false;
    }
}

// --- the messages: built only once a check has failed ---

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

// Whether the fixed-point decimal `s` ("-0.000200", "1.000100", at least four decimals), read as the
// decimal number it shows, is more than 1e-4 from `target` (0 or 1).
inline bool reads_beyond_tolerance(std::string_view s, bool target_is_one) {
    const bool negative = !s.empty() && s.front() == '-';
    if (negative) s.remove_prefix(1);
    const std::size_t dot = s.find('.');
    const std::string_view whole = s.substr(0, dot), fraction = s.substr(dot + 1);
    const std::string zeros(fraction.size() - 4, '0');
    if (!target_is_one) return whole != "0" || fraction > "0001" + zeros;  // |d| > 0.0001
    if (negative) return true;
    if (whole == "0") return fraction < "9999" + zeros;                     // d < 0.9999
    return whole != "1" || fraction > "0001" + zeros;                       // d > 1.0001
}

// A Gram entry that failed the tolerance, printed with as many decimals as it takes for the printed
// number itself to read as beyond the tolerance (six at least): 1.0001000003 is not shown as "1.000100".
inline std::string gram_text(long double g, bool target_is_one) {
    char buf[64];
    if (!(std::fabs(g) < 1e6L)) {
        std::snprintf(buf, sizeof buf, "%.6Lg", g);
        return buf;
    }
    // A failed entry is beyond 1e-4 by at least the excess of the double 1e-4 over 1e-4 (4.8e-21), so
    // 24 decimals always suffice.
    for (int decimals = 6; decimals <= 24; ++decimals) {
        std::snprintf(buf, sizeof buf, "%.*Lf", decimals, g);
        if (reads_beyond_tolerance(buf, target_is_one)) return buf;
    }
    return buf;
}

template <class T>
Validity describe(const Cylinder<T>& c, const std::string& prefix) {
    Validity v;
    if (!check_finite(v, prefix + ".center", c.center)) return v;
    if (!check_finite(v, prefix + ".axis", c.axis)) return v;
    if (is_zero3(c.axis)) return {prefix + ".axis", "is the zero vector"};
    if (!check_nonnegative(v, prefix + ".radius", c.radius)) return v;
    if (!check_nonnegative(v, prefix + ".height", c.height)) return v;
    return v;
}

template <class T>
Validity describe(const AlignedBox<T>& b, const std::string& prefix) {
    Validity v;
    if (!check_finite(v, prefix + ".min", b.min)) return v;
    if (!check_finite(v, prefix + ".max", b.max)) return v;
    for (std::size_t i = 0; i < 3; ++i)
        if (b.max[i] < b.min[i])
            return {prefix + ".max[" + std::to_string(i) + "]",
                    "is less than " + prefix + ".min[" + std::to_string(i) + "]"};
    return v;
}

template <class T>
Validity describe(const CanonicalBox<T>& b, const std::string& prefix) {
    Validity v;
    for (std::size_t i = 0; i < 3; ++i)
        if (!check_nonnegative(v, prefix + ".extents[" + std::to_string(i) + "]", b.extents[i])) return v;
    return v;
}

template <class T>
Validity describe(const OrientedBox<T>& b, const std::string& prefix) {
    Validity v;
    if (!check_finite(v, prefix + ".center", b.center)) return v;
    for (std::size_t i = 0; i < 3; ++i)
        if (!check_finite(v, prefix + ".axes[" + std::to_string(i) + "]", b.axes[i])) return v;
    for (std::size_t i = 0; i < 3; ++i)
        if (!check_nonnegative(v, prefix + ".extents[" + std::to_string(i) + "]", b.extents[i])) return v;
    for (std::size_t i = 0; i < 3; ++i)
        if (is_zero3(b.axes[i])) return {prefix + ".axes[" + std::to_string(i) + "]", "is the zero vector"};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = i; j < 3; ++j) {
            if (gram_entry_ok(b.axes, i, j)) continue;
            const std::string si = std::to_string(i), sj = std::to_string(j);
            std::string what = (i == j) ? "is not unit length (|axes[" : "are not orthogonal (axes[";
            what += si;
            what += (i == j) ? "]|² = " : "]·axes[" + sj + "] = ";
            what += gram_text(gram(b.axes, i, j), i == j);
            what += ", tolerance 1e-4)";
            return {prefix + ".axes" + (i == j ? "[" + si + "]" : std::string()), what};
        }
    return v;
}

// Any axes are valid: zero or parallel ones give the flat solid they span.
template <class T>
Validity describe(const Parallelepiped<T>& b, const std::string& prefix) {
    Validity v;
    if (!check_finite(v, prefix + ".center", b.center)) return v;
    for (std::size_t i = 0; i < 3; ++i)
        if (!check_finite(v, prefix + ".axes[" + std::to_string(i) + "]", b.axes[i])) return v;
    for (std::size_t i = 0; i < 3; ++i)
        if (!check_nonnegative(v, prefix + ".extents[" + std::to_string(i) + "]", b.extents[i])) return v;
    return v;
}

}  // namespace detail

// True when validate() would say ok: the same checks, without building any text.
template <class T>
bool is_valid(const Cylinder<T>& c) noexcept {
    using namespace detail;
    return (finite3(c.center) & finite3(c.axis) & finite_bits(c.radius) & finite_bits(c.height) & (is_zero3(c.axis) ^ 1) &
            ordered(T(0), c.radius) & ordered(T(0), c.height)) != 0;
}

template <class T>
bool is_valid(const AlignedBox<T>& b) noexcept {
    using namespace detail;
    return (finite3(b.min) & finite3(b.max) & ordered(b.min[0], b.max[0]) &
            ordered(b.min[1], b.max[1]) & ordered(b.min[2], b.max[2])) != 0;
}

template <class T>
bool is_valid(const CanonicalBox<T>& b) noexcept {
    using namespace detail;
    return (finite3(b.extents) & ordered(T(0), b.extents[0]) & ordered(T(0), b.extents[1]) &
            ordered(T(0), b.extents[2])) != 0;
}

template <class T>
bool is_valid(const OrientedBox<T>& b) noexcept {
    using namespace detail;
    const bool others = (finite3(b.center) & finite3(b.extents) & ordered(T(0), b.extents[0]) &
                         ordered(T(0), b.extents[1]) & ordered(T(0), b.extents[2])) != 0;
    // gram_clearly_ok() implies finite, non-zero axes: a NaN or ±Inf component makes a Gram entry NaN
    // or +Inf, a zero axis makes |Ai|² zero.
    if (others && detail::gram_clearly_ok(b.axes)) return true;
    return others && detail::finite3(b.axes[0]) && detail::finite3(b.axes[1]) && detail::finite3(b.axes[2]) &&
           !detail::is_zero3(b.axes[0]) && !detail::is_zero3(b.axes[1]) && !detail::is_zero3(b.axes[2]) &&
           detail::gram_ok(b.axes);
}

// Any axes: only finite fields and non-negative extents are asked.
template <class T>
bool is_valid(const Parallelepiped<T>& b) noexcept {
    using namespace detail;
    return (finite3(b.center) & finite3(b.extents) & finite3(b.axes[0]) & finite3(b.axes[1]) & finite3(b.axes[2]) &
            ordered(T(0), b.extents[0]) & ordered(T(0), b.extents[1]) & ordered(T(0), b.extents[2])) != 0;
}

// Names the first bad field and why. `prefix` names the object in messages ("cylinder", or
// "cylinders[7]" in a batch); it is copied only when something is wrong.
template <class T>
Validity validate(const Cylinder<T>& c, std::string_view prefix = "cylinder") {
    if (is_valid(c)) return {};
    return detail::describe(c, std::string(prefix));
}

template <class T>
Validity validate(const AlignedBox<T>& b, std::string_view prefix = "box") {
    if (is_valid(b)) return {};
    return detail::describe(b, std::string(prefix));
}

template <class T>
Validity validate(const CanonicalBox<T>& b, std::string_view prefix = "box") {
    if (is_valid(b)) return {};
    return detail::describe(b, std::string(prefix));
}

template <class T>
Validity validate(const OrientedBox<T>& b, std::string_view prefix = "box") {
    if (is_valid(b)) return {};
    return detail::describe(b, std::string(prefix));
}

template <class T>
Validity validate(const Parallelepiped<T>& b, std::string_view prefix = "box") {
    if (is_valid(b)) return {};
    return detail::describe(b, std::string(prefix));
}

}  // namespace boxcyl
