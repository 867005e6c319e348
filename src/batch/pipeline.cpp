// The exact default's scalar pipeline (boxcyl/filtered.hpp), compiled once for plain x86-64: the batch
// kernels answer the lanes their filter leaves with it, and the compiled library's scalar, batch and
// grid queries call it too (they declare it extern: BOXCYL_PIPELINE_EXTERN); with and without the
// per-row statistics.
#include "boxcyl/filtered.hpp"

namespace boxcyl::filtered {

template Result query(const AlignedBox<double>&, const Cylinder<double>&);
template Result query(const OrientedBox<double>&, const Cylinder<double>&);
template Result query(const CanonicalBox<double>&, const Cylinder<double>&);
template Result query(const Parallelepiped<double>&, const Cylinder<double>&);
template Result query(const AlignedBox<double>&, const Cylinder<double>&, Stats&);
template Result query(const OrientedBox<double>&, const Cylinder<double>&, Stats&);
template Result query(const CanonicalBox<double>&, const Cylinder<double>&, Stats&);
template Result query(const Parallelepiped<double>&, const Cylinder<double>&, Stats&);

}  // namespace boxcyl::filtered
