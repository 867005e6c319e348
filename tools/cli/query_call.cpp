// The tool's only call into the library's query front door (kept apart so the rest of the tool does
// not depend on which algorithms exist).
#include <variant>  // std::visit over the box kinds

#include "boxcyl/query.hpp"
#include "jsonl_query.hpp"

namespace boxcyl::cli {

bool run_query(const Query& q, const QueryOptions& opt) {
    return std::visit([&](const auto& box) { return boxcyl::intersects(box, q.cylinder, opt); }, q.box);
}

}  // namespace boxcyl::cli
