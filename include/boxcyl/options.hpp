// The query's options: which algorithm, in which arithmetic (documented in boxcyl/query.hpp). A header
// of its own so that the compiled library's declarations (boxcyl/compiled.hpp) need nothing heavier.
#pragma once

#include "boxcyl/filtered/stats.hpp"

namespace boxcyl {

enum class Algorithm { inequalities, hull, lcp, oracle };
enum class Arithmetic { float32, float64, exact, filtered };

struct QueryOptions {
    Algorithm algorithm = Algorithm::inequalities;
    Arithmetic arithmetic = Arithmetic::filtered;
    // The exact default (Arithmetic::filtered) counts and times its pipeline's rows here when given
    // (filtered/stats.hpp): where the time goes on the caller's data. Not thread-safe: one per thread.
    filtered::Stats* stats = nullptr;
};

}  // namespace boxcyl
