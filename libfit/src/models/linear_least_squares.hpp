// Dense linear least squares for the starts of models that are linear in some parameters (internal): min ‖A x − y‖
// by Householder QR (no normal equations: the columns μ mᵖ of the compensation terms are close to collinear).
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace metalfit::detail {

// A is given by columns (each of the rows' length). Returns empty when A is rank deficient (a pivot below 1e-13 of
// the largest column norm).
inline std::optional<std::vector<double>> linear_least_squares(std::vector<std::vector<double>> A,
                                                               std::vector<double> y) {
    const std::size_t n = A.size();
    if (n == 0) return std::vector<double>{};
    const std::size_t m = y.size();
    double scale = 0.0;
    for (const auto& col : A) {
        double s = 0.0;
        for (double v : col) s += v * v;
        scale = std::fmax(scale, std::sqrt(s));
    }
    if (!(scale > 0.0) || m < n) return std::nullopt;
    std::vector<double> diag(n);
    for (std::size_t j = 0; j < n; ++j) {
        double norm = 0.0;
        for (std::size_t i = j; i < m; ++i) norm += A[j][i] * A[j][i];
        norm = std::sqrt(norm);
        if (!(norm > 1e-13 * scale)) return std::nullopt;
        const double alpha = A[j][j] > 0.0 ? -norm : norm;
        // v = a_j − alpha e_j (stored in A[j][j..]), H = I − 2 v vᵀ / vᵀv.
        A[j][j] -= alpha;
        double vv = 0.0;
        for (std::size_t i = j; i < m; ++i) vv += A[j][i] * A[j][i];
        const auto reflect = [&](std::vector<double>& x) {
            double d = 0.0;
            for (std::size_t i = j; i < m; ++i) d += A[j][i] * x[i];
            const double f = 2.0 * d / vv;
            for (std::size_t i = j; i < m; ++i) x[i] -= f * A[j][i];
        };
        for (std::size_t k = j + 1; k < n; ++k) reflect(A[k]);
        reflect(y);
        diag[j] = alpha;
    }
    // R x = Qᵀ y: R's diagonal in diag, above it A[k][j] (k > j).
    std::vector<double> x(n);
    for (std::size_t j = n; j-- > 0;) {
        double s = y[j];
        for (std::size_t k = j + 1; k < n; ++k) s -= A[k][j] * x[k];
        x[j] = s / diag[j];
    }
    return x;
}

}  // namespace metalfit::detail
