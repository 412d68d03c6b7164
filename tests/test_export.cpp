// metalfit export, checked by its consumers' rules: every MaterialX document against the MaterialX definitions, the
// error figures written in the shader headers re-evaluated independently from the written constants, the gamut
// policies, the HLSL token mapping, and failures that leave nothing behind.
#include <gtest/gtest.h>
#include <pugixml.hpp>

#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <thread>

#include "libfit/base/quadrature.hpp"
#include "libfit/color/color_space.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/export/export.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/models/model.hpp"
#include "libfit/reference/reference_curve.hpp"
#include "test_support.hpp"

namespace test_export {

namespace fs = std::filesystem;
using metalfit::test::catalog_material_count;
using metalfit::test::read_file;
using metalfit::test::TempDir;

using Result = metalfit::test::CommandResult;

// Runs the real metalfit with `args` (shell-quoted), OCIO unset.
Result run(const std::string& args, const fs::path& scratch) {
    return metalfit::test::run_command(metalfit::test::kMetalfitExe, args, scratch);
}

std::vector<fs::path> files_with_extension(const fs::path& dir, const std::string& ext) {
    std::vector<fs::path> files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file() && e.path().extension() == ext) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

// One export of the whole catalog, every model, every format, made once for the suite.
class CatalogExport : public ::testing::Test {
protected:
    // `metalfit export --all --model all --format all` with $OCIO unset, made once by the build (tests/CMakeLists.txt)
    // for every test that reads the catalog export; read only.
    static fs::path out() { return metalfit::test::kCatalogExportDir; }
};

// ---- MaterialX: node categories, input names and types, outputs, connections --------------------------------------

struct NodeDef {
    std::map<std::string, std::string> inputs;   // name → type
    std::map<std::string, std::string> outputs;  // name → type
};

// Every <nodedef> of the MaterialX definition files copied into tests/fixtures/materialx (see its SOURCES.md).
std::multimap<std::string, NodeDef> materialx_nodedefs() {
    std::multimap<std::string, NodeDef> defs;
    for (const char* file :
         {"stdlib_defs.mtlx", "pbrlib_defs.mtlx", "open_pbr_surface.mtlx", "standard_surface.mtlx"}) {
        pugi::xml_document doc;
        const fs::path path = metalfit::test::kFixtures / "materialx" / file;
        const pugi::xml_parse_result parsed = doc.load_file(path.c_str());
        EXPECT_TRUE(parsed) << path << ": " << parsed.description();
        for (pugi::xml_node nd : doc.child("materialx").children("nodedef")) {
            NodeDef d;
            for (pugi::xml_node in : nd.children("input"))
                d.inputs[in.attribute("name").value()] = in.attribute("type").value();
            for (pugi::xml_node o : nd.children("output"))
                d.outputs[o.attribute("name").value()] = o.attribute("type").value();
            defs.emplace(nd.attribute("node").value(), std::move(d));
        }
    }
    return defs;
}

// The node's type as its nodedef gives it: the single output's type, or "multioutput".
std::string node_type(const NodeDef& d) { return d.outputs.size() == 1 ? d.outputs.begin()->second : "multioutput"; }

// Errors of one document: empty when every node is a known category whose nodedef (one with the node's type) has
// each input by name and type, and every connection names an existing node and output of the right type.
std::vector<std::string> materialx_errors(const pugi::xml_document& doc,
                                          const std::multimap<std::string, NodeDef>& defs) {
    std::vector<std::string> errors;
    const pugi::xml_node root = doc.child("materialx");
    if (!root) return {"no <materialx> root"};
    if (std::string(root.attribute("version").value()) != "1.39") errors.push_back("version is not 1.39");
    std::map<std::string, const NodeDef*> nodes;
    for (pugi::xml_node node : root.children()) {
        if (node.type() != pugi::node_element) continue;
        const std::string category = node.name(), name = node.attribute("name").value(),
                          type = node.attribute("type").value();
        const auto [first, last] = defs.equal_range(category);
        if (first == last) {
            errors.push_back("unknown node category <" + category + ">");
            continue;
        }
        const NodeDef* match = nullptr;
        for (auto it = first; it != last && !match; ++it) {
            if (node_type(it->second) != type) continue;
            bool all = true;
            for (pugi::xml_node in : node.children("input")) {
                const auto found = it->second.inputs.find(in.attribute("name").value());
                all = all && found != it->second.inputs.end() && found->second == in.attribute("type").value();
            }
            if (all) match = &it->second;
        }
        if (!match)
            errors.push_back("<" + category + " name=\"" + name + "\" type=\"" + type +
                             "\">: no nodedef has these inputs and types");
        nodes[name] = match;
    }
    for (pugi::xml_node node : root.children())
        for (pugi::xml_node in : node.children("input")) {
            if (in.attribute("nodename").empty()) {
                if (in.attribute("value").empty())
                    errors.push_back(std::string(in.attribute("name").value()) + ": neither value nor nodename");
                continue;
            }
            const auto source = nodes.find(in.attribute("nodename").value());
            if (source == nodes.end() || !source->second) {
                errors.push_back(std::string("connection to unknown node ") + in.attribute("nodename").value());
                continue;
            }
            const auto& outputs = source->second->outputs;
            const std::string output =
                in.attribute("output").empty() ? outputs.begin()->first : in.attribute("output").value();
            const auto o = outputs.find(output);
            if (o == outputs.end() || o->second != in.attribute("type").value())
                errors.push_back(std::string("connection ") + in.attribute("nodename").value() + "." + output +
                                 " has no output of type " + in.attribute("type").value());
        }
    if (!root.child("surfacematerial")) errors.push_back("no surfacematerial");
    return errors;
}

TEST(MaterialxDefinitions, TheCheckerRejectsWhatMaterialxLacks) {
    const auto defs = materialx_nodedefs();
    ASSERT_GT(defs.size(), 100u);
    const auto errors_of = [&](const char* text) {
        pugi::xml_document doc;
        EXPECT_TRUE(doc.load_string(text));
        return materialx_errors(doc, defs);
    };
    EXPECT_TRUE(
        errors_of(
            R"(<materialx version="1.39"><conductor_bsdf name="b" type="BSDF"><input name="ior" type="color3" value="1, 1, 1"/></conductor_bsdf>
        <surface name="s" type="surfaceshader"><input name="bsdf" type="BSDF" nodename="b"/></surface>
        <surfacematerial name="m" type="material"><input name="surfaceshader" type="surfaceshader" nodename="s"/></surfacematerial></materialx>)")
            .empty());
    EXPECT_FALSE(
        errors_of(
            R"(<materialx version="1.39"><conductor_bsdf name="b" type="BSDF"><input name="eta" type="color3" value="1, 1, 1"/></conductor_bsdf>
        <surfacematerial name="m" type="material"/></materialx>)")
            .empty());  // no input "eta"
    EXPECT_FALSE(
        errors_of(
            R"(<materialx version="1.39"><conductor_bsdf name="b" type="BSDF"><input name="ior" type="float" value="1"/></conductor_bsdf>
        <surfacematerial name="m" type="material"/></materialx>)")
            .empty());  // ior is a color3
    EXPECT_FALSE(
        errors_of(
            R"(<materialx version="1.39"><lazanyi_bsdf name="b" type="BSDF"/><surfacematerial name="m" type="material"/></materialx>)")
            .empty());
    EXPECT_FALSE(errors_of(R"(<materialx version="1.39"><artistic_ior name="a" type="multioutput"/>
        <conductor_bsdf name="b" type="BSDF"><input name="ior" type="color3" nodename="a" output="eta"/></conductor_bsdf>
        <surfacematerial name="m" type="material"/></materialx>)")
                     .empty());  // artistic_ior has no output "eta"
}

TEST_F(CatalogExport, EveryMaterialxDocumentUsesOnlyDefinedNodesInputsAndTypes) {
    const auto defs = materialx_nodedefs();
    const auto files = files_with_extension(out(), ".mtlx");
    // Every material × every model, in mtlx/ and in openpbr/.
    EXPECT_EQ(files.size(), 2u * catalog_material_count() * metalfit::all_models().size());
    std::set<std::string> categories;
    for (const fs::path& f : files) {
        pugi::xml_document doc;
        const pugi::xml_parse_result parsed = doc.load_file(f.c_str());
        ASSERT_TRUE(parsed) << f << ": " << parsed.description();
        for (const std::string& e : materialx_errors(doc, defs)) ADD_FAILURE() << f << ": " << e;
        for (pugi::xml_node n : doc.child("materialx").children()) categories.insert(n.name());
    }
    EXPECT_EQ(categories,
              (std::set<std::string>{"generalized_schlick_bsdf", "conductor_bsdf", "artistic_ior", "surface",
                                     "surfacematerial", "open_pbr_surface", "roughness_anisotropy"}));
}

TEST_F(CatalogExport, MaterialxMappingFollowsTheModels) {
    const auto category = [&](const std::string& stem) {
        pugi::xml_document doc;
        EXPECT_TRUE(doc.load_file((out() / "mtlx" / (stem + ".mtlx")).c_str()));
        // The BSDF (or artistic_ior) after the roughness node that feeds it.
        pugi::xml_node n = doc.child("materialx").first_child();
        EXPECT_STREQ(n.name(), "roughness_anisotropy");
        return std::string(n.next_sibling().name());
    };
    EXPECT_EQ(category("metalfit_cu_f82_tint"), "generalized_schlick_bsdf");
    EXPECT_EQ(category("metalfit_cu_schlick"), "generalized_schlick_bsdf");
    EXPECT_EQ(category("metalfit_cu_lazanyi_comp"), "generalized_schlick_bsdf");
    EXPECT_EQ(category("metalfit_cu_conductor_rgb"), "conductor_bsdf");
    EXPECT_EQ(category("metalfit_cu_gulbrandsen"), "artistic_ior");
    // schlick: color82 = 1 in every channel.
    pugi::xml_document doc;
    ASSERT_TRUE(doc.load_file((out() / "mtlx" / "metalfit_cu_schlick.mtlx").c_str()));
    EXPECT_STREQ(doc.select_node("//input[@name='color82']").node().attribute("value").value(), "1.0, 1.0, 1.0");
}

// ---- Error figures in the headers, re-evaluated from the written constants ---------------------------------------

struct ShaderExport {
    std::string material, model;
    std::map<std::string, std::array<double, 3>> figures;  // rel_rms, abs_rms, max_rel, max_abs, albedo_err
    std::vector<std::array<double, 3>> params;             // in the order of the model's parameters
};

std::array<double, 3> three(const std::string& text) {
    std::array<double, 3> v{};
    std::istringstream s(text);
    char comma;
    s >> v[0] >> comma >> v[1] >> comma >> v[2];
    return v;
}

ShaderExport parse_glsl_export(const fs::path& file) {
    const std::string text = read_file(file);
    ShaderExport e;
    std::smatch m;
    if (std::regex_search(text, m, std::regex(R"(export: .* \(([^)]+)\)\n)"))) e.material = m[1];
    if (std::regex_search(text, m, std::regex(R"(// model: (\S+) )"))) e.model = m[1];
    for (const char* key : {"rel_rms", "abs_rms", "max_rel", "max_abs", "albedo_err"})
        if (std::regex_search(text, m, std::regex(std::string("//   ") + key + R"( += ([^\n]+))")))
            e.figures[key] = three(m[1]);
    const std::regex constant(R"(const vec3 METALFIT_\w+ = vec3\(([^)]+)\);)");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), constant); it != std::sregex_iterator(); ++it)
        e.params.push_back(three((*it)[1]));
    return e;
}

