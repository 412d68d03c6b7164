// JSON text written in pieces (the streamed records: fit, export, report): a value dumped at the top level placed
// some levels deep in an indented document.
#pragma once

#include <cstddef>
#include <string>

namespace metalfit {

// `text` (the dump of a value at the top level, indented by `indent` spaces a level) as it appears `levels` deep:
// every line after the first indented. Raw newlines occur in a JSON dump only between tokens (strings hold them
// escaped).
inline std::string indented_json(const std::string& text, int levels, int indent) {
    const std::string margin(static_cast<std::size_t>(levels * indent), ' ');
    std::string out;
    out.reserve(text.size() + text.size() / 16);
    for (char c : text) {
        out += c;
        if (c == '\n') out += margin;
    }
    return out;
}

}  // namespace metalfit
