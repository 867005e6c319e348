// boxcyl::boxcyl: the scalar queries of boxcyl/compiled.hpp, the header-only templates
// (boxcyl/query.hpp) for double and float, compiled once here.
#include "boxcyl/query.hpp"

#include "boxcyl/compiled.hpp"

namespace boxcyl::compiled {

bool intersects(const AlignedBox<double>& box, const Cylinder<double>& cyl, const QueryOptions& opt) {
    return boxcyl::detail::dispatch(box, cyl, opt);
}
bool intersects(const OrientedBox<double>& box, const Cylinder<double>& cyl, const QueryOptions& opt) {
    return boxcyl::detail::dispatch(box, cyl, opt);
}
bool intersects(const CanonicalBox<double>& box, const Cylinder<double>& cyl, const QueryOptions& opt) {
    return boxcyl::detail::dispatch(box, cyl, opt);
}
bool intersects(const AlignedBox<float>& box, const Cylinder<float>& cyl, const QueryOptions& opt) {
    return boxcyl::detail::dispatch(box, cyl, opt);
}
bool intersects(const OrientedBox<float>& box, const Cylinder<float>& cyl, const QueryOptions& opt) {
    return boxcyl::detail::dispatch(box, cyl, opt);
}
bool intersects(const CanonicalBox<float>& box, const Cylinder<float>& cyl, const QueryOptions& opt) {
    return boxcyl::detail::dispatch(box, cyl, opt);
}

bool intersects(const Parallelepiped<double>& box, const Cylinder<double>& cyl, const QueryOptions& opt) {
    return boxcyl::detail::dispatch(box, cyl, opt);
}
bool intersects(const Parallelepiped<float>& box, const Cylinder<float>& cyl, const QueryOptions& opt) {
    return boxcyl::detail::dispatch(box, cyl, opt);
}

}  // namespace boxcyl::compiled
