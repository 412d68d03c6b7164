#include "libfit/errors.hpp"

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

}  // namespace metalfit