TEST_F(CatalogExport, HeaderErrorFiguresAreReproducedFromTheWrittenConstants) {
    // The figures are of the written doubles (metalfit_export.json); the GLSL constants are the floats nearest them.
    const auto record = nlohmann::json::parse(read_file(out() / "metalfit_export.json"));
    using namespace metalfit;
    const fs::path data = test::kData;
    const Catalog catalog = Catalog::load(data);
    const Colorimetry colorimetry = Colorimetry::load(data, Observer::cie1931_2deg, Illuminant::D65);
    const ColorSpaceConverter converter = ColorSpaceConverter::create(choose_ocio_config(std::nullopt, data));
    // Own quadrature and grid, not libfit's metrics: the definitions of docs/fitting.md ("Definitions"), written out here.
    const auto nodes = gauss_legendre_unit(128);
    std::vector<double> grid_mu;
    for (int i = 0; i <= 1024; ++i) grid_mu.push_back(i / 1024.0);
    for (const auto& n : nodes) grid_mu.push_back(n.mu);

    std::map<std::string, std::vector<ShaderExport>> by_material;
    for (const fs::path& f : files_with_extension(out() / "glsl", ".glsl"))
        if (f.filename() != "metalfit_models.glsl")
            by_material[parse_glsl_export(f).material].push_back(parse_glsl_export(f));
    ASSERT_EQ(by_material.size(), catalog_material_count());
    int checked = 0;
    for (const auto& [id, exports] : by_material) {
        const ReferenceCurve curve(load_material(catalog, id, ""), colorimetry, converter);
        std::vector<RGB> at_nodes, at_grid;
        for (const auto& n : nodes) at_nodes.push_back(curve(n.mu));
        for (double mu : grid_mu) at_grid.push_back(curve(mu));
        for (const ShaderExport& e : exports) {
            SCOPED_TRACE(id + " " + e.model);
            const Model& model = find_model(e.model);
            ASSERT_EQ(e.params.size(), model.parameters().size());
            ModelParameters p;
            const auto& written = record["materials"][id]["models"][e.model]["export"]["params"];
            for (int c = 0; c < 3; ++c)
                for (std::size_t i = 0; i < e.params.size(); ++i) {
                    const double v = written[std::string(model.parameters()[i].name)][c].get<double>();
                    EXPECT_EQ(static_cast<float>(e.params[i][c]), static_cast<float>(v)) << model.parameters()[i].name;
                    p[c].push_back(v);
                }
            for (int c = 0; c < 3; ++c) {
                double rel = 0, abs = 0, albedo = 0, max_rel = 0, max_abs = 0;
                for (std::size_t i = 0; i < nodes.size(); ++i) {
                    const double d = model.evaluate(std::span<const double>(p[c]), nodes[i].mu) - at_nodes[i][c];
                    rel += nodes[i].weight * std::pow(d / at_nodes[i][c], 2);
                    abs += nodes[i].weight * d * d;
                    albedo += nodes[i].weight * 2 * nodes[i].mu * d;
                }
                for (std::size_t i = 0; i < grid_mu.size(); ++i) {
                    const double d = model.evaluate(std::span<const double>(p[c]), grid_mu[i]) - at_grid[i][c];
                    max_abs = std::max(max_abs, std::abs(d));
                    max_rel = std::max(max_rel, std::abs(d / at_grid[i][c]));
                }
                const std::map<std::string, double> mine{{"rel_rms", std::sqrt(rel)},
                                                         {"abs_rms", std::sqrt(abs)},
                                                         {"max_rel", max_rel},
                                                         {"max_abs", max_abs},
                                                         {"albedo_err", albedo}};
                for (const auto& [key, value] : mine) {
                    ASSERT_TRUE(e.figures.count(key)) << key;
                    const double written = e.figures.at(key)[c];
                    // Six significant digits are written; the JSON's doubles are exact (shortest round trip).
                    EXPECT_NEAR(value, written, 1e-5 * std::abs(written) + 1e-12) << key << " channel " << c;
                }
            }
            ++checked;
        }
    }
    EXPECT_EQ(checked, static_cast<int>(catalog_material_count() * all_models().size()));
}

