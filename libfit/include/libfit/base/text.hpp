// Small text helpers shared by the libraries' messages and explanations.
#pragma once

#include <string>
#include <string_view>
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

// `s` without the spaces and tabs around it.
inline std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

// a == b, ASCII letters compared without case.
inline bool equal_ignoring_case(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const auto lower = [](unsigned char c) { return c >= 'A' && c <= 'Z' ? c + ('a' - 'A') : c; };
        if (lower(static_cast<unsigned char>(a[i])) != lower(static_cast<unsigned char>(b[i]))) return false;
    }
    return true;
}

// Text for HTML: & < > " as entities.
inline std::string html_escaped(std::string_view text) {
    std::string out;
    for (char c : text) switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    return out;
}

}  // namespace metalfit
