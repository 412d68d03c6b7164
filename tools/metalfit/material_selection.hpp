// Which materials a subcommand works on: positional materials (each a catalog name or a file; "Au,Cu,Ag" lists
// several), or --all, and --source for a single catalog material. Shared by show, fit and export.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

#include "libfit/io/catalog.hpp"
#include "libfit/io/material.hpp"

namespace metalfit::cli {

struct MaterialSelection {
    std::vector<std::string> arguments;  // as typed; split at commas by materials()
    bool all = false;
    std::string source;
    UserFileLabels labels;  // --name, --reference: for one file of your own

    // Registers the positional materials (and --all when `with_all`), --source, --name and --reference.
    void add_options(CLI::App& app, bool with_all);
    // The materials named, in order: each argument split at commas unless it names an existing file.
    std::vector<std::string> materials() const;
    // One loader per material (every catalog entry for --all); usage errors (none given, both, --source with several)
    // and unknown names or bad files are thrown before any work. The loaders refer to `catalog`.
    std::vector<std::function<Material()>> loaders(const Catalog& catalog, const std::string& command) const;
};

}  // namespace metalfit::cli
