// metalfit export of layered materials (docs/export.md, Layered exports): OpenPBR, MaterialX and glTF carry the coat
// and the thin film as their own parameters (the stack's data: the coat's index, the film's thickness in each format's
// unit, the film's index at 550 nm) over the BARE metal's constants, which must equal those of an export of the bare
// metal; JSON keeps the stack's fit and describes the layers. The real consumers (MaterialX, the glTF validator) run
// in materialx.consumer and export.gltf_validator.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>
#include <sstream>
#include <string>

#include "test_support.hpp"

namespace test_export_layers {

namespace fs = std::filesystem;
using metalfit::test::read_file;
using metalfit::test::TempDir;
using Json = nlohmann::json;

void export_to(const std::string& args, const fs::path& dir) {
    const auto r = metalfit::test::run_command(metalfit::test::kMetalfitExe, "export " + args + " -o " + dir.string(),
                                               dir.parent_path());
    ASSERT_EQ(r.exit_code, 0) << args << "\n" << r.err;
}

Json json_of(const fs::path& file) { return Json::parse(read_file(file)); }

// The value of <input name=NAME> of the node named NODE.
std::string input_value(const pugi::xml_document& doc, const std::string& node, const std::string& input) {
    const pugi::xml_node n = doc.child("materialx").find_child_by_attribute("name", node.c_str());
    return n.find_child_by_attribute("input", "name", input.c_str()).attribute("value").as_string();
}

pugi::xml_document load_xml(const fs::path& file) {
    pugi::xml_document doc;
    EXPECT_TRUE(doc.load_file(file.c_str())) << file;
    return doc;
}

// n of a refractiveindex.info "tabulated nk" file at `nm`, linearly interpolated between its two neighbours (the
// test's own reading of the file, not libfit's).
double tabulated_n_at(const fs::path& yml, double nm) {
    std::istringstream text(read_file(yml));
    std::string line;
    double previous_um = -1, previous_n = 0;
    while (std::getline(text, line)) {
        std::istringstream fields(line);
        double um = 0, n = 0, k = 0;
        if (!(fields >> um >> n >> k)) continue;
        if (um * 1000.0 >= nm && previous_um > 0) {
            const double t = (nm / 1000.0 - previous_um) / (um - previous_um);
            return previous_n + t * (n - previous_n);
        }
        previous_um = um;
        previous_n = n;
    }
    ADD_FAILURE() << nm << " nm not in " << yml;
    return 0;
}

TEST(ExportLayers, AFilmIsTheFormatsThinFilmOverTheBareMetalsConstants) {
    TempDir tmp;
    const fs::path film = tmp.path() / "film", bare = tmp.path() / "bare";
    const std::string what = " --model f82-tint,conductor-rgb,gulbrandsen --format json,openpbr,mtlx,gltf";
    export_to("Ti --film 2.2:80nm" + what, film);
    export_to("Ti" + what, bare);

    // OpenPBR: thin_film_thickness in micrometres, thin_film_ior the film's index; base_color and specular_color
    // those of the bare metal, not of the stack's fit.
    for (const char* model : {"f82_tint", "conductor_rgb"}) {
        SCOPED_TRACE(model);
        const std::string stem = std::string("metalfit_ti_") + model;
        const Json f = json_of(film / "openpbr" / (stem + ".json"))["open_pbr_surface"];
        const Json b = json_of(bare / "openpbr" / (stem + ".json"))["open_pbr_surface"];
        EXPECT_EQ(f["base_color"], b["base_color"]);
        EXPECT_EQ(f["specular_color"], b["specular_color"]);
        EXPECT_EQ(f["thin_film_weight"], 1.0);
        EXPECT_DOUBLE_EQ(f["thin_film_thickness"].get<double>(), 0.08);
        EXPECT_EQ(f["thin_film_ior"], 2.2);
        EXPECT_FALSE(f.contains("coat_weight"));
        EXPECT_FALSE(b.contains("thin_film_weight"));
        const pugi::xml_document doc = load_xml(film / "openpbr" / (stem + ".mtlx"));
        const pugi::xml_document bare_doc = load_xml(bare / "openpbr" / (stem + ".mtlx"));
        const std::string shader = stem + "_open_pbr_surface";
        EXPECT_EQ(input_value(doc, shader, "base_color"), input_value(bare_doc, shader, "base_color"));
        EXPECT_EQ(input_value(doc, shader, "thin_film_thickness"), "0.08");
        EXPECT_EQ(input_value(doc, shader, "thin_film_ior"), "2.2");
    }
    // The stack's own fit (JSON) is not the base: the film changes the curve.
    const Json record = json_of(film / "metalfit_export.json")["materials"]["Ti"];
    const Json bare_record = json_of(bare / "metalfit_export.json")["materials"]["Ti"];
    EXPECT_NE(record["models"]["f82-tint"]["export"]["params"]["F0"],
              bare_record["models"]["f82-tint"]["export"]["params"]["F0"]);
    EXPECT_EQ(json_of(film / "openpbr" / "metalfit_ti_f82_tint.json")["open_pbr_surface"]["base_color"],
              bare_record["models"]["f82-tint"]["export"]["params"]["F0"]);
    // JSON describes the stack: the film's thickness and index.
    const Json stack = record["data"]["stack"]["film"];
    EXPECT_EQ(stack["thickness_nm"], 80.0);
    EXPECT_EQ(stack["n"], 2.2);
    EXPECT_EQ(stack["k"], 0.0);
    EXPECT_EQ(stack["index_at_nm"], 550.0);

    // MaterialX: thinfilm_thickness in nanometres and thinfilm_ior on the metal's BSDF, whose constants are the bare
    // metal's; no coat layer.
    for (const auto& [model, inputs] :
         {std::pair<std::string, std::vector<std::string>>{"f82_tint", {"color0", "color82"}},
          {"conductor_rgb", {"ior", "extinction"}},
          {"gulbrandsen", {}}}) {
        SCOPED_TRACE(model);
        const std::string stem = "metalfit_ti_" + model;
        const pugi::xml_document doc = load_xml(film / "mtlx" / (stem + ".mtlx"));
        const pugi::xml_document bare_doc = load_xml(bare / "mtlx" / (stem + ".mtlx"));
        EXPECT_EQ(input_value(doc, stem + "_bsdf", "thinfilm_thickness"), "80.0");
        EXPECT_EQ(input_value(doc, stem + "_bsdf", "thinfilm_ior"), "2.2");
        for (const std::string& input : inputs)
            EXPECT_EQ(input_value(doc, stem + "_bsdf", input), input_value(bare_doc, stem + "_bsdf", input)) << input;
        if (model == "gulbrandsen") {
            for (const char* input : {"reflectivity", "edge_color"}) {
                EXPECT_EQ(input_value(doc, stem + "_artistic_ior", input),
                          input_value(bare_doc, stem + "_artistic_ior", input));
            }
        }
        EXPECT_FALSE(doc.child("materialx").child("layer"));
        EXPECT_FALSE(bare_doc.child("materialx")
                         .child("conductor_bsdf")
                         .find_child_by_attribute("input", "name", "thinfilm_thickness"));
    }

    // glTF: KHR_materials_iridescence with the thickness in nanometres, over the bare metal's baseColorFactor.
    for (const char* model : {"f82_tint", "conductor_rgb"}) {
        SCOPED_TRACE(model);
        const std::string stem = std::string("metalfit_ti_") + model;
        const Json g = json_of(film / "gltf" / (stem + ".gltf"));
        const Json b = json_of(bare / "gltf" / (stem + ".gltf"));
        EXPECT_EQ(g["materials"][0]["pbrMetallicRoughness"], b["materials"][0]["pbrMetallicRoughness"]);
        EXPECT_EQ(g["extensionsUsed"], Json::array({"KHR_materials_iridescence"}));
        const Json ir = g["materials"][0]["extensions"]["KHR_materials_iridescence"];
        EXPECT_EQ(ir["iridescenceFactor"], 1.0);
        EXPECT_EQ(ir["iridescenceIor"], 2.2);
        EXPECT_EQ(ir["iridescenceThicknessMinimum"], 80.0);
        EXPECT_EQ(ir["iridescenceThicknessMaximum"], 80.0);
        EXPECT_FALSE(b.contains("extensionsUsed"));
        EXPECT_FALSE(b["materials"][0].contains("extensions"));
    }
}

TEST(ExportLayers, ACoatIsTheFormatsCoatOverTheBareMetalsConstants) {
    TempDir tmp;
    const fs::path coat = tmp.path() / "coat", bare = tmp.path() / "bare";
    const std::string what = " --model f82-tint,conductor-rgb --format openpbr,mtlx,gltf";
    export_to("lacquered-brass" + what, coat);  // data/finishes.json: Cu-Zn under a clear coat of 1.49
    export_to("Cu-Zn" + what, bare);
    for (const char* model : {"f82_tint", "conductor_rgb"}) {
        SCOPED_TRACE(model);
        const std::string stem = std::string("metalfit_lacquered_brass_") + model;
        const std::string bare_stem = std::string("metalfit_cu_zn_") + model;
        const Json f = json_of(coat / "openpbr" / (stem + ".json"));
        const Json b = json_of(bare / "openpbr" / (bare_stem + ".json"))["open_pbr_surface"];
        const Json& s = f["open_pbr_surface"];
        EXPECT_EQ(s["base_color"], b["base_color"]);
        EXPECT_EQ(s["specular_color"], b["specular_color"]);
        EXPECT_EQ(s["coat_weight"], 1.0);
        EXPECT_EQ(s["coat_ior"], 1.49);
        EXPECT_EQ(s["coat_color"], Json::array({1.0, 1.0, 1.0}));
        EXPECT_EQ(s["coat_roughness"], 0.0);
        EXPECT_FALSE(s.contains("thin_film_weight"));
        EXPECT_EQ(f["layers"]["index_at_nm"], 550.0);
        const pugi::xml_document pbr = load_xml(coat / "openpbr" / (stem + ".mtlx"));
        EXPECT_EQ(input_value(pbr, stem + "_open_pbr_surface", "coat_ior"), "1.49");
        EXPECT_EQ(input_value(pbr, stem + "_open_pbr_surface", "coat_weight"), "1.0");

        // MaterialX: <layer> with a dielectric_bsdf of the coat's index on top of the metal's BSDF (the bare
        // metal's constants), and the surface takes the layer.
        const pugi::xml_document doc = load_xml(coat / "mtlx" / (stem + ".mtlx"));
        const pugi::xml_document bare_doc = load_xml(bare / "mtlx" / (bare_stem + ".mtlx"));
        const pugi::xml_node root = doc.child("materialx");
        const pugi::xml_node layer = root.find_child_by_attribute("layer", "name", (stem + "_coated_bsdf").c_str());
        ASSERT_TRUE(layer);
        EXPECT_STREQ(layer.find_child_by_attribute("input", "name", "top").attribute("nodename").as_string(),
                     (stem + "_coat_bsdf").c_str());
        EXPECT_STREQ(layer.find_child_by_attribute("input", "name", "base").attribute("nodename").as_string(),
                     (stem + "_bsdf").c_str());
        const pugi::xml_node top = root.find_child_by_attribute("name", (stem + "_coat_bsdf").c_str());
        EXPECT_STREQ(top.name(), "dielectric_bsdf");
        EXPECT_EQ(input_value(doc, stem + "_coat_bsdf", "ior"), "1.49");
        EXPECT_EQ(input_value(doc, stem + "_coat_bsdf", "scatter_mode"), "R");
        EXPECT_STREQ(root.find_child_by_attribute("name", (stem + "_surface").c_str())
                         .child("input")
                         .attribute("nodename")
                         .as_string(),
                     (stem + "_coated_bsdf").c_str());
        for (const char* input : {"color0", "color82", "ior", "extinction"})
            EXPECT_EQ(input_value(doc, stem + "_bsdf", input), input_value(bare_doc, bare_stem + "_bsdf", input));

        // glTF: KHR_materials_clearcoat, smooth; its fixed index of 1.5 is said where the coat's is another.
        const Json g = json_of(coat / "gltf" / (stem + ".gltf"));
        const Json gb = json_of(bare / "gltf" / (bare_stem + ".gltf"));
        EXPECT_EQ(g["materials"][0]["pbrMetallicRoughness"], gb["materials"][0]["pbrMetallicRoughness"]);
        EXPECT_EQ(g["extensionsUsed"], Json::array({"KHR_materials_clearcoat"}));
        const Json cc = g["materials"][0]["extensions"]["KHR_materials_clearcoat"];
        EXPECT_EQ(cc["clearcoatFactor"], 1.0);
        EXPECT_EQ(cc["clearcoatRoughnessFactor"], 0.0);
        bool said = false;
        for (const Json& note : g["materials"][0]["extras"]["metalfit"]["layers"]["notes"])
            said = said || note.get<std::string>().find("fixed at 1.5") != std::string::npos;
        EXPECT_TRUE(said);
    }
}

TEST(ExportLayers, ADispersiveFilmsIndexIsItsNAt550nmAndTheHeadersSaySo) {
    TempDir tmp;
    const fs::path dir = tmp.path() / "ti";
    export_to("Ti --film TiO2:80nm --coat 1.6 --model f82-tint --format json,openpbr,mtlx,gltf,glsl", dir);
    const double n550 = tabulated_n_at(fs::path(metalfit::test::kDataDir) / "films/TiO2/Siefke.yml", 550.0);
    const std::string stem = "metalfit_ti_f82_tint";
    const Json pbr = json_of(dir / "openpbr" / (stem + ".json"));
    EXPECT_NEAR(pbr["open_pbr_surface"]["thin_film_ior"].get<double>(), n550, 1e-12);
    EXPECT_DOUBLE_EQ(pbr["open_pbr_surface"]["thin_film_thickness"].get<double>(), 0.08);
    EXPECT_EQ(pbr["open_pbr_surface"]["coat_ior"], 1.6);
    const Json g = json_of(dir / "gltf" / (stem + ".gltf"));
    EXPECT_EQ(g["extensionsUsed"], Json::array({"KHR_materials_clearcoat", "KHR_materials_iridescence"}));
    EXPECT_NEAR(g["materials"][0]["extensions"]["KHR_materials_iridescence"]["iridescenceIor"].get<double>(), n550,
                1e-12);
    const std::string mtlx = read_file(dir / "mtlx" / (stem + ".mtlx"));
    EXPECT_NE(mtlx.find("APPROXIMATION: the film is dispersive"), std::string::npos);
    EXPECT_NE(mtlx.find("CANNOT EXPRESS: the film absorbs"), std::string::npos);
    EXPECT_NE(mtlx.find("the base parameters fit the bare titanium's reflectance"), std::string::npos);
    // The shader exports keep the stack's curve and name the layers with their indices.
    const std::string glsl = read_file(dir / "glsl" / (stem + ".glsl"));
    EXPECT_NE(glsl.find("the parameters fit the stack's reflectance"), std::string::npos);
    EXPECT_NE(glsl.find("// film layer: TiO2 (Siefke) film of 80 nm (0.08 um); n(550 nm) = "), std::string::npos);
    EXPECT_NE(glsl.find("// coat layer: coat n = 1.6; n(550 nm) = 1.6"), std::string::npos);
    const Json stack = json_of(dir / "metalfit_export.json")["materials"]["Ti"]["data"]["stack"];
    EXPECT_NEAR(stack["film"]["n"].get<double>(), n550, 1e-12);
    EXPECT_EQ(stack["coat"]["n"], 1.6);
}

}  // namespace test_export_layers
