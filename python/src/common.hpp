// What the files of boxcyl._core share. The areas — poses.cpp (shapes from poses and end points),
// batch.cpp (the batch forms), grid.cpp (the grid query) — are plain C++ declared here; the Python
// side, bindings.hpp, is compiled only in module.cpp (the module: its functions) and shapes.cpp (its
// classes), since every file that includes pybind11 costs seconds of build time on its own.
// Errors are std::invalid_argument, which pybind11 raises as ValueError with the same message.
//
// The library is reached through boxcyl/compiled.hpp's declarations (light headers); library.cpp
// compiles what the module uses of it, once.
#pragma once

#include <array>       // Vec3 <-> std::array
#include <cstddef>     // std::ptrdiff_t
#include <cstdint>     // std::int64_t
#include <cstring>     // std::memcpy: array elements need not be aligned
#include <optional>    // a batch's margin
#include <stdexcept>   // std::invalid_argument, std::runtime_error
#include <stop_token>  // the stop a long run looks at
#include <string>      // messages
#include <vector>      // the grid's cells

#include "boxcyl/compiled.hpp"
#include "boxcyl/number/interval.hpp"  // fp_environment_ok

#if !defined(BOXCYL_HAS_EXACT)
#error "the boxcyl Python module needs the exact backend (GMP): define BOXCYL_HAS_EXACT and link gmpxx"
#endif

namespace boxcyl_python {

using Vec = boxcyl::Vec3<double>;
using Array3 = std::array<double, 3>;
using Matrix3 = std::array<Array3, 3>;
using Matrix4 = std::array<std::array<double, 4>, 4>;
using Cylinder = boxcyl::Cylinder<double>;
using AlignedBox = boxcyl::AlignedBox<double>;
using OrientedBox = boxcyl::OrientedBox<double>;
using Parallelepiped = boxcyl::Parallelepiped<double>;
using Index = std::ptrdiff_t;

inline Vec vec(const Array3& a) { return {a[0], a[1], a[2]}; }

// x, or a ValueError naming its first bad field ("box.max[0]: is less than box.min[0]").
template <class Object>
Object validated(Object x, const char* name) {
    if (!boxcyl::is_valid(x)) throw std::invalid_argument(boxcyl::validate(x, name).message());
    return x;
}

// The filter's exactness assumes gradual underflow; a library loaded into the same process may have
// set flush-to-zero (e.g. one built with -ffast-math). Checked on the thread that runs the query.
inline void require_fp_environment() {
    if (!boxcyl::fp_environment_ok())
        throw std::runtime_error(
            "boxcyl: the floating-point environment flushes subnormals to zero (FTZ/DAZ, often set by a "
            "library built with -ffast-math); exact answers cannot be guaranteed in it");
}

// "boxes[17]" for an element of an array argument, "box" for a single object broadcast.
inline std::string element_name(const char* singular, const char* plural, bool single, Index i) {
    return single ? std::string(singular) : std::string(plural) + "[" + std::to_string(i) + "]";
}

// ---- poses.cpp: the package's named constructors (boxcyl/geometry/pose.hpp), with the package's advice. ----

// `full`: sizes are full side lengths (Size), else half (HalfExtents); `half`: the length is half the
// height (HalfHeight), else the full height; `along`: the local axis, 0, 1, 2 for x, y, z.
OrientedBox box_from_rotation(const Array3& center, const Matrix3& rows, const Array3& sizes, bool full);
OrientedBox box_from_quaternion(const Array3& center, const std::array<double, 4>& wxyz, const Array3& sizes, bool full);
OrientedBox box_from_transform(const Matrix4& t, const Array3& sizes, bool full);
Parallelepiped parallelepiped_from_transform(const Matrix4& t, const Array3& sizes, bool full);
Cylinder cylinder_from_rotation(const Array3& center, const Matrix3& rows, double radius, double length, bool half,
                                int along);
Cylinder cylinder_from_quaternion(const Array3& center, const std::array<double, 4>& wxyz, double radius,
                                  double length, bool half, int along);
Cylinder cylinder_from_transform(const Matrix4& t, double radius, double length, bool half, int along);
Cylinder cylinder_between(const Array3& p0, const Array3& p1, double radius);

// ---- batch.cpp: the batch forms over array fields. ----

// A float64 array argument of shape (M, *tail), any strides: row i (i < M, or row 0 when M == 1:
// broadcast) and element k of the flattened tail. Reads raw memory only, so it may be used while the
// GIL is released (the caller keeps the arrays alive).
struct Field {
    const char* base = nullptr;
    Index count = 1;
    Index step = 0;                 // bytes from one row to the next; 0 when broadcast
    std::array<Index, 9> offset{};  // bytes from a row's start to each tail element

