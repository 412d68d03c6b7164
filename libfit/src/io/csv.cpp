#include "libfit/io/csv.hpp"

#include <algorithm>
#include <optional>
#include <sstream>

#include "base/parse_number.hpp"
#include "io/table_columns.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/file_digest.hpp"
#include "libfit/base/input_file.hpp"
#include "libfit/base/utf8.hpp"
#include "libfit/io/refractiveindex.hpp"

namespace metalfit {

Material load_nk_csv(const std::filesystem::path& file) {
    const std::string bytes = read_input_file(file);  // a regular file within the size limit (input_file.hpp)
    // UTF-8 throughout, as YAML: column names and units reach records and messages (a byte-order mark is UTF-8 too).
    if (const auto problem = find_invalid_utf8(bytes))
        throw InputError({file, problem->line}, problem->reason + " (a table file is UTF-8 text)");
    std::istringstream in(bytes);
    std::optional<detail::TableLayout> layout;  // none until the first header line
    detail::TableSamples samples;
    std::vector<std::string> notes;
    int line_number = 0, blocks = 0;
    for (std::string raw; std::getline(in, raw);) {
        ++line_number;
        const std::string_view line =
            detail::trim(line_number == 1 ? detail::without_byte_order_mark(raw) : std::string_view(raw));
        if (line.empty() || line.front() == '#') continue;
        const InputLocation here{file, line_number};
        // A header line starts a block; a later one starts the next (refractiveindex.info: `wl,n` rows, `wl,k` rows).
        if (auto header = detail::parse_table_header(line, here)) {
            for (const auto& c : header->columns)
                if (c.quantity == detail::ColumnQuantity::ignored)
                    notes.push_back(file.string() + ":" + std::to_string(line_number) + ": column '" + c.header +
                                    "' ignored");
            layout = std::move(header);
            ++blocks;
            continue;
        }
        if (!layout)
            throw InputError(here, "a data row before any header line (expected the header 'wavelength_nm,n,k' or "
                                   "'wavelength_um,n,k', found '" +
                                       std::string(line) + "')");
        if (std::max(samples.n.size(), samples.k.size()) >= kMaxTableRows)
            throw InputError(here, "more than " + std::to_string(kMaxTableRows) + " data rows (the limit)");
        detail::add_table_row(line, *layout, here, samples);
    }
    if (!layout) throw InputError({file, 1}, "empty file (expected the header 'wavelength_nm,n,k')");
    // Rows no material has, far outside the visible range: dropped from there outward (or refused: unphysical_rows.hpp).
    const detail::UnphysicalTrim trim =
        detail::drop_unphysical_ends(samples.unphysical, samples.n, samples.k, 1.0, "nm");
    std::erase_if(samples.small_n, [&](const detail::SmallN& row) { return !trim.n.keeps(row.nm); });
    notes.insert(notes.end(), trim.warnings.begin(), trim.warnings.end());
    if (samples.n.empty() && samples.k.empty()) throw InputError({file, line_number}, "no data rows");
    if (samples.n.empty()) throw InputError({file, line_number}, "no n data (only k)");

    // Rows of n < 1e-6 given without k: |n + ik| with k where it is known (k = 0 without a k column).
    if (!samples.small_n.empty()) {
        const std::optional<Spectrum> k =
            samples.k.empty() ? std::nullopt : std::optional<Spectrum>(Spectrum(samples.k));
        detail::check_small_n(samples.small_n,
                              [&](double nm) { return k ? (*k)(nm, Interpolation::linear, OutOfRange::clamp) : 0.0; });
    }

    Material m;
    m.warnings = notes;
    Spectrum ns(std::move(samples.n));
    std::size_t conflicts = ns.conflicting_duplicates();
    SpectralCurve ks = ConstantSpectrum{0.0};
    if (samples.k.empty()) {
        m.warnings.push_back(file.string() + ": no k column: k = 0 assumed");
    } else {
        Spectrum tabulated_k(std::move(samples.k));
        conflicts = std::max(conflicts, tabulated_k.conflicting_duplicates());
        ks = std::move(tabulated_k);
    }
    if (conflicts > 0)
        m.warnings.push_back(file.string() + ": " + std::to_string(conflicts) +
                             " repeated wavelength(s) with different values: their mean is used");
    m.index = ComplexIndex{std::move(ns), std::move(ks)};
    m.id = m.name = file.stem().string();
    m.source = file.filename().string();
    m.provenance.file = file;
    m.provenance.format = detail::table_format_name(layout->separator);
    m.provenance.data_type = blocks > 1                                  ? "tabulated n + tabulated k"
                             : layout->has(detail::ColumnQuantity::eps1) ? "tabulated e1 e2 (converted to n, k)"
                                                                         : "tabulated nk";
    m.provenance.sha256 = sha256_bytes(bytes);
    return m;
}

Material load_nk_file(const std::filesystem::path& file) {
    // The path becomes the material's id and its provenance: records are UTF-8 (JSON).
    if (const auto problem = find_invalid_utf8(file.native()))
        throw InputError({file}, "the file name is not UTF-8 (" + problem->reason + "); rename the file");
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (detail::is_table_extension(ext)) return load_nk_csv(file);
    if (ext == ".yml" || ext == ".yaml") return load_refractiveindex_yaml(file);
    throw InputError({file}, "unknown file type '" + ext + "' (expected .yml, .yaml, .csv, .tsv, .txt or .dat)");
}

}  // namespace metalfit
