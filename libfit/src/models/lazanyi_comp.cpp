#include "libfit/models/lazanyi_comp.hpp"

#include <cmath>

#include "closed_form_support.hpp"

namespace metalfit::models {

namespace {

constexpr double kMatchMu = 0.15;  // where the thesis matches the compensation to the error
constexpr double kSlopeStep = 1e-3;

// The thesis construction on one channel of a rescaled Schlick F* = Lazanyi(n, k).
ClosedFormChannel compensate(const ClosedFormInput& input, int c, const ChannelParameters& nk) {
    const auto error = [&](double mu) { return input.reference(mu)[c] - Lazanyi::evaluate(nk.data(), mu); };
    // One-sided second-order slope at μ = 0; e(0) is not assumed to be 0.
    const double e0 = error(0.0), e1 = error(kSlopeStep), e2 = error(2.0 * kSlopeStep);
    const double a = -(-3.0 * e0 + 4.0 * e1 - e2) / (2.0 * kSlopeStep);
    const double e_match = error(kMatchMu);
    const auto& a_bounds = LazanyiComp::kParameters[2];
    const auto& alpha_bounds = LazanyiComp::kParameters[3];
    if (a == 0.0) return {{}, "the error's slope at grazing is 0 (a = 0), alpha undefined"};
    if (a < a_bounds.lower || a > a_bounds.upper)
        return {{}, "diverges: a = " + detail::format_number(a) + " outside [" + detail::format_number(a_bounds.lower) +
                        ", " + detail::format_number(a_bounds.upper) + "]"};
    const double argument = e_match / (-kMatchMu * a);
    if (!(argument > 0.0))
        return {{}, "alpha undefined: ln of " + detail::format_number(argument) +
                        " (the error at mu = 0.15 and the slope at grazing disagree in sign)"};
    const double alpha = std::log(argument) / std::log(1.0 - kMatchMu);
    if (!std::isfinite(alpha) || alpha < alpha_bounds.lower || alpha > alpha_bounds.upper)
        return {{}, "diverges: alpha = " + detail::format_number(alpha) + " outside [" +
                        detail::format_number(alpha_bounds.lower) + ", " + detail::format_number(alpha_bounds.upper) +
                        "]"};
    return {ChannelParameters{nk[0], nk[1], a, alpha}, {}};
}

}  // namespace

std::vector<ClosedForm> LazanyiComp::closed_forms(const ClosedFormInput& input) {
    std::vector<ClosedForm> forms;
    for (const ClosedForm& base : Lazanyi::closed_forms(input)) {
        ClosedForm form{base.id, base.description + "; a from the error's slope at grazing, alpha from mu = 0.15", {}};
        for (int c = 0; c < 3; ++c)
            form.channel[c] = base.channel[c].params ? compensate(input, c, *base.channel[c].params) : base.channel[c];
        forms.push_back(std::move(form));
    }
    return forms;
}

}  // namespace metalfit::models
