// `boxcyl explain`: one query in, one SVG picture out (the convex-hull method's view along the cylinder axis,
// the verdict, small orthographic views). The geometry is boxcyl/explain/explanation.hpp; this file only
// draws it.
#pragma once

#include <cstddef>  // std::size_t
#include <iosfwd>   // std::istream, std::ostream
#include <string>   // SVG text, option values
#include <vector>   // text lines

#include "boxcyl/explain/explanation.hpp"
#include "options.hpp"  // default_max_line_bytes

namespace CLI {
class App;
}

namespace boxcyl::cli {

// A standalone SVG document (UTF-8) showing `e`. `label` (e.g. the query's id as JSON text; may be
// empty) goes into the title, `inputs` (lines describing the query) under it; all text is XML-escaped.
std::string render_svg(const explain::Explanation& e, const std::string& label, const std::vector<std::string>& inputs = {});

// The SVG element ids a picture carries (the tests look for them), by what they show; "margin" (the
// cylinder grown by the margin, seen along the axis) only when the query has a margin; "nearest" (the
// nearest pair seen along the axis; "view-top-nearest" etc. in the other views, all of class
// "nearest") only when the explanation has it (with_nearest) and the view's pixels of the pair are finite.
inline constexpr const char* svg_ids[] = {
    "verdict", "polygon", "disk", "axis-point", "closest", "gap", "box-shadow", "axial", "legend",
    "view-top", "view-front", "view-side", "margin", "nearest",
};

// The `explain` subcommand's command-line state.
struct ExplainCommand {
    CLI::App* app = nullptr;  // set by add_explain_command; app->parsed() says it was chosen
    std::string file = "-";   // input; "-": standard input
    std::string output;       // -o: output file; empty: standard output
    std::size_t line = 0;     // --line N: take line N of a JSON Lines input; 0: the input is one query
    std::size_t max_line_bytes = default_max_line_bytes;  // the longest line (or whole input) read
};

// Registers `explain` on the top-level app; `cmd` must outlive the parse.
void add_explain_command(CLI::App& app, ExplainCommand& cmd);

// Runs `explain` after parsing: reads the query (from `in` for "-"; with --line N only lines 1 to N),
// writes the SVG. Exit codes as in app.hpp: 0 done; 1 a bad query (the same message as `intersect`
// gives, on stderr); 2 usage error (an input that cannot be opened, an output that cannot be created,
// no exact backend); 3 a read or write error; 128 + a stop signal that came before the query was read.
int run_explain(const ExplainCommand& cmd, std::istream& in, std::ostream& out, std::ostream& err);

}  // namespace boxcyl::cli
