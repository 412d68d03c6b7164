// What every measurement needs: the catalog, the colorimetry and the OCIO converter (built once), and one material
// prepared for evaluation benchmarks (its reference curve and every model's fitted parameters).
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "libfit/color/color_space.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/models/model.hpp"
#include "libfit/reference/reference_curve.hpp"
#include "libfit/reference/sampled_reference.hpp"

namespace metalfit::bench {

// The default colour set-up of `metalfit fit`: D65, CIE 1931 2°, the role scene_linear, linear interpolation.
struct Environment {
    Catalog catalog;
    OcioConfigChoice config;
    Colorimetry colorimetry;
    ColorSpaceConverter converter;
    SpectralOptions spectral;
    ErrorSettings error;  // 128 nodes, rel metric, uniform weight

    // Throws InputError / ColorConfigError like `metalfit fit`.
    static Environment load(const std::filesystem::path& data_dir,
                            const std::optional<std::filesystem::path>& ocio_config);
};

// One material ready for evaluation benchmarks: its reference curve and the Ceres-fitted parameters of every model.
struct PreparedMaterial {
    Material material;
    ReferenceCurve curve;
    std::map<std::string, ModelParameters, std::less<>> fitted;  // model id → fitted parameters

    // Fits every model (as `metalfit fit` does). Throws UsageError for an unknown material.
    static PreparedMaterial prepare(const Environment& env, const std::string& material_id);
    const ModelParameters& params(std::string_view model_id) const;
};

}  // namespace metalfit::bench
