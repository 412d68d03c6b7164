// C++ export: cpp/metalfit_models.hpp is the GLSL of the model folders made valid C++ by a prelude (a float vec3 with
// GLSL's operators and the built-ins the models use) and `inline` before each top-level function; one header per
// material and model holds constexpr parameter arrays in a namespace; cpp/metalfit_materials.hpp includes them all
// and lists them in one table.
#include <cctype>

#include "export/export_formats.hpp"
#include "libfit/base/names.hpp"
#include "libfit/base/version.hpp"

namespace metalfit {

namespace {

constexpr std::string_view kCppPrelude =
    R"cpp(// The GLSL subset the model functions use, in C++ (docs/export.md): float vec3 arithmetic and built-ins.
#include <array>
#include <cmath>

namespace metalfit_shader {

struct bvec3 {
    bool x, y, z;
};

struct vec3 {
    float x, y, z;
    constexpr vec3() : x(0), y(0), z(0) {}
    constexpr explicit vec3(float s) : x(s), y(s), z(s) {}
    constexpr vec3(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
    constexpr explicit vec3(const std::array<double, 3>& v)
        : x(static_cast<float>(v[0])), y(static_cast<float>(v[1])), z(static_cast<float>(v[2])) {}
};

inline vec3 operator+(vec3 a, vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline vec3 operator-(vec3 a, vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline vec3 operator*(vec3 a, vec3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
inline vec3 operator/(vec3 a, vec3 b) { return {a.x / b.x, a.y / b.y, a.z / b.z}; }
inline vec3 operator+(vec3 a, float s) { return a + vec3(s); }
inline vec3 operator-(vec3 a, float s) { return a - vec3(s); }
inline vec3 operator*(vec3 a, float s) { return a * vec3(s); }
inline vec3 operator/(vec3 a, float s) { return a / vec3(s); }
inline vec3 operator+(float s, vec3 a) { return vec3(s) + a; }
inline vec3 operator-(float s, vec3 a) { return vec3(s) - a; }
inline vec3 operator*(float s, vec3 a) { return vec3(s) * a; }
inline vec3 operator/(float s, vec3 a) { return vec3(s) / a; }
inline vec3 operator-(vec3 a) { return {-a.x, -a.y, -a.z}; }

inline vec3 sqrt(vec3 v) { return {std::sqrt(v.x), std::sqrt(v.y), std::sqrt(v.z)}; }
inline vec3 pow(vec3 a, vec3 b) { return {std::pow(a.x, b.x), std::pow(a.y, b.y), std::pow(a.z, b.z)}; }
inline float glsl_max(float a, float b) { return a < b ? b : a; }
inline vec3 max(vec3 a, vec3 b) { return {glsl_max(a.x, b.x), glsl_max(a.y, b.y), glsl_max(a.z, b.z)}; }
inline vec3 max(vec3 a, float b) { return max(a, vec3(b)); }
inline vec3 mix(vec3 a, vec3 b, bvec3 t) { return {t.x ? b.x : a.x, t.y ? b.y : a.y, t.z ? b.z : a.z}; }
inline vec3 mix(vec3 a, vec3 b, float t) { return a * (1.0f - t) + b * t; }
inline bvec3 greaterThanEqual(vec3 a, vec3 b) { return {a.x >= b.x, a.y >= b.y, a.z >= b.z}; }
inline bvec3 equal(vec3 a, vec3 b) { return {a.x == b.x, a.y == b.y, a.z == b.z}; }

)cpp";

// `inline ` before every line that starts a top-level function definition (a type at column 0).
std::string inline_functions(std::string_view glsl) {
    std::string out;
    std::size_t i = 0;
    while (i < glsl.size()) {
        const std::size_t end = glsl.find('\n', i);
        const std::string_view line =
            glsl.substr(i, end == std::string_view::npos ? std::string_view::npos : end - i + 1);
        for (std::string_view type : {"vec3 ", "bvec3 ", "float "})
            if (line.starts_with(type) && line.find('(') != std::string_view::npos) out += "inline ";
        out += line;
        i += line.size();
    }
    return out;
}

// GLSL's floating literals are float, C++'s double: `f` after each (1.0 → 1.0f, 1e-30 → 1e-30f), so that the
// header is clean under -Wconversion -Wdouble-promotion and evaluates in float as the shader does. Comments,
// identifiers (F82, m6_bar) and integer literals are copied unchanged.
std::string float_literals(std::string_view glsl) {
    const auto digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
    const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    std::string out;
    std::size_t i = 0;
    while (i < glsl.size()) {
        if (glsl.substr(i, 2) == "//") {
            const std::size_t end = std::min(glsl.find('\n', i), glsl.size());
            out += glsl.substr(i, end - i);
            i = end;
        } else if (word(glsl[i]) && !digit(glsl[i])) {
            std::size_t j = i;
            while (j < glsl.size() && word(glsl[j])) ++j;
            out += glsl.substr(i, j - i);
            i = j;
        } else if (digit(glsl[i]) || (glsl[i] == '.' && i + 1 < glsl.size() && digit(glsl[i + 1]))) {
            std::size_t j = i;
            bool floating = false;
            while (j < glsl.size() && (digit(glsl[j]) || glsl[j] == '.')) floating |= glsl[j++] == '.';
            if (j < glsl.size() && (glsl[j] == 'e' || glsl[j] == 'E')) {
                floating = true;
                ++j;
                if (j < glsl.size() && (glsl[j] == '-' || glsl[j] == '+')) ++j;
                while (j < glsl.size() && digit(glsl[j])) ++j;
            }
            out += glsl.substr(i, j - i);
            if (floating) out += 'f';
            i = j;
        } else {
            out += glsl[i++];
        }
    }
    return out;
}

}  // namespace

std::string_view cpp_glsl_prelude() { return kCppPrelude; }

namespace detail {

std::string cpp_materials_index_head() {
    return "// metalfit " METALFIT_VERSION " exports: every material and model of this export, and one table of them.\n"
           "#pragma once\n\n#include <array>\n\n";
}

std::string cpp_materials_index_middle(std::string_view id_prefix, std::size_t count) {
    const std::string name = cpp_index_name(id_prefix);
    return "\nnamespace " + name +
           " {\n\nstruct Entry {\n    const char* material;\n    const char* model;\n"
           "    metalfit_shader::vec3 (*evaluate)(float mu);\n    int parameter_count;\n"
           "    std::array<const std::array<double, 3>*, 4> parameters;  // in the order of `metalfit models`\n};\n\n"
           "inline const std::array<Entry, " +
           std::to_string(count) + "> all{{\n";
}

std::string cpp_materials_index_tail(std::string_view id_prefix) {
    return "}};\n\n}  // namespace " + cpp_index_name(id_prefix) + "\n";
}

std::string cpp_materials_index(const std::vector<CppIndexEntry>& entries, std::string_view id_prefix) {
    std::string umbrella = cpp_materials_index_head();
    std::string table;
    for (const CppIndexEntry& e : entries) {
        umbrella += e.include + "\n";
        table += e.row + "\n";
    }
    return umbrella + cpp_materials_index_middle(id_prefix, entries.size()) + table +
           cpp_materials_index_tail(id_prefix);
}

std::vector<CppIndexEntry> parse_cpp_materials_index(std::string_view text) {
    std::vector<std::string> includes, rows;
    while (!text.empty()) {
        const auto nl = text.find('\n');
        const std::string_view line = text.substr(0, nl);
        if (line.starts_with("#include \"")) includes.emplace_back(line);
        if (line.starts_with("    {\"")) rows.emplace_back(line);
        text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
    }
    if (includes.size() != rows.size()) throw std::invalid_argument("includes and table rows differ in number");
    std::vector<CppIndexEntry> entries;
    for (std::size_t i = 0; i < includes.size(); ++i) entries.push_back({includes[i], rows[i]});
    return entries;
}

std::string cpp_models_file(const std::vector<const Model*>& models) {
    return "// metalfit " METALFIT_VERSION " Fresnel models for C++: the GLSL of libfit/models, unchanged but for "
           "`inline` and float\n// literals (1.0f), over a small vec3 prelude (docs/export.md). F(mu), mu = cos(theta), per "
           "RGB channel. C++20;\n// clean under -Wall -Wextra -Wconversion -Wdouble-promotion.\n"
           "#pragma once\n\n" +
           std::string(kCppPrelude) + inline_functions(float_literals(glsl_library(models))) +
           "\n}  // namespace metalfit_shader\n";
}

std::vector<ExportFile> export_cpp(const std::vector<MaterialExport>& materials, const ExportContext& context) {
    std::vector<ExportFile> files;
    files.push_back({"cpp/metalfit_models.hpp", cpp_models_file(context.request.models)});
    std::vector<CppIndexEntry> index;
    for (const MaterialExport& m : materials)
        for (const ModelExport& e : m.models) {
            const WrittenParameters& w = e.written;
            const std::string stem = file_stem(context.request.id_prefix, m.fit->material.id, w.model->id());
            std::string text = comment_header(m, w, context, "// ");
            text +=
                "#pragma once\n\n#include <array>\n\n#include \"metalfit_models.hpp\"\n\nnamespace " + stem + " {\n\n";
            text += "inline constexpr const char* material = " + c_string_literal(m.fit->material.id) + ";\n";
            text += "inline constexpr const char* model = \"" + std::string(w.model->id()) + "\";\n";
            std::string args, pointers;
            const auto parameters = w.model->parameters();
            for (std::size_t i = 0; i < parameters.size(); ++i) {
                const std::string name(parameters[i].name);
                text += "inline constexpr std::array<double, 3> " + name + "{" + channel_list(w.params, i) + "};  // " +
                        std::string(parameters[i].meaning) + "\n";
                args += "metalfit_shader::vec3(" + name + "), ";
                pointers += (i ? ", &" : "&") + stem + "::" + name;
            }
            text +=
                "\n// F(mu) of this material and model, per RGB channel.\ninline metalfit_shader::vec3 evaluate(float mu) {\n"
                "    return metalfit_shader::" +
                std::string(w.model->glsl_function()) + "(" + args + "mu);\n}\n\n}  // namespace " + stem + "\n";
            files.push_back({"cpp/" + stem + ".hpp", text, colours_out_of_range(m, w, w.model->id())});
            index.push_back({"#include \"" + stem + ".hpp\"", "    {" + c_string_literal(m.fit->material.id) + ", \"" +
                                                                  std::string(w.model->id()) + "\", &" + stem +
                                                                  "::evaluate, " + std::to_string(parameters.size()) +
                                                                  ", {" + pointers + "}},"});
        }
    files.push_back({cpp_index_path(context.request.id_prefix), cpp_materials_index(index, context.request.id_prefix)});
    return files;
}

}  // namespace detail
}  // namespace metalfit
