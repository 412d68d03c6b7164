// Internal: the layout of a user's n,k table (CSV, TSV, instrument .txt/.dat exports): which character separates the
// fields, what each column holds and in which unit, read from a header line; and the rows read under that layout.
// The file is opened and read line by line by load_nk_csv (csv.cpp); everything about columns and units is here.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/parse_number.hpp"
#include "io/unphysical_rows.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/spectral/spectrum.hpp"

namespace metalfit::detail {

enum class FieldSeparator { comma, semicolon, tab, whitespace };

// What a column holds.
enum class ColumnQuantity { wavelength, energy, wavenumber, n, k, eps1, eps2, ignored };

struct TableColumn {
    std::string header;  // as written
    ColumnQuantity quantity = ColumnQuantity::ignored;
    double to_nm = 1.0;  // wavelength: nm per unit; energy: nm·eV (hc); wavenumber: nm·cm⁻¹ (1e7)
};

// One header line: the separator it uses and its columns. A layout has exactly one abscissa column (wavelength,
// energy or wavenumber) and either n and k, ε₁ and ε₂, or n alone or k alone (the refractiveindex.info CSV
// download writes a `wl,n` block and then a `wl,k` block). Other named columns are ignored.
struct TableLayout {
    FieldSeparator separator = FieldSeparator::comma;
    bool decimal_comma = false;  // "0,43" in a semicolon- or tab-separated file
    std::vector<TableColumn> columns;

    bool has(ColumnQuantity q) const;
    // "wavelength (nm), n, k", for messages.
    std::string describe() const;
};

// The layout a header line describes, or nullopt when the line is not a header (its first field is a number).
// Throws InputError at `where` for a header it cannot use, saying what it expects.
std::optional<TableLayout> parse_table_header(std::string_view line, const InputLocation& where);

// The fields of a data line under `layout`.
std::vector<std::string_view> split_table_fields(std::string_view line, const TableLayout& layout);

// n and k samples in nm read from the rows of one or more blocks.
struct TableSamples {
    std::vector<SpectrumSample> n, k;
    std::vector<std::string> ignored_columns;  // headers of columns that were not read
    std::vector<SmallN> small_n;               // rows giving n < 1e-6 without k: checked once k is known
    std::vector<UnphysicalRow> unphysical;     // rows refused by the import range: drop_unphysical_ends decides
};

// Adds one data row read under `layout` to `samples` (ε₁, ε₂ converted to n, k). Throws InputError at `where` for a
// wrong field count, a non-number, a non-positive abscissa; a row with a negative n or k (or ε₂), n or k above 1e6 or
// |n + ik| near 0 goes to `samples.unphysical` (refused or dropped once the file is read: unphysical_rows.hpp).
void add_table_row(std::string_view line, const TableLayout& layout, const InputLocation& where, TableSamples& samples);

// "CSV" for comma-separated files (as before), else "table (tab-separated)" etc.: the provenance format name.
std::string table_format_name(FieldSeparator separator);

// True for the extensions read as tables: ".csv", ".tsv", ".txt", ".dat" (lower case, with the dot).
bool is_table_extension(std::string_view lower_case_extension);

// A UTF-8 byte-order mark at the start of `line` removed.
std::string_view without_byte_order_mark(std::string_view line);

}  // namespace metalfit::detail