    double operator()(Index i, std::size_t k) const {
        double x;
        std::memcpy(&x, base + i * step + offset[k], sizeof x);
        return x;
    }
    // Whether each row's first k numbers are adjacent, in order.
    bool dense(std::size_t k) const {
        for (std::size_t j = 0; j < k; ++j)
            if (offset[j] != static_cast<Index>(8 * j)) return false;
        return true;
    }
};

struct CylinderFields {
    Field center, axis, radius, height;
    Cylinder operator()(Index i) const {
        return {{center(i, 0), center(i, 1), center(i, 2)}, {axis(i, 0), axis(i, 1), axis(i, 2)}, radius(i, 0),
                height(i, 0)};
    }
};

struct AlignedFields {
    Field min, max;
    AlignedBox operator()(Index i) const {
        return {{min(i, 0), min(i, 1), min(i, 2)}, {max(i, 0), max(i, 1), max(i, 2)}};
    }
};

// Oriented boxes and parallelepipeds: center, axes (rows), extents.
template <class Box>
struct FrameFields {
    Field center, axes, extents;
    Box operator()(Index i) const {
        const Field& a = axes;  // row k is axes[k]
        return {{center(i, 0), center(i, 1), center(i, 2)},
                {Vec{a(i, 0), a(i, 1), a(i, 2)}, Vec{a(i, 3), a(i, 4), a(i, 5)}, Vec{a(i, 6), a(i, 7), a(i, 8)}},
                {extents(i, 0), extents(i, 1), extents(i, 2)}};
    }
};

// One batch: n elements (the fields' common length), answers into result[0, n).
struct Batch {
    Index n = 0;
    bool box_single = false, cylinder_single = false;  // given once for all (broadcast)
    boxcyl::QueryOptions options;
    unsigned threads = 0;  // 0: all cores
    bool* result = nullptr;
    // Given: the clearance query, dist(box, cylinder) ≤ *margin (a valid margin), exact whatever the
    // options say, as the scalar boxcyl.intersects(..., margin=) answers it.
    std::optional<double> margin;
};

// Whether the batch is short enough to run on the calling thread, uninterrupted.
bool brief(const Batch& b);
// Answers the batch (the single box and cylinder, and the margin, already validated). Returns the message naming its
// first invalid element by index, or an empty string. Throws boxcyl::batch::Stopped once `stop` is
// requested.
std::string intersects(const AlignedFields& boxes, const CylinderFields& cylinders, const Batch& b,
                       const std::stop_token& stop);
std::string intersects(const FrameFields<OrientedBox>& boxes, const CylinderFields& cylinders, const Batch& b,
                       const std::stop_token& stop);
std::string intersects(const FrameFields<Parallelepiped>& boxes, const CylinderFields& cylinders, const Batch& b,
                       const std::stop_token& stop);

// One distance batch: n elements, answers into lower[i], upper[i] and rows i of on_box and on_cylinder
// (C-contiguous (n, 3) arrays), as the scalar boxcyl::distance gives them; with `normal`, the signed
// distance's, as the scalar boxcyl::signed_distance gives them, its normals into rows i of `normal`.
struct DistanceBatch {
    Index n = 0;
    bool box_single = false, cylinder_single = false;  // given once for all (broadcast)
    unsigned threads = 0;                              // 0: all cores
    double* lower = nullptr;
    double* upper = nullptr;
    double* on_box = nullptr;
    double* on_cylinder = nullptr;
    double* normal = nullptr;  // given: the signed distance
};

// Whether the batch is short enough to run on the calling thread, uninterrupted.
bool brief(const DistanceBatch& b);
// The distances (or signed distances) of the batch (the single box and cylinder already validated):
// the scalar query per element, each element checked first. Returns the message naming the first
// invalid element by index, or an empty string. Throws boxcyl::batch::Stopped once `stop` is requested.
std::string distances(const AlignedFields& boxes, const CylinderFields& cylinders, const DistanceBatch& b,
                      const std::stop_token& stop);
std::string distances(const FrameFields<OrientedBox>& boxes, const CylinderFields& cylinders, const DistanceBatch& b,
                      const std::stop_token& stop);
std::string distances(const FrameFields<Parallelepiped>& boxes, const CylinderFields& cylinders,
                      const DistanceBatch& b, const std::stop_token& stop);

// ---- grid.cpp: the grid query. ----

// The cells (i, j, k) of `grid` that `cylinder` meets, sorted; at most max_cells of them (< 0: no
// limit), or std::invalid_argument. Throws boxcyl::batch::Stopped once `stop` is requested.
std::vector<boxcyl::CellIndex> grid_cells(const boxcyl::Grid& grid, const Cylinder& cylinder, double margin, std::int64_t max_cells,
                                          const std::stop_token& stop);

}  // namespace boxcyl_python
