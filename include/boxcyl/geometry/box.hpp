// The three box kinds (aligned, oriented, canonical; docs/algorithms.md).
#pragma once

#include <array>     // OrientedBox::axes
#include <optional>  // signed_permutation

#include "boxcyl/geometry/vec3.hpp"

namespace boxcyl {

// Aligned box: the closed box min ≤ X ≤ max (componentwise). min == max in a component is a flat box.
template <class T>
struct AlignedBox {
    Vec3<T> min;
    Vec3<T> max;
};

// Oriented box: the closed solid { center + x0·axes[0] + x1·axes[1] + x2·axes[2] : |xi| ≤ extents[i] }.
// The axes are meant to be orthonormal; the exact semantics are "the parallelepiped the axes span,
// exactly as given" (docs in README), so an axis frame that is orthonormal only up to rounding is
// still an exact, well-defined solid.
template <class T>
struct OrientedBox {
    Vec3<T> center;
    std::array<Vec3<T>, 3> axes;
    Vec3<T> extents;
};

// Canonical box: centred at the origin, aligned with the coordinate axes: |xi| ≤ extents[i].
template <class T>
struct CanonicalBox {
    Vec3<T> extents;
};

// A frame whose axes are a signed permutation of the coordinate axes, axes[i] = sign[i]·e_{perm[i]}:
// the only exactly orthonormal frames of doubles (a dyadic unit vector in 3-D is ±e_j, since
// x² + y² + z² = 4^n has only the trivial integer solutions). The box's coordinates are then exact.
struct SignedPermutation {
    std::array<int, 3> perm;
    std::array<int, 3> sign;  // ±1
};
inline std::optional<SignedPermutation> signed_permutation(const std::array<Vec3<double>, 3>& axes) {
    SignedPermutation f{};
    unsigned used = 0;
    for (int i = 0; i < 3; ++i) {
        int nonzero = 0;
        for (int j = 0; j < 3; ++j) {
            const double a = axes[i][j];
            if (a == 0) continue;
            if (a != 1 && a != -1) return std::nullopt;
            ++nonzero;
            f.perm[i] = j;
            f.sign[i] = a > 0 ? 1 : -1;
        }
        if (nonzero != 1 || (used >> f.perm[i] & 1u)) return std::nullopt;
        used |= 1u << f.perm[i];
    }
    return f;
}

}  // namespace boxcyl