TEST_F(CatalogExport, ShaderHeadersStateTheLanguageAndHalfPrecisionSafety) {
    const std::string au_conductor = read_file(out() / "glsl" / "metalfit_au_conductor_rgb.glsl");
    EXPECT_TRUE(metalfit::test::Contains(au_conductor, "GLSL >= 1.30 (tested as 3.30 and 4.50) or GLSL ES 3.00"));
    // Gold's red k (about 1097) squared is beyond half's 65504, and the fit put its n at the lower bound.
    EXPECT_TRUE(
        metalfit::test::Contains(au_conductor, "half precision (16-bit float, mediump): NOT safe: k² or 4n²k² of red"));
    EXPECT_TRUE(metalfit::test::Contains(au_conductor, "n red = 0.001 is the fit's lower bound"));
    // Gulbrandsen's r = 0.99999 rounds to 1 in half.
    EXPECT_TRUE(
        metalfit::test::Contains(read_file(out() / "hlsl" / "metalfit_au_gulbrandsen.hlsl"), "rounds to 1 in half"));
    const std::string cu_f82 = read_file(out() / "glsl" / "metalfit_cu_f82_tint.glsl");
    EXPECT_TRUE(metalfit::test::Contains(cu_f82, "half precision (16-bit float, mediump): in range"));
    EXPECT_TRUE(metalfit::test::Contains(cu_f82, "#ifndef METALFIT_CU_F82_TINT_GLSL"));
    EXPECT_TRUE(metalfit::test::Contains(read_file(out() / "glsl" / "metalfit_models.glsl"),
                                         "#ifdef GL_ES\nprecision highp float;\n#endif\n"));
}

