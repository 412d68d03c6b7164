// Small text helpers shared by the libraries' messages and explanations.
#pragma once

#include <string>
#include <vector>

namespace metalfit {

// "a, b, c" (or with another separator); empty for no items.
inline std::string join(const std::vector<std::string>& items, const char* separator = ", ") {
    std::string text;
    for (const auto& item : items) text += (text.empty() ? "" : separator) + item;
    return text;
}

// Text as one line of plain text: HTML tags dropped, runs of spaces, tabs and line breaks as one space
// (refractiveindex.info writes REFERENCES as HTML over several lines).
inline std::string one_line(const std::string& text) {
    std::string out;
    bool in_tag = false, space = false;
    for (char c : text) {
        if (c == '<')
            in_tag = true;
        else if (c == '>')
            in_tag = false;
        else if (!in_tag && (c == '\n' || c == '\r' || c == ' ' || c == '\t'))
            space = !out.empty();
        else if (!in_tag) {
            if (space) out += ' ';
            out += c;
            space = false;
        }
    }
    return out;
}

}  // namespace metalfit
