// Internal: strict number parsing shared by the importers.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "libfit/base/errors.hpp"
#include "libfit/base/number_text.hpp"

namespace metalfit::detail {

// The whole token must be a finite decimal number ("2.4797e-01", "50e-9", "-3"); else nullopt.
inline std::optional<double> parse_number(std::string_view token) {
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    double value = 0.0;
    const char* end = token.data() + token.size();
    auto [ptr, ec] = std::from_chars(token.data(), end, value);
    if (ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
    return value;
}

inline std::string_view trim(std::string_view s);

// Fields separated by runs of spaces or tabs (refractiveindex.info data rows).
inline std::vector<std::string_view> split_whitespace(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    while (i < line.size()) {
        while (i < line.size() && blank(line[i])) ++i;
        std::size_t j = i;
        while (j < line.size() && !blank(line[j])) ++j;
        if (j > i) out.push_back(line.substr(i, j - i));
        i = j;
    }
    return out;
}

// Comma-separated fields, each trimmed (CSV without quoting).
inline std::vector<std::string_view> split_commas(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t start = 0;
    for (std::size_t comma; (comma = line.find(',', start)) != std::string_view::npos; start = comma + 1)
        out.push_back(trim(line.substr(start, comma - start)));
    out.push_back(trim(line.substr(start)));
    return out;
}

inline std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

// Every field of a table row as a number; the first that is not one is an InputError at `where`.
inline std::vector<double> parse_row(const std::vector<std::string_view>& fields, const InputLocation& where) {
    std::vector<double> values;
    for (auto field : fields) {
        const auto x = parse_number(field);
        if (!x) throw InputError(where, "non-numeric value '" + std::string(field) + "'");
        values.push_back(*x);
    }
    return values;
}

// A row "wavelength value..." of an optical-constants table: the wavelength must be positive and
// every value non-negative. `names` says what each value is ("nk", "n" or "k").
inline void check_optical_row(const std::vector<double>& row, const std::vector<std::string_view>& fields,
                              std::string_view names, const InputLocation& where) {
    if (row[0] <= 0.0) throw InputError(where, "wavelength must be positive");
    for (std::size_t i = 0; i < names.size(); ++i)
        if (row[i + 1] < 0.0)
            throw InputError(where, std::string(names[i] == 'k' ? "negative extinction coefficient k = "
                                                                : "negative refractive index n = ") +
                                        std::string(fields[i + 1]));
}

// The wavelength of a row in nm: `value` × `to_nm` (1 or 1000 for µm), refused when that overflows.
inline double wavelength_nm(double value, double to_nm, std::string_view field, const InputLocation& where) {
    const double nm = value * to_nm;
    if (!std::isfinite(nm) || nm > 1e12)
        throw InputError(where, "wavelength " + std::string(field) + " is out of range (" +
                                    (to_nm == 1.0 ? "nm" : "µm") + ")");
    return nm;
}

// n + ik = 0: no material has it; the Fresnel reflectance is 0/0 there.
inline constexpr const char* kZeroIndex = "n = k = 0: not a material (the Fresnel reflectance is undefined)";

// The range of n and k metalfit accepts (docs/data.md, docs/decisions.md): n, k <= kMaxIndex and |n + ik| >=
// kMinIndexModulus. Inside it the double-precision Fresnel (fresnel_real and the complex form) is within 4e-15 of a
// long-double evaluation at every μ (tests/test_fresnel_real.cpp, FresnelReal.ExactInsideTheImportRange); |η²|² overflows
// at n or k ≈ 1e77 (NaN reflectances) and below |η| ≈ 1e-7 the μ = 1 end loses digits (1e-8: 3e-9 off, 1e-80: 0.5).
inline constexpr double kMaxIndex = 1e6;
inline constexpr double kMinIndexModulus = 1e-6;

// n (or k with `is_k`) above kMaxIndex: refused, naming the value as written.
inline void check_index_limit(double value, bool is_k, std::string_view text, const InputLocation& where) {
    if (value > kMaxIndex)
        throw InputError(where, std::string(is_k ? "extinction coefficient k = " : "refractive index n = ") +
                                    std::string(text) +
                                    " is above 1e6 (the largest n or k metalfit accepts: beyond it the Fresnel "
                                    "reflectance in double precision is not exact)");
}

// n and k of one wavelength with |n + ik| below kMinIndexModulus (kZeroIndex when both are 0).
inline void check_index_modulus(double n, double k, const InputLocation& where) {
    if (n == 0.0 && k == 0.0) throw InputError(where, kZeroIndex);
    if (std::hypot(n, k) < kMinIndexModulus) {
        throw InputError(where, "|n + ik| is below 1e-6 (n = " + significant_text(n, 3) +
                                    ", k = " + significant_text(k, 3) +
                                    "): too close to n = k = 0 for the Fresnel reflectance in double precision");
    }
}

// A row giving n < kMinIndexModulus without its k (an n-only block or table): |n + ik| is checked once k is known.
struct SmallN {
    InputLocation where;
    double nm = 0, n = 0;
};

// check_index_modulus of every such row with k_at(nm): k where the file gives it (0 where it gives none).
template <class KAt>
void check_small_n(const std::vector<SmallN>& rows, const KAt& k_at) {
    for (const SmallN& row : rows) check_index_modulus(row.n, k_at(row.nm), row.where);
}

}  // namespace metalfit::detail
