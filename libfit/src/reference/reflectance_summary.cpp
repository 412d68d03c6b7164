#include "libfit/reference/reflectance_summary.hpp"

#include "libfit/io/layer_stack.hpp"

#include "libfit/base/record_path.hpp"
#include "libfit/base/version.hpp"
#include "libfit/io/material.hpp"

namespace metalfit {
namespace {

constexpr const char* kChannelLetters[] = {"R", "G", "B"};

nlohmann::json rgb_json(const RGB& c) { return nlohmann::json::array({c.r, c.g, c.b}); }

}  // namespace

ReflectanceSummary summarize_reflectance(const ReferenceCurve& curve) {
    ReflectanceSummary summary;
    summary.samples = {{"F0", 1.0, curve(1.0)},
                       {"F82", kMuF82, curve(kMuF82)},
                       {"R(0.5)", 0.5, curve(0.5)},
                       {"R(0.25)", 0.25, curve(0.25)},
                       {"R(0.1)", 0.1, curve(0.1)}};
    for (const ReflectanceSample& s : summary.samples)
        for (int c = 0; c < 3; ++c)
            if (s.value[c] > 1.0 || s.value[c] < 0.0) summary.out_of_gamut.push_back({s.label, c, s.value[c]});
    return summary;
}

nlohmann::json reflectance_record(const Material& material, const ReferenceCurve& curve,
                                  const ReflectanceSummary& summary, const Colorimetry& colorimetry,
                                  const OcioConfigChoice& config, const SpectralOptions& spectral,
                                  const std::filesystem::path& data_dir, Convention convention) {
    const std::vector<ReflectanceSample>& samples = summary.samples;
    nlohmann::json out_of_gamut = nlohmann::json::array();
    for (const OutOfGamutValue& g : summary.out_of_gamut)
        out_of_gamut.push_back({{"quantity", g.quantity}, {"channel", kChannelLetters[g.channel]}, {"value", g.value}});
    const WavelengthRange range = material.index.range();
    nlohmann::json j;
    j["schema"] = "metalfit.show/1";
    j["material"] = material.id;
    j["name"] = material.name;
    j["source"] = material.source;
    j["space"] = curve.converter().space();
    j["F0"] = rgb_json(samples[0].value);
    j["F82"] = rgb_json(samples[1].value);
    j["R"] = {
        {"0.5", rgb_json(samples[2].value)}, {"0.25", rgb_json(samples[3].value)}, {"0.1", rgb_json(samples[4].value)}};
    j["out_of_gamut"] = out_of_gamut;
    j["provenance"] = {{"file", record_path(material.provenance.file, data_dir)},
                       {"sha256", material.provenance.sha256},
                       {"format", material.provenance.format},
                       {"data_type", material.provenance.data_type},
                       {"reference", material.provenance.references},
                       {"note", material.provenance.note},
                       {"conditions", material.provenance.conditions},
                       {"range_nm", {range.min_nm, range.max_nm}},
                       {"points_360_830", material.index.n.tabulated_points_in(kVisibleRange)},
                       {"cmf", to_string(colorimetry.observer())},
                       {"illuminant", to_string(colorimetry.illuminant())},
                       {"adaptation", to_string(colorimetry.adaptation())},
                       {"adapted", colorimetry.adapted()},
                       {"convention", to_string(convention)},
                       {"interpolation", to_string(spectral.interpolation)},
                       {"extrapolate", spectral.out_of_range == OutOfRange::clamp},
                       {"ocio_config", record_path(config.path, data_dir)},
                       {"ocio_config_origin", config.origin},
                       {"white_raw_rgb", rgb_json(curve.raw_white())},
                       {"metalfit_version", METALFIT_VERSION}};
    if (material.layers && !material.layers->empty()) j["provenance"]["stack"] = stack_record(material, data_dir);
    std::vector<std::string> warnings = record_messages(material.warnings, material.provenance.file, data_dir);
    warnings.insert(warnings.end(), curve.held_constant().begin(), curve.held_constant().end());
    j["warnings"] = warnings;
    return j;
}

}  // namespace metalfit
