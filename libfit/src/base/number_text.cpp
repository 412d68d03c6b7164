#include "libfit/base/number_text.hpp"

#include <charconv>
#include <stdexcept>
#include <system_error>

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

}  // namespace metalfit
