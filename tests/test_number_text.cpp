// Numbers as text (libfit/base/number_text.hpp): shortest round-trip and printf's fixed digits, locale-free.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>

#include "libfit/base/number_text.hpp"

namespace test_number_text {

using metalfit::fixed_text;
using metalfit::scientific_text;
using metalfit::shortest_text;
using metalfit::significant_text;

std::string printf_text(const char* format, int digits, double v) {
    char text[512];
    std::snprintf(text, sizeof text, format, digits, v);
    return text;
}

// Doubles from every part of the range: random bit patterns (finite ones), plus values near powers of ten and
// the extremes, where shortest round-trip printers have gone wrong.
std::vector<double> many_doubles() {
    std::vector<double> values{0.0,
                               -0.0,
                               1.0,
                               0.1,
                               0.2,
                               0.3,
                               1.0 / 3,
                               2.0 / 3,
                               5e-324,
                               2.2250738585072014e-308,
                               std::numeric_limits<double>::max(),
                               std::numeric_limits<double>::epsilon(),
                               9007199254740993.0,
                               123456789012345680.0,
                               0.04045,
                               65504.0,
                               1e21,
                               1e22,
                               1e23};
    for (int e = -300; e <= 300; e += 7) {
        const double p = std::pow(10.0, e);
        values.insert(values.end(), {p, std::nextafter(p, 0.0), std::nextafter(p, INFINITY), -p});
    }
    std::mt19937_64 random(20261202);
    while (values.size() < 200000) {
        const double v = std::bit_cast<double>(random());
        if (std::isfinite(v)) values.push_back(v);
    }
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 50000; ++i) values.push_back(unit(random));
    return values;
}

TEST(NumberText, ShortestReadsBackAsTheSameDouble) {
    for (const double v : many_doubles()) {
        const std::string text = shortest_text(v);
        const double back = std::strtod(text.c_str(), nullptr);
        ASSERT_EQ(std::bit_cast<std::uint64_t>(back), std::bit_cast<std::uint64_t>(v)) << text;
        ASSERT_LE(text.size(), 24u) << text;
    }
}

TEST(NumberText, ShortestHasTheFewestDigitsThatReadBack) {
    // The digits of the shortest text are as many as the smallest printf precision that reads back as v.
    for (const double v :
         {0.1, 1.0 / 3, 2.0 / 3, 1e-7, 123.456, 0.04045, 3.2409699, 6.02214076e23, 0.9999999999999999}) {
        int fewest = 1;
        while (std::strtod(printf_text("%.*g", fewest, v).c_str(), nullptr) != v) ++fewest;
        std::string digits;
        const std::string text = shortest_text(v);
        for (char c : text.substr(0, text.find('e')))
            if (c >= '0' && c <= '9') digits += c;
        digits.erase(0, digits.find_first_not_of('0'));
        digits.erase(digits.find_last_not_of('0') + 1);
        EXPECT_EQ(static_cast<int>(digits.size()), fewest) << text;
    }
    EXPECT_EQ(shortest_text(0.1), "0.1");
    EXPECT_EQ(shortest_text(2.0), "2");
    EXPECT_EQ(shortest_text(1e300), "1e+300");
    EXPECT_EQ(shortest_text(-0.0), "-0");
}

TEST(NumberText, ShortestFloatReadsBackAsTheSameFloat) {
    std::mt19937 random(7);
    for (int i = 0; i < 200000; ++i) {
        const float f = std::bit_cast<float>(static_cast<std::uint32_t>(random()));
        if (!std::isfinite(f)) continue;
        const std::string text = shortest_text(f);
        ASSERT_EQ(std::bit_cast<std::uint32_t>(std::strtof(text.c_str(), nullptr)), std::bit_cast<std::uint32_t>(f))
            << text;
    }
    EXPECT_EQ(shortest_text(0.1f), "0.1");
    EXPECT_EQ(shortest_text(static_cast<float>(0.1)), "0.1");  // not the double's 0.10000000149011612
}

TEST(NumberText, FixedDigitsAreWhatPrintfWrites) {
    // significant_text is "%.*g", fixed_text "%.*f", scientific_text "%.*e", digit for digit (the formats that
    // printed with snprintf before keep their bytes).
    std::mt19937_64 random(31);
    std::uniform_real_distribution<double> exponent(-12.0, 12.0);
    for (int i = 0; i < 20000; ++i) {
        const double v = (i % 2 ? -1 : 1) * std::pow(10.0, exponent(random));
        for (int digits : {0, 1, 2, 3, 4, 6, 9, 17}) {
            ASSERT_EQ(significant_text(v, digits), printf_text("%.*g", digits, v));
            ASSERT_EQ(fixed_text(v, digits), printf_text("%.*f", digits, v));
            ASSERT_EQ(scientific_text(v, digits), printf_text("%.*e", digits, v));
        }
    }
    EXPECT_EQ(significant_text(0.123456789, 6), "0.123457");
    EXPECT_EQ(significant_text(1.5e-7, 6), "1.5e-07");
    EXPECT_EQ(significant_text(100.0, 3), "100");
    EXPECT_EQ(fixed_text(0.12345, 4), "0.1235");  // 0.12345 is stored slightly above, so it rounds up
    EXPECT_EQ(fixed_text(0.125, 2), "0.12");      // exactly half: to even, as printf does
    EXPECT_EQ(fixed_text(12.0, 0), "12");
    EXPECT_EQ(fixed_text(1e300, 2).size(), 304u);
    EXPECT_EQ(scientific_text(1.25e-5, 1), "1.3e-05");  // 1.25e-5 is stored slightly above
}

