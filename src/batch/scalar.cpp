// boxcyl::batch_dispatch: the scalar exact default that the AVX2 and AVX-512 kernels send the lanes
// their filter leaves to (boxcyl/batch/dispatch.hpp), compiled once, for plain x86-64.
#include "boxcyl/batch/dispatch.hpp"
#include "boxcyl/filtered.hpp"

namespace boxcyl::batch::dispatch {

bool scalar_intersects(const AlignedBox<double>& box, const Cylinder<double>& cyl) {
    return filtered::query(box, cyl).intersect;
}
bool scalar_intersects(const OrientedBox<double>& box, const Cylinder<double>& cyl) {
    return filtered::query(box, cyl).intersect;
}

}  // namespace boxcyl::batch::dispatch
