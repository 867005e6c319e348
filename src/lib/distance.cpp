// boxcyl::boxcyl: the distance queries of boxcyl/compiled.hpp, the header-only templates
// (boxcyl/distance.hpp) for double and float, compiled once here: checked and unchecked.
#include "boxcyl/distance.hpp"

#include "boxcyl/compiled.hpp"

namespace boxcyl::inline compiled {  // inline, as compiled.hpp declares it

namespace {
// The templates by name (a plain call here would find the compiled functions themselves).
template <class B, class T>
Distance checked(const B& box, const Cylinder<T>& cyl) {
    return boxcyl::distance<B, T>(box, cyl);
}
template <class B, class T>
Distance unchecked(const B& box, const Cylinder<T>& cyl) {
    return boxcyl::distance_unchecked<B, T>(box, cyl);
}
}  // namespace

#define BOXCYL_COMPILED_DISTANCE(Box, T)                                                                      \
    Distance distance(const Box<T>& box, const Cylinder<T>& cyl) { return checked(box, cyl); }             \
    Distance distance_unchecked(const Box<T>& box, const Cylinder<T>& cyl) { return unchecked(box, cyl); }
BOXCYL_COMPILED_DISTANCE(AlignedBox, double)
BOXCYL_COMPILED_DISTANCE(OrientedBox, double)
BOXCYL_COMPILED_DISTANCE(CanonicalBox, double)
BOXCYL_COMPILED_DISTANCE(Parallelepiped, double)
BOXCYL_COMPILED_DISTANCE(AlignedBox, float)
BOXCYL_COMPILED_DISTANCE(OrientedBox, float)
BOXCYL_COMPILED_DISTANCE(CanonicalBox, float)
BOXCYL_COMPILED_DISTANCE(Parallelepiped, float)
#undef BOXCYL_COMPILED_DISTANCE

}  // namespace boxcyl::compiled
