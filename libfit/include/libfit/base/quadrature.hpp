// Gauss–Legendre quadrature on [0, 1]: the nodes μ_i and weights w_i behind every error integral
// ∫₀¹ f(μ) dμ ≈ Σ w_i f(μ_i) (docs/fitting.md, "Definitions").
#pragma once

#include <vector>

namespace metalfit {

struct QuadratureNode {
    double mu = 0.0;      // node in [0, 1]
    double weight = 0.0;  // > 0
};

// Gauss–Legendre rule on [0, 1]: n nodes in ascending μ, weights sum to 1; exact for polynomials
// of degree ≤ 2n − 1. The nodes are the roots of P_n(2μ − 1), found by Newton's method on the
// three-term recurrence in double precision (absolute error ~1e-16, relative error small even for
// the node nearest 0); the rule is mirror symmetric, μ_i + μ_{n−1−i} = 1.
// Throws std::invalid_argument for n < 1 or n > 4096.
std::vector<QuadratureNode> gauss_legendre_unit(int n);

}  // namespace metalfit
