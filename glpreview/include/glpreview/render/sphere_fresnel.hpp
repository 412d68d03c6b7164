// The Fresnel of each sphere, from libfit: the exact reference curve R_c(μ) as a lookup table, or a libfit model with
// its fitted or closed-form parameters. The GPU and the CPU reference use the same data.
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "glpreview/scene/scene.hpp"
#include "libfit/color/color_space.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/fit/fit.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/io/layer_materials.hpp"
#include "libfit/models/model.hpp"

namespace metalfit::glpreview {

// Entries of the reference lookup table (μ_i = i / (n − 1)); the shader interpolates linearly between them.
inline constexpr int kReferenceLutSize = 256;

struct SphereFresnel {
    std::string material;  // "gold"; a layered one's short_stack_name ("titanium + TiO2 60 nm")
    std::string source;    // "Johnson"
    std::string
        stack;  // the layers over the metal, described ("titanium under a TiO2 (Siefke) film of 60 nm"); "" when bare
    std::string fresnel;                    // "reference" or a model id
    std::optional<ParameterSource> params;  // models: fitted or closed-form parameters
    std::vector<RGB> lut;                   // reference: R_c(μ_i)
    const Model* model = nullptr;
    ModelParameters parameters;  // model: values per channel (set with set_parameters)
    double worst_rel_rms = 0;    // model: worst-channel rel_rms of these parameters (0 for the reference)

    // CPU evaluation, as the GPU does it: the table with linear interpolation, or the model in float (any number of
    // parameters; std::logic_error when `parameters` was set without set_parameters).
    RGB operator()(double mu) const;
    // Sets `parameters` and their float values, which the GPU gets and operator() evaluates.
    void set_parameters(ModelParameters values);

private:
    std::array<std::vector<float>, 3> float_parameters_;
};

// Resolves the spheres' materials through libfit's catalog and colour pipeline; one fit per distinct
// (material, source, model, params), cached.
class FresnelLibrary {
public:
    // `space`: the scene's colour space (empty: scene_linear). `scene_file`: named in errors; relative material
    // files are looked up beside it.
    // `paths`: the scene's policy (Scene::paths); material files are checked again on their open descriptor.
    FresnelLibrary(const std::filesystem::path& data_dir, const OcioConfigChoice& config, const std::string& space,
                   const std::filesystem::path& scene_file, std::optional<PathPolicy> paths = {});

    // Throws InputError naming the field (`field`, e.g. "spheres[2].material") for unknown materials/models.
    const SphereFresnel& get(const Sphere& sphere, const std::string& field);
    // Lets go of every Fresnel get() and best_model() made but those in `keep` (the sheet's rows, one at a time):
    // references to them are dangling afterwards.
    void keep_only(const std::vector<const SphereFresnel*>& keep);

    // The model with the lowest worst-channel fitted rel_rms of the sphere's material (and layers), for the sphere
    // sheet (every model's fit is cached for get()).
    std::string best_model(const Sphere& sphere, const std::string& field);

    const ColorSpaceConverter& converter() const { return converter_; }
    // The CMF and illuminant the reference curves integrate with (the spectral reference integrates with them too).
    const Colorimetry& colorimetry() const { return colorimetry_; }
    // The sphere's material with its layers, as get() resolves it (the spectral reference's n, k); InputError
    // naming `field`.
    Material material(const Sphere& sphere, const std::string& field) { return sphere_material(sphere, field); }

private:
    // The model's fitted or best closed-form parameters; InputError naming `field`.params when none is defined.
    std::unique_ptr<SphereFresnel> model_fresnel(const Material& material, const ModelResult& result,
                                                 ParameterSource params, const std::string& field) const;

    // The sphere's material as get() uses it: a file (opened once, under the scene's path policy), a named finish or
    // a catalog material, with its film and coat; InputError naming `field`.
    Material sphere_material(const Sphere& sphere, const std::string& field);
    // The sphere's film and coat (scene keys, as metalfit's --film and --coat) over `material`; InputError naming
    // `field`.film or .coat.
    void put_layers(Material& material, const Sphere& sphere, const std::string& field,
                    const SpectralOptions& spectral);

    Catalog catalog_;
    std::optional<FilmCatalog> films_;  // data/films.json, read for the first sphere with layers
    Colorimetry colorimetry_;
    ColorSpaceConverter converter_;
    std::filesystem::path scene_file_;
    std::optional<PathPolicy> paths_;
    std::map<std::string, std::unique_ptr<SphereFresnel>> cache_;
};

}  // namespace metalfit::glpreview
