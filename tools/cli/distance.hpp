// `boxcyl distance`: JSON Lines in (the lines of `boxcyl intersect`, without "margin"), JSON Lines out
// (a proved enclosure of the distance and a nearest pair: boxcyl/distance.hpp; with --signed, of the
// signed distance, with its normal: boxcyl/signed_distance.hpp). Parsing, ids, error lines, --threads,
// input order, signals and write errors are intersect's (jsonl_query).
#pragma once

#include <cstddef>      // std::size_t
#include <iosfwd>       // std::istream, std::ostream
#include <string>       // option values, output lines
#include <string_view>  // input lines

#include "boxcyl/distance_types.hpp"
#include "jsonl_query.hpp"  // LineAnswer, StreamCounts

namespace CLI {
class App;
}

namespace boxcyl::cli {

struct DistanceOptions {
    std::size_t max_line_bytes = default_max_line_bytes;  // as for `intersect`
    unsigned threads = 1;                                 // as for `intersect`: 0 is one per core
    bool signed_distance = false;                         // --signed: the signed distance
};

// {"id": ID, "lower": L, "upper": U, "on_box": [x, y, z], "on_cylinder": [x, y, z]}: each number in
// the shortest text that reads back as the same double; a number that is not finite (an upper bound
// beyond the largest double) is null, since JSON has no infinity. `id` as for format_answer.
std::string format_distance(const std::string& id, const Distance& d);

// The same for the signed distance (--signed), with the normal after the bounds:
// {"id": ID, "lower": L, "upper": U, "normal": [x, y, z], "on_box": [x, y, z], "on_cylinder": [x, y, z]}.
std::string format_signed_distance(const std::string& id, const SignedDistance& d);

// Answers one input line with format_distance's line (format_signed_distance's when `signed_distance`),
// or an error line as `intersect` writes it. Never throws. `line_number` counts from 1.
LineAnswer answer_distance_line(std::string_view text, std::size_t line_number, bool signed_distance = false);

// Reads `in` line by line, writes one output line per input line in input order (the signed distance's
// when opt.signed_distance), on opt.threads threads; stops early on a write error or a stop signal, as answer_stream does (and throws
// ThreadsUnavailable as it does).
StreamCounts process_distance_stream(std::istream& in, std::ostream& out, const DistanceOptions& opt = {});

// The `distance` subcommand's command-line state.
struct DistanceCommand {
    CLI::App* app = nullptr;  // set by add_distance_command; app->parsed() says it was chosen
    std::string file = "-";   // input; "-": standard input
    DistanceOptions options;
    std::string refused;  // --algorithm / --arithmetic values, refused (they do not apply)
};

// Registers `distance` on the top-level app; `cmd` must outlive the parse.
void add_distance_command(CLI::App& app, DistanceCommand& cmd);

// Runs `distance` after parsing. Exit codes as in app.hpp: 0 every line good, 1 some line bad, 2 usage
// error (unreadable input, --algorithm or --arithmetic, no exact backend), 3 a read or write error,
// 4 threads unavailable (thrown: run_app reports it), 128 + a stop signal.
int run_distance(const DistanceCommand& cmd, std::istream& in, std::ostream& out, std::ostream& err);

}  // namespace boxcyl::cli
