#include "io/table_columns.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "base/parse_number.hpp"
#include "libfit/base/number_text.hpp"
#include "libfit/base/text.hpp"

namespace metalfit::detail {

namespace {

constexpr double kHcEvNm = 1239.84198;  // h·c in eV·nm (CODATA 2018: 1239.841984…)
constexpr const char* kExpected =
    "expected a header such as 'wavelength_nm,n,k', 'wavelength_um,n,k', 'wavelength (nm)<TAB>n<TAB>k', "
    "'energy (eV);e1;e2' or refractiveindex.info's 'wl,n' … 'wl,k'";

std::string lower_ascii(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) {
        return c < 0x80 ? static_cast<char>(std::tolower(c)) : static_cast<char>(c);
    });
    return out;
}

// "wavelength (nm)" → {"wavelength", "nm"}; "lambda/nm", "energy_eV", "E [eV]" likewise; no unit → {"name", ""}.
std::pair<std::string, std::string> name_and_unit(std::string_view header) {
    std::string h = lower_ascii(trim(header));
    if (const auto open = h.find_first_of("(["); open != std::string::npos) {
        const auto close = h.find_first_of(")]", open);
        return {
            std::string(trim(h.substr(0, open))),
            std::string(trim(h.substr(open + 1, close == std::string::npos ? std::string::npos : close - open - 1)))};
    }
    if (const auto slash = h.find('/'); slash != std::string::npos && h.substr(slash) != "/cm")
        return {std::string(trim(h.substr(0, slash))), std::string(trim(h.substr(slash + 1)))};
    if (const auto underscore = h.rfind('_'); underscore != std::string::npos) {
        const std::string unit = h.substr(underscore + 1);
        for (const char* known : {"nm", "um", "\xc2\xb5m", "\xce\xbcm", "micron", "a", "\xc3\x85", "\xc3\xa5",
                                  "\xe2\x84\xab", "angstrom", "ev", "cm-1"})
            if (unit == known) return {h.substr(0, underscore), unit};
    }
    return {h, ""};
}

std::string squeezed(std::string s) {  // "eps_1", "epsilon 1" → "eps1", "epsilon1"
    s.erase(std::remove_if(s.begin(), s.end(), [](char c) { return c == '_' || c == ' ' || c == '-'; }), s.end());
    return s;
}

bool one_of(const std::string& s, std::initializer_list<const char*> names) {
    return std::any_of(names.begin(), names.end(), [&](const char* n) { return s == n; });
}

