// boxcyl::boxcyl: the batch queries of boxcyl/compiled.hpp (intersects, the clearance form
// within_distance and the distances), those of boxcyl/batch.hpp compiled once here (with boxcyl::batch_dispatch linked:
// the AVX2 and AVX-512 kernels are chosen at run time).
#include "boxcyl/batch.hpp"

// The calls into boxcyl/batch.hpp come before boxcyl/compiled.hpp is included: after it, a call
// naming boxcyl::batch::intersects would also find the compiled overloads (same signatures).
namespace {

using boxcyl::Cylinder;
using boxcyl::OrientedBox;
using boxcyl::Parallelepiped;
using boxcyl::batch::AlignedBoxes;
using boxcyl::batch::Options;
using boxcyl::batch::Stats;
using Mask = std::span<std::uint64_t>;
using Bools = std::span<bool>;

bool header_available(boxcyl::batch::Kernel k) { return boxcyl::batch::available(k); }

Stats header_aligned(const Cylinder<double>& c, const AlignedBoxes<double>& b, Mask out, const Options& o) {
    return boxcyl::batch::intersects(c, b, out, o);
}
Stats header_aligned(const Cylinder<double>& c, const AlignedBoxes<double>& b, Bools out, const Options& o) {
    return boxcyl::batch::intersects(c, b, out, o);
}
Stats header_aligned(const Cylinder<double>& c, const AlignedBoxes<float>& b, Mask out, const Options& o) {
    return boxcyl::batch::intersects(c, b, out, o);
}
Stats header_aligned(const Cylinder<double>& c, const AlignedBoxes<float>& b, Bools out, const Options& o) {
    return boxcyl::batch::intersects(c, b, out, o);
}
template <class T>
Stats header_rows(const Cylinder<double>& c, std::span<const boxcyl::AlignedBox<T>> b, Mask out, const Options& o) {
    return boxcyl::batch::intersects(c, b, out, o);
}
template <class T>
Stats header_rows(const Cylinder<double>& c, std::span<const boxcyl::AlignedBox<T>> b, Bools out, const Options& o) {
    return boxcyl::batch::intersects(c, b, out, o);
}
Stats header_oriented(const Cylinder<double>& c, std::span<const OrientedBox<double>> b, Mask out, const Options& o) {
    return boxcyl::batch::intersects(c, b, out, o);
}
Stats header_oriented(const Cylinder<double>& c, std::span<const OrientedBox<double>> b, Bools out, const Options& o) {
    return boxcyl::batch::intersects(c, b, out, o);
}
Stats header_oriented(const Cylinder<double>& c, std::span<const OrientedBox<float>> b, Mask out, const Options& o) {
    return boxcyl::batch::intersects(c, b, out, o);
}
Stats header_oriented(const Cylinder<double>& c, std::span<const OrientedBox<float>> b, Bools out, const Options& o) {
    return boxcyl::batch::intersects(c, b, out, o);
}

template <class T>
Stats header_parallelepiped(const Cylinder<double>& c, std::span<const Parallelepiped<T>> b, Mask out, const Options& o) {
    return boxcyl::batch::intersects(c, b, out, o);
}
template <class T>
Stats header_parallelepiped(const Cylinder<double>& c, std::span<const Parallelepiped<T>> b, Bools out, const Options& o) {
    return boxcyl::batch::intersects(c, b, out, o);
}

// The clearance form for every layout and output (the argument types are those of the compiled
// declarations, so the call resolves to the header's overload).
template <class Boxes, class Out>
Stats header_within(const Cylinder<double>& c, const Boxes& b, double m, Out out, const Options& o) {
    return boxcyl::batch::within_distance(c, b, m, out, o);
}

template <class Boxes>
Stats header_distance(const Cylinder<double>& c, const Boxes& b, std::span<boxcyl::Distance> out, const Options& o) {
    return boxcyl::batch::distance(c, b, out, o);
}
template <class Boxes>
Stats header_distance_within(const Cylinder<double>& c, const Boxes& b, double m, std::span<boxcyl::Distance> out,
                             const Options& o) {
    return boxcyl::batch::distance_within(c, b, m, out, o);
}

template <class Boxes>
Stats header_signed_distance(const Cylinder<double>& c, const Boxes& b, std::span<boxcyl::SignedDistance> out,
                             const Options& o) {
    return boxcyl::batch::signed_distance(c, b, out, o);
}

}  // namespace

#include "boxcyl/compiled.hpp"

