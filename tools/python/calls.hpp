// What the Python module does, as plain C++ over the CLI's own option structs (tools/metalfit): each call resolves
// its options with the same helpers as `metalfit list`, `show`, `fit --json` and `export`, and calls the same libfit
// functions, so that a keyword argument means what the option means and an error carries the same message.
// Nothing here knows Python: module.cpp converts arguments and results, and releases the GIL around these calls.
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "colour_options.hpp"
#include "commands.hpp"
#include "error_options.hpp"
#include "layer_options.hpp"
#include "libfit/color/color.hpp"
#include "material_selection.hpp"

namespace metalfit::python {

// `metalfit list --json`: the text of the record.
std::string catalog_json(const cli::GlobalOptions& global);

// `metalfit show`'s material and colour options, for reference().
struct ReferenceOptions {
    cli::MaterialSelection selection;
    cli::LayerOptions layers;
    cli::ColourOptions colour;
};

// R_c(μ) of one material at each μ (in [0, 1]), as `metalfit show` computes it; warnings on stderr as show prints them.
std::vector<RGB> reference(const ReferenceOptions& options, const cli::GlobalOptions& global,
                           std::span<const double> mu);

// `metalfit fit`'s options that shape the record (the output options --json, -o, --summary, --timings are not here).
struct FitOptions {
    cli::MaterialSelection selection;
    cli::LayerOptions layers;
    std::string models = "all";
    cli::ColourOptions colour;
    cli::ErrorOptions error;
    int jobs = 0;     // 0: all cores
    std::string pin;  // "F0" or empty
    bool gamut_fit = false;
    std::string budget;  // empty: none
    std::string budget_metric = "rel_rms";
    std::filesystem::path costs;
};

// The text `metalfit fit --json` prints for these options (without its final newline).
std::string fit_json(const FitOptions& options, const cli::GlobalOptions& global);

// `metalfit export`'s options (without --model best:BUDGET, which chooses a model per material: docs/python.md).
struct ExportOptions {
    cli::MaterialSelection selection;
    cli::LayerOptions layers;
    std::string models;
    std::string params = "fit";
    std::string formats;
    std::string gamut = "keep";
    bool gamut_fit = false;
    std::string roughness;  // empty: the default roughness
    std::string id_prefix;  // empty: the default prefix
    cli::ColourOptions colour;
    int jobs = 0;
    std::filesystem::path output;
};

// Writes the export folder as `metalfit export` does; returns the files written, relative to the folder, sorted.
std::vector<std::string> export_folder(const ExportOptions& options, const cli::GlobalOptions& global);

}  // namespace metalfit::python
