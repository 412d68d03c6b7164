#include "libfit/models/lazanyi_comp/lazanyi_comp.hpp"

#include <algorithm>
#include <cmath>

#include "models/closed_form_support.hpp"

namespace metalfit::models {

namespace {

constexpr double kMatchMu = 0.15;  // where the thesis matches the compensation to the error
constexpr double kSlopeStep = 1e-3;

// R at the μ the construction looks at (μ = 0, kSlopeStep, 2 kSlopeStep, kMatchMu), evaluated once for every form
// and channel.
struct ReferenceSamples {
    RGB at0, at1, at2, at_match;
    explicit ReferenceSamples(const ClosedFormInput& input)
        : at0(input.reference(0.0)),
          at1(input.reference(kSlopeStep)),
          at2(input.reference(2.0 * kSlopeStep)),
          at_match(input.reference(kMatchMu)) {}
};

// The thesis construction on one channel of a rescaled Schlick F* = Lazanyi(n, k).
ClosedFormChannel compensate(const ReferenceSamples& R, int c, const ChannelParameters& nk) {
    const auto error = [&](const RGB& reference, double mu) { return reference[c] - Lazanyi::evaluate(nk.data(), mu); };
    // One-sided second-order slope at μ = 0; e(0) is not assumed to be 0.
    const double e0 = error(R.at0, 0.0), e1 = error(R.at1, kSlopeStep), e2 = error(R.at2, 2.0 * kSlopeStep);
    const double a = -(-3.0 * e0 + 4.0 * e1 - e2) / (2.0 * kSlopeStep);
    const double e_match = error(R.at_match, kMatchMu);
    const auto& a_bounds = LazanyiComp::kParameters[2];
    const auto& alpha_bounds = LazanyiComp::kParameters[3];
    if (a == 0.0) return {{}, "the error's slope at grazing is 0 (a = 0), alpha undefined"};
    if (a < a_bounds.lower || a > a_bounds.upper)
        return {{},
                "diverges: a = " + detail::format_number(a) + " outside [" + detail::format_number(a_bounds.lower) +
                    ", " + detail::format_number(a_bounds.upper) + "]"};
    const double argument = e_match / (-kMatchMu * a);
    if (!(argument > 0.0))
        return {{},
                "alpha undefined: ln of " + detail::format_number(argument) +
                    " (the error at mu = 0.15 and the slope at grazing disagree in sign)"};
    const double alpha = std::log(argument) / std::log(1.0 - kMatchMu);
    if (!std::isfinite(alpha) || alpha < alpha_bounds.lower || alpha > alpha_bounds.upper)
        return {{},
                "diverges: alpha = " + detail::format_number(alpha) + " outside [" +
                    detail::format_number(alpha_bounds.lower) + ", " + detail::format_number(alpha_bounds.upper) + "]"};
    return {ChannelParameters{nk[0], nk[1], a, alpha}, {}};
}

}  // namespace

std::vector<ChannelParameters> LazanyiComp::target_starts(const ChannelTarget& t) {
    constexpr int kAlphaSteps = 48;
    constexpr std::size_t kKept = 3;
    const auto& alpha_bounds = kParameters[3];
    const auto& a_bounds = kParameters[2];
    struct Candidate {
        double cost, F0, a, alpha;
    };
    std::vector<Candidate> candidates;
    // The projection's normal equations of F0 and a at each α of the grid (residual_i = x1_i F0 + x2_i a − y_i), solved
    // here with F0 capped at 1 and a clamped.
    const Projection projection(t);
    std::vector<double> x2(projection.residuals());
    for (int j = 0; j <= kAlphaSteps; ++j) {
        const double alpha =
            alpha_bounds.lower * std::pow(alpha_bounds.upper / alpha_bounds.lower, double(j) / kAlphaSteps);
        const auto [s11, s12, s22, s1y, s2y] = projection.normal_equations(alpha, x2.data());
        const double det = s11 * s22 - s12 * s12;
        if (!(std::abs(det) > 1e-300)) continue;
        double F0 = (s22 * s1y - s12 * s2y) / det;
        double a = (s11 * s2y - s12 * s1y) / det;
        if (F0 > 1.0) F0 = 1.0, a = (s2y - s12) / s22;  // F* cannot pass 1: solve a with F0 = 1
        a = std::clamp(a, a_bounds.lower, a_bounds.upper);
        // cost = Σ (x1 F0 + x2 a − y)², expanded (Σ y² is the same for every α and left out).
        const double cost = F0 * F0 * s11 + 2 * F0 * a * s12 + a * a * s22 - 2 * F0 * s1y - 2 * a * s2y;
        candidates.push_back({cost, F0, a, alpha});
    }
    std::sort(candidates.begin(), candidates.end(),
              [](const Candidate& x, const Candidate& y) { return x.cost < y.cost; });
    std::vector<ChannelParameters> starts;
    for (std::size_t i = 0; i < std::min(kKept, candidates.size()); ++i) {
        ChannelParameters p = Lazanyi::nk_with_F0(candidates[i].F0);
        p.push_back(candidates[i].a);
        p.push_back(candidates[i].alpha);
        starts.push_back(std::move(p));
    }
    return starts;
}

std::vector<ClosedForm> LazanyiComp::closed_forms(const ClosedFormInput& input) {
    std::vector<ClosedForm> forms;
    const ReferenceSamples samples(input);
    for (const ClosedForm& base : Lazanyi::closed_forms(input)) {
        ClosedForm form{base.id, base.description + "; a from the error's slope at grazing, alpha from mu = 0.15", {}};
        for (int c = 0; c < 3; ++c)
            form.channel[c] =
                base.channel[c].params ? compensate(samples, c, *base.channel[c].params) : base.channel[c];
        forms.push_back(std::move(form));
    }
    return forms;
}

}  // namespace metalfit::models
