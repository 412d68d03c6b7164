// Error types of libfit. Each maps to one documented exit code of the CLI (docs/cli.md).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace metalfit {

// Where in an input file something went wrong: a line (1-based) or a field name, or neither.
struct InputLocation {
    InputLocation(std::filesystem::path file_, int line_ = 0, std::string field_ = {})
        : file(std::move(file_)), line(line_), field(std::move(field_)) {}

    std::filesystem::path file;
    int line = 0;       // 0: unknown
    std::string field;  // e.g. "DATA[0].coefficients"; empty: unknown
};

// A bad input file or bad data in it (exit code 3). what() is one line: "file:line: message" or
// "file: field: message".
class InputError : public std::runtime_error {
public:
    InputError(const InputLocation& where, const std::string& message);
    const InputLocation& location() const noexcept { return where_; }

private:
    InputLocation where_;
};

// A colour-management problem: OCIO config missing, unreadable, or without a needed role or colour
// space (exit code 4). The message names the config.
class ColorConfigError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A request that cannot be understood: unknown material, source or option value (exit code 2).
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The documented exit codes of metalfit's command-line tools (docs/cli.md); glpreview adds 5 for OpenGL/EGL.
enum ExitCode : int { exit_ok = 0, exit_internal = 1, exit_usage = 2, exit_bad_input = 3, exit_colour_config = 4 };

// The longest message metalfit prints (bytes, before "… (N more bytes)").
inline constexpr std::size_t kMaxMessageBytes = 1000;

// A message safe to print on one terminal line: newlines and tabs become spaces, other control characters and
// bytes that are not UTF-8 are written as \xNN, invisible or direction-changing characters (the byte-order mark
// U+FEFF, zero-width spaces, bidirectional overrides) as <U+XXXX>, and a message longer than kMaxMessageBytes is cut
// there with "… (N more bytes)".
std::string sanitised_message(std::string_view message, std::size_t max_bytes = kMaxMessageBytes);

// Inside a catch block: prints "<program>: <message>" (with "internal error: " for unexpected exceptions) on stderr
// and returns the exit code of the exception being handled.
int report_current_exception(const char* program);

// At the end of main: flushes stdout; when anything written there was lost (a full disk, a closed pipe, /dev/full)
// prints "<program>: cannot write to standard output: <why>" and returns exit_bad_input instead of `code`.
int finish_standard_output(const char* program, int code);

}  // namespace metalfit
