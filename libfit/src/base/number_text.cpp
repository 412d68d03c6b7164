#include "libfit/base/number_text.hpp"

#include <charconv>
#include <cstdlib>
#include <stdexcept>
#include <system_error>

#include "libfit/base/text.hpp"

namespace metalfit {

namespace {

// Longest outputs: shortest double 24 characters; "%.<d>f" of 1e308 with d decimals 310 + d.
template <typename... Format>
std::string to_text(double v, Format... format) {
    char text[400];
    const auto [end, error] = std::to_chars(text, text + sizeof text, v, format...);
    if (error != std::errc{}) throw std::length_error("number_text: more than 400 characters");
    return {text, end};
}

}  // namespace

std::string shortest_text(double v) { return to_text(v); }

std::string shortest_text(float f) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, f).ptr;
    return {text, end};
}

std::string significant_text(double v, int digits) { return to_text(v, std::chars_format::general, digits); }

std::string fixed_text(double v, int decimals) { return to_text(v, std::chars_format::fixed, decimals); }

std::string scientific_text(double v, int decimals) { return to_text(v, std::chars_format::scientific, decimals); }

std::string pad_left(std::string text, std::size_t width) {
    if (text.size() < width) text.insert(0, width - text.size(), ' ');
    return text;
}

std::string pad_right(std::string text, std::size_t width) {
    if (text.size() < width) text.append(width - text.size(), ' ');
    return text;
}

std::string hex_text(std::uint64_t value, int digits, HexLetters letters) {
    char text[16];
    const auto end = std::to_chars(text, text + sizeof text, value, 16).ptr;
    std::string out(text, end);
    if (letters == HexLetters::upper)
        for (char& c : out)
            if (c >= 'a' && c <= 'f') c = static_cast<char>(c - 'a' + 'A');
    if (digits > 0 && out.size() < static_cast<std::size_t>(digits))
        out.insert(0, static_cast<std::size_t>(digits) - out.size(), '0');
    return out;
}

std::optional<double> whole_number(std::string_view text) {
    text = trim(text);
    if (text.empty()) return std::nullopt;
    const std::string s(text);
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size()) return std::nullopt;
    return v;
}

}  // namespace metalfit
