#include "glpreview/render/sphere_fresnel.hpp"

#include "glpreview/scene/confined_file.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "glpreview/render/scene_colour.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/text.hpp"
#include "libfit/fit/fit.hpp"
#include "libfit/fit/parameter_source.hpp"
#include "libfit/io/finishes.hpp"
#include "libfit/io/layer_materials.hpp"
#include "libfit/io/layer_stack.hpp"
#include "libfit/reference/reference_curve.hpp"
#include "libfit/reference/stack_grid.hpp"
#include "libfit/spectral/spectrum.hpp"

namespace metalfit::glpreview {

void SphereFresnel::set_parameters(ModelParameters values) {
    parameters = std::move(values);
    for (int c = 0; c < 3; ++c) {
        const ChannelParameters& channel = parameters[c];
        float_parameters_[static_cast<std::size_t>(c)].assign(channel.begin(), channel.end());
    }
}

RGB SphereFresnel::operator()(double mu) const {
    mu = std::clamp(mu, 0.0, 1.0);
    if (model) {
        std::array<double, 3> value{};
        for (int c = 0; c < 3; ++c) {
            const std::vector<float>& p = float_parameters_[static_cast<std::size_t>(c)];
            if (p.size() != model->parameters().size())
                throw std::logic_error("SphereFresnel: " + std::string(model->id()) + " has " +
                                       std::to_string(p.size()) + " parameters set, not " +
                                       std::to_string(model->parameters().size()));
            value[c] = model->evaluate(std::span<const float>(p), static_cast<float>(mu));
        }
        return {value[0], value[1], value[2]};
    }
    const double x = mu * (static_cast<double>(lut.size()) - 1);
    const std::size_t i = std::min(static_cast<std::size_t>(x), lut.size() - 2);
    const double f = x - static_cast<double>(i);
    const RGB& a = lut[i];
    const RGB& b = lut[i + 1];
    return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b)};
}

FresnelLibrary::FresnelLibrary(const std::filesystem::path& data_dir, const OcioConfigChoice& config,
                               const std::string& space, const std::filesystem::path& scene_file,
                               std::optional<PathPolicy> paths)
    : catalog_(Catalog::load(data_dir)),
      colorimetry_(Colorimetry::load(data_dir, Observer::cie1931_2deg, Illuminant::D65)),
      converter_(scene_converter(config, space, scene_file)),
      scene_file_(scene_file),
      paths_(std::move(paths)) {}

namespace {

// A sphere's Fresnel data named after its material: the metal's name (a layered one's short stack name), its source,
// and the whole stack described when it has layers.
std::unique_ptr<SphereFresnel> named_after(const Material& material) {
    auto result = std::make_unique<SphereFresnel>();
    result->material = short_stack_name(material);
    result->source = material.source;
    if (material.layers && !material.layers->empty()) result->stack = describe_stack(material);
    return result;
}

std::string cache_key(const std::string& material, const std::string& source, const FresnelChoice& fresnel,
                      const std::string& film = "", const std::string& coat = "") {
    const auto* model = std::get_if<ModelFresnel>(&fresnel);
    return material + "|" + source + "|" + film + "|" + coat + "|" + fresnel_name(fresnel) + "|" +
           (model ? to_string(model->parameters) : "");
}

}  // namespace

std::unique_ptr<SphereFresnel> FresnelLibrary::model_fresnel(const Material& material, const ModelResult& r,
                                                             ParameterSource params, const std::string& field) const {
    std::unique_ptr<SphereFresnel> result = named_after(material);
    result->fresnel = std::string(r.model->id());
    result->model = r.model;
    result->params = params;
    const std::optional<ChosenParameters> choice = choose_parameters(r, params);
    if (!choice)
        throw InputError(InputLocation(scene_file_, 0, field + ".params"),
                         "no closed form of " + result->fresnel + " is defined for " + material.name + ": " +
                             (r.closed_forms.empty() ? std::string("none") : r.closed_forms.front().undefined));
    const EvaluatedParameters* chosen = choice->value;
    result->set_parameters(chosen->params);
    result->worst_rel_rms = worst_channel(chosen->metrics.rel_rms);
    return result;
}

Material FresnelLibrary::sphere_material(const Sphere& sphere, const std::string& field) {
    // A file is opened once, checked on its descriptor and read through it (ConfinedFile); its errors name the scene,
    // the field and the file as the scene gave it.
    std::optional<ConfinedFile> file;
    if (looks_like_path(sphere.material))
        file.emplace(ConfinedFile::open(scene_file_, paths_, sphere.material, field + ".material"));
    const auto at_material = [&](const std::exception& e) {
        return InputError(InputLocation(scene_file_, 0, field + ".material"),
                          file ? file->in_original_terms(e.what()) : e.what());
    };
    Material material;
    try {
        std::optional<Material> finish;
        if (!file) finish = load_finish_named(catalog_, sphere.material, sphere.source);
        material = finish ? std::move(*finish)
                          : load_material(catalog_, file ? file->path().string() : sphere.material, sphere.source);
    } catch (const UsageError& e) {
        throw at_material(e);
    } catch (const InputError& e) {
        throw at_material(e);
    }
    if (file) {
        material.provenance.file = file->original();
        for (std::string& warning : material.warnings) warning = file->in_original_terms(warning);
    }
    put_layers(material, sphere, field, SpectralOptions{});
    return material;
}