TableColumn classify(std::string_view header, const InputLocation& where) {
    TableColumn c{std::string(trim(header)), ColumnQuantity::ignored, 1.0};
    // Not a structured binding: clang 14 (the fuzz preset's) cannot capture one in the lambda below (C++20 P1091).
    const std::pair<std::string, std::string> name_unit = name_and_unit(header);
    const std::string& raw_name = name_unit.first;
    const std::string& unit = name_unit.second;
    const std::string name = squeezed(raw_name);
    const auto unit_error = [&](const char* expected) {
        throw InputError(where, "unknown unit '" + unit + "' of column '" + c.header + "' (expected " + expected + ")");
    };
    if (one_of(name, {"wavelength", "wavelengths", "lambda", "\xce\xbb", "wl", "wave"})) {
        c.quantity = ColumnQuantity::wavelength;
        if (unit.empty()) {
            // refractiveindex.info's own CSV download writes "wl" in micrometres; any other name must say its unit.
            if (name != "wl") throw InputError(where, "column '" + c.header + "' does not say its unit; " + kExpected);
            c.to_nm = 1000.0;
        } else if (unit == "nm") {
            c.to_nm = 1.0;
        } else if (one_of(unit, {"um", "\xc2\xb5m", "\xce\xbcm", "micron", "microns", "micrometre", "micrometer"})) {
            c.to_nm = 1000.0;
        } else if (one_of(unit, {"a", "\xc3\x85", "\xc3\xa5", "\xe2\x84\xab", "angstrom", "angstroms"})) {
            // Å as U+00C5 (what keyboards type), U+212B (the ångström sign), å U+00E5 or ASCII
            c.to_nm = 0.1;
        } else {
            unit_error("nm, um, \xc2\xb5m or \xc3\x85");
        }
    } else if (one_of(name, {"energy", "photonenergy", "e", "ev", "hv", "h\xce\xbd"})) {
        c.quantity = ColumnQuantity::energy;
        c.to_nm = kHcEvNm;
        if (!(unit == "ev" || (unit.empty() && name == "ev"))) {
            if (unit.empty()) throw InputError(where, "column '" + c.header + "' does not say its unit; " + kExpected);
            unit_error("eV");
        }
    } else if (one_of(name, {"wavenumber", "wavenumbers", "nu", "\xce\xbd"})) {
        c.quantity = ColumnQuantity::wavenumber;
        c.to_nm = 1e7;
        if (!one_of(unit, {"cm-1", "1/cm", "cm^-1", "cm\xe2\x81\xbb\xc2\xb9"})) unit_error("cm-1");
    } else if (one_of(name, {"n", "nr", "nreal"})) {
        c.quantity = ColumnQuantity::n;
    } else if (one_of(name, {"k", "kappa", "\xce\xba", "ni", "nimag"})) {
        c.quantity = ColumnQuantity::k;
    } else if (one_of(name, {"e1", "eps1", "epsilon1",
                             "\xce\xb5"
                             "1",
                             "\xce\xb5\xe2\x82\x81", "er", "epsr", "epsilonr", "\xce\xb5r", "re(eps)", "re(epsilon)",
                             "re(\xce\xb5)"})) {
        c.quantity = ColumnQuantity::eps1;
    } else if (one_of(name, {"e2", "eps2", "epsilon2",
                             "\xce\xb5"
                             "2",
                             "\xce\xb5\xe2\x82\x82", "ei", "epsi", "epsiloni", "\xce\xb5i", "im(eps)", "im(epsilon)",
                             "im(\xce\xb5)"})) {
        c.quantity = ColumnQuantity::eps2;
    }
    return c;
}

// Whitespace-separated headers may spell a unit as its own token: "wavelength (nm) n k".
std::vector<std::string> header_fields(std::string_view line, FieldSeparator separator) {
    std::vector<std::string> out;
    if (separator != FieldSeparator::whitespace) {
        for (std::string_view f : split_table_fields(line, TableLayout{separator, false, {}})) out.emplace_back(f);
        return out;
    }
    for (std::string_view f : split_whitespace(line)) {
        if (!out.empty() && (f.front() == '(' || f.front() == '['))
            out.back() += " " + std::string(f);
        else
            out.emplace_back(f);
    }
    return out;
}

// n and k of a row (from ε₁, ε₂ when given) checked against the import range: InputError at `where` for a negative
// n, k or ε₂, n or k above 1e6 or |n + ik| near 0 (a row giving n alone with n near 0 is checked once k is known).
void physical_values(double& n, double& k, double e1, double e2, std::string_view n_text, std::string_view k_text,
                     std::string_view e1_text, std::string_view e2_text, const InputLocation& where) {
    if (!std::isnan(e1)) {
        if (e2 < 0.0)
            throw InputError(where,
                             "negative \xce\xb5\xe2\x82\x82 = " + std::string(e2_text) + " (absorption must be >= 0)");
        // |ε| = n² + k²: above 2e12, n or k is above the import limit (and near the double maximum (|ε| + ε₁)/2
        // overflowed to inf). Halves first, so that the modulus itself stays finite (the same values otherwise).
        const double half_modulus = std::hypot(e1 / 2.0, e2 / 2.0);
        if (half_modulus > kMaxIndex * kMaxIndex)
            throw InputError(where, "\xce\xb5\xe2\x82\x81 = " + std::string(e1_text) +
                                        ", \xce\xb5\xe2\x82\x82 = " + std::string(e2_text) +
                                        ": n or k would be above 1e6 (the largest n or k metalfit accepts)");
        n = std::sqrt(std::max(0.0, half_modulus + e1 / 2.0));
        k = std::sqrt(std::max(0.0, half_modulus - e1 / 2.0));
        const std::string converted[2]{significant_text(n, 6) + " (from \xce\xb5)",
                                       significant_text(k, 6) + " (from \xce\xb5)"};
        check_index_limit(n, false, converted[0], where);
        check_index_limit(k, true, converted[1], where);
    }
    if (n < 0.0) throw InputError(where, "negative refractive index n = " + std::string(n_text));
    if (k < 0.0) throw InputError(where, "negative extinction coefficient k = " + std::string(k_text));
    if (!std::isnan(n)) check_index_limit(n, false, n_text, where);
    if (!std::isnan(k)) check_index_limit(k, true, k_text, where);
    if (!std::isnan(n) && !std::isnan(k)) check_index_modulus(n, k, where);
}

}  // namespace

