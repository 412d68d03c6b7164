// glpreview takes any number of model parameters: a test-only model with 6 parameters per channel (more than any
// registered model has) renders through the renderer, and every pixel equals the model's C++ evaluation at that
// pixel's μ, computed here from the camera and the sphere, independently of the shader.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "glpreview/gl/gl_context.hpp"
#include "glpreview/render/features.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "glpreview/render/sphere_shader.hpp"
#include "glpreview/scene/camera.hpp"
#include "libfit/models/model.hpp"

namespace metalfit::glpreview {
namespace test_preview_model_parameters {

// F(μ) = Σ_k p_k (1 − μ)^k, k = 0..5: every parameter weighs differently at each μ.
class SixParameterModel final : public Model {
public:
    std::string_view id() const override { return "test-six"; }
    std::string_view title() const override { return "a test-only polynomial in 1 − μ with 6 parameters"; }
    std::span<const Parameter> parameters() const override { return parameters_; }
    double evaluate(std::span<const double> p, double mu) const override { return horner<double>(p, mu); }
    float evaluate(std::span<const float> p, float mu) const override { return horner<float>(p, mu); }
    void evaluate(std::span<const double> p, std::span<const double> mu, std::span<double> out) const override {
        for (std::size_t i = 0; i < mu.size(); ++i) out[i] = horner<double>(p, mu[i]);
    }
    std::vector<ClosedForm> closed_forms(const ClosedFormInput&) const override { return {}; }
    std::vector<ChannelParameters> neutral_starts() const override { return {}; }
    std::vector<ChannelParameters> target_starts(const ChannelTarget&) const override { return {}; }
    ChannelFit fit(const ChannelTarget&, std::span<const NamedStart>, const ChannelConstraints&) const override {
        throw std::logic_error("the test model is not fitted");
    }
    bool can_pin_f0() const override { return false; }
    std::size_t pinned_parameter() const override { return 0; }
    void pin_f0(std::span<double>, double) const override {}
    std::string_view glsl_function() const override { return "test_six"; }
    std::string glsl_source() const override {
        return "vec3 test_six(vec3 p0, vec3 p1, vec3 p2, vec3 p3, vec3 p4, vec3 p5, float mu) {\n"
               "    float x = 1.0 - mu;\n"
               "    return p0 + x * (p1 + x * (p2 + x * (p3 + x * (p4 + x * p5))));\n"
               "}\n";
    }
    std::span<const std::string_view> glsl_files() const override { return {}; }
    std::optional<ChannelParameters> f82_tint_of(std::span<const double>) const override { return std::nullopt; }
    bool is_f82_tint_curve() const override { return false; }
    MaterialxForm materialx_form() const override { return MaterialxForm::stand_in; }
    std::string_view materialx_stand_in_reason() const override { return "a test model"; }

private:
    template <class T>
    static T horner(std::span<const T> p, T mu) {
        const T x = T(1) - mu;
        return p[0] + x * (p[1] + x * (p[2] + x * (p[3] + x * (p[4] + x * p[5]))));
    }
    std::array<Parameter, 6> parameters_{{{"p0", 0, 1, "constant", ParameterKind::shape},
                                          {"p1", -1, 1, "linear", ParameterKind::shape},
                                          {"p2", -1, 1, "quadratic", ParameterKind::shape},
                                          {"p3", -1, 1, "cubic", ParameterKind::shape},
                                          {"p4", -1, 1, "quartic", ParameterKind::shape},
                                          {"p5", -1, 1, "quintic", ParameterKind::shape}}};
};

GlContext& gl() {
    static GlContext context = GlContext::create();
    return context;
}

// A sphere in a sphere room of one radiance (0.5, exact in the half-float cube): each pixel is F(μ) · 0.5.
Scene uniform_room_scene() {
    Scene scene;
    scene.file = "six-parameters.json";
    scene.width = scene.height = 96;
    scene.environment.type = EnvironmentType::sphere_room;
    scene.environment.sphere_room.light = scene.environment.sphere_room.dark = RGB{0.5, 0.5, 0.5};
    scene.environment.cube_size = 32;
    Sphere sphere;
    sphere.center = {0, 1.0, 0};
    sphere.radius = 0.8;
    sphere.reflection = ReflectionMode::classic;
    sphere.fresnel = ModelFresnel{"test-six", ParameterSource::fit};
    scene.spheres = {sphere};
    scene.camera.position = {0, 1.0, 3.0};
    scene.camera.look_at = {0, 1.0, 0};
    return scene;
}

SphereFresnel six_parameter_fresnel(const Model& model, double p5) {
    SphereFresnel f;
    f.material = "test";
    f.fresnel = "test-six";
    f.model = &model;
    f.set_parameters(
        {{0.9, -0.3, 0.2, -0.1, 0.05, p5}, {0.6, 0.1, -0.2, 0.3, -0.15, p5}, {0.3, 0.4, 0.1, -0.2, 0.25, -p5}});
    return f;
}

TEST(PreviewModelParameters, SixParametersRenderAsTheModelsCppEvaluation) {
    gl();
    const SixParameterModel model;
    const Scene scene = uniform_room_scene();
    const SphereFresnel fresnel = six_parameter_fresnel(model, 0.3);
    const std::string variant = sphere_shader(scene, scene.spheres[0], &fresnel).text();
    EXPECT_NE(variant.find("#define FRESNEL_PARAMETERS 6"), std::string::npos);

    GpuRenderer gpu(scene, plan_features(scene), {&fresnel}, nullptr);
    gpu.capture_environment();
    const Image image = gpu.render();

    const CameraBasis basis = camera_basis(scene.camera, scene.width, scene.height);
    const Sphere& sphere = scene.spheres[0];
    int compared = 0;
    double worst = 0;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
            const Vec3 d =
                camera_ray(basis, x, scene.height - 1 - y, scene.width, scene.height);  // image rows run down
            const Vec3 oc = basis.position - sphere.center;
            const double b = dot(oc, d), h = b * b - (dot(oc, oc) - sphere.radius * sphere.radius);
            if (h < 0) continue;
            const Vec3 n = (1.0 / sphere.radius) * (basis.position + (-b - std::sqrt(h)) * d - sphere.center);
            const double mu = -dot(d, n);
            if (mu < 0.05) continue;  // the silhouette: the GPU's float ray may miss where this one hits
            const RGB expected = fresnel(mu);
            const RGB got = image.at(x, y);
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(got[c] - 0.5 * expected[c]));
            ++compared;
        }
    EXPECT_GT(compared, 1000);
    EXPECT_LT(worst, 2e-4);

    // The sixth parameter reaches the shader: another value of it renders another image.
    const SphereFresnel other = six_parameter_fresnel(model, -0.3);
    gpu.set_fresnel(0, &other);
    const Image changed = gpu.render();
    double largest_change = 0;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x)
            for (int c = 0; c < 3; ++c)
                largest_change = std::max(largest_change, std::abs(changed.at(x, y)[c] - image.at(x, y)[c]));
    EXPECT_GT(largest_change, 0.05);
}

TEST(PreviewModelParameters, ParametersSetWithoutTheirFloatValuesAreRefused) {
    const SixParameterModel model;
    SphereFresnel f;
    f.model = &model;
    f.parameters = ModelParameters({1, 0, 0, 0, 0, 0}, {1, 0, 0, 0, 0, 0}, {1, 0, 0, 0, 0, 0});
    EXPECT_THROW(f(0.5), std::logic_error);
}

}  // namespace test_preview_model_parameters
}  // namespace metalfit::glpreview
