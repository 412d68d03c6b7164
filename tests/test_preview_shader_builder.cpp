// The program builder the effects declare into, the frame blackboard they share, and the sphere shader the
// registered effects assemble: units, names and texts checked without a renderer, the link check with GL.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>

#include "glpreview/gl/gl_context.hpp"
#include "glpreview/gl/program_cache.hpp"
#include "glpreview/render/blackboard.hpp"
#include "glpreview/render/shader_builder.hpp"
#include "glpreview/render/sphere_shader.hpp"
#include "libfit/models/model.hpp"

namespace metalfit::glpreview {
namespace test_preview_shader_builder {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(ShaderBuilder, AssignsUnitsInDeclarationOrderOncePerSampler) {
    ShaderBuilder b("test");
    b.sampler("u_a").sampler("u_b").sampler("u_a").sampler("u_c");
    EXPECT_EQ(b.samplers(), (std::vector<std::string>{"u_a", "u_b", "u_c"}));
    const BuiltProgram program(0, b.samplers());
    EXPECT_EQ(program.unit("u_a"), 0);
    EXPECT_EQ(program.unit("u_c"), 2);
    EXPECT_THROW(program.unit("u_missing"), std::logic_error);
    EXPECT_TRUE(program.reads("u_b"));
    EXPECT_FALSE(program.reads("u_d"));
}

TEST(ShaderBuilder, NamesTheVariantBySortedLabelsAndAddsASharedSourceOnce) {
    ShaderBuilder b("sphere");
    b.define("ZED")
        .define("NITER", "8")
        .define("ALPHA")
        .source("float f();\n")
        .source("float g();\n")
        .source("float f();\n");
    EXPECT_EQ(b.labels(), (std::vector<std::string>{"ALPHA", "NITER 8", "ZED"}));
    EXPECT_EQ(b.key(), "sphere ALPHA NITER 8 ZED");
    const std::string text = b.text();
    EXPECT_EQ(text.rfind("#version 450 core\n", 0), 0u);
    EXPECT_TRUE(contains(text, "#define NITER 8\n"));
    EXPECT_EQ(text.find("float f();"), text.rfind("float f();"));  // once
    EXPECT_LT(text.find("float f();"), text.find("float g();"));   // in order
}

TEST(ShaderBuilder, TheModelIsATypedChoiceWithItsParameterCount) {
    const Model& model = find_model("f82-tint");
    ShaderBuilder b("sphere");
    b.source("// before\n").fresnel_model("f82-tint", &model).source("// after\n");
    EXPECT_EQ(b.labels(), (std::vector<std::string>{"FRESNEL_MODEL f82-tint"}));
    const std::string text = b.text();
    EXPECT_TRUE(contains(text, "#define FRESNEL_MODEL\n"));
    EXPECT_TRUE(contains(text, "#define FRESNEL_PARAMETERS " + std::to_string(model.parameters().size()) + "\n"));
    EXPECT_TRUE(
        contains(text, "#define FRESNEL_CALL " + std::string(model.glsl_function()) + "(u_param[0], u_param[1], mu)"));
    // The model's GLSL where it was chosen: after what came before, before what follows.
    const auto at = text.find(std::string(model.glsl_function()) + "(vec3");
    ASSERT_NE(at, std::string::npos);
    EXPECT_LT(text.find("// before"), at);
    EXPECT_GT(text.find("// after"), at);

    ShaderBuilder unresolved("sphere");
    unresolved.fresnel_model("f82-tint", nullptr);
    EXPECT_EQ(unresolved.key(), "sphere FRESNEL_MODEL f82-tint");  // planning names it
    EXPECT_THROW(unresolved.text(), std::logic_error);             // but cannot write it
    ShaderBuilder mismatch("sphere");
    EXPECT_THROW(mismatch.fresnel_model("schlick", &model), std::logic_error);
}

TEST(ShaderBuilder, TheLobeIsReplacedAndAddedTermsAreSummedOrAbsent) {
    ShaderBuilder b("sphere");
    EXPECT_FALSE(contains(b.radiance("mirror()").text(), "SPHERE_ADDED_RADIANCE"));
    b.radiance("glossy()").add_radiance("a()").add_radiance("b()");
    const std::string text = b.text();
    EXPECT_TRUE(contains(text, "#define SPHERE_RADIANCE glossy()\n"));
    EXPECT_FALSE(contains(text, "mirror()"));
    EXPECT_TRUE(contains(text, "#define SPHERE_ADDED_RADIANCE (a() + b())\n"));
}

TEST(Blackboard, ValuesByTypeAndNameAndStateMadeOnce) {
    Blackboard board;
    const int four = 4, eight = 8;
    const double half = 0.5;
    board.put(four, "4");
    board.put(eight, "8");
    board.put(half);
    EXPECT_EQ(*board.find<int>("4"), 4);
    EXPECT_EQ(*board.find<int>("8"), 8);
    EXPECT_EQ(board.find<int>(), nullptr);  // a name is part of the key
    EXPECT_EQ(board.get<double>("half"), 0.5);
    EXPECT_EQ(board.find<float>(), nullptr);  // and so is the type
    try {
        board.get<float>("the float");
        FAIL() << "expected a logic_error";
    } catch (const std::logic_error& e) {
        EXPECT_TRUE(contains(e.what(), "the float")) << e.what();
    }
    board.state<std::vector<int>>().push_back(1);
    board.state<std::vector<int>>().push_back(2);
    EXPECT_EQ(board.state<std::vector<int>>().size(), 2u);
}

Scene one_sphere_scene(Sphere sphere) {
    Scene scene;
    scene.environment.type = EnvironmentType::room;
    scene.spheres = {sphere};
    return scene;
}

TEST(SphereShader, TheRegisteredEffectsNameEachVariant) {
    Sphere mirror;
    mirror.reflection = ReflectionMode::classic;
    const Scene a = one_sphere_scene(mirror);
    EXPECT_EQ(sphere_shader(a, a.spheres[0], nullptr).labels(),
              (std::vector<std::string>{"ENV_ROOM", "FRESNEL_REFERENCE", "REFLECTION_CLASSIC"}));

    Sphere rough;
    rough.roughness = 0.4;
    rough.fresnel = ModelFresnel{"lazanyi", ParameterSource::fit};
    const Scene b = one_sphere_scene(rough);
    const ShaderBuilder prefiltered = sphere_shader(b, b.spheres[0], nullptr);
    const auto labels = prefiltered.labels();
    for (const char* expected : {"ENV_ROOM", "FRESNEL_MODEL lazanyi", "GLOSSY_PREFILTERED",
                                 "REFLECTION_DISTANCE_IMPOSTOR", "STRATEGY_ILLINOIS", "NITER 8", "TOLERANCE 0.0001"})
        EXPECT_NE(std::find(labels.begin(), labels.end(), expected), labels.end()) << expected;
    EXPECT_EQ(prefiltered.samplers(), (std::vector<std::string>{"u_env", "u_prefiltered", "u_dfg"}));

    rough.glossy = GlossyMethod::localized;
    const Scene c = one_sphere_scene(rough);
    const ShaderBuilder localized = sphere_shader(c, c.spheres[0], nullptr, true);
    const auto local_labels = localized.labels();
    EXPECT_NE(std::find(local_labels.begin(), local_labels.end(), "GLOSSY_LOCALIZED"), local_labels.end());
    EXPECT_NE(std::find(local_labels.begin(), local_labels.end(), "LOCALIZATION_DIAGNOSTICS"), local_labels.end());
    const std::set<std::string> samplers(localized.samplers().begin(), localized.samplers().end());
    EXPECT_EQ(samplers.size(), localized.samplers().size());  // one unit each
    EXPECT_TRUE(samplers.count("u_area_radiance") && samplers.count("u_area_position"));
}

TEST(ShaderBuilderGl, ALinkedProgramThatReadsAnUndeclaredSamplerIsRefused) {
    GlContext context = GlContext::create();
    ProgramCache cache;
    ShaderBuilder declared("declared");
    declared
        .source("uniform sampler2D u_a;\nuniform sampler2D u_b;\nout vec4 c;\n"
                "void main() { c = texture(u_a, vec2(0.5)) + texture(u_b, vec2(0.5)); }\n")
        .sampler("u_a")
        .sampler("u_b");
    const BuiltProgram program = link(cache, declared);
    GLint unit = -1;
    glGetUniformiv(program.id(), glGetUniformLocation(program.id(), "u_b"), &unit);
    EXPECT_EQ(unit, 1);

    ShaderBuilder undeclared("undeclared");
    undeclared
        .source("uniform sampler2D u_a;\nuniform samplerCube u_hidden;\nout vec4 c;\n"
                "void main() { c = texture(u_a, vec2(0.5)) + texture(u_hidden, vec3(1.0)); }\n")
        .sampler("u_a");
    EXPECT_THROW(link(cache, undeclared), std::logic_error);
}

}  // namespace test_preview_shader_builder
}  // namespace metalfit::glpreview
