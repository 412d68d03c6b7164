#include "libfit/io/csv.hpp"

#include <algorithm>
#include <sstream>

#include "libfit/base/errors.hpp"
#include "libfit/base/file_digest.hpp"
#include "libfit/base/input_file.hpp"
#include "libfit/io/refractiveindex.hpp"
#include "base/parse_number.hpp"

namespace metalfit {

Material load_nk_csv(const std::filesystem::path& file) {
    const std::string bytes = read_input_file(file);
    std::istringstream in(bytes);
    double to_nm = 0.0;  // 0 until the header is read
    std::vector<SpectrumSample> n, k;
    int line_number = 0;
    for (std::string raw; std::getline(in, raw);) {
        ++line_number;
        const std::string_view line = detail::trim(raw);
        if (line.empty() || line.front() == '#') continue;
        const auto fields = detail::split_commas(line);
        const InputLocation here{file, line_number};
        if (to_nm == 0.0) {
            if (fields.size() == 3 && fields[1] == "n" && fields[2] == "k") {
                if (fields[0] == "wavelength_nm") to_nm = 1.0;
                if (fields[0] == "wavelength_um") to_nm = 1000.0;
            }
            if (to_nm == 0.0)
                throw InputError(here, "expected the header 'wavelength_nm,n,k' or 'wavelength_um,n,k', found '" +
                                           std::string(line) + "'");
            continue;
        }
        if (fields.size() != 3)
            throw InputError(here, "expected 3 fields (wavelength, n, k), found " + std::to_string(fields.size()));
        const std::vector<double> v = detail::parse_row(fields, here);
        detail::check_optical_row(v, fields, "nk", here);
        const double nm = detail::wavelength_nm(v[0], to_nm, fields[0], here);
        if (v[1] == 0.0 && v[2] == 0.0) throw InputError(here, detail::kZeroIndex);
        if (n.size() >= kMaxTableRows) throw InputError(here, "more than " + std::to_string(kMaxTableRows) + " data rows (the limit)");
        n.push_back({nm, v[1]});
        k.push_back({nm, v[2]});
    }
    if (to_nm == 0.0) throw InputError({file, 1}, "empty file (expected the header 'wavelength_nm,n,k')");
    if (n.empty()) throw InputError({file, line_number}, "no data rows");

    Material m;
    Spectrum ns(std::move(n)), ks(std::move(k));
    if (const auto conflicts = std::max(ns.conflicting_duplicates(), ks.conflicting_duplicates()); conflicts > 0)
        m.warnings.push_back(file.string() + ": " + std::to_string(conflicts) +
                             " repeated wavelength(s) with different values: their mean is used");
    m.index = ComplexIndex{std::move(ns), std::move(ks)};
    m.id = m.name = file.stem().string();
    m.source = file.filename().string();
    m.provenance.file = file;
    m.provenance.format = "CSV";
    m.provenance.data_type = "tabulated nk";
    m.provenance.sha256 = sha256_bytes(bytes);
    return m;
}

Material load_nk_file(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext == ".csv") return load_nk_csv(file);
    if (ext == ".yml" || ext == ".yaml") return load_refractiveindex_yaml(file);
    throw InputError({file}, "unknown file type '" + ext + "' (expected .yml, .yaml or .csv)");
}

}  // namespace metalfit
