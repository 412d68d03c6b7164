// What each export format's consumer renders (libfit/export/consumer_curve, docs/export.md "What each consumer
// renders"): glTF's extras give the metrics of Schlick from the baseColorFactor the file writes, rebuilt here from the
// file and evaluated against the material's reference; the shader formats' curve is the model's; MaterialX's is the
// model's node (exact for conductor_bsdf) or the stand-in's; OpenPBR's the F82-tint form or the stand-in's; the export
// record lists every requested format; a layered material under a format's own layers is not evaluated.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "libfit/color/color_space.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/export/consumer_curve.hpp"
#include "libfit/export/export.hpp"
#include "libfit/fit/fit.hpp"
#include "libfit/fit/fit_record.hpp"
#include "libfit/fit/metrics.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/models/model.hpp"
#include "test_environment.hpp"
#include "test_support.hpp"

namespace metalfit {
namespace test_export_consumers {

using namespace metalfit::test;
using Json = nlohmann::json;

const std::vector<std::string> kModels{"schlick", "f82-tint", "lazanyi-comp", "conductor-rgb", "gulbrandsen"};

ExportRequest request() {
    ExportRequest r;
    r.formats = {ExportFormat::json, ExportFormat::glsl, ExportFormat::mtlx, ExportFormat::openpbr, ExportFormat::gltf};
    for (const std::string& id : kModels) r.models.push_back(&find_model(id));
    return r;
}

const MaterialFit& fitted(const std::string& id) {
    static std::map<std::string, MaterialFit> cache;
    auto it = cache.find(id);
    if (it == cache.end()) {
        MaterialFitRequest fit_request{SpectralOptions{}, ErrorSettings{}, models_to_fit(request())};
        it = cache
                 .emplace(id, fit_material(load_material(env().catalog, id, ""), env().colorimetry, env().converter,
                                           fit_request))
                 .first;
    }
    return it->second;
}

// Every file of one material's export, by path.
std::map<std::string, std::string> exported(const std::string& id) {
    const FitRecordContext context{kShipped,        env().converter.space(), Observer::cie1931_2deg,
                                   Illuminant::D65, SpectralOptions{},       ErrorSettings{}};
    std::map<std::string, std::string> files;
    for (ExportFile& f : export_files({fitted(id)}, context, request(), "lin_rec709"))
        files[f.path.generic_string()] = std::move(f.contents);
    return files;
}

double worst(const Json& metrics, const char* name) {
    double w = 0;
    for (const Json& v : metrics.at(name)) w = std::max(w, std::abs(v.get<double>()));
    return w;
}

void expect_same_metrics(const Json& a, const Metrics& b, const std::string& what) {
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(a.at("rel_rms").at(c).get<double>(), b.rel_rms[c], 1e-12 * b.rel_rms[c]) << what;
        EXPECT_NEAR(a.at("max_abs").at(c).get<double>(), b.max_abs[c], 1e-12 * b.max_abs[c]) << what;
    }
    EXPECT_NEAR(a.at("de2000_max").get<double>(), b.de2000_max, 1e-12 * b.de2000_max) << what;
}

const ModelResult& result_of(const MaterialFit& fit, std::string_view model) {
    for (const ModelResult& r : fit.models)
        if (r.model->id() == model) return r;
    throw std::logic_error("not fitted");
}

TEST(ExportConsumers, GltfMetricsAreSchlickFromTheBaseColorFactorTheFileWrites) {
    for (const std::string id : {"Al", "Cu", "Au", "TiN"}) {
        const std::map<std::string, std::string> files = exported(id);
        const MaterialFit& fit = fitted(id);
        for (const std::string& model : kModels) {
            std::string stem = "metalfit_" + id + "_" + model;
            std::transform(stem.begin(), stem.end(), stem.begin(),
                           [](unsigned char ch) { return std::isalnum(ch) ? std::tolower(ch) : '_'; });
            const Json gltf = Json::parse(files.at("gltf/" + stem + ".gltf"));
            const Json& material = gltf["materials"][0];
            const Json& extras = material["extras"]["metalfit"];
            // The viewer's curve, rebuilt from the file alone: Schlick from baseColorFactor.
            ModelParameters schlick;
            for (int c = 0; c < 3; ++c)
                schlick[c] = {material["pbrMetallicRoughness"]["baseColorFactor"][c].get<double>()};
            const Metrics viewer = compute_metrics(find_model("schlick"), schlick, *fit.reference);
            expect_same_metrics(extras["metrics"], viewer, id + " " + model);
            EXPECT_NE(extras["metrics_of"].get<std::string>().find("Schlick from baseColorFactor"), std::string::npos);
            // model_metrics: the curve the params describe, as the export record's.
            const Json record = Json::parse(files.at("metalfit_export.json"));
            const Json& exported_model = record["materials"][id]["models"][model]["export"];
            EXPECT_EQ(extras["model_metrics"], exported_model["metrics"]) << id << " " << model;
            EXPECT_EQ(exported_model["consumers"]["gltf"]["metrics"], extras["metrics"]) << id << " " << model;
            EXPECT_EQ(exported_model["consumers"]["gltf"]["model"], "schlick");
            for (int c = 0; c < 3; ++c)  // the record's F0 error is the factor's: F0 clipped to [0, 1] is an error
                EXPECT_NEAR(exported_model["consumers"]["gltf"]["err_f0"][c].get<double>(), viewer.err_f0[c], 1e-12);
            // Schlick with its F0 inside [0, 1] is its own viewer curve; otherwise (gold's red F0 > 1) the clipped
            // factor renders another curve.
            if (model == "schlick") {
                const RGB f0 = result_of(fit, "schlick").fit.value.params.parameter(0);
                const bool inside = f0.r <= 1 && f0.g <= 1 && f0.b <= 1 && f0.r >= 0 && f0.g >= 0 && f0.b >= 0;
                if (inside)
                    EXPECT_EQ(extras["metrics"], extras["model_metrics"]) << id;
                else
                    EXPECT_NE(extras["metrics"], extras["model_metrics"]) << id;
            }
        }
    }
    // The case the issue names: aluminium's f82-tint reads 0.55 % worst-channel rel_rms while a viewer is ~6 % off.
    const Json al =
        Json::parse(exported("Al").at("gltf/metalfit_al_f82_tint.gltf"))["materials"][0]["extras"]["metalfit"];
    EXPECT_GT(worst(al["metrics"], "rel_rms"), 5 * worst(al["model_metrics"], "rel_rms"));
}

TEST(ExportConsumers, ShaderFormatsRenderTheModelMaterialxItsNodeOpenPbrItsF82TintForm) {
    for (const std::string id : {"Cu", "Au", "Ni"}) {
        const Json record = Json::parse(exported(id).at("metalfit_export.json"));
        const Json& models = record["materials"][id]["models"];
        const Json& f82 = models["f82-tint"]["export"]["metrics"];
        for (const std::string& model : kModels) {
            const Json& e = models[model]["export"];
            const Json& consumers = e["consumers"];
            ASSERT_EQ(consumers.size(), 5u) << "one entry per requested format";
            for (const char* own : {"json", "glsl"}) {
                EXPECT_EQ(consumers[own]["model"], model) << own;
                EXPECT_EQ(consumers[own]["metrics"], e["metrics"]) << own;
            }
            const Json& mtlx = consumers["mtlx"];
            const Json& openpbr = consumers["openpbr"];
            if (model == "conductor-rgb") {  // conductor_bsdf evaluates the exact Fresnel of n, k: the model itself
                EXPECT_EQ(mtlx["metrics"], e["metrics"]);
                EXPECT_EQ(openpbr["model"], "f82-tint");  // OpenPBR: the stand-in
                EXPECT_EQ(openpbr["metrics"], f82);
            } else if (model == "lazanyi-comp") {  // no MaterialX form: the stand-in in both
                EXPECT_EQ(mtlx["model"], "f82-tint");
                EXPECT_EQ(mtlx["metrics"], f82);
                EXPECT_EQ(openpbr["metrics"], f82);
            } else if (model == "schlick") {  // an F82-tint curve: the same curve in F82-tint form, to rounding
                for (int c = 0; c < 3; ++c) {
                    for (const Json* consumer : {&mtlx, &openpbr}) {
                        EXPECT_NEAR((*consumer)["metrics"]["rel_rms"][c].get<double>(),
                                    e["metrics"]["rel_rms"][c].get<double>(), 1e-9)
                            << id;
                        EXPECT_NEAR((*consumer)["err_f0"][c].get<double>(), e["err_f0"][c].get<double>(), 1e-9) << id;
                    }
                }
            }
        }
    }
}

TEST(ExportConsumers, ALayeredMaterialUnderAFormatsOwnLayersIsNotEvaluated) {
    TempDir dir;
    const CommandResult r =
        run_command(kMetalfitExe,
                    "export Ti --film TiO2:80nm --model f82-tint --format json,glsl,gltf,openpbr -o " +
                        (dir.path() / "out").string(),
                    dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json record = Json::parse(read_file(dir.path() / "out" / "metalfit_export.json"));
    const Json& material = record["materials"].begin().value();
    const Json& consumers = material["models"]["f82-tint"]["export"]["consumers"];
    EXPECT_TRUE(consumers["glsl"].contains("metrics"));  // the stack's fitted curve
    EXPECT_EQ(consumers["glsl"]["metrics"], material["models"]["f82-tint"]["export"]["metrics"]);
    for (const char* layered : {"gltf", "openpbr"}) {
        EXPECT_FALSE(consumers[layered].contains("metrics")) << layered;
        EXPECT_TRUE(consumers[layered].contains("not_evaluated")) << layered;
    }
}

}  // namespace test_export_consumers

}  // namespace metalfit