bool TableLayout::has(ColumnQuantity q) const {
    return std::any_of(columns.begin(), columns.end(), [q](const TableColumn& c) { return c.quantity == q; });
}

std::string TableLayout::describe() const {
    std::vector<std::string> names;
    for (const TableColumn& c : columns) names.push_back(c.header);
    return join(names);
}

std::string table_format_name(FieldSeparator separator) {
    switch (separator) {
        case FieldSeparator::comma: return "CSV";
        case FieldSeparator::semicolon: return "table (semicolon-separated)";
        case FieldSeparator::tab: return "table (tab-separated)";
        case FieldSeparator::whitespace: return "table (whitespace-separated)";
    }
    return "table";
}

bool is_table_extension(std::string_view ext) {
    return ext == ".csv" || ext == ".tsv" || ext == ".txt" || ext == ".dat";
}

std::string_view without_byte_order_mark(std::string_view line) {
    if (line.substr(0, 3) == "\xef\xbb\xbf") line.remove_prefix(3);
    return line;
}

std::vector<std::string_view> split_table_fields(std::string_view line, const TableLayout& layout) {
    if (layout.separator == FieldSeparator::whitespace) return split_whitespace(line);
    const char sep = layout.separator == FieldSeparator::comma       ? ','
                     : layout.separator == FieldSeparator::semicolon ? ';'
                                                                     : '\t';
    std::vector<std::string_view> out;
    std::size_t start = 0;
    for (std::size_t at; (at = line.find(sep, start)) != std::string_view::npos; start = at + 1)
        out.push_back(trim(line.substr(start, at - start)));
    out.push_back(trim(line.substr(start)));
    return out;
}

std::optional<TableLayout> parse_table_header(std::string_view line, const InputLocation& where) {
    TableLayout layout;
    layout.separator = line.find('\t') != std::string_view::npos  ? FieldSeparator::tab
                       : line.find(';') != std::string_view::npos ? FieldSeparator::semicolon
                       : line.find(',') != std::string_view::npos ? FieldSeparator::comma
                                                                  : FieldSeparator::whitespace;
    const std::vector<std::string> fields = header_fields(line, layout.separator);
    if (fields.empty()) return std::nullopt;
    std::string first = fields.front();
    std::replace(first.begin(), first.end(), ',', '.');  // "0,3009": a number with a decimal comma
    if (parse_number(fields.front()) || (layout.separator != FieldSeparator::comma && parse_number(first)))
        return std::nullopt;
    for (const std::string& f : fields) layout.columns.push_back(classify(f, where));

    const auto count = [&](ColumnQuantity q) {
        return std::count_if(layout.columns.begin(), layout.columns.end(),
                             [q](const TableColumn& c) { return c.quantity == q; });
    };
    const auto abscissae =
        count(ColumnQuantity::wavelength) + count(ColumnQuantity::energy) + count(ColumnQuantity::wavenumber);
    const std::string found = " (found '" + std::string(line) + "')";
    if (abscissae != 1)
        throw InputError(where, (abscissae == 0 ? std::string("no wavelength or energy column; ")
                                                : std::string("more than one wavelength or energy column; ")) +
                                    kExpected + found);
    if (layout.columns.front().quantity == ColumnQuantity::ignored)
        throw InputError(where, "unrecognised column '" + layout.columns.front().header + "'; " + kExpected + found);
    for (ColumnQuantity q : {ColumnQuantity::n, ColumnQuantity::k, ColumnQuantity::eps1, ColumnQuantity::eps2})
        if (count(q) > 1) throw InputError(where, "a quantity is given by two columns" + found);
    const bool nk = layout.has(ColumnQuantity::n) || layout.has(ColumnQuantity::k);
    const bool eps = layout.has(ColumnQuantity::eps1) || layout.has(ColumnQuantity::eps2);
    if (nk && eps) throw InputError(where, "both n, k and \xce\xb5 columns: give one pair" + found);
    if (eps && !(layout.has(ColumnQuantity::eps1) && layout.has(ColumnQuantity::eps2)))
        throw InputError(where, "\xce\xb5\xe2\x82\x81 and \xce\xb5\xe2\x82\x82 must both be given" + found);
    if (!nk && !eps) throw InputError(where, "no n, k (or e1, e2) column; " + std::string(kExpected) + found);
    return layout;
}

