#include "export_options.hpp"

#include <algorithm>

#include "libfit/base/errors.hpp"

namespace metalfit::cli {

std::string export_format_list() {
    std::string list;
    for (const auto& [format, name] : kExportFormatNames.names) list += (list.empty() ? "" : ", ") + std::string(name);
    return list;
}

std::vector<ExportFormat> parse_export_formats(std::string_view list) {
    std::vector<ExportFormat> formats;
    if (list == "all") {
        for (const auto& [format, name] : kExportFormatNames.names) formats.push_back(format);
        return formats;
    }
    const std::string known = "(" + kExportFormatNames.known() + ", or all)";
    while (!list.empty()) {
        const auto comma = list.find(',');
        const std::string_view name = list.substr(0, comma);
        const std::optional<ExportFormat> format = kExportFormatNames.find(name);
        if (!format) throw UsageError("unknown export format '" + std::string(name) + "' " + known);
        if (std::find(formats.begin(), formats.end(), *format) == formats.end()) formats.push_back(*format);
        list = comma == std::string_view::npos ? std::string_view{} : list.substr(comma + 1);
    }
    if (formats.empty()) throw UsageError("empty export format list " + known);
    return formats;
}

double parse_roughness(const std::string& text) {
    if (const std::optional<double> roughness = roughness_from_text(text)) return *roughness;
    throw UsageError("--roughness '" + text + "': expected a number in [0, 1] (OpenPBR's specular_roughness)");
}

std::string parse_id_prefix(const std::string& text) {
    if (const std::string problem = id_prefix_problem(text); !problem.empty())
        throw UsageError("--id-prefix '" + text + "': " + problem);
    return text;
}

}  // namespace metalfit::cli
