// The values of `metalfit export`'s options that name export things: --format, --roughness, --id-prefix. Each a
// UsageError naming the option and the value, before any work.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "libfit/export/export.hpp"

namespace metalfit::cli {

// "glsl,mtlx" or "all", in the order given (duplicates removed); UsageError naming the unknown format.
std::vector<ExportFormat> parse_export_formats(std::string_view list);
// The formats as --help lists them: "json, glsl, hlsl, mtlx, openpbr, cpp, gltf".
std::string export_format_list();
// "0.25" → 0.25; UsageError naming the value when it is not a number in [0, 1].
double parse_roughness(const std::string& text);
// "studio" → "studio"; UsageError naming the value when it cannot be an id prefix (id_prefix_problem).
std::string parse_id_prefix(const std::string& text);

}  // namespace metalfit::cli