void add_table_row(std::string_view line, const TableLayout& layout, const InputLocation& where,
                   TableSamples& samples) {
    const std::vector<std::string_view> fields = split_table_fields(line, layout);
    if (fields.size() != layout.columns.size())
        throw InputError(where, "expected " + std::to_string(layout.columns.size()) + " fields (" + layout.describe() +
                                    "), found " + std::to_string(fields.size()));
    double x = 0.0, n = NAN, k = NAN, e1 = NAN, e2 = NAN;
    std::string_view n_text, k_text, e1_text, e2_text, x_text;
    const TableColumn* abscissa = nullptr;
    for (std::size_t i = 0; i < fields.size(); ++i) {
        const TableColumn& c = layout.columns[i];
        if (c.quantity == ColumnQuantity::ignored) continue;
        std::string text(fields[i]);
        if (layout.separator != FieldSeparator::comma && text.find(',') != std::string::npos &&
            text.find('.') == std::string::npos)
            std::replace(text.begin(), text.end(), ',', '.');  // decimal comma
        const auto value = parse_number(text);
        if (!value)
            throw InputError(where, "non-numeric value '" + std::string(fields[i]) + "' in column '" + c.header + "'");
        switch (c.quantity) {
            case ColumnQuantity::wavelength:
            case ColumnQuantity::energy:
            case ColumnQuantity::wavenumber:
                x = *value;
                x_text = fields[i];
                abscissa = &c;
                break;
            case ColumnQuantity::n:
                n = *value;
                n_text = fields[i];
                break;
            case ColumnQuantity::k:
                k = *value;
                k_text = fields[i];
                break;
            case ColumnQuantity::eps1:
                e1 = *value;
                e1_text = fields[i];
                break;
            case ColumnQuantity::eps2:
                e2 = *value;
                e2_text = fields[i];
                break;
            case ColumnQuantity::ignored: break;
        }
    }
    if (x <= 0.0) throw InputError(where, "column '" + abscissa->header + "' must be positive");
    const double nm = abscissa->quantity == ColumnQuantity::wavelength ? x * abscissa->to_nm : abscissa->to_nm / x;
    if (!std::isfinite(nm) || nm <= 0.0)
        throw InputError(where, "wavelength " + std::string(x_text) + " (column '" + abscissa->header +
                                    "') is out of range after unit conversion to nm");
    try {
        physical_values(n, k, e1, e2, n_text, k_text, e1_text, e2_text, where);
    } catch (const InputError& e) {
        samples.unphysical.push_back(
            {nm, e,
             (layout.has(ColumnQuantity::n) || layout.has(ColumnQuantity::eps1) ? 1u : 0u) |
                 (layout.has(ColumnQuantity::k) || layout.has(ColumnQuantity::eps2) ? 2u : 0u)});
        return;
    }
    if (std::isnan(k) && !std::isnan(n) && n < kMinIndexModulus) samples.small_n.push_back({where, nm, n});
    if (!std::isnan(n)) samples.n.push_back({nm, n});
    if (!std::isnan(k)) samples.k.push_back({nm, k});
}

}  // namespace metalfit::detail
