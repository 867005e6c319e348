// boxcyl::boxcyl: the signed distance queries of boxcyl/compiled.hpp, the header-only templates
// (boxcyl/signed_distance.hpp) for double and float, compiled once here: checked and unchecked.
#include "boxcyl/signed_distance.hpp"

#include "boxcyl/compiled.hpp"

namespace boxcyl::inline compiled {  // inline, as compiled.hpp declares it

namespace {
// The templates by name (a plain call here would find the compiled functions themselves).
template <class B, class T>
SignedDistance checked(const B& box, const Cylinder<T>& cyl) {
    return boxcyl::signed_distance<B, T>(box, cyl);
}
template <class B, class T>
SignedDistance unchecked(const B& box, const Cylinder<T>& cyl) {
    return boxcyl::signed_distance_unchecked<B, T>(box, cyl);
}
}  // namespace

#define BOXCYL_COMPILED_SIGNED_DISTANCE(Box, T)                                                                         \
    SignedDistance signed_distance(const Box<T>& box, const Cylinder<T>& cyl) { return checked(box, cyl); }             \
    SignedDistance signed_distance_unchecked(const Box<T>& box, const Cylinder<T>& cyl) { return unchecked(box, cyl); }
BOXCYL_COMPILED_SIGNED_DISTANCE(AlignedBox, double)
BOXCYL_COMPILED_SIGNED_DISTANCE(OrientedBox, double)
BOXCYL_COMPILED_SIGNED_DISTANCE(CanonicalBox, double)
BOXCYL_COMPILED_SIGNED_DISTANCE(Parallelepiped, double)
BOXCYL_COMPILED_SIGNED_DISTANCE(AlignedBox, float)
BOXCYL_COMPILED_SIGNED_DISTANCE(OrientedBox, float)
BOXCYL_COMPILED_SIGNED_DISTANCE(CanonicalBox, float)
BOXCYL_COMPILED_SIGNED_DISTANCE(Parallelepiped, float)
#undef BOXCYL_COMPILED_SIGNED_DISTANCE

}  // namespace boxcyl::compiled
