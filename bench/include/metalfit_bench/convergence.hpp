// How an integral estimated with N Gauss–Legendre nodes on [0, 1] (libfit's gauss_legendre_unit) changes with N:
// the estimate at each N, its change from the previous N and its distance to the estimate at a reference N.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "metalfit_bench/environment.hpp"

namespace metalfit::bench {

struct ConvergencePoint {
    int nodes = 0;
    double estimate = 0;      // Σ w_i f(μ_i)
    double change = 0;        // |estimate − estimate at the previous N| (NaN for the first N)
    double to_reference = 0;  // |estimate − estimate at the reference N|
    double seconds = 0;       // time to evaluate f at the N nodes and sum
};

struct Convergence {
    int reference_nodes = 0;
    double reference_estimate = 0;
    std::vector<ConvergencePoint> points;
};

// ∫₀¹ f(μ) dμ at each N of `nodes` (in the order given) and at `reference_nodes`.
Convergence gauss_legendre_convergence(const std::function<double(double)>& f, std::span<const int> nodes,
                                       int reference_nodes);

// The node counts of the issue: 8, 16, …, 512.
std::vector<int> convergence_node_counts();

// On one material: the cost of the spectral integration at each N (the exact reference at the N nodes, computed
// once), and how much each model's fitted worst-channel rel_rms changes with N, relative to reference_nodes:
// |rms(N) − rms(ref)| / rms(ref), each channel's ∫ ((M − R) / R)² dμ integrated by gauss_legendre_convergence.
struct FittedConvergence {
    int reference_nodes = 0;
    std::vector<int> nodes;
    std::vector<double> integration_ms;               // per N
    std::vector<std::string> models;                  // all_models() order
    std::vector<std::vector<double>> rel_rms_change;  // [N][model]
};
FittedConvergence fitted_rel_rms_convergence(const PreparedMaterial& material, int reference_nodes = 2048);

}  // namespace metalfit::bench
