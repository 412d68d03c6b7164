#include "metalfit_bench/environment.hpp"

#include <stdexcept>

#include "libfit/fit/fit.hpp"

namespace metalfit::bench {

Environment Environment::load(const std::filesystem::path& data_dir,
                              const std::optional<std::filesystem::path>& ocio_config) {
    Catalog catalog = Catalog::load(data_dir);
    OcioConfigChoice config = choose_ocio_config(ocio_config, data_dir, "--ocio-config");
    Colorimetry colorimetry = Colorimetry::load(data_dir, Observer::cie1931_2deg, Illuminant::D65);
    ColorSpaceConverter converter = ColorSpaceConverter::create(config);
    return {std::move(catalog),   std::move(config), std::move(colorimetry),
            std::move(converter), SpectralOptions{}, ErrorSettings{}};
}

PreparedMaterial PreparedMaterial::prepare(const Environment& env, const std::string& material_id) {
    const Material material = load_material(env.catalog, material_id);
    const std::span<const Model* const> models = all_models();
    const MaterialFitRequest request{env.spectral, env.error, {models.begin(), models.end()}};
    const MaterialFit fit = fit_material(material, env.colorimetry, env.converter, request);
    PreparedMaterial prepared{material, ReferenceCurve(material, env.colorimetry, env.converter, env.spectral), {}};
    for (const ModelResult& r : fit.models) prepared.fitted.emplace(std::string(r.model->id()), r.fit.value.params);
    return prepared;
}

const ModelParameters& PreparedMaterial::params(std::string_view model_id) const {
    const auto it = fitted.find(model_id);
    if (it == fitted.end()) throw std::out_of_range("no fitted parameters for model '" + std::string(model_id) + "'");
    return it->second;
}

}  // namespace metalfit::bench
