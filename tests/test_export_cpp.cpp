// The C++ export compiled in this translation unit: the build runs `metalfit export --all --model all --format
// cpp,json` (tests/CMakeLists.txt) and this file includes the generated metalfit_materials.hpp. Its model functions
// (the GLSL text over a vec3 prelude, in float) must equal libfit's models, and its constants the JSON record's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "libfit/models/model.hpp"
#include "metalfit_materials.hpp"
#include "test_support.hpp"

namespace test_export_cpp {

TEST(ExportCpp, HeaderFunctionsEvaluateLikeLibfitAtThousandsOfMu) {
    ASSERT_EQ(metalfit_materials::all.size(), metalfit::test::catalog_material_count() * metalfit::all_models().size());
    double worst = 0;
    for (const metalfit_materials::Entry& e : metalfit_materials::all) {
        SCOPED_TRACE(std::string(e.material) + " " + e.model);
        const metalfit::Model& model = metalfit::find_model(e.model);
        ASSERT_EQ(static_cast<std::size_t>(e.parameter_count), model.parameters().size());
        metalfit::ModelParameters p;
        for (int c = 0; c < 3; ++c)
            for (int i = 0; i < e.parameter_count; ++i) p[c].push_back((*e.parameters[i])[c]);
        for (int i = 0; i <= 2000; ++i) {
            const double mu = i / 2000.0;
            const metalfit_shader::vec3 header = e.evaluate(static_cast<float>(mu));
            const metalfit::RGB lib = model.evaluate(p, mu);
            const float h[3] = {header.x, header.y, header.z};
            for (int c = 0; c < 3; ++c) {
                const double d = std::abs(h[c] - lib[c]);
                worst = std::max(worst, d);
                ASSERT_LE(d, 1e-5) << "mu " << mu << " channel " << c;
            }
        }
    }
    std::printf("export cpp: worst |header (float) - libfit (double)| = %.3g over 2001 mu, every material and model\n",
                worst);
}

// Issue 12 item 3: the exported functions (the GLSL text) are defined at μ a hair outside [0, 1] and give the value at
// the end of the range (lazanyi-comp was NaN above 1; every model exceeded 1 below 0).
TEST(ExportCpp, MuOutsideTheUnitIntervalGivesTheEndValue) {
    const auto same = [](metalfit_shader::vec3 a, metalfit_shader::vec3 b) {
        return a.x == b.x && a.y == b.y && a.z == b.z;
    };
    for (const metalfit_materials::Entry& e : metalfit_materials::all) {
        SCOPED_TRACE(std::string(e.material) + " " + e.model);
        const metalfit_shader::vec3 at0 = e.evaluate(0.0f), at1 = e.evaluate(1.0f);
        EXPECT_TRUE(std::isfinite(at1.x) && std::isfinite(at1.y) && std::isfinite(at1.z));
        for (float mu : {std::nextafter(0.0f, -1.0f), -0.01f}) EXPECT_TRUE(same(e.evaluate(mu), at0)) << mu;
        for (float mu : {std::nextafter(1.0f, 2.0f), 1.0000001f, 1.01f}) EXPECT_TRUE(same(e.evaluate(mu), at1)) << mu;
        EXPECT_LE(std::max({at0.x, at0.y, at0.z}), 1.0f + 1e-6f);  // F(0) = 1
    }
}

TEST(ExportCpp, ConstantsAreTheRecordsWrittenParameters) {
    std::ifstream in(metalfit::test::kCatalogExportJson);
    const auto record = nlohmann::json::parse(in);
    for (const metalfit_materials::Entry& e : metalfit_materials::all) {
        const auto& written = record["materials"][e.material]["models"][e.model]["export"]["params"];
        const auto parameters = metalfit::find_model(e.model).parameters();
        for (int i = 0; i < e.parameter_count; ++i)
            for (int c = 0; c < 3; ++c)
                EXPECT_EQ((*e.parameters[i])[c], written[std::string(parameters[i].name)][c].get<double>())
                    << e.material << " " << e.model << " " << parameters[i].name;
    }
}

}  // namespace test_export_cpp
