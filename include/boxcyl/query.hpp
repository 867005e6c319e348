// The front door: boxcyl::intersects(box, cylinder[, options]) for aligned, oriented and canonical
// boxes. Closed solids: touching counts as intersecting. Inputs must satisfy validate() (finite, non-zero
// axis, non-negative sizes, min ≤ max, orthonormal oriented-box axes); that is asserted in debug builds.
//
// Options choose the algorithm and arithmetic:
//   Algorithm::inequalities  §4 linear inequalities (default), in float32 or float64 arithmetic
//                            (rounded: may err on near-touching inputs; issue #4 makes it exact)
//   Algorithm::oracle        the exact reference (oracle/oracle.hpp): exact for the inputs as given,
//                            slow. Needs the exact backend (link boxcyl::exact, which defines
//                            BOXCYL_HAS_EXACT); without it, choosing it throws std::invalid_argument.
#pragma once

#include <cassert>    // debug-build precondition checks
#include <stdexcept>  // std::invalid_argument for an unavailable option

#include "boxcyl/algo/linear_inequalities.hpp"
#include "boxcyl/geometry/box.hpp"
#include "boxcyl/geometry/cylinder.hpp"
#include "boxcyl/geometry/reduce.hpp"
#include "boxcyl/geometry/validate.hpp"
#if defined(BOXCYL_HAS_EXACT)
#include "boxcyl/oracle/oracle.hpp"
#endif

namespace boxcyl {

enum class Algorithm { inequalities, oracle };
enum class Arithmetic { float32, float64 };

struct QueryOptions {
    Algorithm algorithm = Algorithm::inequalities;
    Arithmetic arithmetic = Arithmetic::float64;
};

namespace detail {

template <class U, class T>
Vec3<U> cast(const Vec3<T>& v) {
    return {static_cast<U>(v[0]), static_cast<U>(v[1]), static_cast<U>(v[2])};
}
template <class U, class T>
Cylinder<U> cast(const Cylinder<T>& c) {
    return {cast<U>(c.center), cast<U>(c.axis), static_cast<U>(c.radius), static_cast<U>(c.height)};
}
template <class U, class T>
AlignedBox<U> cast(const AlignedBox<T>& b) {
    return {cast<U>(b.min), cast<U>(b.max)};
}
template <class U, class T>
OrientedBox<U> cast(const OrientedBox<T>& b) {
    return {cast<U>(b.center), {cast<U>(b.axes[0]), cast<U>(b.axes[1]), cast<U>(b.axes[2])}, cast<U>(b.extents)};
}
template <class U, class T>
CanonicalBox<U> cast(const CanonicalBox<T>& b) {
    return {cast<U>(b.extents)};
}

template <class Box, class T>
bool dispatch(const Box& box, const Cylinder<T>& cyl, const QueryOptions& opt) {
    assert(validate(box).ok() && "boxcyl::intersects: invalid box (see boxcyl::validate)");
    assert(validate(cyl).ok() && "boxcyl::intersects: invalid cylinder (see boxcyl::validate)");
    switch (opt.algorithm) {
        case Algorithm::inequalities:
            if (opt.arithmetic == Arithmetic::float32) {
                const auto q = to_canonical(cast<float>(box), to_unit(cast<float>(cyl)));
                return algo::linear_inequalities(q.box, q.cylinder);
            } else {
                const auto q = to_canonical(cast<double>(box), to_unit(cast<double>(cyl)));
                return algo::linear_inequalities(q.box, q.cylinder);
            }
        case Algorithm::oracle:
#if defined(BOXCYL_HAS_EXACT)
            return oracle::intersects(to_exact(cast<double>(box)), to_exact(cast<double>(cyl)));
#else
            throw std::invalid_argument("boxcyl: Algorithm::oracle needs the exact backend (boxcyl::exact)");
#endif
    }
    throw std::invalid_argument("boxcyl: unknown Algorithm value");
}

}  // namespace detail

template <class T>
bool intersects(const AlignedBox<T>& box, const Cylinder<T>& cyl, const QueryOptions& opt = {}) {
    return detail::dispatch(box, cyl, opt);
}
template <class T>
bool intersects(const OrientedBox<T>& box, const Cylinder<T>& cyl, const QueryOptions& opt = {}) {
    return detail::dispatch(box, cyl, opt);
}
// The cylinder is given in the canonical box's frame (box centred at the origin, axis-aligned).
template <class T>
bool intersects(const CanonicalBox<T>& box, const Cylinder<T>& cyl, const QueryOptions& opt = {}) {
    return detail::dispatch(box, cyl, opt);
}

}  // namespace boxcyl
