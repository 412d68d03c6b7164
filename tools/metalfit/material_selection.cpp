#include "material_selection.hpp"

#include <filesystem>
#include <sstream>

#include "libfit/base/errors.hpp"
#include "libfit/fit/fit_batch.hpp"

namespace metalfit::cli {

void MaterialSelection::add_options(CLI::App& app, bool with_all) {
    app.add_option("material", arguments,
                   "Catalog materials (id, name or alias; several as Au,Cu,Ag or as separate arguments) or "
                   ".yml/.csv/.tsv/.txt/.dat files")
        ->default_str("");
    if (with_all) app.add_flag("--all", all, "Every material of the built-in catalog, in parallel");
    app.add_option("--source", source, "Alternate source of a catalog material (default: its primary)");
    app.add_option("--name", labels.name, "Name of the material in a file of your own (default: the file stem)");
    app.add_option("--reference", labels.reference,
                   "Literature reference of a file of your own, shown and exported (default: the file's REFERENCES)");
}

std::vector<std::string> MaterialSelection::materials() const {
    std::vector<std::string> names;
    for (const std::string& argument : arguments) {
        std::error_code error;
        // A file's path with a comma in it stays whole; a bare name is a list however the current folder's files are named.
        if (argument.find(',') == std::string::npos ||
            (looks_like_path(argument) && std::filesystem::is_regular_file(argument, error))) {
            names.push_back(argument);
            continue;
        }
        std::stringstream list(argument);
        for (std::string name; std::getline(list, name, ',');)
            if (!name.empty()) names.push_back(name);
    }
    return names;
}

std::vector<std::function<Material()>> MaterialSelection::loaders(const Catalog& catalog,
                                                                  const std::string& command) const {
    const std::vector<std::string> names = materials();
    if (!all && names.empty()) throw UsageError(command + ": give a material (catalog name or file), or --all");
    if (all && !names.empty()) throw UsageError(command + ": give materials or --all, not both");
    if (!source.empty() && (all || names.size() > 1)) throw UsageError(command + ": --source needs a single material");
    return material_loaders(catalog, all, names, source, labels);
}

}  // namespace metalfit::cli
