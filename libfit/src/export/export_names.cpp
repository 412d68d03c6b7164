// The names and numbers every export writes: the per-material identifiers (`<prefix>_<material>_<model>`) and the
// numbers as floating-point literals (shortest round trip, libfit/base/number_text).
#include <cctype>

#include "export/export_formats.hpp"
#include "libfit/base/number_text.hpp"

namespace metalfit::detail {

std::string file_stem(std::string_view id_prefix, const std::string& material_id, std::string_view model_id) {
    std::string s = std::string(id_prefix) + "_" + material_id + "_" + std::string(model_id);
    for (char& ch : s)
        ch = std::isalnum(static_cast<unsigned char>(ch))
                 ? static_cast<char>(std::tolower(static_cast<unsigned char>(ch)))
                 : '_';
    return s;
}

std::string constant_stem(std::string_view id_prefix, const std::string& material_id, std::string_view model_id) {
    std::string s = file_stem(id_prefix, material_id, model_id);
    for (char& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    return s;
}

std::string cpp_index_name(std::string_view id_prefix) { return std::string(id_prefix) + "_materials"; }
std::string cpp_index_path(std::string_view id_prefix) { return "cpp/" + cpp_index_name(id_prefix) + ".hpp"; }

namespace {

// "2" → "2.0": every exported number reads as a floating-point literal (GLSL, HLSL, C++, MaterialX floats).
std::string with_point(std::string s) {
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
    return s;
}

}  // namespace

std::string number(double v) { return with_point(shortest_text(v)); }

std::string shader_number(double v) { return with_point(shortest_text(static_cast<float>(v))); }

std::string channel_list(const ModelParameters& params, std::size_t index) {
    const RGB v = params.parameter(index);
    return number(v.r) + ", " + number(v.g) + ", " + number(v.b);
}

std::string shader_channel_list(const ModelParameters& params, std::size_t index) {
    const RGB v = params.parameter(index);
    return shader_number(v.r) + ", " + shader_number(v.g) + ", " + shader_number(v.b);
}

}  // namespace metalfit::detail
