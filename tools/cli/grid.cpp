// See grid.hpp. The grid and the counts are read here; everything else (JSON rules, the id, the
// cylinder, error lines) is jsonl_query's, and the geometry is the library's (boxcyl/grid.hpp, called
// through the compiled library).
#include "grid.hpp"

#include <algorithm>   // std::sort
#include <array>       // the counts
#include <cstdint>     // std::int64_t, std::uint64_t
#include <cstring>     // std::strerror
#include <exception>   // failures of the library call
#include <memory>      // the input file
#include <istream>     // std::getline
#include <limits>      // the int64 range
#include <new>         // std::bad_alloc
#include <ostream>     // output lines
#include <string>      // help text, output lines
#include <vector>      // the cells

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "app.hpp"  // exit codes
#include "boxcyl/geometry/validate.hpp"
#include "boxcyl/margin.hpp"
#if defined(BOXCYL_CLI_EXACT)
#include "boxcyl/compiled.hpp"  // for_each_cell, from libboxcyl
#endif

namespace boxcyl::cli {

namespace {

constexpr const char* grid_help = R"(INPUT
  JSON Lines (UTF-8): one query per line, a JSON object
    {"id": ID, "grid": GRID, "cylinder": CYLINDER, "margin": M}
  ID        optional; a string or a number, echoed back unchanged as the first key
  M         optional; a number >= 0: list the cells within distance M of the cylinder instead
            (as `boxcyl intersect` answers a line with that margin), exactly
  GRID      {"origin": [x,y,z], "cell_size": [x,y,z], "counts": [nx,ny,nz]}
            cell_size > 0 per axis; counts: integers, 0 <= counts <= 2^53 (0: no cells)
  CYLINDER  {"center": [x,y,z], "axis": [x,y,z], "radius": r, "height": h}  (r, h >= 0),
            as for `boxcyl intersect`
  Numbers, ids, other keys and duplicate keys are treated as by `boxcyl intersect`.

SEMANTICS
  Cell (i,j,k), 0 <= i < nx etc., is the closed box whose bounds along each axis are
    bound(n) = origin + n*cell_size, rounded once to the nearest double (as fma(n, cell_size, origin))
  for n = i and i+1 (j, j+1 along y; k, k+1 along z). Adjacent cells share their faces exactly and
  the cells tile the grid's box. A cell is listed if and only if the cylinder intersects that box,
  exactly (as `boxcyl intersect` answers by default: closed solids, touching counts). The far bound
  origin + counts*cell_size must stay within the double range.

OUTPUT
  Exactly one JSON line per input line, in input order:
    {"id": ID, "cells": [[i,j,k], ...], "count": N}   the cells, in lexicographic order of (i,j,k)
    {"id": ID, "error": "line N: FIELD: REASON"}       for a bad line, as `boxcyl intersect`
  ("id" only when the line has a valid one). The tool reports a bad line and goes on. A line
  whose answer has more than --max-cells cells (default 1000000) gets the error line
  "line N: the answer has more than M cells ...", found without listing them all; lines
  longer than --max-line-bytes, and lines memory does not suffice for, as for intersect.

EXAMPLE
  echo '{"grid":{"origin":[0,0,0],"cell_size":[1,1,1],"counts":[4,4,4]},"cylinder":{"center":[1,2,2],"axis":[1,0,0],"radius":0,"height":1}}' | boxcyl grid
  {"cells": [[0, 1, 1], [0, 1, 2], [0, 2, 1], [0, 2, 2], [1, 1, 1], [1, 1, 2], [1, 2, 1], [1, 2, 2]], "count": 8}
)";

using json = nlohmann::json;

#if defined(BOXCYL_CLI_EXACT)
std::string read_counts(const json& g, std::array<std::int64_t, 3>& out) {
    const auto it = g.find("counts");
    if (it == g.end()) return "grid.counts: missing";
    const json& c = *it;
    if (!c.is_array() || c.size() != 3 || !c[0].is_number_integer() || !c[1].is_number_integer() ||
        !c[2].is_number_integer())
        return "grid.counts: expected an array of 3 integers";
    for (std::size_t a = 0; a < 3; ++a) {
        // Beyond int64 (up to 2^64 − 1) the value is unsigned; validate() names anything above 2^53.
        if (c[a].is_number_unsigned() && c[a].get<std::uint64_t>() > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
            return "grid.counts[" + std::to_string(a) + "]: exceeds 2^53";
        out[a] = c[a].get<std::int64_t>();
    }
    return {};
}

std::string read_grid(const json& root, Grid& g) {
    const auto it = root.find("grid");
    if (it == root.end()) return "grid: missing";
    if (!it->is_object()) return "grid: expected an object";
    if (auto e = check_keys_field(*it, "grid", {"origin", "cell_size", "counts"}); !e.empty()) return e;
    if (auto e = read_vec3_field(*it, "origin", "grid.origin", g.origin); !e.empty()) return e;
    if (auto e = read_vec3_field(*it, "cell_size", "grid.cell_size", g.cell_size); !e.empty()) return e;
    return read_counts(*it, g.counts);
}

std::string format_cells(const std::string& id, const std::vector<CellIndex>& cells) {
    std::string s = "{";
    if (!id.empty()) s += "\"id\": " + id + ", ";
    s += "\"cells\": [";
    for (std::size_t n = 0; n < cells.size(); ++n) {
        if (n > 0) s += ", ";
        s += '[';
        s += std::to_string(cells[n][0]);
        s += ", ";
        s += std::to_string(cells[n][1]);
        s += ", ";
        s += std::to_string(cells[n][2]);
        s += ']';
    }
    s += "], \"count\": " + std::to_string(cells.size()) + "}";
    return s;
}
#endif

}  // namespace

namespace {

#if defined(BOXCYL_CLI_EXACT)
// Thrown out of the grid walk when the answer would exceed --max-cells.
struct TooManyCells {};

// for_each_cell's cells, at most max_cells of them, in lexicographic order; throws TooManyCells
// as soon as there are more, without finishing the walk.
// With a margin, the cells within that distance (for_each_cell_within).
std::vector<CellIndex> bounded_cells(const Grid& grid, const Cylinder<double>& cylinder, double margin,
                                     std::int64_t max_cells) {
    std::vector<CellIndex> out;
    const auto max = static_cast<std::size_t>(max_cells);
    auto keep = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
        if (out.size() == max) throw TooManyCells{};
        out.push_back({i, j, k});
    };
    if (margin == 0)
        for_each_cell(grid, cylinder, keep);
    else
        for_each_cell_within(grid, cylinder, margin, keep);
    std::sort(out.begin(), out.end());
    return out;
}
#endif

LineAnswer answer_grid_line_unguarded(std::string_view text, std::size_t line_number, const GridOptions& opt) {
#if defined(BOXCYL_CLI_EXACT)
    Grid grid;
    Cylinder<double> cylinder;
    double margin = 0;
    const ObjectLine o = parse_object_line(text, line_number, [&](const json& root) -> std::string {
        if (auto e = check_keys_field(root, "", {"id", "grid", "cylinder", "margin"}); !e.empty()) return e;
        if (auto e = read_grid(root, grid); !e.empty()) return e;
        if (auto e = read_cylinder_field(root, cylinder); !e.empty()) return e;
        if (const auto m = root.find("margin"); m != root.end()) {
            if (!m->is_number()) return "margin: expected a number";
            margin = m->get<double>();
        }
        if (const Validity v = validate(grid); !v.ok()) return v.message();
        if (const Validity v = validate(cylinder); !v.ok()) return v.message();
        if (const Validity v = validate_margin(margin); !v.ok()) return v.message();
        return {};
    });
    if (!o.error.empty()) return {format_error(o.id, o.error), false};
    const std::string where = "line " + std::to_string(line_number) + ": ";
    try {
        return {format_cells(o.id, bounded_cells(grid, cylinder, margin, opt.max_cells)), true};
    } catch (const TooManyCells&) {
        return {format_error(o.id, where + "the answer has more than " + std::to_string(opt.max_cells) +
                                       " cells (--max-cells)"),
                false};
    } catch (const std::bad_alloc&) {
        return {format_error(o.id, where + "out of memory answering the line"), false};
    } catch (const std::exception& e) {
        // Not expected for validated input; reported per line.
        return {format_error(o.id, where + "query failed: " + e.what()), false};
    }
#else
    (void)text, (void)opt;
    return {format_error({}, "line " + std::to_string(line_number) + ": grid needs the exact backend (GMP)"), false};
#endif
}

}  // namespace

