// SPIR-V instruction counts per category (bench/spirv_cost.hpp): a hand-assembled module, a tiny compiled shader and
// the models' shaders.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "libfit/fit/model_cost.hpp"
#include "metalfit_bench/spirv_cost.hpp"
#include "metalfit_bench/subprocess.hpp"
#include "test_paths.hpp"

namespace test_bench_spirv {

using namespace metalfit::bench;

std::uint32_t op(std::uint32_t opcode, std::uint32_t words) { return (words << 16) | opcode; }

// A module by hand: OpExtInstImport "GLSL.std.450" as %1, a float type, and one function with an FMul, an FAdd,
// ext-inst Sqrt (transcendental) and FMax (arithmetic), an image sample, a load, a store and a return; a type
// declaration outside the function must not count.
std::vector<std::uint32_t> hand_module() {
    std::vector<std::uint32_t> w{0x07230203, 0x00010000, 0, 100, 0};
    std::uint32_t name[4] = {};
    std::memcpy(name, "GLSL.std.450", 12);
    w.insert(w.end(), {op(11, 6), 1, name[0], name[1], name[2], name[3]});  // OpExtInstImport %1 "GLSL.std.450"
    w.insert(w.end(), {op(22, 3), 2, 32});                                  // OpTypeFloat %2 32
    w.insert(w.end(), {op(54, 5), 3, 4, 0, 5});                             // OpFunction
    w.insert(w.end(), {op(248, 2), 6});                                     // OpLabel
    w.insert(w.end(), {op(61, 4), 2, 7, 8});                                // OpLoad
    w.insert(w.end(), {op(133, 5), 2, 9, 7, 7});                            // OpFMul
    w.insert(w.end(), {op(129, 5), 2, 10, 9, 7});                           // OpFAdd
    w.insert(w.end(), {op(12, 6), 2, 11, 1, 31, 10});                       // OpExtInst Sqrt
    w.insert(w.end(), {op(12, 7), 2, 12, 1, 40, 11, 7});                    // OpExtInst FMax
    w.insert(w.end(), {op(87, 5), 13, 14, 15, 16});                         // OpImageSampleImplicitLod
    w.insert(w.end(), {op(62, 3), 8, 12});                                  // OpStore
    w.insert(w.end(), {op(253, 1)});                                        // OpReturn
    w.insert(w.end(), {op(56, 1)});                                         // OpFunctionEnd
    return w;
}

TEST(SpirvCost, CountsAHandAssembledModuleByCategory) {
    const SpirvCounts c = count_spirv(hand_module());
    EXPECT_EQ(c.arithmetic, 3);      // FMul, FAdd, FMax
    EXPECT_EQ(c.transcendental, 1);  // Sqrt
    EXPECT_EQ(c.texture, 1);
    EXPECT_EQ(c.other, 3);  // load, store, return
    EXPECT_EQ(c.compute(), 5);
    EXPECT_EQ(c.weighted, 1 + 1 + 4 + 1 + 4);  // FMul, FAdd, Sqrt, FMax (scalar lanes), the sample
}

TEST(SpirvCost, RejectsMalformedModules) {
    std::vector<std::uint32_t> bad = hand_module();
    bad[0] = 0x12345678;
    EXPECT_THROW(count_spirv(bad), std::runtime_error);
    std::vector<std::uint32_t> truncated = hand_module();
    truncated.resize(truncated.size() - 2);  // drops the return and the function end
    truncated.push_back(op(129, 9));         // and ends with an FAdd that claims 9 words but has 1
    EXPECT_THROW(count_spirv(truncated), std::runtime_error);
    std::vector<std::uint32_t> zero = hand_module();
    zero.push_back(0);  // an instruction of length 0
    EXPECT_THROW(count_spirv(zero), std::runtime_error);
}

class CompiledSpirv : public ::testing::Test {
protected:
    void SetUp() override {
        validator_ = find_on_path("glslangValidator");
        if (!validator_) GTEST_SKIP() << "glslangValidator not installed (scripts/install-deps.sh installs it)";
    }
    std::optional<std::filesystem::path> validator_;
};

TEST_F(CompiledSpirv, ATinyShaderHasKnownCounts) {
    const std::string source = R"(#version 450
layout(location = 0) in float mu;
layout(location = 0) out vec4 color;
layout(binding = 0) uniform sampler1D lut;
void main() { color = vec4(sqrt(mu) + texture(lut, mu).rgb, 1.0); }
)";
    const SpirvCounts c = count_spirv(compile_fragment_shader(*validator_, source));
    EXPECT_EQ(c.transcendental, 1);
    EXPECT_EQ(c.texture, 1);
    EXPECT_EQ(c.arithmetic, 1);  // the vec3 + float (one instruction whatever the width)
    EXPECT_GT(c.other, 0);
}

