// metalfit table: F0 and F82 tint of every catalog metal (or of the materials named, under --film/--coat when given),
// linear and as 8-bit display values / hex, with the source and caveat (libfit's metal_table), as CSV, JSON or
// Markdown; or, in srgb-linear and ACEScg at once, in physicallybased.info's material shape (libfit's
// physicallybased_table).
#include <nlohmann/json.hpp>

#include "colour_options.hpp"
#include "commands.hpp"
#include "layer_options.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/fit/fit_batch.hpp"
#include "libfit/fit/metal_table.hpp"
#include "libfit/fit/physicallybased_table.hpp"
#include "material_selection.hpp"

namespace metalfit::cli {
namespace {

struct TableOptions {
    MaterialSelection selection;
    LayerOptions layers;
    ColourOptions colour;
    std::string format = "md";
    std::filesystem::path output;
};

}  // namespace

std::function<void()> add_table_command(CLI::App& app, const GlobalOptions& global) {
    auto o = std::make_shared<TableOptions>();
    o->selection.add_options(app, false);
    o->layers.add_options(app);
    add_colour_options(app, o->colour);
    app.add_option("--format", o->format,
                   "csv, json, md (Markdown; default md) or physicallybased (physicallybased.info's "
                   "material JSON, srgb-linear and ACEScg whatever --space says)")
        ->check(CLI::IsMember({"csv", "json", "md", "physicallybased"}));
    app.add_option("-o,--output", o->output, "Write to this file instead of stdout");
    return [o, &global] {
        const Catalog catalog = Catalog::load(global.data_dir);
        const ColourSetup setup = resolve_colour_options(o->colour, global);
        const bool every_metal = o->selection.materials().empty();
        if (o->format == "physicallybased") {
            if (!every_metal || !o->layers.film.empty() || !o->layers.coat.empty())
                throw UsageError(
                    "table --format physicallybased writes the catalog's bare metals: no materials, --film or --coat");
            const ColorSpaceConverter srgb_linear =
                ColorSpaceConverter::create(setup.config, kPhysicallyBasedSrgbLinear, o->colour.xyz_space);
            const ColorSpaceConverter acescg =
                ColorSpaceConverter::create(setup.config, kPhysicallyBasedAcescg, o->colour.xyz_space);
            const PhysicallyBasedTable table =
                physicallybased_table(catalog, {setup.colorimetry, srgb_linear, acescg, setup.spectral});
            emit(physicallybased_json(table).dump(2) + "\n", o->output);
            return;
        }
        const ColorSpaceConverter scene_linear = ColorSpaceConverter::create(setup.config);
        const DisplayTransform display = DisplayTransform::create(setup.config);
        // No material named: every catalog metal (under the layers, when given).
        const auto selected = every_metal ? material_loaders(catalog, true, {}, "", o->selection.labels)
                                          : o->selection.loaders(catalog, "table");
        const auto loaders = o->layers.over(selected, global.data_dir, setup.spectral);
        const MetalTable table =
            metal_table(loaders, catalog, {setup.colorimetry, setup.converter, scene_linear, display, setup.spectral});
        if (o->format == "csv")
            emit(metal_table_csv(table), o->output);
        else if (o->format == "json")
            emit(metal_table_json(table).dump(2) + "\n", o->output);
        else
            emit(metal_table_markdown(table), o->output);
    };
}

}  // namespace metalfit::cli
