#include "libfit/fit/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

namespace metalfit {

double worst_channel(const PerChannel& values) {
    if (std::any_of(values.begin(), values.end(), [](double v) { return std::isnan(v); }))
        return std::numeric_limits<double>::quiet_NaN();
    return *std::max_element(values.begin(), values.end());
}

namespace {

// The model's three channels at every μ of `mu`, as colours (one evaluate per channel over all of them).
std::vector<RGB> model_values(const Model& model, const ModelParameters& params, std::span<const double> mu) {
    const std::size_t n = mu.size();
    std::vector<double> curves(3 * n);
    for (int c = 0; c < 3; ++c)
        model.evaluate(std::span<const double>(params[c]), mu, std::span<double>(curves.data() + c * n, n));
    std::vector<RGB> values;
    values.reserve(n);
    for (std::size_t i = 0; i < n; ++i) values.emplace_back(curves[i], curves[n + i], curves[2 * n + i]);
    return values;
}

// The errors whose maxima are reported: |M − R| and |M − R| / R per channel, ΔE2000.
constexpr int kAbs = 0, kRel = 3, kDeltaE = 6, kErrors = 7;
// A floor under each kind of error's (abs, rel, ΔE2000) local wiggle below: OCIO works in float32, so the errors
// wiggle from one μ to the next where they are flat (ΔE2000 by 3e-5 on tungsten's conductor-rgb closed form near
// μ = 1, where the grid's maximum lies between two nodes neither of which is a local maximum).
constexpr double kNoise[3] = {1e-7, 1e-7, 1e-5};

// Marks the grid points whose errors could exceed the largest error of the samples `mu` (the grid's ends, the nodes,
// in increasing μ): those strictly between two neighbouring samples where the larger of their errors, raised by twice
// the samples' local wiggle (how far a sample lies off the chord of its neighbours, the next two intervals' either
// side: the curvature between samples where the errors are smooth, the noise where they are not), by `noise` and by
// a thousandth of the largest error, reaches the largest error.
void mark_brackets(std::span<const double> mu, std::span<const double> error, double noise, std::vector<char>& marked) {
    const std::size_t m = mu.size();
    double largest = -std::numeric_limits<double>::infinity();
    for (const double e : error)
        if (e > largest) largest = e;
    if (!std::isfinite(largest)) {  // NaN or infinite errors: every grid point, as the whole scan did
        std::fill(marked.begin(), marked.end(), 1);
        return;
    }
    std::vector<double> wiggle(m, 0.0);
    for (std::size_t j = 1; j + 1 < m; ++j) {
        const double t = (mu[j] - mu[j - 1]) / (mu[j + 1] - mu[j - 1]);
        wiggle[j] = std::abs(error[j] - (error[j - 1] + t * (error[j + 1] - error[j - 1])));
    }
    const double threshold = largest - 1e-3 * std::abs(largest) - noise;
    for (std::size_t j = 0; j + 1 < m; ++j) {
        const int first = static_cast<int>(std::floor(mu[j] * kDenseIntervals)) + 1;
        const int last = static_cast<int>(std::ceil(mu[j + 1] * kDenseIntervals)) - 1;
        if (first > last) continue;
        double local = 0;
        for (std::size_t i = j == 0 ? 0 : j - 1; i <= std::min(j + 2, m - 1); ++i) local = std::max(local, wiggle[i]);
        if (!(std::max(error[j], error[j + 1]) + 2 * local < threshold))
            for (int i = first; i <= last; ++i) marked[static_cast<std::size_t>(i)] = 1;
    }
}

}  // namespace

Metrics compute_metrics(const Model& model, const ModelParameters& params, const SampledReference& reference) {
    // The integrals and the maxima of docs/fitting.md, "Metrics": the integrals on the nodes; the maxima over the nodes
    // and the grid μ = i / kDenseIntervals. The grid is visited where the nodes bracket a maximum (mark_brackets),
    // except where the reference is sampled whole (few nodes, R near 0): there all of it, as the record defines.
    const std::span<const SampledReference::Sample> nodes = reference.nodes();
    const std::size_t n = nodes.size();
    // The model at the nodes, then at both ends of the grid, and their colours in one OCIO apply.
    std::vector<double> mu;
    mu.reserve(n + 2);
    for (const auto& s : nodes) mu.push_back(s.mu);
    mu.push_back(0.0);
    mu.push_back(1.0);
    const std::vector<RGB> values = model_values(model, params, mu);
    const std::vector<Lab> labs = reference.lab(values);

    const bool rel_defined = !reference.rel_undefined();
    // The seven errors of one sample (ΔE2000 only where its colour is given; else 0).
    const auto errors_of = [&](const SampledReference::Sample& s, const RGB& value, const Lab* lab, double* e) {
        const double M[3] = {value.r, value.g, value.b};  // RGB's operator[] checks its index on every access
        const double R[3] = {s.value.r, s.value.g, s.value.b};
        for (int c = 0; c < 3; ++c) {
            e[kAbs + c] = M[c] - R[c];  // signed here; the maxima take |·|
            e[kRel + c] = rel_defined ? (M[c] - R[c]) / R[c] : 0.0;
        }
        e[kDeltaE] = lab ? ciede2000(s.lab, *lab) : 0.0;
    };
    Metrics m;
    PerChannel rel_sum{}, abs_sum{};
    const auto keep_max = [](double value, double mu, double& max, double& max_mu) {
        if (value > max) max = value, max_mu = mu;
    };
    // The sums on the nodes; the maxima over every sample visited, in the order nodes, grid.
    const auto visit = [&](const SampledReference::Sample& s, const double* e, bool node, bool with_lab) {
        for (int c = 0; c < 3; ++c) {
            const double d = e[kAbs + c];
            if (node) {
                abs_sum[c] += s.weight * d * d;
                m.albedo_err[c] += s.albedo_weight * d;
            }
            keep_max(std::abs(d), s.mu, m.max_abs[c], m.max_abs_mu[c]);
            if (rel_defined) {
                const double r = e[kRel + c];
                if (node) rel_sum[c] += s.weight * r * r;
                keep_max(std::abs(r), s.mu, m.max_rel[c], m.max_rel_mu[c]);
            }
        }
        if (with_lab) {
            if (node) m.de2000_mean += s.weight * e[kDeltaE];
            keep_max(e[kDeltaE], s.mu, m.de2000_max, m.de2000_max_mu);
        }
    };
    // The errors at μ = 0, the nodes, μ = 1 (increasing μ).
    const std::size_t samples = n + 2;
    std::vector<double> errors(kErrors * samples);
    const auto errors_at = [&](std::size_t position) { return &errors[position * kErrors]; };
    for (std::size_t i = 0; i < n; ++i) {
        errors_of(nodes[i], values[i], &labs[i], errors_at(i + 1));
        visit(nodes[i], errors_at(i + 1), true, true);
    }
    const SampledReference::Sample& at_zero = reference.grid(0);
    const SampledReference::Sample& normal = reference.normal();
    errors_of(at_zero, values[n], &labs[n], errors_at(0));
    errors_of(normal, values[n + 1], &labs[n + 1], errors_at(samples - 1));

    std::vector<int> grid;  // the grid points visited besides the ends, increasing
    std::vector<char> with_lab;
    if (reference.whole_grid()) {
        for (int i = 1; i < kDenseIntervals; ++i) grid.push_back(i);
        with_lab.assign(grid.size(), 1);
    } else {
        std::vector<double> sample_mu(samples), error(samples);
        sample_mu.front() = 0.0;
        for (std::size_t i = 0; i < n; ++i) sample_mu[i + 1] = nodes[i].mu;
        sample_mu.back() = 1.0;
        std::vector<char> marked(kDenseIntervals + 1, 0), marked_lab(kDenseIntervals + 1, 0);
        for (int k = 0; k < kErrors; ++k) {
            if (!rel_defined && k >= kRel && k < kDeltaE) continue;
            for (std::size_t j = 0; j < samples; ++j) error[j] = std::abs(errors_at(j)[k]);
            mark_brackets(sample_mu, error, kNoise[k / 3], k == kDeltaE ? marked_lab : marked);
        }
        for (int i = 1; i < kDenseIntervals; ++i)
            if (marked[static_cast<std::size_t>(i)] || marked_lab[static_cast<std::size_t>(i)]) {
                grid.push_back(i);
                with_lab.push_back(marked_lab[static_cast<std::size_t>(i)]);
            }
        reference.sample_grid(grid);
    }
    // The grid in its order: μ = 0, the points visited, μ = 1.
    std::vector<double> grid_mu;
    grid_mu.reserve(grid.size());
    for (const int i : grid) grid_mu.push_back(reference.grid(i).mu);
    const std::vector<RGB> grid_values = model_values(model, params, grid_mu);
    std::vector<RGB> lab_values;
    for (std::size_t j = 0; j < grid.size(); ++j)
        if (with_lab[j]) lab_values.push_back(grid_values[j]);
    const std::vector<Lab> grid_labs = reference.lab(lab_values);
    visit(at_zero, errors_at(0), false, true);
    double e[kErrors];
    for (std::size_t j = 0, next_lab = 0; j < grid.size(); ++j) {
        const Lab* lab = with_lab[j] ? &grid_labs[next_lab++] : nullptr;
        errors_of(reference.grid(grid[j]), grid_values[j], lab, e);
        visit(reference.grid(grid[j]), e, false, lab != nullptr);
    }
    visit(normal, errors_at(samples - 1), false, true);

    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int c = 0; c < 3; ++c) {
        m.abs_rms[c] = std::sqrt(abs_sum[c]);
        m.rel_rms[c] = rel_defined ? std::sqrt(rel_sum[c]) : nan;
        if (!rel_defined) m.max_rel[c] = m.max_rel_mu[c] = nan;
    }
    // The model at normal incidence against R(1).
    for (int c = 0; c < 3; ++c) m.err_f0[c] = normal.value[c] > 0.0 ? values[n + 1][c] / normal.value[c] - 1.0 : nan;
    return m;
}

}  // namespace metalfit