TEST(NumberText, NotFiniteNumbers) {
    EXPECT_EQ(shortest_text(std::numeric_limits<double>::infinity()), "inf");
    EXPECT_EQ(shortest_text(-std::numeric_limits<double>::infinity()), "-inf");
    EXPECT_EQ(shortest_text(std::numeric_limits<double>::quiet_NaN()), "nan");
    EXPECT_EQ(significant_text(std::numeric_limits<double>::quiet_NaN(), 6), "nan");
    EXPECT_EQ(fixed_text(-std::numeric_limits<double>::infinity(), 2), "-inf");
}

// A table's column: pad_left(text, width) is printf's "%<width>s", and with fixed_text printf's "%<width>.<d>f" (the
// bench's Markdown tables), for every sign, size and width, wider numbers included (nothing cut).
TEST(NumberText, PaddedColumnsAreWhatPrintfWrites) {
    std::mt19937_64 random(2031);
    std::uniform_real_distribution<double> exponent(-8.0, 14.0);
    std::vector<double> values{0.0,
                               -0.0,
                               0.5,
                               -0.0004,
                               999.9995,
                               std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity(),
                               std::numeric_limits<double>::quiet_NaN(),
                               1e300};
    for (int i = 0; i < 5000; ++i) values.push_back((i % 3 ? 1 : -1) * std::pow(10.0, exponent(random)));
    char text[512];
    for (const double v : values)
        for (int width : {0, 1, 7, 9, 13}) {
            for (int decimals : {0, 1, 2, 3}) {
                std::snprintf(text, sizeof text, "%*.*f", width, decimals, v);
                ASSERT_EQ(metalfit::pad_left(fixed_text(v, decimals), static_cast<std::size_t>(width)), text) << v;
            }
            std::snprintf(text, sizeof text, "%*g", width, v);
            ASSERT_EQ(metalfit::pad_left(significant_text(v, 6), static_cast<std::size_t>(width)), text) << v;
        }
    for (const char* word : {"", "a", "materials", "window wait s", "longer than the column"})
        for (int width = 0; width < 30; ++width) {
            std::snprintf(text, sizeof text, "%*s", width, word);
            ASSERT_EQ(metalfit::pad_left(word, static_cast<std::size_t>(width)), text);
        }
}

// A table's left-aligned column: pad_right(text, width) is printf's "%-<width>s" (glpreview's names beside their
// numbers), and with fixed_text printf's "%-<width>.<d>f", for every width, wider text included (nothing cut).
TEST(NumberText, LeftAlignedColumnsAreWhatPrintfWrites) {
    char text[512];
    for (const char* word : {"", "a", "gold", "conductor-rgb", "distance-impostor", "longer than the column", "é"})
        for (int width = 0; width < 30; ++width) {
            std::snprintf(text, sizeof text, "%-*s", width, word);
            ASSERT_EQ(metalfit::pad_right(word, static_cast<std::size_t>(width)), text) << word << " " << width;
        }
    for (const double v : {0.0, -0.0, 0.5, -12.345, 999.9995, 1e300, -std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::quiet_NaN()})
        for (int width : {0, 1, 5, 9, 13})
            for (int decimals : {0, 2, 3}) {
                std::snprintf(text, sizeof text, "%-*.*f", width, decimals, v);
                ASSERT_EQ(metalfit::pad_right(fixed_text(v, decimals), static_cast<std::size_t>(width)), text) << v;
            }
}

// hex_text(value, digits, letters) is printf's "%0<digits>x" / "%0<digits>X": zeros in front up to `digits`, never
// cut, every bit of a 64-bit value.
TEST(NumberText, HexDigitsAreWhatPrintfWrites) {
    using metalfit::hex_text;
    using metalfit::HexLetters;
    std::mt19937_64 random(0x31);
    std::vector<std::uint64_t> values{0, 1, 9, 10, 15, 16, 0xff, 0x100, 0xabcdef, 0x10ffff, UINT32_MAX, UINT64_MAX};
    for (int i = 0; i < 20000; ++i) values.push_back(random() >> (random() % 64));
    char text[64];
    for (const std::uint64_t v : values)
        for (int digits : {0, 1, 2, 4, 8, 17, 20}) {
            std::snprintf(text, sizeof text, "%0*llx", digits, static_cast<unsigned long long>(v));
            ASSERT_EQ(hex_text(v, digits, HexLetters::lower), text);
            std::snprintf(text, sizeof text, "%0*llX", digits, static_cast<unsigned long long>(v));
            ASSERT_EQ(hex_text(v, digits, HexLetters::upper), text);
        }
    EXPECT_EQ(hex_text(0x500, 4, HexLetters::lower), "0500");  // GL_INVALID_ENUM, as glpreview's errors name it
    EXPECT_EQ(hex_text(0xe9, 2, HexLetters::upper), "E9");
}

}  // namespace test_number_text