const SphereFresnel& FresnelLibrary::get(const Sphere& sphere, const std::string& field) {
    const std::string key = cache_key(sphere.material, sphere.source, sphere.fresnel, sphere.film, sphere.coat);
    if (auto it = cache_.find(key); it != cache_.end()) return *it->second;

    const Material material = sphere_material(sphere, field);
    const SpectralOptions spectral{};
    std::unique_ptr<SphereFresnel> result;
    if (shows_reference(sphere)) {
        result = named_after(material);
        result->fresnel = "reference";
        const ReferenceCurve curve(material, colorimetry_, converter_, spectral);
        for (int i = 0; i < kReferenceLutSize; ++i) result->lut.push_back(curve(i / double(kReferenceLutSize - 1)));
    } else {
        const ModelFresnel& chosen = std::get<ModelFresnel>(sphere.fresnel);
        const Model* model = nullptr;
        try {
            model = &find_model(chosen.model);
        } catch (const UsageError& e) {
            throw InputError(InputLocation(scene_file_, 0, field + ".fresnel"),
                             std::string(e.what()) + " (or 'reference')");
        }
        MaterialFitRequest request{spectral, ErrorSettings{}, {model}};
        result = model_fresnel(material, fit_material(material, colorimetry_, converter_, request).models.front(),
                               chosen.parameters, field);
    }
    return *cache_.emplace(key, std::move(result)).first->second;
}

void FresnelLibrary::keep_only(const std::vector<const SphereFresnel*>& keep) {
    std::erase_if(cache_, [&keep](const auto& entry) {
        return std::find(keep.begin(), keep.end(), entry.second.get()) == keep.end();
    });
}

void FresnelLibrary::put_layers(Material& material, const Sphere& sphere, const std::string& field,
                                const SpectralOptions& spectral) {
    if (sphere.film.empty() && sphere.coat.empty()) return;
    const std::string first = field + (sphere.film.empty() ? ".coat" : ".film");
    if (material.layers && !material.layers->empty())
        throw InputError(InputLocation(scene_file_, 0, first),
                         material.id + " is a named finish with layers of its own: give its metal with film and coat, "
                                       "or the finish alone");
    if (!films_) films_ = FilmCatalog::load(catalog_.data_dir());
    // Each layer loaded and checked on its own, so that an error names its key. A layer's file is opened once beside
    // the scene under its path policy and read through that descriptor (ConfinedFile, as a material file), by the
    // importer and limits of metalfit's --film FILE; its messages and provenance name the file as the scene gave it.
    const auto checked = [&](const std::string& key, const std::string& text) {
        std::optional<ConfinedFile> file;
        const auto in_original_terms = [&](const std::exception& e) {
            return InputError(InputLocation(scene_file_, 0, field + "." + key),
                              file ? file->in_original_terms(e.what()) : e.what());
        };
        std::string argument = text;
        try {
            const LayerArgument a = parse_layer_argument("--" + key, text);
            if (const std::string name(trim(a.material)); looks_like_path(name)) {
                // Its errors name the scene, the key and the file already.
                file.emplace(ConfinedFile::open(scene_file_, paths_, name, field + "." + key));
                argument = file->path().string() + text.substr(a.material.size());
            }
        } catch (const UsageError& e) {
            throw in_original_terms(e);
        }
        try {
            LayerStack one = key == "film" ? load_layers(*films_, argument, "") : load_layers(*films_, "", argument);
            require_layer_coverage(one, kVisibleRange, spectral);
            if (file) {
                LayerMaterial& layer = one.film ? one.film->material : one.coat->material;
                layer.provenance.file = file->original();
                for (std::string& warning : layer.warnings) warning = file->in_original_terms(warning);
            }
            return one;
        } catch (const UsageError& e) {
            throw in_original_terms(e);
        } catch (const InputError& e) {
            throw in_original_terms(e);
        }
    };
    LayerStack stack;
    if (!sphere.film.empty()) stack.film = checked("film", sphere.film).film;
    if (!sphere.coat.empty()) stack.coat = checked("coat", sphere.coat).coat;
    const std::vector<std::string> warnings = layer_warnings(stack);
    material.warnings.insert(material.warnings.end(), warnings.begin(), warnings.end());
    material.layers = std::make_shared<const LayerStack>(std::move(stack));
}

std::string FresnelLibrary::best_model(const Sphere& sphere, const std::string& field) {
    const Material material = sphere_material(sphere, field);
    std::vector<const Model*> models(all_models().begin(), all_models().end());
    const MaterialFit fit =
        fit_material(material, colorimetry_, converter_, {SpectralOptions{}, ErrorSettings{}, models});
    std::string best;
    double best_error = std::numeric_limits<double>::infinity();
    for (const ModelResult& r : fit.models) {
        // Every model's fit is kept, so that get() of the winner does not fit it again.
        cache_.try_emplace(cache_key(sphere.material, sphere.source,
                                     ModelFresnel{std::string(r.model->id()), ParameterSource::fit}, sphere.film,
                                     sphere.coat),
                           model_fresnel(material, r, ParameterSource::fit, field));
        const double e = worst_channel(r.fit.value.metrics.rel_rms);
        if (e < best_error) {
            best_error = e;
            best = std::string(r.model->id());
        }
    }
    return best;
}

}  // namespace metalfit::glpreview
