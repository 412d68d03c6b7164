#include "metalfit_bench/convergence.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>

#include "libfit/base/quadrature.hpp"

namespace metalfit::bench {
namespace {

double integrate(const std::function<double(double)>& f, int n) {
    double sum = 0;
    for (const QuadratureNode& q : gauss_legendre_unit(n)) sum += q.weight * f(q.mu);
    return sum;
}

}  // namespace

std::vector<int> convergence_node_counts() { return {8, 16, 32, 64, 128, 256, 512}; }

Convergence gauss_legendre_convergence(const std::function<double(double)>& f, std::span<const int> nodes,
                                       int reference_nodes) {
    Convergence c;
    c.reference_nodes = reference_nodes;
    c.reference_estimate = integrate(f, reference_nodes);
    double previous = std::numeric_limits<double>::quiet_NaN();
    for (int n : nodes) {
        const auto start = std::chrono::steady_clock::now();
        const double estimate = integrate(f, n);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        c.points.push_back(
            {n, estimate, std::abs(estimate - previous), std::abs(estimate - c.reference_estimate), seconds});
        previous = estimate;
    }
    return c;
}

FittedConvergence fitted_rel_rms_convergence(const PreparedMaterial& material, int reference_nodes) {
    std::map<double, RGB> cache;
    const auto reference = [&](double mu) -> const RGB& {
        auto it = cache.find(mu);
        if (it == cache.end()) it = cache.emplace(mu, material.curve(mu)).first;
        return it->second;
    };
    FittedConvergence out;
    out.reference_nodes = reference_nodes;
    out.nodes = convergence_node_counts();
    for (int n : out.nodes) {
        const auto start = std::chrono::steady_clock::now();
        for (const QuadratureNode& q : gauss_legendre_unit(n)) reference(q.mu);  // the first use of these nodes
        out.integration_ms.push_back(1e3 *
                                     std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    out.rel_rms_change.assign(out.nodes.size(), {});
    for (const Model* model : all_models()) {
        out.models.emplace_back(model->id());
        const ModelParameters& p = material.params(model->id());
        std::array<Convergence, 3> channel;
        for (int c = 0; c < 3; ++c) {
            const auto integrand = [&](double mu) {
                const double r = reference(mu)[c];
                const double e = (model->evaluate(std::span<const double>(p[c]), mu) - r) / r;
                return e * e;
            };
            channel[c] = gauss_legendre_convergence(integrand, out.nodes, reference_nodes);
        }
        double at_reference = 0;
        for (int c = 0; c < 3; ++c) at_reference = std::max(at_reference, std::sqrt(channel[c].reference_estimate));
        for (std::size_t i = 0; i < out.nodes.size(); ++i) {
            double at_n = 0;
            for (int c = 0; c < 3; ++c) at_n = std::max(at_n, std::sqrt(channel[c].points[i].estimate));
            out.rel_rms_change[i].push_back(std::abs(at_n - at_reference) / at_reference);
        }
    }
    return out;
}

}  // namespace metalfit::bench