TEST_F(CatalogExport, MaterialxProvenanceIsTheDocOfTheMaterialAsWellAsTheComment) {
    for (const char* file : {"mtlx/metalfit_au_lazanyi_comp.mtlx", "openpbr/metalfit_cu_f82_tint.mtlx"}) {
        pugi::xml_document doc;
        ASSERT_TRUE(doc.load_file((out() / file).c_str(), pugi::parse_default | pugi::parse_comments));
        std::string comment;
        for (pugi::xml_node n : doc.children())
            if (n.type() == pugi::node_comment) comment = n.value();
        comment = std::regex_replace(comment, std::regex("\n  "), "\n");
        while (!comment.empty() && (comment.front() == '\n')) comment.erase(0, 1);
        while (!comment.empty() && (comment.back() == '\n' || comment.back() == ' ')) comment.pop_back();
        const std::string doc_string = doc.select_node("//surfacematerial").node().attribute("doc").value();
        EXPECT_TRUE(metalfit::test::Contains(doc_string, "data source: ")) << file;
        EXPECT_EQ(std::regex_replace(doc_string, std::regex("- -"), "--"),
                  std::regex_replace(comment, std::regex("- -"), "--"))
            << file;
    }
}

// ---- Roughness: the same value in MaterialX, OpenPBR and JSON --------------------------------------------------------

