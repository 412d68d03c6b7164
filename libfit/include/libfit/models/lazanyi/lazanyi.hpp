// Lazányi's rescaled Schlick (thesis eq. 3.2): Schlick with the exact normal-incidence reflectance of η = n + i k,
// F*(μ) = ((n − 1)² + k² + 4n(1 − μ)^5) / ((n + 1)² + k²). Only F0(n, k) shapes the curve, so F0 < 1 and the fitted
// n, k are one point of a one-dimensional family (the one nearest the start). GLSL: lazanyi.glsl beside this header.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>
#include <vector>

#include "libfit/models/model.hpp"
#include "libfit/models/model_math.hpp"
#include "libfit/reference/channel_target.hpp"

namespace metalfit::models {

struct Lazanyi {
    static constexpr std::string_view kId = "lazanyi";
    static constexpr std::string_view kTitle = "Lazányi's rescaled Schlick (thesis eq. 3.2)";
    static constexpr std::array<Parameter, 2> kParameters{{
        {"n", 1e-3, 100.0, "refractive index", ParameterKind::index},
        {"k", 0.0, 1e4, "extinction coefficient", ParameterKind::index},
    }};
    static constexpr std::string_view kGlslFunction = "metalfit_lazanyi";
    static constexpr std::array<std::string_view, 1> kGlslFiles{"lazanyi"};
    static constexpr MaterialxForm kMaterialx = MaterialxForm::generalized_schlick;
    // --pin F0: F(1) = F0(n, k) = F0 with k² = (F0 (n + 1)² − (n − 1)²) / (1 − F0) for the fitted n (k = 0 below the
    // dielectric F0 of that n; F0 ≥ 1 has no k: the bound, and the record reports the pin as not met).
    static constexpr std::size_t kPinnedParameter = 1;
    template <class T>
    static T pinned_value(const T* p, const T& F0) {
        if (!(F0 < T(1))) return T(kParameters[1].upper);
        const T& n = p[0];
        return model_math::sqrt_or_zero((F0 * (n + T(1)) * (n + T(1)) - (n - T(1)) * (n - T(1))) / (T(1) - F0));
    }
    // F* is Schlick with F0 = F0(n, k): F82-tint with that F0 and tint 1.
    static std::array<double, 2> to_f82_tint(const double* p) {
        const double n = p[0], k2 = p[1] * p[1];
        return {((n - 1) * (n - 1) + k2) / ((n + 1) * (n + 1) + k2), 1.0};
    }

    template <class T>
    static T evaluate(const T* p, const T& mu_in) {
        const T mu = model_math::clamp_mu(mu_in);
        const T& n = p[0];
        const T k2 = p[1] * p[1];
        return ((n - T(1)) * (n - T(1)) + k2 + T(4) * n * model_math::schlick_weight(mu)) /
               ((n + T(1)) * (n + T(1)) + k2);
    }

    // "nk-700-550-435": n, k of the data at the thesis's wavelengths; "r1": F0 = R(1) with n from those wavelengths
    // and k solved (k = 0 and n solved where F0 is below the dielectric value; undefined where R(1) ≥ 1).
    static std::vector<ClosedForm> closed_forms(const ClosedFormInput& input);
    static std::vector<ChannelParameters> neutral_starts() { return {{1.0, 3.0}}; }
    // The least-squares F0 of the target (F* is linear in F0), as n, k.
    static std::vector<ChannelParameters> target_starts(const ChannelTarget& target);
    // That F0, unbounded (NaN for a target without weight).
    static double least_squares_F0(const ChannelTarget& target);

    // An n, k with the given F0: n = 1, k = 2 sqrt(F0 / (1 − F0)); F0 ≥ 1 (out of gamut) goes to the corner of the
    // bounds nearest it (n lowest, k highest), where k no longer moves F0 and a solver started lower would stall.
    static ChannelParameters nk_with_F0(double F0);
    // The fit by variable projection (ProjectedFit): F* = w + F0 (1 − w) (w = (1 − μ)⁵) is linear in F0 alone, so no
    // parameter is left for Ceres: F0 is the least-squares solution in [0, 1] and n, k come from it keeping each
    // start's n where some k allows it (the first start wins ties).
    class Projection {
    public:
        static constexpr std::array<std::size_t, 0> kNonlinearParameters{};
        explicit Projection(const ChannelTarget& t) : residuals_(t.mu.size()) {
            const double F0 = least_squares_F0(t);
            F0_ = std::isfinite(F0) ? std::clamp(F0, 0.0, 1.0) : 0.0;
        }
        std::size_t residuals() const { return residuals_; }
        ChannelParameters parameters(const double*, const ChannelParameters& start) const {
            return nk_near(F0_, start[0]);
        }

    private:
        std::size_t residuals_;
        double F0_ = 0;
    };

    // An n, k with the given F0 keeping n where some k ≥ 0 allows it; otherwise k = 0 and the dielectric n nearest
    // it; F0 ≥ 1 and F0 ≤ 0 as nk_with_F0.
    static ChannelParameters nk_near(double F0, double n);
};

}  // namespace metalfit::models
