#include "libfit/base/quadrature.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace metalfit {

namespace {

// P_n and its derivative at x = 1 − d, evaluated in terms of d so that a root near x = 1 keeps
// its relative accuracy in d = 1 − x (x itself could only resolve it to an ulp of 1).
struct Legendre {
    double p = 0.0;   // P_n(x)
    double dp = 0.0;  // P_n'(x)
};

Legendre legendre_at(int n, double d) {
    // (k + 1) P_{k+1} = (2k + 1) x P_k − k P_{k−1}, with x P_k = P_k − d P_k.
    double p_prev = 1.0, p = 1.0 - d;  // P_0, P_1
    for (int k = 1; k < n; ++k) {
        const double p_next = ((2 * k + 1) * (p - d * p) - k * p_prev) / (k + 1);
        p_prev = p;
        p = p_next;
    }
    // (1 − x²) P_n' = n (P_{n−1} − x P_n), 1 − x² = d (2 − d).
    const double dp = n * (p_prev - (p - d * p)) / (d * (2.0 - d));
    return {p, dp};
}

}  // namespace

std::vector<QuadratureNode> gauss_legendre_unit(int n) {
    if (n < 1 || n > 4096)
        throw std::invalid_argument("Gauss–Legendre needs 1 ≤ n ≤ 4096 nodes, got " + std::to_string(n));

    std::vector<QuadratureNode> nodes(static_cast<std::size_t>(n));
    constexpr double eps = std::numeric_limits<double>::epsilon();
    // Roots x_1 > x_2 > … of P_n on (0, 1); the rest follow by symmetry. Node i sits at
    // μ = (1 − x)/2 = d/2 and its mirror at 1 − d/2; the weight on [0, 1] is 1 / ((1 − x²) P_n'²).
    for (int i = 1; i <= n / 2; ++i) {
        const double theta = std::numbers::pi * (i - 0.25) / (n + 0.5);  // Tricomi's first guess
        const double s = std::sin(0.5 * theta);
        double d = 2.0 * s * s;  // 1 − cos θ
        // Newton converges quadratically from this guess; stop at full relative precision in d,
        // or once the steps stop shrinking (rounding noise in P_n near the middle of the interval).
        double previous_step = INFINITY;
        for (int iter = 0; iter < 100; ++iter) {
            const Legendre l = legendre_at(n, d);
            const double step = l.p / l.dp;  // x ← x − P/P'  ⇔  d ← d + P/P'
            d += step;
            if (std::abs(step) <= 2.0 * eps * d) break;
            if (std::abs(step) < 1e-12 && std::abs(step) >= 0.5 * previous_step) break;
            previous_step = std::abs(step);
        }
        const Legendre l = legendre_at(n, d);
        const double weight = 1.0 / (d * (2.0 - d) * l.dp * l.dp);
        const double mu = 0.5 * d;
        nodes[static_cast<std::size_t>(i - 1)] = {mu, weight};
        nodes[static_cast<std::size_t>(n - i)] = {1.0 - mu, weight};
    }
    if (n % 2 == 1) {
        // x = 0 is a root of every odd P_n; there P_n' = n P_{n−1}(0) and 1 − x² = 1.
        const Legendre l = legendre_at(n, 1.0);
        nodes[static_cast<std::size_t>(n / 2)] = {0.5, 1.0 / (l.dp * l.dp)};
    }
    return nodes;
}

}  // namespace metalfit
