// See app.hpp. CLI11 parses the command line; jsonl_query does the work.
#include "app.hpp"

#include <cerrno>        // errno after a failed open
#include <csignal>       // signal names
#include <cstring>       // std::strerror
#include <exception>     // the last-resort handler
#include <filesystem>    // refuse directories (they "open" but read nothing)
#include <iostream>      // std::cerr
#include <limits>        // option ranges
#include <new>           // std::bad_alloc
#include <string>        // help text
#include <system_error>  // threads that cannot be started
#include <vector>        // option value lists

#include <CLI/CLI.hpp>

#include "boxcyl/version.hpp"
#include "distance.hpp"
#include "explain.hpp"
#include "grid.hpp"
#include "io.hpp"
#include "jsonl_query.hpp"
#include "options.hpp"

namespace boxcyl::cli {

namespace {

constexpr const char* help_body = R"(INPUT
  JSON Lines (UTF-8): one query per line, a JSON object
    {"id": ID, "box": BOX, "cylinder": CYLINDER, "margin": M}
  ID        optional; a string or a number, echoed back unchanged as the first key
  M         optional; a number >= 0: the question becomes "does the box come within
            distance M of the cylinder?" (M = 0: do they touch?), answered exactly
            whatever --algorithm and --arithmetic say
  BOX       an aligned box   {"min": [x,y,z], "max": [x,y,z]}                 (min <= max)
            or an oriented box
                             {"center": [x,y,z], "axes": [[x,y,z],[x,y,z],[x,y,z]],
                              "extents": [a,b,c]}                           (extents >= 0)
            or any parallelepiped (axes of any length and angle, zero or parallel ones too)
                             {"kind": "parallelepiped", "center": [x,y,z],
                              "axes": [[x,y,z],[x,y,z],[x,y,z]], "extents": [a,b,c]}
            ("kind" is optional for the other two: "aligned" or "oriented")
  CYLINDER  {"center": [x,y,z], "axis": [x,y,z], "radius": r, "height": h}  (r, h >= 0)
  No other key is accepted: a key the format does not have makes the line bad, and the
  message names it with the accepted key nearest to it ("cylinder.heigth: unknown key; did
  you mean "height"?"). A number is read as the nearest double (correctly rounded), so
  values written with 17 significant digits round-trip exactly; integers are numbers too.
  A number beyond the double range (e.g. 1e400) makes the line bad, as do duplicate keys,
  a NUL byte, and anything but blanks after the object.

SEMANTICS
  Both solids are closed: touching counts as intersecting. The cylinder is the set of
  points X with |u.(X - center)| <= height/2 and distance from X to the axis line
  <= radius, where u = axis/|axis|: the axis need not be unit length (only its direction
  counts) but must not be zero. radius 0 is a segment, height 0 a disk. The aligned box
  is min <= X <= max componentwise (min == max in a component gives a flat box). The
  oriented box is the parallelepiped { center + x0*A0 + x1*A1 + x2*A2 : |xi| <= extents[i] }
  spanned by its axes A0, A1, A2 exactly as given; the axes must be orthonormal within
  1e-4 (|Ai.Aj - delta_ij| <= 1e-4), else the line is bad. A "parallelepiped" is the same
  set for any axes (no orthonormality asked; dependent axes give a flat solid). NaN and Inf cannot be written
  in JSON and are never accepted. With --arithmetic float the inputs are rounded to float
  first and must still be valid then (finite, non-zero axis, ...).

OUTPUT
  Exactly one JSON line per input line, in input order:
    {"id": ID, "intersect": true}   or   {"id": ID, "intersect": false}
    {"id": ID, "error": "line N: FIELD: REASON"}       for a bad line
  ("id" only when the line has a valid one). A bad line is invalid JSON, a missing or
  mistyped field, an invalid value (e.g. "line 7: cylinder.radius: is negative"), an
  empty line, a line longer than --max-line-bytes (skipped without being kept in memory:
  "line 2: line is longer than N bytes ...") or a line that memory did not suffice to
  answer ("line 2: out of memory answering the line"); the tool reports it and goes on
  with the next line.

EXAMPLE
  boxcyl intersect examples/queries.jsonl
  echo '{"box":{"min":[0,0,0],"max":[1,1,1]},"cylinder":{"center":[2,0.5,0.5],"axis":[0,0,1],"radius":1,"height":1}}' | boxcyl intersect
)";

template <class Table>
std::vector<std::string> names_of(const Table& table) {
    std::vector<std::string> names;
    names.reserve(table.size());
    for (const auto& row : table) names.emplace_back(row.name);
    return names;
}

// The options of `intersect`, from the tables, for the top-level --help (which CLI11 would not show).
std::string options_section() {
    std::string s = "OPTIONS OF intersect\n  boxcyl intersect [--algorithm NAME] [--arithmetic NAME] [--threads N] [--max-line-bytes N] [FILE|-]\n";
    s += "  FILE: JSON Lines input; '-' or none reads standard input.\n";
    s += "  --threads N: answer blocks of lines on N threads (default 1; 0: one per core); same output\n";
    s += "  --max-line-bytes N: longest line read (default " + std::to_string(default_max_line_bytes) +
         "); a longer line\n    is skipped without being kept in memory and answered with an error line\n";
    s += "  --algorithm NAME (default " + std::string(default_algorithm) + ")\n";
    for (const auto& row : algorithm_choices)
        s += "    " + std::string(row.name) + ": " + std::string(row.description) + "\n";
    s += "  --arithmetic NAME (default " + std::string(default_arithmetic) + ")\n";
    for (const auto& row : arithmetic_choices)
        s += "    " + std::string(row.name) + ": " + std::string(row.description) + "\n";
    return s + "\n";
}

template <class Table>
std::string describe(const std::string& what, const Table& table) {
    std::string s = what;
    for (const auto& row : table) {
        s += "\n  ";
        s += row.name;
        s += ": ";
        s += row.description;
    }
    return s;
}

// When the command line chose no subcommand, what to say instead of CLI11's "A subcommand is required"
// (which it also says for a misspelt one): the unknown word or option, and the valid subcommands.
// Empty when a subcommand was chosen.
std::string missing_subcommand_message(CLI::App& app) {
    std::string valid;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
        if (sub->parsed()) return {};
        valid += valid.empty() ? "" : ", ";
        valid += sub->get_name();
    }
    const std::vector<std::string> rest = app.remaining();
    if (rest.empty()) return "boxcyl: a subcommand is required: " + valid;
    const std::string& first = rest.front();
    if (!first.empty() && first.front() == '-')
        return "boxcyl: unknown option '" + first + "' (a subcommand is required: " + valid + ")";
    return "boxcyl: unknown subcommand '" + first + "'; valid subcommands: " + valid;
}

const char* signal_name(int sig) {
    if (sig == SIGINT) return "SIGINT";
    if (sig == SIGTERM) return "SIGTERM";
    return "a signal";
}

// The help goes to `out`: a failed write of it is an error too.
int help_written(int code, std::ostream& out, std::ostream& err) {
    out.flush();
    if (out) return code;
    err << "boxcyl: cannot write standard output: " << describe_error(stream_error(out), "write error") << "\n";
    return exit_io;
}

int run_app_unguarded(int argc, const char* const* argv, std::istream& in, std::ostream& out, std::ostream& err);

}  // namespace

