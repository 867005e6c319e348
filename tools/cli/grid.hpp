// `boxcyl grid`: JSON Lines in (a grid and a cylinder per line), JSON Lines out (the indices of the
// cells the cylinder intersects, exactly: boxcyl/grid.hpp). Parsing shares jsonl_query's JSON layer,
// so numbers, ids, duplicate keys and error lines behave exactly as in `intersect`.
#pragma once

#include <cstddef>      // std::size_t
#include <cstdint>      // std::int64_t
#include <iosfwd>       // std::istream, std::ostream
#include <string>       // option values, output lines
#include <string_view>  // input lines

#include "jsonl_query.hpp"  // LineAnswer

namespace CLI {
class App;
}

namespace boxcyl::cli {

// The most cells one answer may list (--max-cells); beyond it the line gets an error line. A cell
// costs about 40 bytes of memory while the answer is built (24 as an index, ~17 as output text).
inline constexpr std::int64_t default_max_cells = 1'000'000;

struct GridOptions {
    std::int64_t max_cells = default_max_cells;
    std::size_t max_line_bytes = default_max_line_bytes;  // as for `intersect`
};

// Answers one input line: {"id": ID, "cells": [[i,j,k], ...], "count": N} with the cells in
// lexicographic order, or an error line as `intersect` writes it (also when the answer would have more
// than opt.max_cells cells, or memory runs out). Never throws. `line_number` counts from 1.
LineAnswer answer_grid_line(std::string_view text, std::size_t line_number, const GridOptions& opt = {});

// Reads `in` line by line, writes one output line per input line in order; returns the counts. Flushes
// whenever no more input is buffered, and stops early on a write error or a stop signal (as
// process_stream does).
StreamCounts process_grid_stream(std::istream& in, std::ostream& out, const GridOptions& opt = {});

// The `grid` subcommand's command-line state.
struct GridCommand {
    CLI::App* app = nullptr;  // set by add_grid_command; app->parsed() says it was chosen
    std::string file = "-";   // input; "-": standard input
    GridOptions options;
};

// Registers `grid` on the top-level app; `cmd` must outlive the parse.
void add_grid_command(CLI::App& app, GridCommand& cmd);

// Runs `grid` after parsing. Exit codes as in app.hpp: 0 every line good, 1 some line bad, 2 usage
// error (unreadable input, no exact backend), 3 a read or write error, 128 + a stop signal.
int run_grid(const GridCommand& cmd, std::istream& in, std::ostream& out, std::ostream& err);

}  // namespace boxcyl::cli