// The roughness a MaterialX document gives its BSDF: roughness_anisotropy's input, followed from the BSDF's
// roughness connection; -1 when the BSDF has none.
double materialx_roughness(const fs::path& file) {
    pugi::xml_document doc;
    EXPECT_TRUE(doc.load_file(file.c_str())) << file;
    const pugi::xml_node bsdf = doc.select_node("//*[@type='BSDF' and input[@name='roughness']]").node();
    if (!bsdf) return -1;
    const std::string node = bsdf.select_node("input[@name='roughness']").node().attribute("nodename").value();
    const pugi::xml_node r = doc.select_node(("//roughness_anisotropy[@name='" + node + "']").c_str()).node();
    return r ? r.select_node("input[@name='roughness']").node().attribute("value").as_double(-1) : -1;
}

TEST_F(CatalogExport, EveryDocumentCarriesTheDefaultRoughness) {
    for (const fs::path& f : files_with_extension(out() / "mtlx", ".mtlx"))
        EXPECT_EQ(materialx_roughness(f), metalfit::kDefaultRoughness) << f;
    for (const fs::path& f : files_with_extension(out() / "openpbr", ".json"))
        EXPECT_EQ(nlohmann::json::parse(read_file(f))["open_pbr_surface"]["specular_roughness"],
                  metalfit::kDefaultRoughness)
            << f;
    const auto record = nlohmann::json::parse(read_file(out() / "metalfit_export.json"));
    EXPECT_EQ(record["materials"]["Cu"]["models"]["schlick"]["export"]["roughness"], metalfit::kDefaultRoughness);
}

TEST(ExportRoughness, TheGivenRoughnessIsWrittenInEveryFormatAndBadValuesAreUsageErrors) {
    TempDir tmp;
    const fs::path out = tmp.path() / "out";
    const Result r =
        run("export Au --model f82-tint,conductor-rgb,gulbrandsen --format mtlx,openpbr,json --roughness 0.25 -o '" +
                out.string() + "'",
            tmp.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* stem : {"metalfit_au_f82_tint", "metalfit_au_conductor_rgb", "metalfit_au_gulbrandsen"}) {
        EXPECT_EQ(materialx_roughness(out / "mtlx" / (std::string(stem) + ".mtlx")), 0.25) << stem;
        EXPECT_EQ(nlohmann::json::parse(read_file(
                      out / "openpbr" / (std::string(stem) + ".json")))["open_pbr_surface"]["specular_roughness"],
                  0.25)
            << stem;
        pugi::xml_document doc;
        ASSERT_TRUE(doc.load_file((out / "openpbr" / (std::string(stem) + ".mtlx")).c_str()));
        EXPECT_STREQ(
            doc.select_node("//open_pbr_surface/input[@name='specular_roughness']").node().attribute("value").value(),
            "0.25");
    }
    EXPECT_EQ(nlohmann::json::parse(read_file(
                  out / "metalfit_export.json"))["materials"]["Au"]["models"]["gulbrandsen"]["export"]["roughness"],
              0.25);
    for (const char* bad : {"1.5", "-0.1", "rough", "nan"}) {
        const Result e = run(std::string("export Au --model schlick --format json --roughness ") + bad + " -o '" +
                                 (tmp.path() / "bad").string() + "'",
                             tmp.path());
        EXPECT_EQ(e.exit_code, 2) << bad;
        EXPECT_TRUE(metalfit::test::Contains(e.err, "--roughness")) << e.err;
        EXPECT_FALSE(fs::exists(tmp.path() / "bad"));
    }
}

