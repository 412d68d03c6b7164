// Cheap Fresnel models: each checked against an independent form written here (the complex-form exact Fresnel,
// the published formulas: docs/fitting.md, "Models", and docs/references.md), against finite differences (Ceres Jets), and its GLSL text parsed.
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <map>
#include <regex>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "libfit/base/errors.hpp"
#include "libfit/base/quadrature.hpp"
#include "libfit/models/lazanyi_comp/lazanyi_comp.hpp"
#include "libfit/models/model.hpp"
#include "libfit/models/registry.hpp"
#include "libfit/optics/fresnel.hpp"
#include "test_support.hpp"

namespace metalfit {
namespace test_models {

using C = std::complex<double>;
using Params = std::vector<double>;

// ---- independent forms (docs/fitting.md, "Models"), written without the library's helpers ----

double schlick(double f0, double mu) { return f0 + (1.0 - f0) * std::pow(1.0 - mu, 5.0); }

double normal_incidence(double n, double k) { return ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k); }

// Lazányi's compensated form, eq. 3.3: F*(μ) − a μ (1 − μ)^α with F* from eq. 3.2.
double lazanyi_comp(double n, double k, double a, double alpha, double mu) {
    const double fstar = ((n - 1) * (n - 1) + k * k + 4.0 * n * std::pow(1.0 - mu, 5.0)) / ((n + 1) * (n + 1) + k * k);
    return fstar - a * mu * std::pow(1.0 - mu, alpha);
}

double eval(const Model& m, const Params& p, double mu) { return m.evaluate(std::span<const double>(p), mu); }
float eval_f(const Model& m, const std::vector<float>& p, float mu) {
    return m.evaluate(std::span<const float>(p), mu);
}

// μ = 0, 1e-6, 1e-3, 0.01, 0.02, …, 1.
std::vector<double> mu_grid() {
    std::vector<double> mus{0.0, 1e-6, 1e-3};
    for (int i = 1; i <= 100; ++i) mus.push_back(i / 100.0);
    return mus;
}

// Typical parameters of each model (a metal-like channel and, where it makes sense, a dielectric-like one).
const std::map<std::string, std::vector<Params>>& typical_params() {
    static const std::map<std::string, std::vector<Params>> kTypical{
        {"schlick", {{0.04}, {0.56}, {0.95}, {1.06}}},
        {"lazanyi", {{0.2, 3.0}, {1.5, 0.0}, {0.05, 8.0}, {2.9, 3.0}}},
        {"lazanyi-comp", {{0.2, 3.0, 0.3, 6.0}, {1.5, 0.0, -0.2, 2.0}, {0.05, 8.0, 1.5, 0.5}}},
        {"f82-tint", {{0.9, 0.8}, {0.56, 1.0}, {1.06, 1.2}, {0.04, 0.5}}},
        {"conductor-rgb", {{0.2, 3.0}, {1.5, 0.0}, {0.05, 8.0}, {2.9, 3.0}, {0.5, 0.0}}},
        {"gulbrandsen", {{0.9, 0.5}, {0.04, 0.0}, {0.56, 0.9}, {0.99, 0.2}}},
    };
    return kTypical;
}

// The model's reflectance at normal incidence, from its parameters, by the model's own definition.
double expected_at_normal_incidence(const std::string& id, const Params& p) {
    if (id == "schlick" || id == "f82-tint") return p[0];
    if (id == "lazanyi" || id == "lazanyi-comp") return normal_incidence(p[0], p[1]);
    if (id == "conductor-rgb") return fresnel_normal_incidence({p[0], p[1]});
    if (id == "gulbrandsen") return p[0];
    ADD_FAILURE() << "no normal-incidence value for model " << id;
    return 0.0;
}

// ---- 1. limits ----

// The models of the thesis, the renderers and the papers with hand-picked parameters and their F(1) by their own
// definitions; what holds for every registered model (F(0) = 1, float against double) is in test_model_registry.cpp.
TEST(Models, GrazingIsOneAndNormalIncidenceIsTheModelsF0) {
    for (const auto& [id, sets] : typical_params()) {
        const Model* m = &find_model(id);
        for (const Params& p : sets) {
            ASSERT_EQ(p.size(), m->parameters().size()) << id;
            EXPECT_NEAR(eval(*m, p, 0.0), 1.0, 1e-14) << id << " p[0]=" << p[0];
            EXPECT_NEAR(eval(*m, p, 1.0), expected_at_normal_incidence(id, p), 1e-12) << id << " p[0]=" << p[0];
            // The RGB overload is the per-channel one.
            const ModelParameters rgb{p, p, p};
            const RGB c = m->evaluate(rgb, 0.3);
            EXPECT_EQ(c.r, eval(*m, p, 0.3)) << id;
            EXPECT_EQ(c.b, eval(*m, p, 0.3)) << id;
        }
    }
}

// ---- 2. conductor-rgb against the complex form ----

TEST(ModelConductorRgb, MatchesComplexFormExactFresnelOverWideGrid) {
    const Model& m = find_model("conductor-rgb");
    for (double n : {0.01, 0.05, 0.2, 0.5, 1.0, 1.5, 3.0, 10.0})
        for (double k : {0.0, 1e-4, 0.01, 0.5, 2.0, 5.0, 20.0, 100.0, 1000.0})
            for (double mu : mu_grid()) {
                const double got = eval(m, {n, k}, mu);
                ASSERT_TRUE(std::isfinite(got)) << "n=" << n << " k=" << k << " mu=" << mu;
                EXPECT_NEAR(got, fresnel(mu, {n, k}), 1e-10) << "n=" << n << " k=" << k << " mu=" << mu;
            }
}

TEST(ModelConductorRgb, FloatOverloadAgreesWithDouble) {
    // The float path rounds every intermediate to 2^-24 ≈ 6e-8 relative. The form has no cancellation that grows
    // with k (r ± 2aμ + μ² are sums of same-signed terms when a ≥ 0), so the error stays a few dozen float ulps of
    // F ≤ 1, i.e. ~1e-6; 2e-5 leaves margin. For k > 100, t = n² − k² − s² in float loses s² below k²·6e-8 and the
    // curve near μ = 0 is then not resolved, so the bound is only claimed for k ≤ 100. Both overloads are fed the
    // same float-rounded inputs, so the comparison measures arithmetic only, not the rounding of μ, n, k.
    // η = 1 + 0i (no interface) is left out below μ = 1e-3: in float s² = 1 − μ² rounds to 1 for μ < 2.4e-4, so
    // t = r = a = 0 and F_s = μ²/μ² = 1 instead of 0 (the GLSL does the same); a degenerate input, not a metal.
    const Model& m = find_model("conductor-rgb");
    for (double n : {0.01, 0.05, 0.2, 0.5, 1.0, 1.5, 3.0, 10.0})
        for (double k : {0.0, 1e-4, 0.01, 0.5, 2.0, 5.0, 20.0, 100.0})
            for (double mu : mu_grid()) {
                if (n == 1.0 && k == 0.0 && mu > 0.0 && mu < 1e-3) continue;
                const float nf = static_cast<float>(n), kf = static_cast<float>(k), muf = static_cast<float>(mu);
                const float got = eval_f(m, {nf, kf}, muf);
                ASSERT_TRUE(std::isfinite(got)) << "n=" << n << " k=" << k << " mu=" << mu;
                EXPECT_NEAR(got, eval(m, {nf, kf}, muf), 2e-5) << "n=" << n << " k=" << k << " mu=" << mu;
            }
}

TEST(Models, FloatOverloadsAgreeWithDoubleForTypicalParameters) {
    // The closed forms are a handful of float operations on values of order 1 (F0 ≤ 1.06, n, k ≤ 8): a few ulps.
    for (const auto& [id, sets] : typical_params())
        for (const Model* m = &find_model(id); const Params& p : sets)
            for (double mu : mu_grid()) {
                std::vector<float> pf(p.begin(), p.end());
                const Params pd(pf.begin(), pf.end());
                const float muf = static_cast<float>(mu);
                EXPECT_NEAR(eval_f(*m, pf, muf), eval(*m, pd, muf), 2e-5) << m->id() << " mu=" << mu;
            }
}

// ---- 3. Lazányi ----

TEST(ModelLazanyi, IsSchlickWithNormalIncidenceReflectance) {
    const Model& m = find_model("lazanyi");
    for (double n : {0.05, 0.2, 1.0, 1.5, 3.0})
        for (double k : {0.0, 0.5, 3.0, 10.0})
            for (double mu : mu_grid())
                EXPECT_NEAR(eval(m, {n, k}, mu), schlick(normal_incidence(n, k), mu), 1e-14)
                    << "n=" << n << " k=" << k << " mu=" << mu;
}

TEST(ModelLazanyiComp, ZeroAmplitudeIsLazanyi) {
    const Model& comp = find_model("lazanyi-comp");
    const Model& laz = find_model("lazanyi");
    for (double n : {0.05, 0.2, 1.5, 3.0})
        for (double k : {0.0, 3.0, 10.0})
            for (double alpha : {0.05, 1.0, 6.0, 64.0})
                for (double mu : mu_grid())
                    EXPECT_EQ(eval(comp, {n, k, 0.0, alpha}, mu), eval(laz, {n, k}, mu))
                        << "n=" << n << " k=" << k << " alpha=" << alpha << " mu=" << mu;
}

TEST(ModelLazanyiComp, MatchesThesisEquation) {
    const Model& m = find_model("lazanyi-comp");
    for (double n : {0.05, 0.2, 1.5})
        for (double k : {0.0, 3.0, 10.0})
            for (double a : {-2.0, 0.3, 1.5})
                for (double alpha : {0.05, 0.5, 2.0, 6.0, 64.0})
                    for (double mu : mu_grid())
                        EXPECT_NEAR(eval(m, {n, k, a, alpha}, mu), lazanyi_comp(n, k, a, alpha, mu), 1e-13)
                            << "n=" << n << " k=" << k << " a=" << a << " alpha=" << alpha << " mu=" << mu;
}

// The fit's variable projection: for a fixed α, F0 and a are the least-squares solution (a target built from a known
// curve comes back exactly; elsewhere moving F0 or a raises the cost), the residuals are the full curve's at the
// parameters it returns, and the derivative of the projected cost in α is its finite difference.
ChannelTarget lazanyi_comp_target(const std::array<double, 4>& p) {
    ChannelTarget t;
    for (const QuadratureNode& q : gauss_legendre_unit(64)) {
        t.mu.push_back(q.mu);
        t.value.push_back(models::LazanyiComp::evaluate(p.data(), q.mu));
        t.scale.push_back(std::sqrt(q.weight) / t.value.back());
    }
    return t;
}
double projected_cost(const ChannelTarget& t, const ChannelParameters& p) {
    double cost = 0;
    for (std::size_t i = 0; i < t.mu.size(); ++i) {
        const double r = t.scale[i] * (models::LazanyiComp::evaluate(p.data(), t.mu[i]) - t.value[i]);
        cost += 0.5 * r * r;
    }
    return cost;
}

TEST(ModelLazanyiComp, ProjectionSolvesF0AndAmplitudeExactly) {
    const std::array<double, 4> truth{0.4, 3.0, 0.25, 5.0};
    const ChannelTarget t = lazanyi_comp_target(truth);
    const models::LazanyiComp::Projection projection(t);
    ASSERT_EQ(projection.residuals(), t.mu.size());
    const double alpha = truth[3];
    const ChannelParameters p = projection.parameters(&alpha, {0.4, 1.0, 0.0, 1.0});
    const auto F0 = [](const ChannelParameters& q) {
        return ((q[0] - 1) * (q[0] - 1) + q[1] * q[1]) / ((q[0] + 1) * (q[0] + 1) + q[1] * q[1]);
    };
    EXPECT_NEAR(F0(p), F0({truth[0], truth[1]}), 1e-12);
    EXPECT_DOUBLE_EQ(p[0], 0.4);  // the start's n kept (some k gives that F0)
    EXPECT_NEAR(p[2], truth[2], 1e-10);
    EXPECT_EQ(p[3], alpha);
    EXPECT_LT(projected_cost(t, p), 1e-24);
}

TEST(ModelLazanyiComp, ProjectionIsTheLeastSquaresOptimumAtEachAlpha) {
    const ChannelTarget t = lazanyi_comp_target({0.4, 3.0, 0.25, 5.0});
    models::LazanyiComp::Projection projection(t);
    for (double alpha : {0.5, 2.0, 9.0, 30.0}) {
        const ChannelParameters p = projection.parameters(&alpha, {1.0, 3.0, 0.0, 1.0});
        std::vector<double> r(projection.residuals());
        projection.residuals(alpha, r.data());
        double cost = 0;
        for (double v : r) cost += 0.5 * v * v;
        EXPECT_NEAR(cost, projected_cost(t, p), 1e-12 * cost) << alpha;
        EXPECT_NEAR(projection.at(alpha).cost, cost, 1e-14 * cost) << alpha;
        ASSERT_GT(cost, 0) << alpha;
        for (double dn : {-1e-3, 1e-3}) {  // F0 moves through n; a directly
            EXPECT_GT(projected_cost(t, {p[0] + dn, p[1], p[2], p[3]}), cost) << alpha;
            EXPECT_GT(projected_cost(t, {p[0], p[1], p[2] + dn, p[3]}), cost) << alpha;
        }
        // d cost / d alpha (the partial derivative at the linear solution) against central differences of the
        // projected cost, F0 and a solved again at each side.
        const double h = 1e-5 * alpha;
        const double central = (projection.at(alpha + h).cost - projection.at(alpha - h).cost) / (2 * h);
        EXPECT_NEAR(projection.at(alpha).slope, central, 1e-6 * std::abs(central) + 1e-12 * cost) << alpha;
        EXPECT_NE(central, 0) << alpha;
    }
}

// With a bound held (a at its upper bound, the other solved again) the derivative is still that of the projected cost.
TEST(ModelLazanyiComp, ProjectionDerivativeHoldsWithTheAmplitudeOnItsBound) {
    const ChannelTarget t = lazanyi_comp_target({0.4, 3.0, 25.0, 40.0});  // a beyond its bound
    models::LazanyiComp::Projection projection(t);
    for (double alpha : {36.0, 44.0}) {
        const ChannelParameters p = projection.parameters(&alpha, {1.0, 3.0, 0.0, 1.0});
        ASSERT_EQ(p[2], models::LazanyiComp::kParameters[2].upper) << alpha;
        const double h = 1e-5 * alpha;
        const double central = (projection.at(alpha + h).cost - projection.at(alpha - h).cost) / (2 * h);
        EXPECT_NEAR(projection.at(alpha).slope, central, 1e-6 * std::abs(central)) << alpha;
        EXPECT_NE(central, 0) << alpha;
    }
}

// ---- 4. F82-tint ----

TEST(ModelF82Tint, ValueAtOneSeventhIsTintTimesSchlick) {
    const Model& m = find_model("f82-tint");
    const double mu_bar = 1.0 / 7.0;
    for (double f0 : {0.0, 0.04, 0.56, 0.95, 1.0, 1.06, 1.5})
        for (double tint : {0.0, 0.5, 0.8, 1.0, 1.2, 2.0, 3.5})
            EXPECT_NEAR(eval(m, {f0, tint}, mu_bar), tint * schlick(f0, mu_bar), 1e-14)
                << "F0=" << f0 << " tint=" << tint;
}

TEST(ModelF82Tint, UnitTintIsSchlick) {
    const Model& f82 = find_model("f82-tint");
    const Model& s = find_model("schlick");
    for (double f0 : {0.0, 0.04, 0.56, 0.95, 1.06})
        for (double mu : mu_grid()) {
            EXPECT_EQ(eval(f82, {f0, 1.0}, mu), eval(s, {f0}, mu)) << "F0=" << f0 << " mu=" << mu;
            EXPECT_NEAR(eval(s, {f0}, mu), schlick(f0, mu), 1e-15) << "F0=" << f0 << " mu=" << mu;
        }
}

TEST(ModelF82Tint, CorrectionIsMuTimesOneMinusMuToTheSixth) {
    // F − Schlick is proportional to μ(1 − μ)^6 (Hoffman 2019): the ratio is the same b at every μ.
    const Model& m = find_model("f82-tint");
    const double mu_bar = 1.0 / 7.0;
    for (double f0 : {0.04, 0.9, 1.06})
        for (double tint : {0.5, 1.3}) {
            const double b = (1.0 - tint) * schlick(f0, mu_bar) / (mu_bar * std::pow(1.0 - mu_bar, 6.0));
            for (double mu : mu_grid())
                EXPECT_NEAR(eval(m, {f0, tint}, mu), schlick(f0, mu) - b * mu * std::pow(1.0 - mu, 6.0), 1e-14)
                    << "F0=" << f0 << " tint=" << tint << " mu=" << mu;
        }
}

// ---- 5. Gulbrandsen ----

TEST(ModelGulbrandsen, RoundTripsMetalAndGlassIndices) {
    std::vector<C> etas{C(1.5, 0.0)};
    for (double n : {0.05, 0.1, 0.27, 0.5, 1.0, 1.5, 2.0, 3.0})
        for (double k : {0.5, 1.0, 2.5, 3.6, 7.0, 10.0}) etas.emplace_back(n, k);
    // Measured metals at 650 / 550 / 450 nm-ish: all inside Gulbrandsen's domain (g in [0, 1]).
    for (C eta : {C(0.06, 4.2), C(0.27, 2.8), C(1.2, 1.8), C(0.15, 3.5), C(2.9, 3.1), C(1.44, 7.5)}) {
        const auto [r, g] = models::Gulbrandsen::from_nk(eta);
        EXPECT_GE(g, 0.0) << eta;
        EXPECT_LE(g, 1.0) << eta;
        etas.push_back(eta);
    }
    for (C eta : etas) {
        const auto [r, g] = models::Gulbrandsen::from_nk(eta);
        EXPECT_DOUBLE_EQ(r, fresnel_normal_incidence(eta)) << eta;
        // g = (n_max − n)/(n_max − n_min) is in [0, 1] exactly when n_min = (1 − r)/(1 + r) ≤ n ≤ n_max; below n_min
        // (low n with low k, e.g. 0.5 + 0.5i) Gulbrandsen's mapping has no g in [0, 1] and from_nk gives g > 1,
        // which to_nk still inverts. n ≤ n_max always holds (k² ≥ 0). Rounding may put a dielectric's g at −4e-16.
        const double n_min = (1.0 - r) / (1.0 + r);
        EXPECT_GE(g, -1e-12) << eta;
        if (eta.real() >= n_min) {
            EXPECT_LE(g, 1.0 + 1e-12) << eta << " n_min=" << n_min;
        } else {
            EXPECT_GT(g, 1.0) << eta << " n_min=" << n_min;
        }
        const C back = models::Gulbrandsen::to_nk(r, g);
        EXPECT_NEAR(back.real(), eta.real(), 1e-9 * std::abs(eta.real())) << eta << " r=" << r << " g=" << g;
        EXPECT_NEAR(back.imag(), eta.imag(), 1e-9 * std::abs(eta)) << eta << " r=" << r << " g=" << g;
    }
}

TEST(ModelGulbrandsen, IsExactConductorFresnelAtMappedIndex) {
    const Model& gul = find_model("gulbrandsen");
    const Model& cond = find_model("conductor-rgb");
    for (double r : {0.0, 1e-6, 0.04, 0.3, 0.56, 0.9, 0.99, 0.99999})
        for (double g : {0.0, 1e-6, 0.2, 0.5, 0.8, 1.0}) {
            const C eta = models::Gulbrandsen::to_nk(r, g);
            ASSERT_TRUE(std::isfinite(eta.real()) && std::isfinite(eta.imag())) << "r=" << r << " g=" << g;
            for (double mu : mu_grid()) {
                const double got = eval(gul, {r, g}, mu);
                ASSERT_TRUE(std::isfinite(got)) << "r=" << r << " g=" << g << " mu=" << mu;
                EXPECT_NEAR(got, eval(cond, {eta.real(), eta.imag()}, mu), 1e-10)
                    << "r=" << r << " g=" << g << " mu=" << mu;
                EXPECT_NEAR(got, fresnel(mu, eta), 1e-10) << "r=" << r << " g=" << g << " mu=" << mu << " eta=" << eta;
            }
        }
}

TEST(ModelGulbrandsen, BoundaryParametersGiveFiniteReflectanceInUnitInterval) {
    const Model& m = find_model("gulbrandsen");
    const auto& bounds = m.parameters();
    std::vector<Params> points;
    for (double r : {0.0, bounds[0].lower, bounds[0].upper, 0.5})
        for (double g : {0.0, 1.0, bounds[1].lower, bounds[1].upper, 0.5}) points.push_back({r, g});
    for (const Params& p : points)
        for (double mu : mu_grid()) {
            const double f = eval(m, p, mu);
            EXPECT_TRUE(std::isfinite(f)) << "r=" << p[0] << " g=" << p[1] << " mu=" << mu;
            // r = 0 is η = 1, where F_s's numerator r − 2aμ + μ² is μ² − 2μ² + μ² and rounds to ±5e-17.
            EXPECT_GE(f, -1e-15) << "r=" << p[0] << " g=" << p[1] << " mu=" << mu;
            EXPECT_LE(f, 1.0) << "r=" << p[0] << " g=" << p[1] << " mu=" << mu;
        }
    // g = 0 is the dielectric with F0 = r (k = 0, n = n_max); r = 0 is no interface at all.
    for (double mu : mu_grid()) {
        const double n_max = (1.0 + std::sqrt(0.04)) / (1.0 - std::sqrt(0.04));
        EXPECT_NEAR(eval(m, {0.04, 0.0}, mu), fresnel(mu, {n_max, 0.0}), 1e-12) << "mu=" << mu;
        if (mu > 0.0) {
            // η = 1 reflects nothing; at μ = 1e-6 the real form keeps s² = 1 − μ² to 1e-16 only, so t = μ² is
            // off by 1e-4 relative and F ≈ 3e-11 (the same bound as ConductorRgb's grid against the complex form).
            EXPECT_NEAR(eval(m, {0.0, 0.5}, mu), 0.0, 1e-10) << "mu=" << mu;
        }
    }
}

// ---- 6. derivatives: Jets against finite differences ----

enum class Difference { central, forward };

// A point in parameter space and how to difference there (forward at a lower bound the function has a kink at).
struct JetCase {
    Params p;
    std::vector<Difference> kind;  // per parameter; empty: all central
};

template <class M>
double value_of(const Params& p, double mu) {
    return M::evaluate(p.data(), mu);
}

template <class M>
void check_jet_derivatives(const std::vector<JetCase>& cases, const std::vector<double>& mus) {
    constexpr int P = static_cast<int>(M::kParameters.size());
    using J = ceres::Jet<double, P>;
    for (const JetCase& c : cases) {
        ASSERT_EQ(c.p.size(), static_cast<std::size_t>(P)) << M::kId;
        for (double mu : mus) {
            std::array<J, P> x;
            for (int i = 0; i < P; ++i) x[i] = J(c.p[i], i);
            const J f = M::evaluate(x.data(), J(mu));
            EXPECT_NEAR(f.a, value_of<M>(c.p, mu), 1e-15) << M::kId;
            for (int i = 0; i < P; ++i) {
                const double d = f.v[i];
                ASSERT_TRUE(std::isfinite(d)) << M::kId << " d/d" << M::kParameters[i].name << " p[0]=" << c.p[0]
                                              << " p[1]=" << (P > 1 ? c.p[1] : 0.0) << " mu=" << mu;
                const double h = 1e-6 * std::max(1.0, std::abs(c.p[i]));
                auto at = [&](double delta) {
                    Params q = c.p;
                    q[i] += delta;
                    return value_of<M>(q, mu);
                };
                const bool forward = !c.kind.empty() && c.kind[i] == Difference::forward;
                // Second order either way: central (f(+h) − f(−h))/2h, forward (−3f(0) + 4f(h) − f(2h))/2h.
                const double fd =
                    forward ? (-3.0 * at(0.0) + 4.0 * at(h) - at(2.0 * h)) / (2.0 * h) : (at(h) - at(-h)) / (2.0 * h);
                const double tol = std::max(1e-8, 1e-5 * std::abs(fd));
                EXPECT_NEAR(d, fd, tol) << M::kId << " d/d" << M::kParameters[i].name << " p=(" << c.p[0]
                                        << (P > 1 ? ", " + std::to_string(c.p[1]) : std::string())
                                        << (P > 2 ? ", " + std::to_string(c.p[2]) + ", " + std::to_string(c.p[3])
                                                  : std::string())
                                        << ") mu=" << mu << (forward ? " (forward)" : " (central)");
            }
        }
    }
}

const std::vector<double> kJetMus{0.01, 0.05, 1.0 / 7.0, 0.3, 0.5, 0.7, 0.95, 0.999};

TEST(ModelDerivatives, Schlick) {
    check_jet_derivatives<models::Schlick>({{{0.04}, {}}, {{0.56}, {}}, {{1.06}, {}}, {{0.0}, {}}, {{-0.5}, {}}},
                                           kJetMus);
}

TEST(ModelDerivatives, Lazanyi) {
    check_jet_derivatives<models::Lazanyi>(
        {{{0.2, 3.0}, {}}, {{1.5, 0.0}, {}}, {{0.05, 8.0}, {}}, {{2.9, 0.5}, {}}, {{1.0, 1e-3}, {}}}, kJetMus);
}

TEST(ModelDerivatives, LazanyiComp) {
    check_jet_derivatives<models::LazanyiComp>({{{0.2, 3.0, 0.3, 6.0}, {}},
                                                {{1.5, 0.0, -0.2, 2.0}, {}},
                                                {{0.05, 8.0, 1.5, 0.5}, {}},
                                                {{0.2, 3.0, 0.0, 0.05}, {}},
                                                {{0.2, 3.0, 2.0, 64.0}, {}}},
                                               kJetMus);
}

TEST(ModelDerivatives, F82Tint) {
    check_jet_derivatives<models::F82Tint>(
        {{{0.9, 0.8}, {}}, {{0.04, 1.0}, {}}, {{1.06, 1.2}, {}}, {{0.56, 0.0}, {}}, {{0.95, 3.5}, {}}}, kJetMus);
}

TEST(ModelDerivatives, ConductorRgb) {
    // k = 0 is the fit's lower bound: with n = 1.5 (no total reflection) F is even in k, with n = 0.5 the form's
    // a = nk / sqrt((r − t)/2) is odd and smooth through k = 0 where t < 0; central differences apply to both.
    check_jet_derivatives<models::ConductorRgb>({{{0.2, 3.0}, {}},
                                                 {{0.05, 8.0}, {}},
                                                 {{2.9, 3.0}, {}},
                                                 {{1.5, 0.0}, {}},
                                                 {{0.5, 0.0}, {}},
                                                 {{0.5, 0.01}, {}},
                                                 {{1.0, 2.0}, {}},
                                                 {{3.0, 100.0}, {}}},
                                                kJetMus);
}

TEST(ModelDerivatives, Gulbrandsen) {
    // g = 0 is where k² reaches 0 (n = n_max): a one-sided kink, so a forward difference in g (g ≥ 0 is the fit's
    // bound, so the derivative into the domain is the one the solver needs). The unfactored k² cancelled to ±1e-16
    // there and its clamp dropped dk²/dg for r = 0.04, 0.1, 0.3, 0.5 (∂F/∂g of the wrong sign): these rows catch it.
    // g = 1 (n = n_min, k² = 4r/(1 + r)² > 0) is smooth: central.
    using D = Difference;
    check_jet_derivatives<models::Gulbrandsen>({{{0.9, 0.5}, {}},
                                                {{0.9, 1.0}, {}},
                                                {{0.9, 0.0}, {D::central, D::forward}},
                                                {{0.04, 0.0}, {D::central, D::forward}},
                                                {{0.2, 0.0}, {D::central, D::forward}},
                                                {{0.5, 0.0}, {D::central, D::forward}},
                                                {{0.56, 0.9}, {}},
                                                {{0.3, 0.2}, {}},
                                                {{0.99, 0.5}, {}}},
                                               kJetMus);
}

TEST(ModelDerivatives, FiniteAtBounds) {
    // Values and derivatives at the lower bounds the fit clamps to (k = 0, g = 0, g = 1, r = 0) and at μ = 0, 1.
    auto finite = [](const auto& jet) {
        if (!std::isfinite(jet.a)) return false;
        for (int i = 0; i < jet.v.size(); ++i)
            if (!std::isfinite(jet.v[i])) return false;
        return true;
    };
    using J2 = ceres::Jet<double, 2>;
    for (double mu : {0.0, 1e-6, 0.3, 0.9, 1.0}) {
        for (double n : {0.5, 1.0, 1.5}) {
            const std::array<J2, 2> p{J2(n, 0), J2(0.0, 1)};
            EXPECT_TRUE(finite(models::ConductorRgb::evaluate(p.data(), J2(mu)))) << "n=" << n << " k=0 mu=" << mu;
            EXPECT_TRUE(finite(models::Lazanyi::evaluate(p.data(), J2(mu)))) << "n=" << n << " k=0 mu=" << mu;
        }
        for (double r : {0.0, 0.04, 0.9})
            for (double g : {0.0, 1.0}) {
                const std::array<J2, 2> p{J2(r, 0), J2(g, 1)};
                EXPECT_TRUE(finite(models::Gulbrandsen::evaluate(p.data(), J2(mu))))
                    << "r=" << r << " g=" << g << " mu=" << mu;
            }
    }
}

// ---- 7. registry ----

TEST(ModelRegistry, AllModelsInFixedOrder) {
    // The registry's order, and the published models first in the order of the records and tables since 0.1.
    std::vector<std::string_view> registered;
    for_each_model(Registry{}, [&]<class M>() { registered.push_back(M::kId); });
    const auto models = all_models();
    ASSERT_EQ(models.size(), registered.size());
    for (std::size_t i = 0; i < registered.size(); ++i) {
        EXPECT_EQ(models[i]->id(), registered[i]);
        EXPECT_EQ(&find_model(registered[i]), models[i]);
        EXPECT_FALSE(models[i]->title().empty()) << registered[i];
    }
    const std::vector<std::string_view> published{"schlick",  "lazanyi",       "lazanyi-comp",
                                                  "f82-tint", "conductor-rgb", "gulbrandsen"};
    ASSERT_GE(registered.size(), published.size());
    EXPECT_TRUE(std::equal(published.begin(), published.end(), registered.begin()));
}

TEST(ModelRegistry, UnknownIdThrowsUsageErrorListingKnownIds) {
    try {
        (void)find_model("nope");
        FAIL() << "no exception";
    } catch (const UsageError& e) {
        const std::string what = e.what();
        EXPECT_TRUE(test::Contains(what, "nope"));
        for (const Model* m : all_models()) EXPECT_TRUE(test::Contains(what, std::string(m->id())));
    }
    EXPECT_THROW(parse_model_list("schlick,nope"), UsageError);
    EXPECT_THROW(parse_model_list(""), UsageError);
}

TEST(ModelRegistry, ParseModelList) {
    const auto all = parse_model_list("all");
    ASSERT_EQ(all.size(), Registry::size);
    for (std::size_t i = 0; i < all.size(); ++i) EXPECT_EQ(all[i], all_models()[i]);
    const auto two = parse_model_list("schlick,f82-tint,schlick");
    ASSERT_EQ(two.size(), 2u);
    EXPECT_EQ(two[0]->id(), "schlick");
    EXPECT_EQ(two[1]->id(), "f82-tint");
    const auto reordered = parse_model_list("gulbrandsen,lazanyi");
    ASSERT_EQ(reordered.size(), 2u);
    EXPECT_EQ(reordered[0]->id(), "gulbrandsen");
    EXPECT_EQ(reordered[1]->id(), "lazanyi");
}

TEST(ModelRegistry, ParametersHaveBoundsAndNeutralStartsInside) {
    for (const Model* m : all_models()) {
        std::set<std::string_view> names;
        for (const Parameter& p : m->parameters()) {
            EXPECT_LT(p.lower, p.upper) << m->id() << " " << p.name;
            EXPECT_FALSE(p.name.empty()) << m->id();
            EXPECT_FALSE(p.meaning.empty()) << m->id() << " " << p.name;
            EXPECT_TRUE(names.insert(p.name).second) << m->id() << " duplicate " << p.name;
        }
        for (const ChannelParameters& s : m->neutral_starts()) {
            ASSERT_EQ(s.size(), m->parameters().size()) << m->id();
            for (std::size_t i = 0; i < s.size(); ++i) {
                EXPECT_GE(s[i], m->parameters()[i].lower) << m->id() << " " << m->parameters()[i].name;
                EXPECT_LE(s[i], m->parameters()[i].upper) << m->id() << " " << m->parameters()[i].name;
            }
        }
    }
}

TEST(ModelRegistry, F0BoundsAllowOutOfGamutRed) {
    // Gold's and copper's red channel reaches ~1.06 in Linear Rec.709: the bounds must not clip it.
    for (std::string_view id : {"schlick", "f82-tint"}) {
        const Parameter& f0 = find_model(id).parameters()[0];
        EXPECT_EQ(f0.name, "F0") << id;
        EXPECT_LE(f0.lower, 0.0) << id;
        EXPECT_GE(f0.upper, 1.06) << id;
    }
}

// ---- 8. GLSL text ----

struct GlslFunction {
    std::string return_type;
    std::string name;
    std::vector<std::pair<std::string, std::string>> params;  // (type, name)
    std::size_t position = 0;
};

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r\n");
    const auto e = s.find_last_not_of(" \t\r\n");
    return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

std::string strip_comments(const std::string& src) {
    std::string out = std::regex_replace(src, std::regex(R"(//[^\n]*)"), "");
    // Block comments: none are expected, but remove them so that they cannot hide or fake a definition.
    std::string result;
    for (std::size_t i = 0; i < out.size();) {
        if (out.compare(i, 2, "/*") == 0) {
            const auto end = out.find("*/", i + 2);
            i = end == std::string::npos ? out.size() : end + 2;
        } else {
            result += out[i++];
        }
    }
    return result;
}

// Function definitions at top level: "<type> <name>(<params>) {".
std::vector<GlslFunction> glsl_definitions(const std::string& src) {
    std::vector<GlslFunction> defs;
    const std::regex def(R"((?:^|\n)\s*(void|float|vec2|vec3|vec4|bool|int)\s+(\w+)\s*\(([^)]*)\)\s*\{)");
    for (auto it = std::sregex_iterator(src.begin(), src.end(), def); it != std::sregex_iterator(); ++it) {
        GlslFunction f{(*it)[1], (*it)[2], {}, static_cast<std::size_t>(it->position(2))};
        const std::string params = (*it)[3];
        std::size_t start = 0;
        while (start <= params.size()) {
            const auto comma = params.find(',', start);
            const std::string one =
                trim(params.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
            if (!one.empty()) {
                const auto space = one.find_last_of(" \t");
                f.params.emplace_back(space == std::string::npos ? "" : trim(one.substr(0, space)),
                                      space == std::string::npos ? one : one.substr(space + 1));
            }
            if (comma == std::string::npos) break;
            start = comma + 1;
        }
        defs.push_back(std::move(f));
    }
    return defs;
}

// Every "metalfit_*(" in the text (definitions included), with its position.
std::vector<std::pair<std::string, std::size_t>> glsl_metalfit_calls(const std::string& src) {
    std::vector<std::pair<std::string, std::size_t>> calls;
    const std::regex call(R"(\b(metalfit_\w+)\s*\()");
    for (auto it = std::sregex_iterator(src.begin(), src.end(), call); it != std::sregex_iterator(); ++it)
        calls.emplace_back((*it)[1], static_cast<std::size_t>(it->position(1)));
    return calls;
}

TEST(ModelGlsl, SourceDefinesTheModelFunctionAndEverythingItCalls) {
    for (const Model* m : all_models()) {
        const std::string src = m->glsl_source();
        const std::string fn(m->glsl_function());
        EXPECT_TRUE(test::Contains(src, "vec3 " + fn + "(")) << m->id();
        const std::string code = strip_comments(src);
        const auto defs = glsl_definitions(code);
        std::map<std::string, std::size_t> defined;
        for (const auto& d : defs) {
            EXPECT_TRUE(defined.emplace(d.name, d.position).second) << m->id() << " defines " << d.name << " twice";
        }
        ASSERT_TRUE(defined.count(fn)) << m->id() << ": " << fn << " not defined";
        // Every metalfit_* that is called is defined, and before its first use (GLSL has no forward lookup).
        for (const auto& [name, pos] : glsl_metalfit_calls(code)) {
            const auto d = defined.find(name);
            ASSERT_NE(d, defined.end()) << m->id() << " calls undefined " << name;
            EXPECT_LE(d->second, pos) << m->id() << " uses " << name << " before defining it";
        }
    }
    // The calls the brief names explicitly.
    EXPECT_TRUE(test::Contains(find_model("lazanyi-comp").glsl_source(), "vec3 metalfit_lazanyi("));
    EXPECT_TRUE(test::Contains(find_model("f82-tint").glsl_source(), "vec3 metalfit_schlick("));
    EXPECT_TRUE(test::Contains(find_model("gulbrandsen").glsl_source(), "vec3 metalfit_conductor_fresnel("));
}

TEST(ModelGlsl, SignatureMatchesParameterNames) {
    for (const Model* m : all_models()) {
        const auto defs = glsl_definitions(strip_comments(m->glsl_source()));
        const auto it =
            std::find_if(defs.begin(), defs.end(), [&](const GlslFunction& f) { return f.name == m->glsl_function(); });
        ASSERT_NE(it, defs.end()) << m->id();
        EXPECT_EQ(it->return_type, "vec3") << m->id();
        const auto params = m->parameters();
        ASSERT_EQ(it->params.size(), params.size() + 1) << m->id();
        for (std::size_t i = 0; i < params.size(); ++i) {
            EXPECT_EQ(it->params[i].first, "vec3") << m->id() << " parameter " << i;
            EXPECT_EQ(it->params[i].second, params[i].name) << m->id() << " parameter " << i;
        }
        EXPECT_EQ(it->params.back().first, "float") << m->id();
        EXPECT_EQ(it->params.back().second, "mu") << m->id();
    }
}

TEST(ModelGlsl, LibraryOfAllModelsDefinesEachFunctionOnce) {
    const std::string lib = strip_comments(glsl_library(all_models()));
    std::map<std::string, int> count;
    for (const auto& d : glsl_definitions(lib)) ++count[d.name];
    for (const Model* m : all_models()) EXPECT_EQ(count[std::string(m->glsl_function())], 1) << m->id();
    for (const auto& [name, c] : count) {
        EXPECT_EQ(c, 1) << name;
        EXPECT_EQ(name.rfind("metalfit_", 0), 0u) << name << " is not in the metalfit_ namespace";
    }
    std::map<std::string, std::size_t> defined;
    for (const auto& d : glsl_definitions(lib)) defined.emplace(d.name, d.position);
    for (const auto& [name, pos] : glsl_metalfit_calls(lib)) {
        ASSERT_TRUE(defined.count(name)) << "library calls undefined " << name;
        EXPECT_LE(defined[name], pos) << name << " used before its definition";
    }
    // Any subset works on its own, too (each shared function once, callees first).
    const std::vector<const Model*> subset{&find_model("gulbrandsen"), &find_model("f82-tint"),
                                           &find_model("conductor-rgb")};
    std::map<std::string, int> sub_count;
    for (const auto& d : glsl_definitions(strip_comments(glsl_library(subset)))) ++sub_count[d.name];
    for (const auto& [name, c] : sub_count) EXPECT_EQ(c, 1) << name;
    EXPECT_EQ(sub_count.count("metalfit_lazanyi"), 0u);
    EXPECT_THROW((void)shader_file("no_such_file"), std::out_of_range);
}

}  // namespace test_models
}  // namespace metalfit
