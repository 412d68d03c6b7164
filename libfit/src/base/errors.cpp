#include "libfit/base/errors.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

namespace metalfit {
namespace {

std::string format_location(const InputLocation& where, const std::string& message) {
    std::string out = where.file.string();
    if (where.line > 0) out += ":" + std::to_string(where.line);
    out += ": ";
    if (!where.field.empty()) out += where.field + ": ";
    out += message;
    // One line, always: newlines from parsers or file contents are folded.
    for (char& c : out)
        if (c == '\n' || c == '\r') c = ' ';
    return out;
}

}  // namespace

InputError::InputError(const InputLocation& where, const std::string& message)
    : std::runtime_error(format_location(where, message)), where_(where) {}

int report_current_exception(const char* program) {
    try {
        throw;
    } catch (const UsageError& e) {
        std::cerr << program << ": " << e.what() << "\n";
        return exit_usage;
    } catch (const InputError& e) {
        std::cerr << program << ": " << e.what() << "\n";
        return exit_bad_input;
    } catch (const ColorConfigError& e) {
        std::cerr << program << ": " << e.what() << "\n";
        return exit_colour_config;
    } catch (const std::exception& e) {
        std::cerr << program << ": internal error: " << e.what() << "\n";
        return exit_internal;
    }
}

int finish_standard_output(const char* program, int code) {
    errno = 0;
    std::cout.flush();
    const bool lost = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout);
    if (!lost) return code;
    const int error = errno;
    std::fprintf(stderr, "%s: cannot write to standard output: %s\n", program,
                 error == ENOSPC ? "disk full" : error != 0 ? std::strerror(error) : "a write failed (disk full?)");
    return code == exit_ok ? exit_bad_input : code;
}

}  // namespace metalfit
