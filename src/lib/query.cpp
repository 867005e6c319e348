// boxcyl::boxcyl: the scalar queries of boxcyl/compiled.hpp, the header-only templates
// (boxcyl/query.hpp) for double and float, compiled once here: checked (intersects) and unchecked.
#include "boxcyl/query.hpp"

#include "boxcyl/compiled.hpp"

namespace boxcyl::inline compiled {  // inline, as compiled.hpp declares it

#define BOXCYL_COMPILED_QUERY(Box, T)                                                                          \
    bool intersects(const Box<T>& box, const Cylinder<T>& cyl, const QueryOptions& opt) {                     \
        boxcyl::detail::require_valid(box, cyl);                                                              \
        return boxcyl::detail::dispatch(box, cyl, opt);                                                       \
    }                                                                                                          \
    bool intersects_unchecked(const Box<T>& box, const Cylinder<T>& cyl, const QueryOptions& opt) {           \
        return boxcyl::detail::dispatch(box, cyl, opt);                                                       \
    }
BOXCYL_COMPILED_QUERY(AlignedBox, double)
BOXCYL_COMPILED_QUERY(OrientedBox, double)
BOXCYL_COMPILED_QUERY(CanonicalBox, double)
BOXCYL_COMPILED_QUERY(Parallelepiped, double)
BOXCYL_COMPILED_QUERY(AlignedBox, float)
BOXCYL_COMPILED_QUERY(OrientedBox, float)
BOXCYL_COMPILED_QUERY(CanonicalBox, float)
BOXCYL_COMPILED_QUERY(Parallelepiped, float)
#undef BOXCYL_COMPILED_QUERY

}  // namespace boxcyl::compiled
