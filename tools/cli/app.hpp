// The command line of `boxcyl`: options, help text, input selection and exit codes.
#pragma once

#include <cstddef>  // std::size_t
#include <iosfwd>   // std::istream, std::ostream
#include <memory>   // open_input's stream
#include <string>   // file names

namespace CLI {
class App;
}

namespace boxcyl::cli {

struct StreamCounts;

// Exit codes (also documented in --help).
inline constexpr int exit_ok = 0;         // every line was a good query
inline constexpr int exit_bad_lines = 1;  // some line was bad (it got an "error" line)
inline constexpr int exit_usage = 2;      // unknown option or value, a file that cannot be opened
inline constexpr int exit_io = 3;         // reading the input or writing the output failed
inline constexpr int exit_resources = 4;  // threads could not be started, memory ran out outside any line, or
                                          // another failure stopped the run
inline constexpr int exit_signal_base = 128;  // + the signal: stopped by SIGINT (130) or SIGTERM (143)

// The EXIT STATUS section of the subcommands' --help.
extern const char* const exit_status_help;

// Runs the tool; `in` is what "-" (or no file) reads.
int run_app(int argc, const char* const* argv, std::istream& in, std::ostream& out, std::ostream& err);

// The same on the process's standard streams.
int run_app(int argc, const char* const* argv);

// Adds --max-line-bytes (the longest input line kept; default_max_line_bytes) to a subcommand.
void add_max_line_bytes_option(CLI::App& sub, std::size_t& value);

// Opens a subcommand's input file, or says on `err` why not ("boxcyl: cannot open 'F': ..."; a
// directory is refused: it opens but reads nothing) and returns nullptr: exit with exit_usage.
std::unique_ptr<std::istream> open_input(const std::string& file, std::ostream& err);

// How the input is named in messages: "standard input" for "-", else 'FILE'.
std::string input_name(const std::string& file);

// The exit code of a run of `intersect`, `grid` or `distance` over `in` (named `name`) that wrote `out`, after
// saying on `err` why the run ended early: the output could not be written (exit_io), the input could
// not be read (exit_io), a stop signal (exit_signal_base + signal); else exit_ok or exit_bad_lines.
int end_of_run(const StreamCounts& counts, const std::istream& in, const std::string& name, std::ostream& out,
               std::ostream& err);

// What a failed read or write says: strerror(error), or `fallback` when no errno was kept.
std::string describe_error(int error, const char* fallback);

}  // namespace boxcyl::cli
