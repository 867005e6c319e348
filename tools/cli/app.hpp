// The command line of `boxcyl`: options, help text, input selection and exit codes.
#pragma once

#include <cstddef>   // std::size_t
#include <fstream>   // std::ifstream
#include <iosfwd>    // std::istream, std::ostream
#include <optional>  // open_input's failure
#include <string>    // file names

namespace CLI {
class App;
}

namespace boxcyl::cli {

// Exit codes (also documented in --help).
inline constexpr int exit_ok = 0;         // every line was a good query
inline constexpr int exit_bad_lines = 1;  // some line was bad (it got an "error" line)
inline constexpr int exit_usage = 2;      // unknown option or value, unreadable file

// Runs the tool; `in` is what "-" (or no file) reads.
int run_app(int argc, const char* const* argv, std::istream& in, std::ostream& out, std::ostream& err);

// The same on the process's standard streams.
int run_app(int argc, const char* const* argv);

// Adds --max-line-bytes (the longest input line kept; default_max_line_bytes) to a subcommand.
void add_max_line_bytes_option(CLI::App& sub, std::size_t& value);

// Opens a subcommand's input file (binary), or says on `err` why not ("boxcyl: cannot open 'F': ...";
// a directory is refused: it opens but reads nothing) and returns nullopt: exit with exit_usage.
std::optional<std::ifstream> open_input(const std::string& file, std::ostream& err);

}  // namespace boxcyl::cli
