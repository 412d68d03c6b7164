#include "metalfit_bench/convergence.hpp"

#include <chrono>
#include <cmath>
#include <limits>

#include "libfit/quadrature.hpp"

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
        c.points.push_back({n, estimate, std::abs(estimate - previous), std::abs(estimate - c.reference_estimate), seconds});
        previous = estimate;
    }
    return c;
}

}  // namespace metalfit::bench
