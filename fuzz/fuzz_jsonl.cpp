// libFuzzer target: the CLI's JSON Lines processor (tools/cli/jsonl_query.hpp) on arbitrary bytes.
// Claims checked: no crash or sanitizer report; exactly one output line per input line, in order
// ("line N: " in the N-th output's error); each output line is a JSON object holding either a boolean
// "intersect" or a string "error" (plus an optional "id"); the count of error lines is the count
// process_stream returns. Run with the default options (the exact query) and with --arithmetic float
// (inputs rounded to float first: another validation path), and with 2 threads: the same output.
#include <cstddef>  // std::size_t
#include <cstdint>  // std::uint8_t
#include <cstdio>   // std::fprintf
#include <cstdlib>  // std::abort
#include <sstream>  // process_stream on strings
#include <string>

#include <nlohmann/json.hpp>

#include "jsonl_query.hpp"
#include "options.hpp"

namespace {

[[noreturn]] void fail(const std::string& what, const std::string& output) {
    std::fprintf(stderr, "fuzz_jsonl: %s\n--- output ---\n%s\n", what.c_str(), output.substr(0, 4000).c_str());
    std::abort();
}

void check(const std::string& input, const boxcyl::cli::RunOptions& opt) {
    std::istringstream in(input);
    std::ostringstream out;
    const std::size_t bad = boxcyl::cli::process_stream(in, out, opt);
    const std::string s = out.str();

    // std::getline semantics: every '\n' ends a line; a non-empty tail without one is a last line.
    std::size_t want_lines = 0;
    for (char c : input) want_lines += c == '\n';
    if (!input.empty() && input.back() != '\n') ++want_lines;

    std::size_t lines = 0, errors = 0, begin = 0;
    while (begin < s.size()) {
        const std::size_t end = s.find('\n', begin);
        if (end == std::string::npos) fail("output does not end with a newline", s);
        const std::string line = s.substr(begin, end - begin);
        begin = end + 1;
        ++lines;
        const nlohmann::json j = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
        if (!j.is_object()) fail("output line " + std::to_string(lines) + " is not a JSON object: " + line, s);
        const bool answer = j.contains("intersect") && j["intersect"].is_boolean();
        const bool error = j.contains("error") && j["error"].is_string();
        if (answer == error || j.size() != 1u + (j.contains("id") ? 1u : 0u))
            fail("output line " + std::to_string(lines) + " is neither an answer nor an error: " + line, s);
        if (error) {
            ++errors;
            const std::string prefix = "line " + std::to_string(lines) + ": ";
            if (j["error"].get<std::string>().rfind(prefix, 0) != 0)
                fail("error line " + std::to_string(lines) + " does not start with '" + prefix + "': " + line, s);
        }
    }
    if (lines != want_lines)
        fail(std::to_string(lines) + " output lines for " + std::to_string(want_lines) + " input lines", s);
    if (errors != bad) fail(std::to_string(errors) + " error lines but process_stream counted " + std::to_string(bad), s);

    // The multi-threaded path (intersect --threads) must give the same bytes and count.
    std::istringstream in2(input);
    std::ostringstream out2;
    const std::size_t bad2 = boxcyl::cli::process_stream(in2, out2, opt, 2);
    if (out2.str() != s || bad2 != bad) fail("--threads 2 output differs from the single-threaded one", out2.str());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string input(reinterpret_cast<const char*>(data), size);
    check(input, boxcyl::cli::make_run_options(boxcyl::cli::default_algorithm, boxcyl::cli::default_arithmetic));
    check(input, boxcyl::cli::make_run_options("inequalities", "float"));
    return 0;
}
