// The index files of a second export into a folder (metalfit_export.json, cpp/<prefix>_materials.hpp and the shared
// model files): merged with what is there, so that no entry is lost. Which files a format shares is its
// format_registry entry's merge_index.
#include <algorithm>

#include "export/format_registry.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/models/model.hpp"

namespace metalfit::detail {

namespace {

// The registered models whose functions a shared model file defines ("vec3 metalfit_schlick(", "float3 …", "fn …").
std::vector<const Model*> models_defined_in(std::string_view text) {
    std::vector<const Model*> models;
    for (const Model* m : all_models()) {
        const std::string name = std::string(m->glsl_function()) + "(";
        if (text.find("vec3 " + name) != std::string_view::npos ||
            text.find("float3 " + name) != std::string_view::npos || text.find("fn " + name) != std::string_view::npos)
            models.push_back(m);
    }
    return models;
}

// A shared model file: the one there already defines only models of this one (then this one), or the union of both
// written again (registry order).
std::string merge_models_file(const std::string& existing, const std::string& mine,
                              std::string (*models_file)(const std::vector<const Model*>&)) {
    std::vector<const Model*> models = models_defined_in(existing);
    const std::vector<const Model*> now = models_defined_in(mine);
    if (std::all_of(models.begin(), models.end(),
                    [&](const Model* m) { return std::find(now.begin(), now.end(), m) != now.end(); }))
        return mine;
    std::vector<const Model*> all;  // registry order
    for (const Model* m : all_models())
        if (std::find(models.begin(), models.end(), m) != models.end() ||
            std::find(now.begin(), now.end(), m) != now.end())
            all.push_back(m);
    return models_file(all);
}

}  // namespace

std::optional<std::string> merge_json_index(const std::string& relative, const std::string& existing,
                                            const std::string& mine) {
    if (relative != "metalfit_export.json") return std::nullopt;
    return merge_json_record(existing, mine);
}

std::optional<std::string> merge_glsl_index(const std::string& relative, const std::string& existing,
                                            const std::string& mine) {
    if (relative != "glsl/metalfit_models.glsl") return std::nullopt;
    return merge_models_file(existing, mine, &glsl_models_file);
}

std::optional<std::string> merge_hlsl_index(const std::string& relative, const std::string& existing,
                                            const std::string& mine) {
    if (relative != "hlsl/metalfit_models.hlsl") return std::nullopt;
    return merge_models_file(existing, mine, &hlsl_models_file);
}

std::optional<std::string> merge_msl_index(const std::string& relative, const std::string& existing,
                                           const std::string& mine) {
    if (relative != "msl/metalfit_models.metal") return std::nullopt;
    return merge_models_file(existing, mine, &msl_models_file);
}

std::optional<std::string> merge_wgsl_index(const std::string& relative, const std::string& existing,
                                            const std::string& mine) {
    if (relative != "wgsl/metalfit_models.wgsl") return std::nullopt;
    return merge_models_file(existing, mine, &wgsl_models_file);
}

std::optional<std::string> merge_cpp_index(const std::string& relative, const std::string& existing,
                                           const std::string& mine) {
    if (relative == "cpp/metalfit_models.hpp") return merge_models_file(existing, mine, &cpp_models_file);
    if (!relative.starts_with("cpp/") || !relative.ends_with("_materials.hpp")) return std::nullopt;
    const std::string prefix =
        relative.substr(4, relative.size() - 4 - std::string_view("_materials.hpp").size());  // of cpp_index_path
    std::vector<CppIndexEntry> entries = parse_cpp_materials_index(existing);
    for (const CppIndexEntry& e : parse_cpp_materials_index(mine)) {
        const auto same = std::find_if(entries.begin(), entries.end(),
                                       [&](const CppIndexEntry& x) { return x.include == e.include; });
        if (same != entries.end())
            *same = e;
        else
            entries.push_back(e);
    }
    return cpp_materials_index(entries, prefix);
}

std::string merge_index(const std::filesystem::path& dir, const std::filesystem::path& relative,
                        const std::string& existing, const std::string& mine) {
    const std::string name = relative.generic_string();
    try {
        for (const ExportFormatEntry& format : export_format_entries())
            if (format.merge_index)
                if (std::optional<std::string> merged = format.merge_index(name, existing, mine))
                    return *std::move(merged);
    } catch (const std::invalid_argument& e) {
        throw InputError({dir / relative}, std::string("cannot add this export to the folder: ") + e.what() +
                                               "; export into another folder or remove this one");
    }
    return mine;
}

}  // namespace metalfit::detail