TEST_F(CompiledSpirv, CompileErrorsNameTheCompiler) {
    try {
        compile_fragment_shader(*validator_, "#version 450\nvoid main() { undefined_function(); }\n");
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("glslangValidator failed"), std::string::npos) << e.what();
    }
}

TEST_F(CompiledSpirv, EveryModelCompilesAndCostsMoreThanTheWrapper) {
    const std::vector<SpirvRow> rows = spirv_costs(*validator_);
    ASSERT_EQ(rows.size(), metalfit::all_models().size() + 2);
    std::map<std::string, SpirvCounts> counts;
    for (const SpirvRow& r : rows) {
        ASSERT_TRUE(r.counts) << r.id << ": " << r.error;
        counts[r.id] = *r.counts;
    }
    EXPECT_EQ(counts["wrapper"].compute(), 0);
    EXPECT_EQ(counts["schlick"].transcendental, 0);        // (1 − μ)^5 by multiplication
    EXPECT_EQ(counts["lazanyi-comp"].transcendental, 1);   // pow(1 − μ, α)
    EXPECT_GE(counts["conductor-rgb"].transcendental, 2);  // square roots
    EXPECT_EQ(counts["reference-lut"].texture, 1);
    EXPECT_LT(counts["schlick"].compute(), counts["conductor-rgb"].compute());
    EXPECT_LT(counts["conductor-rgb"].compute(), counts["gulbrandsen"].compute());  // n, k from r, g first
}

// The weighted count (SpirvCounts::weighted): lanes × class weight, from the documented weights: a vec3 pow is 3 × 9,
// a vec3 × float multiply 3, a dot product of two vec3 3, a float division 5, a vec3 square root 3 × 4.
TEST_F(CompiledSpirv, TheWeightedCountCountsLanesAndWeighsClasses) {
    const auto weighted = [&](const std::string& expression) {
        const std::string source =
            "#version 450\nlayout(location = 0) in float mu;\nlayout(location = 0) out vec4 color;\n"
            "layout(std140, binding = 0) uniform P { vec3 p; vec3 q; };\n"
            "void main() { color = vec4(" +
            expression + ", 1.0); }\n";
        return count_spirv(compile_fragment_shader(*validator_, source)).weighted;
    };
    EXPECT_EQ(weighted("p"), 0);
    EXPECT_EQ(weighted("pow(p, q)"), 27);
    EXPECT_EQ(weighted("p * mu"), 3);
    EXPECT_EQ(weighted("vec3(dot(p, q))"), 3);
    EXPECT_EQ(weighted("vec3(p.x / mu)"), 5);
    EXPECT_EQ(weighted("sqrt(p)"), 12);
}

// data/model-costs.json (libfit's built-in cost table) holds the counts the bench computes for every registered
// model, plain and weighted, so that a model's GLSL cannot change without the table being measured again.
TEST_F(CompiledSpirv, TheMeasuredCostTableHasTheBenchCounts) {
    std::ifstream in(std::filesystem::path(metalfit::test::kDataDir) / "model-costs.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    std::map<std::string, std::pair<int, double>> file;
    for (const auto& m : j["models"]) file[m["model"]] = {m["spirv_ops"].get<int>(), m["spirv_weighted"].get<double>()};
    for (const SpirvRow& r : spirv_costs(*validator_)) {
        ASSERT_TRUE(r.counts) << r.id << ": " << r.error;
        if (r.id == "wrapper" || r.id == "reference-lut") continue;
        ASSERT_TRUE(file.count(r.id)) << r.id << " is missing from data/model-costs.json";
        EXPECT_EQ(file[r.id].first, r.counts->compute()) << r.id << ": run scripts/measure-model-costs.sh";
        EXPECT_EQ(file[r.id].second, r.counts->weighted) << r.id << ": run scripts/measure-model-costs.sh";
    }
    EXPECT_EQ(file.size(), metalfit::all_models().size());
}

}  // namespace test_bench_spirv