// ---- JSON: the fit record's schema, the written parameters in "export" ---------------------------------------------

TEST_F(CatalogExport, JsonIsTheFitRecordWithTheWrittenParameters) {
    const auto j = nlohmann::json::parse(read_file(out() / "metalfit_export.json"));
    EXPECT_EQ(j["schema"], "metalfit.fit/1");
    ASSERT_EQ(j["materials"].size(), catalog_material_count());
    const auto& au = j["materials"]["Au"]["models"]["f82-tint"];
    EXPECT_EQ(au["export"]["from"], "fit");
    EXPECT_EQ(au["export"]["params"], au["fit"]["params"]);  // keep: the fit as it is
    EXPECT_EQ(au["export"]["metrics"], au["fit"]["metrics"]);
    // The GLSL constants are the floats nearest the same numbers, as the shortest text of that float (<= 9 digits).
    const ShaderExport g = parse_glsl_export(out() / "glsl" / "metalfit_au_f82_tint.glsl");
    for (int c = 0; c < 3; ++c)
        EXPECT_EQ(static_cast<float>(g.params[0][c]),
                  static_cast<float>(au["export"]["params"]["F0"][c].get<double>()));
    const std::string text = read_file(out() / "glsl" / "metalfit_au_f82_tint.glsl");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(text, m, std::regex(R"(_F0 = vec3\(([-0-9.e]+),)")));
    EXPECT_LE(std::regex_replace(m[1].str(), std::regex("[-.]|e.*"), "").size(), 9u) << m[1];
}

// ---- Gamut policies ------------------------------------------------------------------------------------------------

TEST(ExportGamut, ClipAndScaleWriteInGamutColoursAndTheirOwnErrors) {
    TempDir tmp;
    std::map<std::string, nlohmann::json> records;
    for (const char* policy : {"keep", "clip", "scale"}) {
        const fs::path dir = tmp.path() / policy;
        const Result r = run(std::string("export gold --model f82-tint,schlick --format json --gamut ") + policy +
                                 " -o '" + dir.string() + "'",
                             tmp.path());
        ASSERT_EQ(r.exit_code, 0) << r.err;
        records[policy] = nlohmann::json::parse(read_file(dir / "metalfit_export.json"))["materials"]["Au"]["models"];
    }
    for (const char* model : {"f82-tint", "schlick"}) {
        SCOPED_TRACE(model);
        const auto& keep = records["keep"][model]["export"];
        const auto& clip = records["clip"][model]["export"];
        const auto& scale = records["scale"][model]["export"];
        const auto F0 = [](const nlohmann::json& e, int c) { return e["params"]["F0"][c].get<double>(); };
        ASSERT_GT(F0(keep, 0), 1.0);  // gold's red F0 is out of gamut in Linear Rec.709
        EXPECT_FALSE(keep["out_of_gamut"].empty());
        EXPECT_EQ(F0(clip, 0), 1.0);
        EXPECT_EQ(F0(clip, 1), F0(keep, 1));
        EXPECT_DOUBLE_EQ(F0(scale, 0), 1.0);
        EXPECT_DOUBLE_EQ(F0(scale, 1), F0(keep, 1) / F0(keep, 0));
        // The figures are those of the written values.
        EXPECT_NE(clip["metrics"]["rel_rms"][0], keep["metrics"]["rel_rms"][0]);
        // Schlick's green is in gamut: clipping leaves it alone (f82-tint's green tint, 1.003, is clipped too).
        if (std::string(model) == "schlick")
            EXPECT_EQ(clip["metrics"]["rel_rms"][1], keep["metrics"]["rel_rms"][1]);
        else
            EXPECT_NE(clip["metrics"]["rel_rms"][1], keep["metrics"]["rel_rms"][1]);
        EXPECT_NE(scale["metrics"]["rel_rms"][1], keep["metrics"]["rel_rms"][1]);
        EXPECT_EQ(keep["metrics"], records["keep"][model]["fit"]["metrics"]);
    }
}