const char* const exit_status_help = R"(EXIT STATUS
  0  every line was a good query (also for empty input)
  1  at least one line was bad
  2  usage error: unknown option or value, a file that cannot be opened
  3  input/output error: reading the input or writing the output failed (message on
     standard error; the output is incomplete)
  4  out of resources: the threads of --threads could not be started, or memory ran out
     outside any one line, or another failure stopped the run (message on standard error;
     the answers written before it stand, in input order)
  128+N  stopped by signal N: 130 for SIGINT, 143 for SIGTERM. Reading stops; every line
     read in full is answered and written, in input order (a line cut short by the signal
     is not); a second signal ends the tool at once
)";

std::string describe_error(int error, const char* fallback) { return error != 0 ? std::strerror(error) : fallback; }

std::string input_name(const std::string& file) { return file == "-" ? "standard input" : "'" + file + "'"; }

int end_of_run(const StreamCounts& counts, const std::istream& in, const std::string& name, std::ostream& out,
               std::ostream& err) {
    out.flush();
    if (!out) {
        err << "boxcyl: cannot write standard output: " << describe_error(stream_error(out), "write error")
            << " (stopped after " << counts.lines << " input lines; their answers may be lost)\n";
        return exit_io;
    }
    if (in.bad()) {
        err << "boxcyl: cannot read " << name << ": " << describe_error(stream_error(in), "read error") << " (the "
            << counts.lines << " lines before the error are answered; the rest is not)\n";
        return exit_io;
    }
    if (const int sig = stop_signal(); sig != 0) {
        err << "boxcyl: stopped by " << signal_name(sig) << ": the " << counts.lines
            << " lines read in full are answered, in order; the rest of the input was not read\n";
        return exit_signal_base + sig;
    }
    return counts.bad == 0 ? exit_ok : exit_bad_lines;
}

int run_app(int argc, const char* const* argv, std::istream& in, std::ostream& out, std::ostream& err) {
    try {
        return run_app_unguarded(argc, argv, in, out, err);
    } catch (const ThreadsUnavailable& e) {
        out.flush();
        err << "boxcyl: " << e.what() << " (nothing was read; try fewer threads)\n";
        return exit_resources;
    } catch (const std::system_error& e) {
        out.flush();
        err << "boxcyl: stopped: " << e.what() << " (the answers written so far stand, in input order)\n";
        return exit_resources;
    } catch (const std::bad_alloc&) {
        // Lines report their own failures (memory included); this is memory outside any one line.
        out.flush();
        err << "boxcyl: stopped: out of memory outside any one line (the answers written so far stand, in input "
               "order)\n";
        return exit_resources;
    } catch (const std::exception& e) {
        out.flush();
        err << "boxcyl: stopped: " << e.what() << " (the answers written so far stand, in input order)\n";
        return exit_resources;
    }
}

