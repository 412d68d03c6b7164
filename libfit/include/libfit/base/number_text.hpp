// Numbers as text: the one formatter every writer, message and table uses (std::to_chars, locale-independent).
// Shortest round-trip for what is read back (records, exports), and a fixed number of digits where a format asks
// for one (tables, messages: the printf conversions %.*g and %.*f, which std::to_chars reproduces exactly); a table's
// padded column, right- or left-aligned; hexadecimal with a fixed number of digits (byte escapes, code points, GL's
// error codes).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace metalfit {

// The shortest text that reads back as exactly v ("0.1", "1e+300", "2"; "nan", "inf", "-inf").
std::string shortest_text(double v);
// The shortest text that reads back as exactly the float f (at most 9 significant digits).
std::string shortest_text(float f);
// v with `digits` significant digits, as printf's "%.<digits>g" writes it ("0.123457", "1.5e-07").
std::string significant_text(double v, int digits);
// v with `decimals` digits after the point, as printf's "%.<decimals>f" writes it ("0.1235", "12").
std::string fixed_text(double v, int decimals);
// v with `decimals` digits after the point of its mantissa, as printf's "%.<decimals>e" writes it ("1.5e-05").
std::string scientific_text(double v, int decimals);

// `text` with spaces in front up to `width` characters, as printf's "%<width>s" writes it (a table's column; text as
// wide already is left as it is): pad_left(fixed_text(v, 3), 9) is "%9.3f".
std::string pad_left(std::string text, std::size_t width);
// `text` with spaces after it up to `width` characters, as printf's "%-<width>s" writes it (a table's left-aligned
// column: names; text as wide already is left as it is).
std::string pad_right(std::string text, std::size_t width);

// The case of the letters a to f in hexadecimal digits.
enum class HexLetters { lower, upper };
// `value` in hexadecimal, at least `digits` digits with zeros in front, as printf's "%0<digits>x" ("00e9", lower) or
// "%0<digits>X" ("00E9", upper) writes it; no "0x".
std::string hex_text(std::uint64_t value, int digits, HexLetters letters);

// The reading side: the whole text (spaces and tabs around it allowed) as a number, strtod's forms, "nan" and "inf"
// included so that a caller can refuse them as not finite; nullopt when anything else is left.
std::optional<double> whole_number(std::string_view text);

}  // namespace metalfit
