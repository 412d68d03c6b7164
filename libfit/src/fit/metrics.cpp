#include "libfit/fit/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <span>
#include <vector>

namespace metalfit {

double worst_channel(const PerChannel& values) {
    if (std::any_of(values.begin(), values.end(), [](double v) { return std::isnan(v); }))
        return std::numeric_limits<double>::quiet_NaN();
    return *std::max_element(values.begin(), values.end());
}

Metrics compute_metrics(const Model& model, const ModelParameters& params, const SampledReference& reference) {
    // The model at every sample at once (nodes, then the dense grid: reference.mu()), and the colours of all of them
    // through one OCIO apply; then the sums in the samples' order.
    const std::span<const double> mu = reference.mu();
    const std::size_t n = mu.size();
    const auto curves = std::make_unique_for_overwrite<double[]>(3 * n);  // each written in full by evaluate
    for (int c = 0; c < 3; ++c)
        model.evaluate(std::span<const double>(params[c]), mu, std::span<double>(&curves[c * n], n));
    std::vector<RGB> values;
    values.reserve(n);
    for (std::size_t i = 0; i < n; ++i) values.emplace_back(curves[i], curves[n + i], curves[2 * n + i]);
    const std::vector<Lab> labs = reference.lab(values);

    const bool rel_defined = !reference.rel_undefined();
    Metrics m;
    PerChannel rel_sum{}, abs_sum{};
    const auto keep_max = [](double value, double mu, double& max, double& max_mu) {
        if (value > max) max = value, max_mu = mu;
    };
    std::size_t next = 0;
    const auto visit = [&](const SampledReference::Sample& s) {
        // The channels as plain arrays (RGB's operator[] checks its index on every access).
        const double M[3] = {values[next].r, values[next].g, values[next].b};
        const double R[3] = {s.value.r, s.value.g, s.value.b};
        for (int c = 0; c < 3; ++c) {
            const double d = M[c] - R[c];
            abs_sum[c] += s.weight * d * d;
            m.albedo_err[c] += s.albedo_weight * d;
            keep_max(std::abs(d), s.mu, m.max_abs[c], m.max_abs_mu[c]);
            if (rel_defined) {
                const double r = d / R[c];
                rel_sum[c] += s.weight * r * r;
                keep_max(std::abs(r), s.mu, m.max_rel[c], m.max_rel_mu[c]);
            }
        }
        const double de = ciede2000(s.lab, labs[next++]);
        m.de2000_mean += s.weight * de;
        keep_max(de, s.mu, m.de2000_max, m.de2000_max_mu);
    };
    for (const auto& s : reference.nodes()) visit(s);
    for (const auto& s : reference.dense()) visit(s);

    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int c = 0; c < 3; ++c) {
        m.abs_rms[c] = std::sqrt(abs_sum[c]);
        m.rel_rms[c] = rel_defined ? std::sqrt(rel_sum[c]) : nan;
        if (!rel_defined) m.max_rel[c] = m.max_rel_mu[c] = nan;
    }
    // The dense grid ends at μ = 1 exactly (SampledReference): the last value is the model at normal incidence.
    const SampledReference::Sample& normal = reference.dense().back();
    const RGB& at_normal = values.back();
    for (int c = 0; c < 3; ++c) m.err_f0[c] = normal.value[c] > 0.0 ? at_normal[c] / normal.value[c] - 1.0 : nan;
    return m;
}

}  // namespace metalfit
