// Error metrics of a model's parameters against a sampled reference curve (the definitions of docs/fitting.md, "Definitions").
#pragma once

#include <array>

#include "libfit/models/model.hpp"
#include "libfit/reference/sampled_reference.hpp"

namespace metalfit {

using PerChannel = std::array<double, 3>;

struct Metrics {
    // sqrt(∫ w ((M − R)/R)² dμ); NaN where the relative metric is undefined (R ≤ 0 somewhere).
    PerChannel rel_rms{};
    PerChannel abs_rms{};  // sqrt(∫ w (M − R)² dμ)
    PerChannel max_rel{};  // max |M − R| / R over the dense grid and the nodes, and where
    PerChannel max_rel_mu{};
    PerChannel max_abs{};  // max |M − R|, and where
    PerChannel max_abs_mu{};
    double de2000_mean = 0;  // ∫ w ΔE2000 dμ (w integrates to 1)
    double de2000_max = 0;   // over the dense grid and the nodes, and where
    double de2000_max_mu = 0;
    PerChannel albedo_err{};  // ∫ 2μ (M − R) dμ, signed (energy the model adds)
    // The error at normal incidence, signed and relative: M(1) / R(1) − 1 (NaN where R(1) ≤ 0). Not one of the seven
    // metrics of docs/fitting.md, "Definitions": reported beside them (docs/fit-record.md), for the pinned-F0 convention (--pin F0).
    PerChannel err_f0{};

    // The metric the fit minimises, per channel.
    const PerChannel& rms(ErrorMetric metric) const { return metric == ErrorMetric::rel ? rel_rms : abs_rms; }
};

double worst_channel(const PerChannel& values);  // max over R, G, B (NaN if any is NaN)

Metrics compute_metrics(const Model& model, const ModelParameters& params, const SampledReference& reference);

}  // namespace metalfit
