// The model registry (libfit/models/registry.hpp): typed tests over every registered model, derived from the one
// list, and the compile-time trait checks that make a model without an exporter's trait fail to build.
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "libfit/models/registry.hpp"

namespace metalfit {
namespace test_model_registry {

template <class List>
struct GtestTypes;
template <class... M>
struct GtestTypes<ModelList<M...>> {
    using type = ::testing::Types<M...>;
};

template <class M>
class EveryModel : public ::testing::Test {};
TYPED_TEST_SUITE(EveryModel, GtestTypes<Registry>::type);

// Parameter sets inside the bounds of M: its neutral starts and points at a quarter and three quarters of each
// parameter's range (clamped to a finite, moderate span so that n, k up to 1e4 stay meaningful).
template <class M>
std::vector<ChannelParameters> sample_parameters() {
    std::vector<ChannelParameters> sets = M::neutral_starts();
    for (double t : {0.25, 0.75}) {
        ChannelParameters p;
        for (const Parameter& q : M::kParameters) {
            const double upper = std::min(q.upper, q.lower + 10.0);
            p.push_back(q.lower + t * (upper - q.lower));
        }
        sets.push_back(p);
    }
    return sets;
}

TYPED_TEST(EveryModel, TheRuntimeModelIsTheStruct) {
    using M = TypeParam;
    const Model& model = model_of<M>();
    EXPECT_EQ(model.id(), M::kId);
    EXPECT_EQ(model.title(), M::kTitle);
    ASSERT_EQ(model.parameters().size(), M::kParameters.size());
    EXPECT_EQ(model.materialx_form(), M::kMaterialx);
    EXPECT_EQ(model.is_f82_tint_curve(), F82TintCurve<M>);
    for (const ChannelParameters& p : sample_parameters<M>())
        for (double mu : {0.0, 0.1, 0.5, 0.9, 1.0})
            EXPECT_EQ(model.evaluate(std::span<const double>(p), mu), M::evaluate(p.data(), mu)) << mu;
    // Over an array of μ (what the metrics evaluate): the values one at a time, bit for bit.
    std::vector<double> mu{-0.1, 0.0, 1e-9, 1.0 / 3.0, 0.999, 1.0, 1.5};
    for (int i = 0; i <= 1024; ++i) mu.push_back(i / 1024.0);
    for (const ChannelParameters& p : sample_parameters<M>()) {
        std::vector<double> out(mu.size(), -7.0);
        model.evaluate(std::span<const double>(p), mu, out);
        for (std::size_t i = 0; i < mu.size(); ++i) {
            const double one = M::evaluate(p.data(), mu[i]);
            EXPECT_TRUE(out[i] == one || (std::isnan(out[i]) && std::isnan(one))) << "mu=" << mu[i];
        }
    }
    std::vector<double> short_out(2);
    EXPECT_THROW(model.evaluate(std::span<const double>(sample_parameters<M>()[0]), mu, short_out), std::logic_error);
    // Its GLSL defines the function the model names.
    EXPECT_NE(model.glsl_source().find("vec3 " + std::string(M::kGlslFunction) + "("), std::string::npos);
    // Its WGSL (the .wgsl beside each of its GLSL files) defines it too, and every function the GLSL defines.
    const Model* self = &model;
    const std::string wgsl = wgsl_library(std::span<const Model* const>(&self, 1));
    EXPECT_NE(wgsl.find("fn " + std::string(M::kGlslFunction) + "("), std::string::npos);
    const std::string glsl = "\n" + model.glsl_source();
    for (std::size_t at = glsl.find("\nvec3 "); at != std::string::npos; at = glsl.find("\nvec3 ", at + 1)) {
        const std::string name = glsl.substr(at + 6, glsl.find('(', at) - at - 6);
        EXPECT_NE(wgsl.find("fn " + name + "("), std::string::npos) << name << " has no WGSL";
    }
}

// Where a model gives its gradient in closed form (AnalyticGradient), the fits use it as their Jacobian instead of
// autodiff: value and every derivative must be what Ceres's Jets compute, to the bit, so that the fits take the path
// autodiff takes (NaN where the Jets give NaN: α < 1 at μ = 1). A model that states kGradientTolerance has a closed
// form of its own: its value is evaluate's, its derivatives the Jets' within that fraction of the largest one.
template <class M>
constexpr double gradient_tolerance() {
    if constexpr (requires { M::kGradientTolerance; }) return M::kGradientTolerance;
    return 0.0;
}

TYPED_TEST(EveryModel, AnalyticGradientIsAutodiffs) {
    using M = TypeParam;
    if constexpr (!AnalyticGradient<M>) {
        GTEST_SKIP() << M::kId << " is fitted with autodiff";
    } else {
        constexpr int N = static_cast<int>(M::kParameters.size());
        using Jet = ceres::Jet<double, N>;
        const auto same = [](double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; };
        std::vector<ChannelParameters> sets = sample_parameters<M>();
        sets.push_back(ChannelParameters(N, 0.0));
        for (int i = 0; i < N; ++i) sets.back()[i] = M::kParameters[i].lower;  // α at its lower bound 0.05 < 1
        int checked = 0;
        for (const ChannelParameters& p : sets)
            for (double mu : {0.0, 1e-6, 0.013, 0.25, 0.5, 0.77, 0.999, 1.0, -0.1, 1.1}) {
                std::array<Jet, N> q;
                for (int i = 0; i < N; ++i) q[i] = Jet(p[i], i);
                const Jet F = M::evaluate(q.data(), Jet(mu));
                std::array<double, N> g{};
                const double value = M::evaluate_with_gradient(p.data(), model_math::CurveNode::at(mu), g.data());
                constexpr double tolerance = gradient_tolerance<M>();
                if constexpr (tolerance == 0.0) {
                    EXPECT_TRUE(same(value, F.a)) << M::kId << " mu=" << mu << ": " << value << " against " << F.a;
                } else {
                    EXPECT_TRUE(same(value, M::evaluate(p.data(), mu))) << M::kId << " mu=" << mu;
                    EXPECT_NEAR(value, F.a, 1e-15 * std::abs(F.a)) << M::kId << " mu=" << mu;
                }
                // Below μ = 10⁻³ the Jets lose digits as 1/μ (their derivatives are differences of O(1) terms that
                // are O(μ)): the tolerance follows. Where every derivative vanishes (μ = 0, F = 1) the Jets give
                // rounding (their division takes a·(1/b)): the scale is then a thousandth of the value.
                double scale = 1e-3 * std::abs(F.a);
                for (int i = 0; i < N; ++i) scale = std::max(scale, std::abs(F.v[i]));
                if (const double m = model_math::clamp_mu(mu); m > 0.0 && m < 1e-3) scale *= 1e-3 / m;
                for (int i = 0; i < N; ++i)
                    EXPECT_TRUE(tolerance == 0.0 ? same(g[i], F.v[i]) : std::abs(g[i] - F.v[i]) <= tolerance * scale)
                        << M::kId << " d/d" << M::kParameters[i].name << " mu=" << mu << ": " << g[i] << " against "
                        << F.v[i];
                ++checked;
            }
        EXPECT_GT(checked, 0);
    }
}

TYPED_TEST(EveryModel, GrazingIsOneAndFloatAgreesWithDouble) {
    // F(0) = 1 is built into every model (docs/colour.md, "White balance"); the float overload (what shaders and the bench evaluate) follows
    // the double one to float precision on curves of order 1.
    using M = TypeParam;
    for (const ChannelParameters& p : sample_parameters<M>()) {
        EXPECT_NEAR(M::evaluate(p.data(), 0.0), 1.0, 1e-12);
        const std::vector<float> pf(p.begin(), p.end());
        const ChannelParameters pd(pf.begin(), pf.end());
        for (int i = 0; i <= 32; ++i) {
            const float mu = static_cast<float>(i) / 32.0f;
            const double exact = M::evaluate(pd.data(), static_cast<double>(mu));
            EXPECT_NEAR(M::evaluate(pf.data(), mu), exact, 1e-4 * std::max(1.0, std::abs(exact))) << "mu=" << mu;
        }
    }
}

// Issue 12 item 3: a cosine a hair outside [0, 1] (dot(N, V) = 1.0000001 is routine) gives the value at the end of
// the range, in double, in float (what the shaders and exports compute) and through the runtime model: never NaN,
// never above 1 where the curve at the ends is in [0, 1].
TYPED_TEST(EveryModel, MuOutsideTheUnitIntervalGivesTheValueAtItsEnd) {
    using M = TypeParam;
    for (const ChannelParameters& p : sample_parameters<M>()) {
        const std::vector<float> pf(p.begin(), p.end());
        const double at0 = M::evaluate(p.data(), 0.0), at1 = M::evaluate(p.data(), 1.0);
        const float at0f = M::evaluate(pf.data(), 0.0f), at1f = M::evaluate(pf.data(), 1.0f);
        for (double mu : {std::nextafter(0.0, -1.0), -1e-7, -0.01, -1.0})
            EXPECT_EQ(M::evaluate(p.data(), mu), at0) << "mu=" << mu;
        for (double mu : {std::nextafter(1.0, 2.0), 1.0000001, 1.01, 2.0})
            EXPECT_EQ(M::evaluate(p.data(), mu), at1) << "mu=" << mu;
        for (float mu : {std::nextafter(0.0f, -1.0f), -0.01f})
            EXPECT_EQ(M::evaluate(pf.data(), mu), at0f) << "mu=" << mu;
        for (float mu : {std::nextafter(1.0f, 2.0f), 1.01f}) EXPECT_EQ(M::evaluate(pf.data(), mu), at1f) << "mu=" << mu;
        EXPECT_EQ(model_of<M>().evaluate(std::span<const double>(p), 1.01), at1);
        EXPECT_TRUE(std::isfinite(at1f) || !std::isfinite(at1));
        // Just inside the ends the curve moves continuously from the end values (no kink hidden by the clamp).
        EXPECT_NEAR(M::evaluate(p.data(), std::nextafter(1.0, 0.0)), at1, 1e-6 * std::max(1.0, std::abs(at1)));
    }
    // The GLSL function clamps too (the HLSL and C++ exports are its mechanical translations).
    EXPECT_NE(model_of<M>().glsl_source().find("mu = mu < 0.0 ? 0.0 : (mu > 1.0 ? 1.0 : mu);"), std::string::npos);
}

TYPED_TEST(EveryModel, AppearsOnceInTheRuntimeList) {
    int found = 0;
    for (const Model* m : all_models()) found += m->id() == TypeParam::kId;
    EXPECT_EQ(found, 1);
    EXPECT_EQ(all_models().size(), Registry::size);
}

TYPED_TEST(EveryModel, F82TintMappingIsTheSameCurve) {
    using M = TypeParam;
    const Model& model = model_of<M>();
    for (const ChannelParameters& p : sample_parameters<M>()) {
        const std::optional<ChannelParameters> f82 = model.f82_tint_of(p);
        if constexpr (!F82TintCurve<M>) {
            EXPECT_FALSE(f82.has_value());
        } else {
            ASSERT_TRUE(f82.has_value());
            ASSERT_EQ(f82->size(), 2u);
            // Evaluated by the F82-tint model, the mapped parameters give the model's own curve.
            for (int i = 0; i <= 64; ++i) {
                const double mu = i / 64.0;
                EXPECT_NEAR(models::F82Tint::evaluate(f82->data(), mu), M::evaluate(p.data(), mu), 1e-12)
                    << "mu=" << mu;
            }
        }
    }
}

TYPED_TEST(EveryModel, StandInReasonIsGivenExactlyWhenMaterialxCannotExpressTheModel) {
    const Model& model = model_of<TypeParam>();
    EXPECT_EQ(model.materialx_form() == MaterialxForm::stand_in, !model.materialx_stand_in_reason().empty());
}

TEST(ModelRegistry, TheStandInModelCanBeWrittenNatively) {
    // What the exporters write in place of a model MaterialX or OpenPBR cannot express must itself be expressible.
    EXPECT_EQ(StandInModel::kMaterialx, MaterialxForm::generalized_schlick);
    EXPECT_TRUE(F82TintCurve<StandInModel>);
}

// A model defined only here, as a new family would be: Schlick with a free exponent, F0 + (1 − F0)(1 − μ)^p. It
// is complete (it passes every trait check) and would be registered with one line in Registry.
struct FreeExponentSchlick {
    static constexpr std::string_view kId = "schlick-p";
    static constexpr std::string_view kTitle = "Schlick with a free exponent (test model)";
    static constexpr std::array<Parameter, 2> kParameters{{
        {"F0", -1.0, 2.0, "reflectance at normal incidence", ParameterKind::colour},
        {"p", 1.0, 10.0, "exponent", ParameterKind::shape},
    }};
    static constexpr std::string_view kGlslFunction = "metalfit_schlick_p";
    static constexpr std::array<std::string_view, 1> kGlslFiles{"schlick_p"};
    static constexpr MaterialxForm kMaterialx = MaterialxForm::stand_in;
    static constexpr std::string_view kMaterialxStandIn =
        "generalized_schlick_bsdf's exponent is a scalar, p is per channel";
    template <class T>
    static T evaluate(const T* p, const T& mu) {
        using std::pow;
        return p[0] + (T(1) - p[0]) * pow(T(1) - mu, p[1]);
    }
    static std::vector<ClosedForm> closed_forms(const ClosedFormInput&) { return {}; }
    static std::vector<ChannelParameters> neutral_starts() { return {{0.5, 5.0}}; }
};
static_assert(ModelDefinition<FreeExponentSchlick>);
static_assert(check_model_traits<FreeExponentSchlick>());
static_assert(check_registry(ModelList<models::Schlick, FreeExponentSchlick>{}));

// Without its MaterialX form a model is not a ModelDefinition: check_model_traits<> (and so the registry) rejects it
// at compile time.
struct WithoutMaterialxForm {
    static constexpr std::string_view kId = "x";
    static constexpr std::string_view kTitle = "x";
    static constexpr std::array<Parameter, 1> kParameters{{{"F0", 0.0, 1.0, "F0", ParameterKind::colour}}};
    static constexpr std::string_view kGlslFunction = "metalfit_x";
    static constexpr std::array<std::string_view, 1> kGlslFiles{"x"};
    template <class T>
    static T evaluate(const T* p, const T&) {
        return p[0];
    }
    static std::vector<ClosedForm> closed_forms(const ClosedFormInput&) { return {}; }
    static std::vector<ChannelParameters> neutral_starts() { return {{0.5}}; }
};
static_assert(!ModelDefinition<WithoutMaterialxForm>);
// A model written as generalized_schlick_bsdf must map to F82-tint.
struct ClaimsGeneralizedSchlick : WithoutMaterialxForm {
    static constexpr MaterialxForm kMaterialx = MaterialxForm::generalized_schlick;
};
static_assert(ModelDefinition<ClaimsGeneralizedSchlick> && !F82TintCurve<ClaimsGeneralizedSchlick>);

TEST(ModelRegistry, TheTestModelEvaluatesItsOwnCurve) {
    // The test model above is a model, not only a type that compiles: F(0) = 1, F(1) = F0, p = 5 is Schlick.
    const double p[2] = {0.3, 5.0};
    EXPECT_DOUBLE_EQ(FreeExponentSchlick::evaluate(p, 0.0), 1.0);
    EXPECT_DOUBLE_EQ(FreeExponentSchlick::evaluate(p, 1.0), 0.3);
    for (double mu : {0.1, 0.4, 0.8})
        EXPECT_NEAR(FreeExponentSchlick::evaluate(p, mu), models::Schlick::evaluate(p, mu), 1e-15);
}

}  // namespace test_model_registry
}  // namespace metalfit