// ---- HLSL: a token mapping of the GLSL, comments untouched ---------------------------------------------------------

TEST(ExportHlsl, TranslationIsATokenMapping) {
    const std::string hlsl = metalfit::hlsl_from_glsl(
        "// vec3 mix equal stay in comments\nvec3 f(vec3 a, bvec3 b, float mu) { vec3 c = vec3(1e-30) + vec3 (mu); "
        "return mix(a, c, greaterThanEqual(a, c)) + vec3(equal(a, c).x ? 1.0 : 0.0); }\n");
    const std::string body = hlsl.substr(hlsl.find("// vec3 mix"));
    EXPECT_EQ(
        body,
        "// vec3 mix equal stay in comments\nfloat3 f(float3 a, bool3 b, float mu) { float3 c = metalfit_vec3(1e-30) + "
        "metalfit_vec3 (mu); return metalfit_mix(a, c, metalfit_greaterThanEqual(a, c)) + "
        "metalfit_vec3(metalfit_equal(a, c).x ? 1.0 : 0.0); }\n");
}

// ---- Failures: one line, non-zero exit, nothing left behind --------------------------------------------------------

TEST(ExportErrors, BadRequestsFailWithOneLineAndWriteNothing) {
    TempDir tmp;
    const fs::path dir = tmp.path() / "out";
    struct Case {
        std::string args;
        int exit_code;
        std::string message;
    };
    const std::vector<Case> cases{
        {"export unobtainium --model f82-tint --format glsl", 2, "unobtainium"},
        {"export Au --model f83-tint --format glsl", 2, "f83-tint"},
        {"export Au --model f82-tint --format vulkan", 2, "vulkan"},
        {"export Au --model f82-tint --format glsl --gamut squash", 2, "squash"},
        {"export --all Au --model f82-tint --format glsl", 2, "not both"},
    };
    for (const Case& c : cases) {
        const Result r = run(c.args + " -o '" + dir.string() + "'", tmp.path());
        EXPECT_EQ(r.exit_code, c.exit_code) << c.args << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir)) << c.args;
    }
}

TEST(ExportErrors, AnUnwritableDestinationLeavesNoPartialFiles) {
    TempDir tmp;
    // Below a regular file: no folder can be made there (whoever runs the test, root included).
    const fs::path blocker = tmp.write("file", "x");
    Result r = run("export Au --model f82-tint --format glsl -o '" + (blocker / "out").string() + "'", tmp.path());
    EXPECT_EQ(r.exit_code, 3) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("file"), std::string::npos) << r.err;

    // glsl/ can be written but hlsl/ cannot (a file is in the way): the GLSL files must not stay behind either.
    const fs::path dir = tmp.path() / "out";
    fs::create_directories(dir);
    tmp.write("out/hlsl", "in the way");
    r = run("export Au --model f82-tint --format glsl,hlsl,json -o '" + dir.string() + "'", tmp.path());
    EXPECT_EQ(r.exit_code, 3) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    std::vector<std::string> left;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        left.push_back(e.path().lexically_relative(dir).string());
    EXPECT_EQ(left, std::vector<std::string>{"hlsl"});
}

TEST(ExportErrors, ClosedParametersThatDoNotExistAreAnErrorNamingTheReason) {
    TempDir tmp;
    const Result r =
        run("export Au --model lazanyi-comp --params closed --format glsl -o '" + (tmp.path() / "out").string() + "'",
            tmp.path());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("no closed form is defined"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(tmp.path() / "out"));
}

