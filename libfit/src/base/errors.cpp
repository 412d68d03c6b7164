#include "libfit/base/errors.hpp"
#include "libfit/base/standard_output.hpp"

#include "libfit/base/utf8.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <optional>

namespace metalfit {
namespace {

std::string format_location(const InputLocation& where, const std::string& message) {
    std::string out = where.file.string();
    if (where.line > 0) out += ":" + std::to_string(where.line);
    out += ": ";
    if (!where.field.empty()) out += where.field + ": ";
    out += message;
    return sanitised_message(out);
}

bool invisible(char32_t code) {
    return code == 0xFEFF || (code >= 0x200B && code <= 0x200F) || (code >= 0x202A && code <= 0x202E) ||
           (code >= 0x2066 && code <= 0x2069) || (code >= 0x80 && code < 0xA0) || code == 0x2028 || code == 0x2029;
}

}  // namespace

std::string sanitised_message(std::string_view message, std::size_t max_bytes) {
    std::string out;
    std::size_t i = 0;
    while (i < message.size()) {
        if (out.size() >= max_bytes) {
            out += "… (" + std::to_string(message.size() - i) + " more bytes)";
            break;
        }
        char32_t code = 0;
        const std::size_t length = utf8_sequence(message, i, code);
        if (length == 0) {
            out += byte_escape(static_cast<unsigned char>(message[i]));
            ++i;
            continue;
        }
        if (code == '\n' || code == '\r' || code == '\t') {
            out += ' ';
        } else if (code < 0x20 || code == 0x7F) {
            out += byte_escape(static_cast<unsigned char>(code));
        } else if (invisible(code)) {
            out += "<" + code_point_name(code) + ">";
        } else {
            out.append(message.substr(i, length));
        }
        i += length;
    }
    return out;
}

InputError::InputError(const InputLocation& where, const std::string& message)
    : std::runtime_error(format_location(where, message)), where_(where) {}

int report_current_exception(const char* program) {
    try {
        throw;
    } catch (const UsageError& e) {
        std::cerr << program << ": " << sanitised_message(e.what()) << "\n";
        return exit_usage;
    } catch (const InputError& e) {
        std::cerr << program << ": " << e.what() << "\n";
        return exit_bad_input;
    } catch (const ColorConfigError& e) {
        std::cerr << program << ": " << sanitised_message(e.what()) << "\n";
        return exit_colour_config;
    } catch (const std::exception& e) {
        std::cerr << program << ": internal error: " << sanitised_message(e.what()) << "\n";
        return exit_internal;
    }
}

namespace {
bool g_standard_output_loss_reported = false;

// Flushes stdout; when anything written there was lost, why, in words ("disk full", the system's words).
std::optional<std::string> standard_output_loss() {
    errno = 0;
    std::cout.flush();
    const bool lost = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout);
    if (!lost) return std::nullopt;
    const int error = errno;
    return error == ENOSPC ? "disk full" : error != 0 ? std::strerror(error) : "a write failed (disk full?)";
}
}  // namespace

void flush_standard_output() {
    const std::optional<std::string> loss = standard_output_loss();
    if (!loss) return;
    g_standard_output_loss_reported = true;
    throw InputError(InputLocation("standard output"), "cannot write: " + *loss + " (nothing was written)");
}

int finish_standard_output(const char* program, int code) {
    const std::optional<std::string> loss = standard_output_loss();
    if (!loss) return code;
    if (!g_standard_output_loss_reported)
        std::fprintf(stderr, "%s: cannot write to standard output: %s\n", program, loss->c_str());
    return code == exit_ok ? exit_bad_input : code;
}

}  // namespace metalfit
