// Colour value types: an XYZ is not an RGB. Both are small values with component-wise arithmetic and checked
// indexing (an index outside 0..2 throws std::out_of_range instead of reading a neighbour).
#pragma once

#include <array>
#include <stdexcept>
#include <string>

namespace metalfit {

namespace detail {

// Component-wise arithmetic shared by the three-component colour types; T names its components in its own terms
// (X, Y, Z or r, g, b) and exposes them to this base through T::component(i).
template <class T>
struct ColorTriple {
    friend constexpr T operator+(const T& a, const T& b) {
        return T::from_components(a.c0() + b.c0(), a.c1() + b.c1(), a.c2() + b.c2());
    }
    friend constexpr T operator-(const T& a, const T& b) {
        return T::from_components(a.c0() - b.c0(), a.c1() - b.c1(), a.c2() - b.c2());
    }
    friend constexpr T operator*(const T& a, const T& b) {
        return T::from_components(a.c0() * b.c0(), a.c1() * b.c1(), a.c2() * b.c2());
    }
    friend constexpr T operator/(const T& a, const T& b) {
        return T::from_components(a.c0() / b.c0(), a.c1() / b.c1(), a.c2() / b.c2());
    }
    friend constexpr T operator*(double s, const T& a) {
        return T::from_components(s * a.c0(), s * a.c1(), s * a.c2());
    }
    friend constexpr T operator*(const T& a, double s) { return s * a; }
    friend constexpr T operator/(const T& a, double s) {
        return T::from_components(a.c0() / s, a.c1() / s, a.c2() / s);
    }
    friend constexpr T operator-(const T& a) { return T::from_components(-a.c0(), -a.c1(), -a.c2()); }
    friend constexpr T& operator+=(T& a, const T& b) { return a = a + b; }
    friend constexpr T& operator-=(T& a, const T& b) { return a = a - b; }
    friend constexpr T& operator*=(T& a, double s) { return a = a * s; }
    friend constexpr T& operator/=(T& a, double s) { return a = a / s; }
    friend constexpr bool operator==(const T& a, const T& b) {
        return a.c0() == b.c0() && a.c1() == b.c1() && a.c2() == b.c2();
    }

    static void check_index(int i) {
        if (i < 0 || i > 2) throw std::out_of_range("colour component " + std::to_string(i) + " (valid: 0, 1, 2)");
    }
};

}  // namespace detail

// CIE tristimulus values (1931 2°, 1964 10° or 2015 observers), Y = 1 for a perfect reflector.
struct XYZ : detail::ColorTriple<XYZ> {
    double X = 0.0, Y = 0.0, Z = 0.0;

    constexpr XYZ() = default;
    constexpr XYZ(double x, double y, double z) : X(x), Y(y), Z(z) {}
    static constexpr XYZ from_components(double a, double b, double c) { return {a, b, c}; }

    double operator[](int i) const {
        check_index(i);
        return i == 0 ? X : i == 1 ? Y : Z;
    }
    double& operator[](int i) {
        check_index(i);
        return i == 0 ? X : i == 1 ? Y : Z;
    }
    constexpr double c0() const { return X; }
    constexpr double c1() const { return Y; }
    constexpr double c2() const { return Z; }
};

// Linear RGB in some working space (which one is carried by whoever made it).
struct RGB : detail::ColorTriple<RGB> {
    double r = 0.0, g = 0.0, b = 0.0;

    constexpr RGB() = default;
    constexpr RGB(double red, double green, double blue) : r(red), g(green), b(blue) {}
    static constexpr RGB from_components(double a, double b, double c) { return {a, b, c}; }
    // All three channels equal.
    static constexpr RGB splat(double v) { return {v, v, v}; }

    double operator[](int c) const {
        check_index(c);
        return c == 0 ? r : c == 1 ? g : b;
    }
    double& operator[](int c) {
        check_index(c);
        return c == 0 ? r : c == 1 ? g : b;
    }
    constexpr double c0() const { return r; }
    constexpr double c1() const { return g; }
    constexpr double c2() const { return b; }
    constexpr std::array<double, 3> array() const { return {r, g, b}; }
    constexpr double max() const { return r > g ? (r > b ? r : b) : (g > b ? g : b); }
    constexpr double min() const { return r < g ? (r < b ? r : b) : (g < b ? g : b); }
};

// Channel names in messages and records, in R, G, B order.
inline constexpr const char* kChannelNames[3] = {"red", "green", "blue"};

}  // namespace metalfit