TEST(MaterialxColorspace, MatchesTheSpacesNameOrAliasesCaseInsensitively) {
    using metalfit::materialx_colorspace;
    const metalfit::OcioConfigChoice ours{metalfit::test::kData / "ocio" / "config.ocio", "test"};
    EXPECT_EQ(materialx_colorspace(ours, "Linear Rec.709 (sRGB)"), "lin_rec709");
    EXPECT_EQ(materialx_colorspace(ours, "ACEScg"), "acescg");
    EXPECT_EQ(materialx_colorspace(ours, "Linear P3-D65"), "lin_displayp3");
    EXPECT_EQ(materialx_colorspace(ours, "Linear Rec.2020"), "");  // MaterialX has no name for these
    EXPECT_EQ(materialx_colorspace(ours, "ACES2065-1"), "");
    // A studio's config that names the space its own way and lists a MaterialX name among its aliases.
    TempDir dir;
    std::string config = read_file(ours.path);
    const auto replace_all = [&config](const std::string& from, const std::string& to) {
        ASSERT_NE(config.find(from), std::string::npos) << from;
        for (std::size_t at = config.find(from); at != std::string::npos; at = config.find(from, at + to.size()))
            config.replace(at, from.size(), to);
    };
    replace_all("Linear Rec.709 (sRGB)", "studio linear");  // the space and the roles naming it
    replace_all("[lin_rec709_srgb, lin_rec709, lin_srgb, Utility - Linear - sRGB]", "[Lin_Rec709]");
    const fs::path studio = dir.write("studio.ocio", config);
    EXPECT_EQ(materialx_colorspace({studio, "test"}, "studio linear"), "lin_rec709");
    EXPECT_EQ(materialx_colorspace({studio, "test"}, "Linear Rec.709"), "lin_rec709");  // a name configs use
}

}  // namespace test_export

// ---- A second export into a folder (issue 12, item 5) and parallel exports (issue 13, item 6) ------------------------

namespace test_export {
std::map<std::string, std::string> files_below(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) files[e.path().lexically_relative(dir).string()] = metalfit::test::read_file(e.path());
    return files;
}

TEST(ExportMerge, ASecondMaterialIsAddedToTheIndexesNotSwappedForThem) {
    TempDir tmp;
    const fs::path dir = tmp.path() / "out";
    Result r = run("export Au --model f82-tint --format json,cpp,glsl -o '" + dir.string() + "'", tmp.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = run("export Cu --model schlick --format json,cpp,glsl -o '" + dir.string() + "'", tmp.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json record = nlohmann::json::parse(metalfit::test::read_file(dir / "metalfit_export.json"));
    EXPECT_TRUE(record["materials"].contains("Au"));
    EXPECT_TRUE(record["materials"].contains("Cu"));
    EXPECT_TRUE(record["materials"]["Au"]["models"].contains("f82-tint"));
    const std::string index = metalfit::test::read_file(dir / "cpp" / "metalfit_materials.hpp");
    EXPECT_NE(index.find("#include \"metalfit_au_f82_tint.hpp\""), std::string::npos) << index;
    EXPECT_NE(index.find("#include \"metalfit_cu_schlick.hpp\""), std::string::npos) << index;
    EXPECT_NE(index.find("std::array<Entry, 2>"), std::string::npos) << index;
    const std::string models = metalfit::test::read_file(dir / "glsl" / "metalfit_models.glsl");
    EXPECT_NE(models.find("vec3 metalfit_f82_tint("), std::string::npos);  // Au's file still finds its function
    EXPECT_NE(models.find("vec3 metalfit_schlick("), std::string::npos);

    // Another colour space cannot share the record: refused, saying why, and the folder is unchanged.
    const auto before = files_below(dir);
    r = run("export Ag --model schlick --format json --space ACEScg -o '" + dir.string() + "'", tmp.path());
    EXPECT_EQ(r.exit_code, 3) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("ACEScg"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("metalfit_export.json"), std::string::npos) << r.err;
    EXPECT_EQ(files_below(dir), before);
}

TEST(ExportMerge, ParallelExportsIntoOneNewNestedFolderAllSucceed) {
    TempDir tmp;
    const fs::path dir = tmp.path() / "a" / "b" / "out";
    std::vector<std::thread> runs;
    std::vector<Result> results(4);
    const std::vector<std::string> materials{"Au", "Cu", "Ag", "Al"};
    for (std::size_t i = 0; i < materials.size(); ++i)
        runs.emplace_back([&, i] {
            const fs::path scratch = tmp.path() / ("s" + std::to_string(i));
            fs::create_directories(scratch);
            results[i] = run("export " + materials[i] + " --model f82-tint --format json,cpp -o '" + dir.string() + "'",
                             scratch);
        });
    for (auto& t : runs) t.join();
    for (const Result& r : results) EXPECT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json record = nlohmann::json::parse(metalfit::test::read_file(dir / "metalfit_export.json"));
    EXPECT_EQ(record["materials"].size(), 4u);
}

TEST(ExportMerge, TheCurrentFolderIsRefusedWithAReason) {
    TempDir tmp;
    const Result r = run("export Au --model f82-tint --format json -o .", tmp.path());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("current folder"), std::string::npos) << r.err;
}

}  // namespace test_export
