#include "glpreview/effects/caustics_bench.hpp"

#include <cmath>
#include <memory>

#include "../lights/light.hpp"
#include "../rings/ring.hpp"
#include "caustic_closed_form.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/color/color_space.hpp"
#include "photon_tracer.hpp"

namespace metalfit::glpreview {
namespace {

using Json = nlohmann::ordered_json;

Json rgb_json(const RGB& c) { return Json::array({c.r, c.g, c.b}); }

// Per channel a / b − 1, and the channel of largest magnitude.
Json relative(const RGB& a, const RGB& b) {
    RGB e{0, 0, 0};
    double worst = 0;
    for (int c = 0; c < 3; ++c) {
        e[c] = b[c] != 0 ? a[c] / b[c] - 1 : 0;
        if (std::abs(e[c]) > std::abs(worst)) worst = e[c];
    }
    return Json{{"rgb", rgb_json(e)}, {"worst", worst}};
}

RGB total_power(const CausticMap& map) { return map.budget().deposited; }
RGB shares(const RGB& p) {
    const double sum = p.r + p.g + p.b;
    return sum > 0 ? (1.0 / sum) * p : RGB{0, 0, 0};
}

}  // namespace

Json bench_caustics(const PreviewOptions& options, bool quick) {
    Scene scene;
    scene.file = "caustics-bench.json";
    Ring ring;
    ring.base = {0, 0, 0};
    ring.radius = 1;
    ring.height = 0.35;
    ring.arc_deg = 180;
    ring.facing_deg = -90;
    Light light;
    light.type = LightType::directional;
    light.direction = normalize(Vec3{0, -0.35, -1});
    light.intensity = 3;
    Lights lights{{light}};
    FresnelLibrary library(options.data_dir, options.ocio, scene.space, scene.file);
    const RgbUplift uplift(library.colorimetry(), library.converter());
    const RGB luminance{0.2126, 0.7152, 0.0722};  // the weights the peak is found by (Rec. 709 Y)

    PhotonOptions photon_options;
    photon_options.photons = quick ? 100000 : 1000000;
    photon_options.sigma = 0.03;
    photon_options.threads = options.threads;
    photon_options.record_paths = true;

    Json j;
    j["scene"] = "a ring (radius 1 m, 0.35 m tall, a half circle facing -z) in the default 6 x 3 x 6 m room";
    j["light"] = "directional, direction (0, -0.35, -1) (elevation 19.3 deg), 3 W/m2, white";
    j["photons"] = photon_options.photons;
    j["filter_width"] = photon_options.sigma;
    j["metals"] = Json::array();
    std::optional<CausticMap> traced;  // the photons' paths, traced once with the first metal
    for (const char* metal : {"Au", "Cu", "Al"}) {
        ring.material = metal;
        Sphere surface = ring.surface();
        const SphereFresnel& reference_lut = library.get(surface, "rings[0]");
        const SpectralFresnel spectral(library.material(surface, "rings[0]"), library.colorimetry());
        PhotonFresnel exact;
        exact.spectral = {&spectral};
        exact.uplift = &uplift;
        if (!traced) {
            Rings rings{{ring}, {}};
            scene.effects.set(rings);
            scene.effects.set(lights);
            traced = trace_caustics(scene, rings, lights, exact, photon_options);
        }
        const CausticMap reference = reweight(*traced, exact, options.threads);
        const IrradiancePeak peak = measure_receiver(reference, Receiver::floor, luminance);
        const RGB reference_power = total_power(reference);
        Json m;
        m["metal"] = reference_lut.material;
        m["source"] = reference_lut.source;
        Json ref{{"power", rgb_json(reference_power)},
                 {"power_after_several_reflections", rgb_json(reference.budget().deposited_multiple)},
                 {"peak_irradiance", rgb_json(peak.irradiance)},
                 {"peak_position", Json::array({peak.u, 0.0, peak.v})}};
        if (const std::optional<CausticFocus> focus = caustic_focus(ring, light)) {
            ref["focus"] = Json::array({focus->point.x, focus->point.y, focus->point.z});
            ref["focus_distance"] = std::hypot(peak.u - focus->point.x, peak.v - focus->point.z);
        }
        m["reference"] = ref;
        m["rows"] = Json::array();
        m["skipped"] = Json::array();
        const auto row = [&](const std::string& model, const std::string& params, const SphereFresnel& fresnel) {
            PhotonFresnel rgb;
            rgb.rgb = {&fresnel};
            const CausticMap map = reweight(*traced, rgb, options.threads);
            const RGB power = total_power(map);
            const RGB at_peak = map.irradiance(Receiver::floor, peak.u, peak.v);
            const IrradiancePeak own = measure_receiver(map, Receiver::floor, luminance);
            m["rows"].push_back(Json{{"model", model},
                                     {"params", params},
                                     {"power", rgb_json(power)},
                                     {"peak_irradiance", rgb_json(at_peak)},
                                     {"power_rel", relative(power, reference_power)},
                                     {"peak_rel", relative(at_peak, peak.irradiance)},
                                     {"colour_rel", relative(shares(power), shares(reference_power))},
                                     {"peak_shift", std::hypot(own.u - peak.u, own.v - peak.v)}});
        };
        row("reference-lut", "-", reference_lut);
        for (const Model* model : all_models())
            for (const ParameterSource params : {ParameterSource::fit, ParameterSource::closed}) {
                Sphere s = surface;
                s.fresnel = ModelFresnel{std::string(model->id()), params};
                const SphereFresnel* fresnel = nullptr;
                try {
                    fresnel = &library.get(s, "rings[0]");
                } catch (const InputError& e) {
                    m["skipped"].push_back({{"model", model->id()}, {"params", to_string(params)}, {"why", e.what()}});
                    continue;
                }
                row(std::string(model->id()), to_string(params), *fresnel);
            }
        j["metals"].push_back(m);
    }
    return j;
}

}  // namespace metalfit::glpreview