namespace {

int run_app_unguarded(int argc, const char* const* argv, std::istream& in, std::ostream& out, std::ostream& err) {
    CLI::App app{"boxcyl " BOXCYL_VERSION_STRING
                 ": exact box-cylinder intersection queries (does a finite cylinder intersect a box?)",
                 "boxcyl"};
    app.footer(options_section() + help_body + "\n" + exit_status_help);
    app.set_version_flag("--version", "boxcyl " BOXCYL_VERSION_STRING, "Print the version and exit");
    app.require_subcommand(1);

    std::string algorithm{default_algorithm};
    std::string arithmetic{default_arithmetic};
    std::string file = "-";
    unsigned threads = 1;
    CLI::App* intersect = app.add_subcommand(
        "intersect", "Answer one query per input line: does the cylinder intersect the box?");
    intersect->footer(std::string(help_body) + "\n" + exit_status_help);  // its options are listed by CLI11 above it
    intersect->add_option("--algorithm", algorithm,
                          describe("Algorithm (default " + std::string(default_algorithm) + "):", algorithm_choices))
        ->check(CLI::IsMember(names_of(algorithm_choices)));
    intersect->add_option("--arithmetic", arithmetic,
                          describe("Arithmetic (default " + std::string(default_arithmetic) + "):", arithmetic_choices))
        ->check(CLI::IsMember(names_of(arithmetic_choices)));
    intersect->add_option("--threads", threads,
                          "Threads answering lines (default 1; 0: one per core); the output is the same, in input order")
        ->check(CLI::Range(0u, 1024u));
    intersect->add_option("file", file, "JSON Lines input; '-' or none: standard input");
    std::size_t max_line_bytes = default_max_line_bytes;
    add_max_line_bytes_option(*intersect, max_line_bytes);
    ExplainCommand explain;
    add_explain_command(app, explain);
    GridCommand grid;
    add_grid_command(app, grid);
    DistanceCommand distance;
    add_distance_command(app, distance);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (const std::string m = e.get_exit_code() == 0 ? std::string() : missing_subcommand_message(app); !m.empty()) {
            err << m << "\nRun with --help for more information.\n";
            return exit_usage;
        }
        const int code = app.exit(e, out, err);
        return help_written(code == 0 ? exit_ok : exit_usage, out, err);
    }

    if (explain.app->parsed()) return run_explain(explain, in, out, err);
    if (grid.app->parsed()) return run_grid(grid, in, out, err);
    if (distance.app->parsed()) return run_distance(distance, in, out, err);

    RunOptions options = make_run_options(algorithm, arithmetic);
    options.max_line_bytes = max_line_bytes;
#if !defined(BOXCYL_CLI_EXACT)
    if (options.query.algorithm == Algorithm::oracle) {
        err << "boxcyl: --algorithm oracle needs the exact backend (GMP); this build has none\n";
        return exit_usage;
    }
#endif
    std::unique_ptr<std::istream> f;
    if (file != "-") {
        f = open_input(file, err);
        if (!f) return exit_usage;
    }
    std::istream& input = f ? *f : in;
    return end_of_run(answer_stream(input, out, options, threads), input, input_name(file), out, err);
}

}  // namespace

void add_max_line_bytes_option(CLI::App& sub, std::size_t& value) {
    sub.add_option("--max-line-bytes", value,
                   "Longest input line read, in bytes (default " + std::to_string(default_max_line_bytes) +
                       "); a longer line is skipped unread and gets an error line")
        ->check(CLI::Range(std::size_t{1}, std::numeric_limits<std::size_t>::max() / 2));
}

std::unique_ptr<std::istream> open_input(const std::string& file, std::ostream& err) {
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec)) {
        err << "boxcyl: cannot read '" << file << "': is a directory\n";
        return nullptr;
    }
    std::unique_ptr<InputFd> f = open_input_fd(file);
    if (!f) {
        err << "boxcyl: cannot open '" << file << "': " << std::strerror(errno) << "\n";
        return nullptr;
    }
    return f;
}

int run_app(int argc, const char* const* argv) {
    guard_standard_descriptors();
    install_stop_handlers();
    // The tool's own streams over descriptors 0 and 1: they keep the errno of a failed read or write
    // (app.hpp's messages say it) and a stop signal wakes the reader. The answers flush whenever input
    // runs dry (process_stream decides).
    InputFd in(0);
    OutputFd out(1);
    std::cerr.tie(&out);  // a message comes after the answers before it
    const int code = run_app(argc, argv, in, out, std::cerr);
    std::cerr.tie(nullptr);
    return code;
}

}  // namespace boxcyl::cli
