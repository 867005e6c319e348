// A 3-vector over any number type T (float, double, GMP rationals, quadratic-field numbers).
// Only the operations the algorithms need; nothing here rounds by itself.
#pragma once

#include <array>    // storage
#include <cstddef>  // std::size_t
#include <utility>  // std::move

namespace boxcyl {

// Tag for a Vec3 whose components are left uninitialised (trivial T only: others are default-constructed),
// for hot structs that are filled field by field right away (filtered/semi_static.hpp's Problem).
struct Uninitialized {};
inline constexpr Uninitialized uninitialized{};

template <class T>
struct Vec3 {
    std::array<T, 3> c;

    constexpr Vec3() : c{} {}  // zero for arithmetic T
    explicit Vec3(Uninitialized) noexcept {}
    constexpr Vec3(T x, T y, T z) : c{std::move(x), std::move(y), std::move(z)} {}

    constexpr T& operator[](std::size_t i) { return c[i]; }
    constexpr const T& operator[](std::size_t i) const { return c[i]; }

    friend constexpr bool operator==(const Vec3&, const Vec3&) = default;
};

template <class T>
constexpr Vec3<T> operator+(const Vec3<T>& a, const Vec3<T>& b) {
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
template <class T>
constexpr Vec3<T> operator-(const Vec3<T>& a, const Vec3<T>& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
template <class T>
constexpr Vec3<T> operator-(const Vec3<T>& a) {
    return {-a[0], -a[1], -a[2]};
}
template <class T>
constexpr Vec3<T> operator*(const T& s, const Vec3<T>& a) {
    return {s * a[0], s * a[1], s * a[2]};
}
template <class T>
constexpr T dot(const Vec3<T>& a, const Vec3<T>& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class T>
constexpr Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Converts component-wise (e.g. double -> exact rational, exact -> exact).
template <class U, class T, class F>
Vec3<U> convert(const Vec3<T>& v, F&& f) {
    return {f(v[0]), f(v[1]), f(v[2])};
}

}  // namespace boxcyl