namespace boxcyl::batch::inline compiled {  // inline, as compiled.hpp declares it

bool available(Kernel k) { return header_available(k); }

Stats intersects(const Cylinder<double>& c, const AlignedBoxes<double>& b, Mask out, const Options& o) {
    return header_aligned(c, b, out, o);
}
Stats intersects(const Cylinder<double>& c, const AlignedBoxes<double>& b, Bools out, const Options& o) {
    return header_aligned(c, b, out, o);
}
Stats intersects(const Cylinder<double>& c, const AlignedBoxes<float>& b, Mask out, const Options& o) {
    return header_aligned(c, b, out, o);
}
Stats intersects(const Cylinder<double>& c, const AlignedBoxes<float>& b, Bools out, const Options& o) {
    return header_aligned(c, b, out, o);
}
Stats intersects(const Cylinder<double>& c, std::span<const AlignedBox<double>> b, Mask out, const Options& o) {
    return header_rows(c, b, out, o);
}
Stats intersects(const Cylinder<double>& c, std::span<const AlignedBox<double>> b, Bools out, const Options& o) {
    return header_rows(c, b, out, o);
}
Stats intersects(const Cylinder<double>& c, std::span<const AlignedBox<float>> b, Mask out, const Options& o) {
    return header_rows(c, b, out, o);
}
Stats intersects(const Cylinder<double>& c, std::span<const AlignedBox<float>> b, Bools out, const Options& o) {
    return header_rows(c, b, out, o);
}
Stats intersects(const Cylinder<double>& c, std::span<const OrientedBox<double>> b, Mask out, const Options& o) {
    return header_oriented(c, b, out, o);
}
Stats intersects(const Cylinder<double>& c, std::span<const OrientedBox<double>> b, Bools out, const Options& o) {
    return header_oriented(c, b, out, o);
}
Stats intersects(const Cylinder<double>& c, std::span<const OrientedBox<float>> b, Mask out, const Options& o) {
    return header_oriented(c, b, out, o);
}
Stats intersects(const Cylinder<double>& c, std::span<const OrientedBox<float>> b, Bools out, const Options& o) {
    return header_oriented(c, b, out, o);
}

Stats intersects(const Cylinder<double>& c, std::span<const Parallelepiped<double>> b, Mask out, const Options& o) {
    return header_parallelepiped(c, b, out, o);
}
Stats intersects(const Cylinder<double>& c, std::span<const Parallelepiped<double>> b, Bools out, const Options& o) {
    return header_parallelepiped(c, b, out, o);
}
Stats intersects(const Cylinder<double>& c, std::span<const Parallelepiped<float>> b, Mask out, const Options& o) {
    return header_parallelepiped(c, b, out, o);
}
Stats intersects(const Cylinder<double>& c, std::span<const Parallelepiped<float>> b, Bools out, const Options& o) {
    return header_parallelepiped(c, b, out, o);
}


Stats within_distance(const Cylinder<double>& c, const AlignedBoxes<double>& b, double m, Mask out, const Options& o) {
    return header_within(c, b, m, out, o);
}
Stats within_distance(const Cylinder<double>& c, const AlignedBoxes<double>& b, double m, Bools out, const Options& o) {
    return header_within(c, b, m, out, o);
}
Stats within_distance(const Cylinder<double>& c, const AlignedBoxes<float>& b, double m, Mask out, const Options& o) {
    return header_within(c, b, m, out, o);
}
Stats within_distance(const Cylinder<double>& c, const AlignedBoxes<float>& b, double m, Bools out, const Options& o) {
    return header_within(c, b, m, out, o);
}
Stats within_distance(const Cylinder<double>& c, std::span<const AlignedBox<double>> b, double m, Mask out, const Options& o) {
    return header_within(c, b, m, out, o);
}
Stats within_distance(const Cylinder<double>& c, std::span<const AlignedBox<double>> b, double m, Bools out, const Options& o) {
    return header_within(c, b, m, out, o);
}
Stats within_distance(const Cylinder<double>& c, std::span<const AlignedBox<float>> b, double m, Mask out, const Options& o) {
    return header_within(c, b, m, out, o);
}
Stats within_distance(const Cylinder<double>& c, std::span<const AlignedBox<float>> b, double m, Bools out, const Options& o) {
    return header_within(c, b, m, out, o);
}
Stats within_distance(const Cylinder<double>& c, std::span<const OrientedBox<double>> b, double m, Mask out, const Options& o) {
    return header_within(c, b, m, out, o);
}
Stats within_distance(const Cylinder<double>& c, std::span<const OrientedBox<double>> b, double m, Bools out, const Options& o) {
    return header_within(c, b, m, out, o);
}
Stats within_distance(const Cylinder<double>& c, std::span<const OrientedBox<float>> b, double m, Mask out, const Options& o) {
    return header_within(c, b, m, out, o);
}
Stats within_distance(const Cylinder<double>& c, std::span<const OrientedBox<float>> b, double m, Bools out, const Options& o) {
    return header_within(c, b, m, out, o);
}
Stats within_distance(const Cylinder<double>& c, std::span<const Parallelepiped<double>> b, double m, Mask out, const Options& o) {
    return header_within(c, b, m, out, o);
}
Stats within_distance(const Cylinder<double>& c, std::span<const Parallelepiped<double>> b, double m, Bools out, const Options& o) {
    return header_within(c, b, m, out, o);
}
Stats within_distance(const Cylinder<double>& c, std::span<const Parallelepiped<float>> b, double m, Mask out, const Options& o) {
    return header_within(c, b, m, out, o);
}
Stats within_distance(const Cylinder<double>& c, std::span<const Parallelepiped<float>> b, double m, Bools out, const Options& o) {
    return header_within(c, b, m, out, o);
}

Stats distance(const Cylinder<double>& c, const AlignedBoxes<double>& b, std::span<Distance> out, const Options& o) {
    return header_distance(c, b, out, o);
}
Stats distance_within(const Cylinder<double>& c, const AlignedBoxes<double>& b, double m, std::span<Distance> out, const Options& o) {
    return header_distance_within(c, b, m, out, o);
}
Stats distance(const Cylinder<double>& c, const AlignedBoxes<float>& b, std::span<Distance> out, const Options& o) {
    return header_distance(c, b, out, o);
}
Stats distance_within(const Cylinder<double>& c, const AlignedBoxes<float>& b, double m, std::span<Distance> out, const Options& o) {
    return header_distance_within(c, b, m, out, o);
}
Stats distance(const Cylinder<double>& c, std::span<const AlignedBox<double>> b, std::span<Distance> out, const Options& o) {
    return header_distance(c, b, out, o);
}
Stats distance_within(const Cylinder<double>& c, std::span<const AlignedBox<double>> b, double m, std::span<Distance> out, const Options& o) {
    return header_distance_within(c, b, m, out, o);
}
Stats distance(const Cylinder<double>& c, std::span<const AlignedBox<float>> b, std::span<Distance> out, const Options& o) {
    return header_distance(c, b, out, o);
}
Stats distance_within(const Cylinder<double>& c, std::span<const AlignedBox<float>> b, double m, std::span<Distance> out, const Options& o) {
    return header_distance_within(c, b, m, out, o);
}
Stats distance(const Cylinder<double>& c, std::span<const OrientedBox<double>> b, std::span<Distance> out, const Options& o) {
    return header_distance(c, b, out, o);
}
Stats distance_within(const Cylinder<double>& c, std::span<const OrientedBox<double>> b, double m, std::span<Distance> out, const Options& o) {
    return header_distance_within(c, b, m, out, o);
}
Stats distance(const Cylinder<double>& c, std::span<const OrientedBox<float>> b, std::span<Distance> out, const Options& o) {
    return header_distance(c, b, out, o);
}
Stats distance_within(const Cylinder<double>& c, std::span<const OrientedBox<float>> b, double m, std::span<Distance> out, const Options& o) {
    return header_distance_within(c, b, m, out, o);
}
Stats distance(const Cylinder<double>& c, std::span<const Parallelepiped<double>> b, std::span<Distance> out, const Options& o) {
    return header_distance(c, b, out, o);
}
Stats distance_within(const Cylinder<double>& c, std::span<const Parallelepiped<double>> b, double m, std::span<Distance> out, const Options& o) {
    return header_distance_within(c, b, m, out, o);
}
Stats distance(const Cylinder<double>& c, std::span<const Parallelepiped<float>> b, std::span<Distance> out, const Options& o) {
    return header_distance(c, b, out, o);
}
Stats distance_within(const Cylinder<double>& c, std::span<const Parallelepiped<float>> b, double m, std::span<Distance> out, const Options& o) {
    return header_distance_within(c, b, m, out, o);
}

Stats signed_distance(const Cylinder<double>& c, const AlignedBoxes<double>& b, std::span<SignedDistance> out, const Options& o) {
    return header_signed_distance(c, b, out, o);
}
Stats signed_distance(const Cylinder<double>& c, const AlignedBoxes<float>& b, std::span<SignedDistance> out, const Options& o) {
    return header_signed_distance(c, b, out, o);
}
Stats signed_distance(const Cylinder<double>& c, std::span<const AlignedBox<double>> b, std::span<SignedDistance> out, const Options& o) {
    return header_signed_distance(c, b, out, o);
}
Stats signed_distance(const Cylinder<double>& c, std::span<const AlignedBox<float>> b, std::span<SignedDistance> out, const Options& o) {
    return header_signed_distance(c, b, out, o);
}
Stats signed_distance(const Cylinder<double>& c, std::span<const OrientedBox<double>> b, std::span<SignedDistance> out, const Options& o) {
    return header_signed_distance(c, b, out, o);
}
Stats signed_distance(const Cylinder<double>& c, std::span<const OrientedBox<float>> b, std::span<SignedDistance> out, const Options& o) {
    return header_signed_distance(c, b, out, o);
}
Stats signed_distance(const Cylinder<double>& c, std::span<const Parallelepiped<double>> b, std::span<SignedDistance> out, const Options& o) {
    return header_signed_distance(c, b, out, o);
}
Stats signed_distance(const Cylinder<double>& c, std::span<const Parallelepiped<float>> b, std::span<SignedDistance> out, const Options& o) {
    return header_signed_distance(c, b, out, o);
}

}  // namespace boxcyl::batch::compiled
