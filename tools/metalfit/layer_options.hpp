// --film and --coat: layers over every material a subcommand works on (docs/cli.md, "Layers"). Shared by show, fit,
// export, report and table (the one place they are parsed).
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "libfit/io/layer_stack.hpp"
#include "libfit/io/material.hpp"
#include "libfit/reference/reference_curve.hpp"

namespace metalfit::cli {

struct LayerOptions {
    std::string film;  // IOR|MATERIAL|FILE:THICKNESS
    std::string coat;  // IOR|MATERIAL|FILE[:THICKNESS]

    void add_options(CLI::App& app);
    // The loaders with the layers put over each material. The layers are loaded and checked here, before any work
    // (an unknown name: UsageError; a bad thickness, index or file, or a table not covering the colour range:
    // InputError); without --film and --coat the loaders are returned as they are.
    std::vector<std::function<Material()>> over(std::vector<std::function<Material()>> loaders,
                                                const std::filesystem::path& data_dir,
                                                const SpectralOptions& spectral) const;

    // The oxide chart's layers (`table --thickness`): the film's material without a thickness (--film is required
    // then) and the coat, if any, loaded and checked as for over().
    struct ChartLayers {
        LayerMaterial film;
        std::optional<ClearCoat> coat;
    };
    ChartLayers chart_layers(const std::filesystem::path& data_dir) const;
};

}  // namespace metalfit::cli
