#include "libfit/base/names.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>

#include "libfit/base/errors.hpp"
#include "libfit/base/utf8.hpp"

namespace metalfit {

std::string comment_text(std::string_view text) {
    std::string out = sanitised_message(text, SIZE_MAX);
    if (!out.empty() && out.back() == '\\') out.replace(out.size() - 1, 1, "\\x5C");
    return out;
}

std::string c_string_literal(std::string_view text) {
    std::string out = "\"";
    char octal[8];
    for (const char ch : text) {
        const auto byte = static_cast<unsigned char>(ch);
        if (ch == '"' || ch == '\\') {
            out += '\\';
            out += ch;
        } else if (byte < 0x20 || byte > 0x7E) {
            std::snprintf(octal, sizeof octal, "\\%03o", static_cast<unsigned>(byte));
            out += octal;
        } else {
            out += ch;
        }
    }
    return out + "\"";
}

std::string python_string_expression(std::string_view text) {
    const bool plain = std::all_of(text.begin(), text.end(), [](char ch) {
        const auto byte = static_cast<unsigned char>(ch);
        return byte >= 0x20 && byte <= 0x7E;
    });
    std::string out = plain ? "'" : "b'";
    for (const char ch : text) {
        const auto byte = static_cast<unsigned char>(ch);
        if (ch == '\'' || ch == '\\') {
            out += '\\';
            out += ch;
        } else if (byte < 0x20 || byte > 0x7E) {
            out += byte_escape(byte, HexLetters::lower);
        } else {
            out += ch;
        }
    }
    return out + (plain ? "'" : "'.decode('utf-8', 'replace')");
}

std::string path_component(std::string_view name) {
    std::string out(name);
    for (char& ch : out) {
        const auto byte = static_cast<unsigned char>(ch);
        const bool kept = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
                          ch == '-' || ch == '_' || ch == '.' || byte >= 0x80;
        if (!kept) ch = '_';
    }
    if (out.empty()) return "_";
    if (out.front() == '.') out.front() = '_';  // ".", "..", hidden files
    return out;
}

}  // namespace metalfit