LineAnswer answer_grid_line(std::string_view text, std::size_t line_number, const GridOptions& opt) {
    try {
        return answer_grid_line_unguarded(text, line_number, opt);
    } catch (const std::bad_alloc&) {
        return {format_error({}, "line " + std::to_string(line_number) + ": out of memory answering the line"), false};
    } catch (const std::exception& e) {
        return {format_error({}, "line " + std::to_string(line_number) + ": " + e.what()), false};
    }
}

StreamCounts process_grid_stream(std::istream& in, std::ostream& out, const GridOptions& opt) {
    return process_lines(in, out, opt.max_line_bytes,
                         [&opt](std::string_view line, std::size_t n) { return answer_grid_line(line, n, opt); });
}

void add_grid_command(CLI::App& app, GridCommand& cmd) {
    cmd.app = app.add_subcommand(
        "grid", "For each input line (a grid and a cylinder), list the grid cells the cylinder intersects");
    cmd.app->footer(std::string(grid_help) + "\n" + exit_status_help);
    cmd.app->add_option("file", cmd.file, "JSON Lines input; '-' or none: standard input");
    add_max_line_bytes_option(*cmd.app, cmd.options.max_line_bytes);
    cmd.app->add_option("--max-cells", cmd.options.max_cells,
                        "Most cells one answer may list (default " + std::to_string(default_max_cells) +
                            "); a line whose answer has more gets an error line")
        ->check(CLI::Range(std::int64_t{0}, std::numeric_limits<std::int64_t>::max()));
}

int run_grid(const GridCommand& cmd, std::istream& in, std::ostream& out, std::ostream& err) {
#if !defined(BOXCYL_CLI_EXACT)
    (void)cmd, (void)in, (void)out;
    err << "boxcyl: grid needs the exact backend (GMP); this build has none\n";
    return exit_usage;
#else
    std::unique_ptr<std::istream> f;
    if (cmd.file != "-") {
        f = open_input(cmd.file, err);
        if (!f) return exit_usage;
    }
    std::istream& input = f ? *f : in;
    return end_of_run(process_grid_stream(input, out, cmd.options), input, input_name(cmd.file), out, err);
#endif
}

}  // namespace boxcyl::cli
