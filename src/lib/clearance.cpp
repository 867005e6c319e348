// boxcyl::boxcyl: the clearance queries of boxcyl/compiled.hpp, the header-only templates
// (boxcyl/clearance.hpp) for double and float, compiled once here: checked and unchecked.
#include "boxcyl/clearance.hpp"

#include "boxcyl/compiled.hpp"

namespace boxcyl::inline compiled {  // inline, as compiled.hpp declares it

namespace {
// The templates by name (a plain call here would find the compiled functions themselves).
template <class B, class T>
bool checked(const B& box, const Cylinder<T>& cyl, T margin) {
    return boxcyl::within_distance<B, T>(box, cyl, margin);
}
template <class B, class T>
bool unchecked(const B& box, const Cylinder<T>& cyl, T margin) {
    return boxcyl::within_distance_unchecked<B, T>(box, cyl, margin);
}
}  // namespace

#define BOXCYL_COMPILED_CLEARANCE(Box, T)                                                          \
    bool within_distance(const Box<T>& box, const Cylinder<T>& cyl, T margin) {                    \
        return checked(box, cyl, margin);                                                          \
    }                                                                                              \
    bool within_distance_unchecked(const Box<T>& box, const Cylinder<T>& cyl, T margin) {          \
        return unchecked(box, cyl, margin);                                                        \
    }
BOXCYL_COMPILED_CLEARANCE(AlignedBox, double)
BOXCYL_COMPILED_CLEARANCE(OrientedBox, double)
BOXCYL_COMPILED_CLEARANCE(CanonicalBox, double)
BOXCYL_COMPILED_CLEARANCE(Parallelepiped, double)
BOXCYL_COMPILED_CLEARANCE(AlignedBox, float)
BOXCYL_COMPILED_CLEARANCE(OrientedBox, float)
BOXCYL_COMPILED_CLEARANCE(CanonicalBox, float)
BOXCYL_COMPILED_CLEARANCE(Parallelepiped, float)
#undef BOXCYL_COMPILED_CLEARANCE

}  // namespace boxcyl::compiled
