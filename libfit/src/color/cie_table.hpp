// Internal: reading the CIE's CSV tables ("wavelength_nm,c1[,c2,c3]", a header line, integer wavelengths).
#pragma once

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "base/parse_number.hpp"
#include "libfit/base/errors.hpp"

namespace metalfit::detail {

using CieTable = std::map<int, std::vector<double>>;  // wavelength → the values of its row

inline CieTable read_cie_table(const std::filesystem::path& file, std::size_t columns) {
    std::ifstream in(file);
    if (!in) throw InputError({file}, "cannot open CIE table");
    CieTable rows;
    int line_number = 0;
    for (std::string raw; std::getline(in, raw);) {
        ++line_number;
        const auto line = trim(raw);
        if (line.empty() || line_number == 1) continue;  // header
        const auto fields = split_commas(line);
        if (fields.size() != columns + 1)
            throw InputError({file, line_number}, "expected " + std::to_string(columns + 1) + " fields");
        const std::vector<double> v = parse_row(fields, {file, line_number});
        rows[static_cast<int>(std::lround(v[0]))] = std::vector<double>(v.begin() + 1, v.end());
    }
    return rows;
}

inline const std::vector<double>& cie_row(const CieTable& table, int nm, const std::filesystem::path& file,
                                          const std::string& needed) {
    const auto it = table.find(nm);
    if (it == table.end()) throw InputError({file}, "no row for " + std::to_string(nm) + " nm (" + needed + " needed)");
    return it->second;
}

}  // namespace metalfit::detail
