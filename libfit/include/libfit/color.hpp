// Colour value types: an XYZ is not an RGB.
#pragma once

#include <array>

namespace metalfit {

// CIE 1931 tristimulus values (or CIE 1964 with the 10° observer), Y = 1 for a perfect reflector.
struct XYZ {
    double X = 0.0, Y = 0.0, Z = 0.0;
};

// Linear RGB in some working space (which one is carried by whoever made it).
struct RGB {
    double r = 0.0, g = 0.0, b = 0.0;

    double operator[](int c) const { return c == 0 ? r : c == 1 ? g : b; }
    std::array<double, 3> array() const { return {r, g, b}; }
    double max() const { return r > g ? (r > b ? r : b) : (g > b ? g : b); }
    double min() const { return r < g ? (r < b ? r : b) : (g < b ? g : b); }
};

// Channel names in messages and records, in R, G, B order.
inline constexpr const char* kChannelNames[3] = {"red", "green", "blue"};

inline RGB operator/(const RGB& a, const RGB& b) { return {a.r / b.r, a.g / b.g, a.b / b.b}; }

}  // namespace metalfit
