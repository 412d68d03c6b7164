// Fit targets and constraints as one seam (issue 28 item 8): the fitter takes its curve from a FitTarget, so a
// measured reflectance (rows of μ and RGB, no spectrum, no complex index) is fitted by the same fit_models as a
// catalog metal; and each constraint's result and its fallback rule checked against a direct computation here: a
// pinned F(1), the gamut on 4097 points, |err_f0| within T, the closed forms that may not be kept.
#include <gtest/gtest.h>

#include "test_environment.hpp"
#include "test_support.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <span>
#include <string>
#include <vector>

#include "libfit/base/errors.hpp"
#include "libfit/base/quadrature.hpp"
#include "libfit/color/color_space.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/fit/fit.hpp"
#include "libfit/fit/material_target.hpp"
#include "libfit/fit/reflectance_target.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/models/model.hpp"

namespace metalfit {
namespace test_fit_target {

using namespace metalfit::test;

constexpr const char* kChannel[] = {"red", "green", "blue"};

std::vector<const Model*> every_model() { return {all_models().begin(), all_models().end()}; }

const ModelResult& result_of(const std::vector<ModelResult>& results, std::string_view id) {
    for (const ModelResult& r : results)
        if (r.model->id() == id) return r;
    throw std::logic_error("no result for " + std::string(id));
}

// Every μ a SampledReference of `nodes` nodes samples (the Gauss–Legendre nodes and the uniform grid of the maxima),
// with μ_F82 = 1/7 where the closed forms read the tint: rows there give the target's values exactly at those μ.
std::vector<double> sampled_mu(int nodes) {
    std::vector<double> mu;
    for (const QuadratureNode& q : gauss_legendre_unit(nodes)) mu.push_back(q.mu);
    for (int i = 0; i <= kDenseIntervals; ++i) mu.push_back(double(i) / kDenseIntervals);
    mu.push_back(1.0 / 7.0);
    std::sort(mu.begin(), mu.end());
    mu.erase(std::unique(mu.begin(), mu.end()), mu.end());
    return mu;
}

ReflectanceTarget measured(const std::string& id, const std::vector<double>& mu, const auto& curve,
                           ErrorSettings error = {}) {
    std::vector<ReflectanceRow> rows;
    for (const double m : mu) rows.push_back({m, curve(m)});
    return ReflectanceTarget(id, id + ".csv", std::move(rows), env().colorimetry, env().converter, error);
}

// The unpolarised Fresnel reflectance of a conductor of index eta in air, written out with std::complex: the
// independent form conductor-rgb must reproduce.
double conductor_fresnel(std::complex<double> eta, double mu) {
    const std::complex<double> cos_t = std::sqrt(1.0 - (1.0 - mu * mu) / (eta * eta));
    const std::complex<double> rs = (mu - eta * cos_t) / (mu + eta * cos_t);
    const std::complex<double> rp = (eta * mu - cos_t) / (eta * mu + cos_t);
    return 0.5 * (std::norm(rs) + std::norm(rp));
}

// A catalog metal and the same curve as a measured reflectance (its values at every μ the fit samples): the fitter
// gives the same fits from both, although the measured target has no η (its n, k closed forms are undefined, said
// so) and its closed forms read a linear interpolation elsewhere. The reference is the material's, bit for bit.
TEST(FitTarget, AMeasuredReflectanceOfAMetalsCurveFitsAsTheMetal) {
    const Material copper = load_material(env().catalog, "Cu", "");
    const ErrorSettings error{};
    const MaterialTarget spectral(copper, env().colorimetry, env().converter, SpectralOptions{}, error);
    EXPECT_FALSE(spectral.layered());
    const ReflectanceTarget table = measured(
        "copper-measured", sampled_mu(error.nodes), [&](double mu) { return spectral(mu); }, error);
    for (std::size_t i = 0; i < spectral.reference()->nodes().size(); ++i)
        for (int c = 0; c < 3; ++c)
            ASSERT_EQ(table.reference()->nodes()[i].value[c], spectral.reference()->nodes()[i].value[c]);

    const auto models = every_model();
    const std::vector<ModelResult> from_metal = fit_models(spectral, models);
    const std::vector<ModelResult> from_table = fit_models(table, models);
    ASSERT_EQ(from_metal.size(), from_table.size());
    int undefined_eta_forms = 0;
    for (std::size_t m = 0; m < models.size(); ++m) {
        const ModelResult &a = from_metal[m], &b = from_table[m];
        SCOPED_TRACE(std::string(models[m]->id()));
        for (int c = 0; c < 3; ++c) {
            SCOPED_TRACE(kChannel[c]);
            const double rms_a = a.fit.value.metrics.rel_rms[c], rms_b = b.fit.value.metrics.rel_rms[c];
            EXPECT_NEAR(rms_b, rms_a, 1e-6 * rms_a + 1e-12);
            EXPECT_NEAR(b.fit.value.metrics.err_f0[c], a.fit.value.metrics.err_f0[c], 1e-5);
        }
        for (const ClosedFormResult& form : b.closed_forms)
            if (form.id.starts_with("nk-")) {
                EXPECT_FALSE(form.value) << form.id;
                EXPECT_TRUE(Contains(form.undefined, "the target has no complex index")) << form.undefined;
                ++undefined_eta_forms;
            }
    }
    EXPECT_GE(undefined_eta_forms, 4);  // conductor-rgb's and gulbrandsen's two each, lazanyi's
}

// A measured curve that is exactly the Fresnel reflectance of one n, k per channel: conductor-rgb recovers those n,
// k from the curve alone (no η to start from: its closed forms are undefined), and its error is rounding.
TEST(FitTarget, AMeasuredConductorCurveGivesBackItsIndex) {
    const std::complex<double> eta[3] = {{0.27, 3.4}, {0.9, 2.6}, {1.3, 1.9}};
    const ReflectanceTarget table = measured("conductor", sampled_mu(128), [&](double mu) {
        return RGB{conductor_fresnel(eta[0], mu), conductor_fresnel(eta[1], mu), conductor_fresnel(eta[2], mu)};
    });
    const Model& conductor = find_model("conductor-rgb");
    const std::vector<const Model*> models{&conductor};
    const ModelResult r = fit_models(table, models).front();
    for (int c = 0; c < 3; ++c) {
        SCOPED_TRACE(kChannel[c]);
        EXPECT_NEAR(r.fit.value.params[c][0], eta[c].real(), 1e-6);
        EXPECT_NEAR(r.fit.value.params[c][1], eta[c].imag(), 1e-6);
        EXPECT_LT(r.fit.value.metrics.rel_rms[c], 1e-9);
    }
    for (const ClosedFormResult& form : r.closed_forms) EXPECT_FALSE(form.value) << form.id;
}

// --pin F0 on a measured target: F(1) is the last row's value to 1e-12 in every channel the model can hold it in,
// computed here from the parameters; only closed forms with that F(1) are kept as fallbacks.
TEST(FitConstraintObjects, APinnedFitHoldsTheMeasuredF0) {
    const std::complex<double> eta[3] = {{0.27, 3.4}, {0.9, 2.6}, {1.3, 1.9}};
    const ReflectanceTarget table = measured("conductor", sampled_mu(128), [&](double mu) {
        return RGB{conductor_fresnel(eta[0], mu), conductor_fresnel(eta[1], mu), conductor_fresnel(eta[2], mu)};
    });
    const RGB R1 = table(1.0);
    FitConstraints pin;
    pin.pin_f0 = true;
    std::vector<const Model*> pinnable;
    for (const Model* m : all_models())
        if (m->can_pin_f0()) pinnable.push_back(m);
    int held = 0;
    for (const ModelResult& r : fit_models(table, pinnable, pin))
        for (int c = 0; c < 3; ++c) {
            SCOPED_TRACE(std::string(r.model->id()) + " " + kChannel[c]);
            if (!r.fit.refused[c].empty()) continue;
            const ChannelParameters& p = r.fit.value.params[c];
            EXPECT_NEAR(r.model->evaluate(std::span<const double>(p), 1.0), R1[c], 1e-12);
            ++held;
            if (r.fit.fallback[c].empty()) continue;
            for (const ClosedFormResult& form : r.closed_forms) {
                if (form.id != r.fit.fallback[c]) continue;
                EXPECT_NEAR(r.model->evaluate(std::span<const double>(form.value->params[c]), 1.0), R1[c], 1e-12);
            }
        }
    EXPECT_GE(held, 3 * static_cast<int>(pinnable.size()) - 3);
}

// --gamut-fit on a measured curve brighter than white at normal incidence (a Schlick curve with red F0 = 1.04):
// Schlick's own closed form r1 (F0 = R(1)) is that curve exactly, rel_rms 0, but leaves [0, 1], so it must not be
// the fallback; every model's curve holds [0, 1] on 4097 points (counted here), and Schlick's red F0 is the exact
// constrained optimum, 1 (Schlick is linear in F0 and F ≤ 1 ⇔ F0 ≤ 1).
TEST(FitConstraintObjects, AGamutFitStaysInTheUnitIntervalAndKeepsNoClosedFormOutsideIt) {
    const RGB F0{1.04, 0.8, 0.5};
    const auto schlick = [](double f0, double mu) { return f0 + (1 - f0) * std::pow(1 - mu, 5); };
    const ReflectanceTarget table = measured("bright", sampled_mu(128), [&](double mu) {
        return RGB{schlick(F0.r, mu), schlick(F0.g, mu), schlick(F0.b, mu)};
    });
    FitConstraints gamut;
    gamut.gamut_fit = true;
    const std::vector<const Model*> schlick_alone{&find_model("schlick")};  // the free fit is only checked on it
    const std::vector<ModelResult> free = fit_models(table, schlick_alone);
    EXPECT_LT(result_of(free, "schlick").fit.value.metrics.rel_rms[0], 1e-12);  // unconstrained: the curve itself
    const std::vector<ModelResult> held = fit_models(table, every_model(), gamut);
    for (const ModelResult& r : held)
        for (int c = 0; c < 3; ++c) {
            SCOPED_TRACE(std::string(r.model->id()) + " " + kChannel[c]);
            EXPECT_LE(curve_excess_outside_unit_range(*r.model, r.fit.value.params[c]), 0.0);
        }
    const ModelResult& s = result_of(held, "schlick");
    EXPECT_NE(s.fit.fallback[0], "r1");
    EXPECT_NEAR(s.fit.value.params[0][0], 1.0, 1e-6);
    EXPECT_GT(s.fit.value.metrics.rel_rms[0], 1e-3);
}

// --f0-tolerance T on a measured conductor curve, which Schlick's free fit misses at normal incidence by more than
// T: |F(1)/R(1) − 1| ≤ T in every representable channel (computed here), and the price in rel_rms lies between the
// free fit's and the pinned one's.
TEST(FitConstraintObjects, AnF0RangeFitMeetsTheTolerance) {
    const std::complex<double> eta[3] = {{0.27, 3.4}, {0.9, 2.6}, {1.3, 1.9}};
    const ReflectanceTarget table = measured("conductor", sampled_mu(128), [&](double mu) {
        return RGB{conductor_fresnel(eta[0], mu), conductor_fresnel(eta[1], mu), conductor_fresnel(eta[2], mu)};
    });
    const RGB R1 = table(1.0);
    constexpr double T = 0.002;
    FitConstraints tolerance, pin;
    tolerance.f0_tolerance = T;
    pin.pin_f0 = true;
    const Model& schlick = find_model("schlick");
    const std::vector<const Model*> models{&schlick, &find_model("f82-tint"), &find_model("schlick-comp")};
    const std::vector<ModelResult> free = fit_models(table, models);
    const std::vector<ModelResult> bounded = fit_models(table, models, tolerance);
    const std::vector<ModelResult> pinned = fit_models(table, models, pin);
    int missed_freely = 0;
    for (std::size_t m = 0; m < models.size(); ++m)
        for (int c = 0; c < 3; ++c) {
            SCOPED_TRACE(std::string(models[m]->id()) + " " + kChannel[c]);
            const ChannelParameters& p = bounded[m].fit.value.params[c];
            const double err = models[m]->evaluate(std::span<const double>(p), 1.0) / R1[c] - 1;
            EXPECT_LE(std::abs(err), T);
            const double f = free[m].fit.value.metrics.rel_rms[c], b = bounded[m].fit.value.metrics.rel_rms[c],
                         q = pinned[m].fit.value.metrics.rel_rms[c];
            EXPECT_GE(b, f * (1 - 1e-9));
            EXPECT_LE(b, q * (1 + 1e-9));
            missed_freely += std::abs(free[m].fit.value.metrics.err_f0[c]) > T;
        }
    EXPECT_GE(missed_freely, 1);  // the constraint had work to do
}

// A measured target is checked like any input: rows that do not run from μ = 0 to 1 in increasing order are refused
// naming the file and the row, and a curve that reaches 0 leaves the relative metric undefined (the file named).
TEST(FitTarget, BadMeasuredRowsAreRefusedNamingTheRow) {
    const auto rows_of = [](std::vector<double> mu) {
        std::vector<ReflectanceRow> rows;
        for (double m : mu) rows.push_back({m, RGB{0.9, 0.8, 0.7}});
        return rows;
    };
    const auto make = [&](std::vector<ReflectanceRow> rows) {
        return ReflectanceTarget("bad", "bad.csv", std::move(rows), env().colorimetry, env().converter, {});
    };
    try {
        make(rows_of({0.0, 0.5, 0.5, 1.0}));
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_TRUE(StartsWith(e.what(), "bad.csv:3:")) << e.what();
    }
    EXPECT_THROW(make(rows_of({0.1, 1.0})), InputError);
    EXPECT_THROW(make(rows_of({0.0, 0.9})), InputError);
    EXPECT_THROW(make(rows_of({0.0})), InputError);
    std::vector<ReflectanceRow> dark = rows_of({0.0, 0.5, 1.0});
    dark[2].value.g = 0;
    const ReflectanceTarget zero = make(dark);
    const std::vector<const Model*> models{&find_model("schlick")};
    try {
        fit_models(zero, models);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_TRUE(StartsWith(e.what(), "bad.csv: relative error undefined for bad")) << e.what();
    }
}

}  // namespace test_fit_target
}  // namespace metalfit
