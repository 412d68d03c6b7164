#include "layer_options.hpp"

#include <memory>

#include "libfit/base/errors.hpp"
#include "libfit/io/layer_materials.hpp"
#include "libfit/io/layer_stack.hpp"
#include "libfit/reference/stack_grid.hpp"

namespace metalfit::cli {

void LayerOptions::add_options(CLI::App& app) {
    app.add_option("--film", film,
                   "A thin film over the metal, IOR|MATERIAL|FILE:THICKNESS with a unit (2.2:80nm, TiO2:80nm, "
                   "my-oxide.csv:0.12um; 0 to 2 µm): coherent, per polarisation (docs/colour.md)");
    app.add_option("--coat", coat,
                   "A smooth clear coat over the metal (and film), IOR|MATERIAL|FILE[:THICKNESS] (1.5, PMMA, "
                   "PMMA:20um: the thickness makes its k absorb): incoherent (docs/colour.md)");
}

std::vector<std::function<Material()>> LayerOptions::over(std::vector<std::function<Material()>> loaders,
                                                          const std::filesystem::path& data_dir,
                                                          const SpectralOptions& spectral) const {
    if (film.empty() && coat.empty()) return loaders;
    auto stack = std::make_shared<LayerStack>(load_layers(FilmCatalog::load(data_dir), film, coat));
    require_layer_coverage(*stack, kVisibleRange, spectral);
    const std::vector<std::string> warnings = layer_warnings(*stack);
    std::shared_ptr<const LayerStack> layers = std::move(stack);
    for (auto& load : loaders)
        load = [load = std::move(load), layers, warnings] {
            Material m = load();
            if (m.layers && !m.layers->empty())
                throw UsageError(m.id + " is a named finish with layers of its own: give its metal with --film/--coat, "
                                        "or the finish alone");
            m.layers = layers;
            m.warnings.insert(m.warnings.end(), warnings.begin(), warnings.end());
            return m;
        };
    return loaders;
}

LayerOptions::ChartLayers LayerOptions::chart_layers(const std::filesystem::path& data_dir) const {
    if (film.empty()) throw UsageError("--thickness charts a film: give --film MATERIAL (TiO2) or an index (2.2)");
    const FilmCatalog films = FilmCatalog::load(data_dir);
    ChartLayers layers{load_film_material(films, film), std::nullopt};
    if (!coat.empty()) layers.coat = load_coat(films, coat);
    return layers;
}

}  // namespace metalfit::cli
