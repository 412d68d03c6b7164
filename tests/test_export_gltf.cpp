// metalfit export --format gltf (docs/export.md): each asset's material is the model's F0 (clipped, or scaled with
// --gamut scale), metallic 1 and the roughness asked for, checked against the JSON record's parameters with
// independent F0 forms; the sphere's buffer decodes to the declared lengths, unit normals and outward triangles; other
// colour spaces are refused. The Khronos validator itself runs in ctest export.gltf_validator.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "libfit/export/export.hpp"
#include "libfit/models/model.hpp"
#include "test_support.hpp"

namespace test_export_gltf {

namespace fs = std::filesystem;
using metalfit::test::read_file;
using metalfit::test::TempDir;
using Json = nlohmann::json;

const fs::path kCatalogExport{
    metalfit::test::kCatalogExportDir};  // `export --all --model all --format all`, made by the build

metalfit::test::CommandResult run(const std::string& args, const fs::path& scratch) {
    return metalfit::test::run_command(metalfit::test::kMetalfitExe, args, scratch);
}

// F0 = F(mu = 1) of a model from its written parameters, in the forms the models define it (docs/fitting.md, "Models") rather than
// through the models' code: F0 itself, Gulbrandsen's reflectivity r, or the normal-incidence Fresnel of n, k (the
// compensation term a mu (1 - mu)^alpha of lazanyi-comp vanishes at mu = 1). Empty for the other models.
std::optional<double> independent_f0(const std::string& model, const Json& params, int c) {
    const auto p = [&](const char* name) { return params.at(name).at(c).get<double>(); };
    // The compensated Schlick forms add terms in mu (1 - mu)^... that vanish at mu = 1.
    if (model == "schlick" || model == "f82-tint" || model.starts_with("schlick-comp")) return p("F0");
    if (model == "gulbrandsen") return p("r");
    if (model == "conductor-rgb" || model == "lazanyi" || model == "lazanyi-comp") {
        const double n = p("n"), k = p("k");
        return ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
    }
    return std::nullopt;
}

// The model evaluated at mu = 1 through libfit (every model, also those without an independent form above).
double libfit_f0(const std::string& model_id, const Json& params, int c) {
    const metalfit::Model& model = metalfit::find_model(model_id);
    metalfit::ChannelParameters channel;
    for (const auto& parameter : model.parameters())
        channel.push_back(params.at(std::string(parameter.name)).at(c).get<double>());
    return model.evaluate(std::span<const double>(channel), 1.0);
}

std::string base64_decode(const std::string& text) {
    static const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::uint32_t bits = 0;
    int count = 0;
    for (char ch : text) {
        if (ch == '=') break;
        const auto v = alphabet.find(ch);
        if (v == std::string::npos) throw std::invalid_argument(std::string("not base64: ") + ch);
        bits = (bits << 6) | static_cast<std::uint32_t>(v);
        if ((count += 6) >= 8) {
            count -= 8;
            out += static_cast<char>((bits >> count) & 0xFFu);
        }
    }
    return out;
}

TEST(ExportGltf, EveryAssetIsTheModelsF0ClippedMetallicAndTheDefaultRoughness) {
    const Json record = Json::parse(read_file(kCatalogExport / "metalfit_export.json"));
    std::size_t assets = 0, clipped = 0, independent = 0;
    for (const auto& [material, entry] : record["materials"].items())
        for (const auto& [model, result] : entry["models"].items()) {
            SCOPED_TRACE(material + " " + model);
            std::string stem = "metalfit_" + material + "_" + model;
            std::transform(stem.begin(), stem.end(), stem.begin(), [](unsigned char ch) {
                return std::isalnum(ch) ? static_cast<char>(std::tolower(ch)) : '_';
            });
            const Json gltf = Json::parse(read_file(kCatalogExport / "gltf" / (stem + ".gltf")));
            ++assets;
            EXPECT_EQ(gltf["asset"]["version"], "2.0");
            ASSERT_EQ(gltf["materials"].size(), 1u);
            const Json& m = gltf["materials"][0];
            const Json& pbr = m["pbrMetallicRoughness"];
            EXPECT_EQ(pbr["metallicFactor"], 1.0);
            EXPECT_EQ(pbr["roughnessFactor"], metalfit::kDefaultRoughness);
            ASSERT_EQ(pbr["baseColorFactor"].size(), 4u);
            EXPECT_EQ(pbr["baseColorFactor"][3], 1.0);
            const Json& params = result["export"]["params"];
            bool outside = false;
            for (int c = 0; c < 3; ++c) {
                const double f0 = libfit_f0(model, params, c);
                if (const auto own = independent_f0(model, params, c)) {
                    EXPECT_NEAR(f0, *own, 1e-12 * std::max(1.0, *own)) << "channel " << c;
                    ++independent;
                }
                EXPECT_NEAR(m["extras"]["metalfit"]["f0"][c].get<double>(), f0, 1e-15) << "channel " << c;
                const double factor = pbr["baseColorFactor"][c].get<double>();
                if (f0 > 1.0) {
                    EXPECT_EQ(factor, 1.0) << "channel " << c;  // the default gamut (keep): clipped for glTF
                    outside = true;
                } else {
                    EXPECT_NEAR(factor, std::max(0.0, f0), 1e-15) << "channel " << c;
                }
            }
            clipped += outside;
            const Json& extras = m["extras"]["metalfit"];
            EXPECT_EQ(extras["material"], material);
            EXPECT_EQ(extras["model"], model);
            EXPECT_EQ(extras["color_space"], record["provenance"]["color_space"]);
            EXPECT_EQ(extras["base_color_factor"].get<std::string>().find("clipped") != std::string::npos, outside);
        }
    EXPECT_EQ(assets, metalfit::test::catalog_material_count() * metalfit::all_models().size());
    EXPECT_GT(clipped, 0u) << "gold and copper have F0 > 1 in red in Linear Rec.709";
    EXPECT_GT(independent, assets);
}

TEST(ExportGltf, GamutScaleScalesTheColourAndTheRoughnessIsTheOneAsked) {
    TempDir tmp;
    const fs::path out = tmp.path() / "out";
    const auto r = run("export Au --model f82-tint,conductor-rgb --format gltf --gamut scale --roughness 0.25 -o '" +
                           out.string() + "'",
                       tmp.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // The catalog export is the same fit, kept: scaling divides its F0 by the largest channel.
    const Json record = Json::parse(read_file(kCatalogExport / "metalfit_export.json"));
    const Json& keep = record["materials"]["Au"]["models"]["f82-tint"]["export"]["params"]["F0"];
    const double max = std::max({keep[0].get<double>(), keep[1].get<double>(), keep[2].get<double>()});
    ASSERT_GT(max, 1.0);
    const Json gltf = Json::parse(read_file(out / "gltf" / "metalfit_au_f82_tint.gltf"));
    const Json& pbr = gltf["materials"][0]["pbrMetallicRoughness"];
    for (int c = 0; c < 3; ++c)
        EXPECT_DOUBLE_EQ(pbr["baseColorFactor"][c].get<double>(), keep[c].get<double>() / max) << c;
    EXPECT_EQ(pbr["roughnessFactor"], 0.25);
    EXPECT_EQ(gltf["materials"][0]["extras"]["metalfit"]["gamut"], "scale");
    // n, k give F0 < 1 at normal incidence: nothing to scale.
    const Json nk = Json::parse(read_file(out / "gltf" / "metalfit_au_conductor_rgb.gltf"));
    const Json& nk_params = record["materials"]["Au"]["models"]["conductor-rgb"]["export"]["params"];
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(nk["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"][c].get<double>(),
                    *independent_f0("conductor-rgb", nk_params, c), 1e-12)
            << c;
    EXPECT_EQ(nk["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"], 0.25);
}

TEST(ExportGltf, TheSphereBufferHoldsUnitNormalsAndOutwardTriangles) {
    const Json gltf = Json::parse(read_file(kCatalogExport / "gltf" / "metalfit_cu_schlick.gltf"));
    const std::string uri = gltf["buffers"][0]["uri"];
    const std::string prefix = "data:application/octet-stream;base64,";
    ASSERT_EQ(uri.rfind(prefix, 0), 0u);
    const std::string bytes = base64_decode(uri.substr(prefix.size()));
    ASSERT_EQ(bytes.size(), gltf["buffers"][0]["byteLength"].get<std::size_t>());
    const auto view = [&](int accessor) {
        const Json& v = gltf["bufferViews"][gltf["accessors"][accessor]["bufferView"].get<int>()];
        const std::size_t offset = v["byteOffset"], length = v["byteLength"];
        EXPECT_LE(offset + length, bytes.size());
        return std::string_view(bytes).substr(offset, length);
    };
    const auto floats = [&](int accessor) {
        const std::string_view raw = view(accessor);
        std::vector<std::array<float, 3>> v(gltf["accessors"][accessor]["count"].get<std::size_t>());
        EXPECT_EQ(raw.size(), v.size() * 12);
        std::memcpy(v.data(), raw.data(), std::min(raw.size(), v.size() * 12));
        return v;
    };
    const auto positions = floats(0), normals = floats(1);
    const std::string_view index_bytes = view(2);
    std::vector<std::uint16_t> indices(gltf["accessors"][2]["count"].get<std::size_t>());
    ASSERT_EQ(index_bytes.size(), indices.size() * 2);
    std::memcpy(indices.data(), index_bytes.data(), index_bytes.size());
    ASSERT_EQ(indices.size() % 3, 0u);
    for (int c = 0; c < 3; ++c) {
        float lo = positions[0][c], hi = positions[0][c];
        for (const auto& p : positions) lo = std::min(lo, p[c]), hi = std::max(hi, p[c]);
        EXPECT_EQ(gltf["accessors"][0]["min"][c].get<double>(), lo);
        EXPECT_EQ(gltf["accessors"][0]["max"][c].get<double>(), hi);
    }
    for (const auto& n : normals) EXPECT_NEAR(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), 1.0, 1e-6);
    std::vector<bool> used(positions.size(), false);
    for (std::size_t t = 0; t < indices.size(); t += 3) {
        ASSERT_LT(std::max({indices[t], indices[t + 1], indices[t + 2]}), positions.size());
        const auto& a = positions[indices[t]];
        const auto& b = positions[indices[t + 1]];
        const auto& c = positions[indices[t + 2]];
        const std::array<double, 3> u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const std::array<double, 3> n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        const double outward = n[0] * (a[0] + b[0] + c[0]) + n[1] * (a[1] + b[1] + c[1]) + n[2] * (a[2] + b[2] + c[2]);
        EXPECT_GT(outward, 0.0) << "triangle " << t / 3 << " is not counter-clockwise seen from outside";
        used[indices[t]] = used[indices[t + 1]] = used[indices[t + 2]] = true;
    }
    EXPECT_TRUE(std::all_of(used.begin(), used.end(), [](bool u) { return u; }));
}

TEST(ExportGltf, AnotherColourSpaceIsRefusedBeforeAnyWork) {
    TempDir tmp;
    const fs::path out = tmp.path() / "out";
    for (const char* formats : {"gltf", "json,gltf"}) {
        const auto r = run(std::string("export Au --model schlick --format ") + formats + " --space ACEScg -o '" +
                               out.string() + "'",
                           tmp.path());
        EXPECT_EQ(r.exit_code, 2) << formats << ": " << r.err;
        EXPECT_TRUE(metalfit::test::Contains(r.err, "glTF 2.0's colours are linear Rec.709")) << r.err;
        EXPECT_TRUE(metalfit::test::Contains(r.err, "'ACEScg'")) << r.err;
        EXPECT_FALSE(fs::exists(out));
    }
    const auto ok = run("export Au --model schlick --format json --space ACEScg -o '" + out.string() + "'", tmp.path());
    EXPECT_EQ(ok.exit_code, 0) << ok.err;
    // --format all: every format the space can carry, glTF left out with a warning saying why.
    const fs::path all = tmp.path() / "all";
    const auto r = run("export Au --model schlick --format all --space ACEScg -o '" + all.string() + "'", tmp.path());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(metalfit::test::Contains(r.err, "--format all: glTF left out")) << r.err;
    EXPECT_TRUE(fs::exists(all / "mtlx"));
    EXPECT_FALSE(fs::exists(all / "gltf"));
}

}  // namespace test_export_gltf
