// Levenberg–Marquardt for a few bounded parameters (K ≤ 4), with the normal equations solved directly: what the
// variable-projection fits solve when two non-linear parameters are left (schlick-comp-general's p and α,
// rational's c and d), at a fraction of a general solver's cost per iteration. The step control is Ceres's
// Levenberg–Marquardt strategy (Nielsen's radius update, the Jacobian's column norms as the damping's scaling; the
// same tolerances as the Ceres fits); bounds are kept by an active set: a parameter on a bound the gradient points
// out of is held there for the step, and every step is clamped into the box.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace metalfit {

struct BoundedLmSettings {
    static constexpr int kMaxIterations = 400;
    static constexpr double kFunctionTolerance = 1e-15;   // |Δcost| / cost of an accepted step
    static constexpr double kGradientTolerance = 1e-16;   // max |x − clamp(x − g)|
    static constexpr double kParameterTolerance = 1e-14;  // |step| / (|x| + tolerance)
    static constexpr double kInitialRadius = 1e4;
    static constexpr double kMinRadius = 1e-32;
    static constexpr double kMinRelativeDecrease = 1e-3;
};

template <std::size_t K>
struct BoundedLmResult {
    std::array<double, K> x{};
    double initial_cost = std::numeric_limits<double>::quiet_NaN();
    double cost = std::numeric_limits<double>::quiet_NaN();  // NaN: the start could not be evaluated
    int iterations = 0;
    bool converged = false;
    bool abandoned = false;  // keep_going said no
};

// f(x, r, J) writes the n residuals r and their Jacobian J (n × K, row-major) at x and returns false where x cannot
// be evaluated (the step is then rejected, as a Ceres cost function returning false). keep_going(iteration, cost, x)
// is asked after every accepted step; false abandons the solve (result.abandoned).
template <std::size_t K, class F, class Keep>
BoundedLmResult<K> bounded_levenberg_marquardt(F&& f, std::size_t n, std::array<double, K> x,
                                               const std::array<double, K>& lower, const std::array<double, K>& upper,
                                               Keep&& keep_going) {
    using S = BoundedLmSettings;
    BoundedLmResult<K> result;
    for (std::size_t j = 0; j < K; ++j) x[j] = std::clamp(x[j], lower[j], upper[j]);
    result.x = x;
    std::vector<double> r(n), J(n * K), r_trial(n), J_trial(n * K);
    const auto cost_of = [n](const std::vector<double>& v) {
        double c = 0;
        for (std::size_t i = 0; i < n; ++i) c += 0.5 * v[i] * v[i];
        return c;
    };
    if (!f(x.data(), r.data(), J.data())) return result;
    double cost = cost_of(r);
    if (!std::isfinite(cost)) return result;
    result.initial_cost = result.cost = cost;
    double radius = S::kInitialRadius, decrease_factor = 2.0;
    for (int iteration = 1; iteration <= S::kMaxIterations; ++iteration) {
        result.iterations = iteration;
        // g = Jᵀ r, H = Jᵀ J.
        std::array<double, K> g{};
        std::array<std::array<double, K>, K> H{};
        for (std::size_t i = 0; i < n; ++i) {
            const double* row = &J[i * K];
            for (std::size_t a = 0; a < K; ++a) {
                g[a] += row[a] * r[i];
                for (std::size_t b = 0; b <= a; ++b) H[a][b] += row[a] * row[b];
            }
        }
        for (std::size_t a = 0; a < K; ++a)
            for (std::size_t b = 0; b < a; ++b) H[b][a] = H[a][b];
        double projected_gradient = 0;
        for (std::size_t j = 0; j < K; ++j)
            projected_gradient =
                std::max(projected_gradient, std::abs(x[j] - std::clamp(x[j] - g[j], lower[j], upper[j])));
        if (projected_gradient <= S::kGradientTolerance) {
            result.converged = true;
            break;
        }
        // The free parameters: not on a bound the descent direction −g leaves the box through.
        std::array<bool, K> free{};
        for (std::size_t j = 0; j < K; ++j)
            free[j] = !((x[j] <= lower[j] && g[j] > 0) || (x[j] >= upper[j] && g[j] < 0));
        // (H + D / radius) δ = −g over the free parameters, D = diag(H) clamped as Ceres does.
        std::array<std::array<double, K + 1>, K> system{};
        std::array<std::size_t, K> index{};
        std::size_t m = 0;
        for (std::size_t a = 0; a < K; ++a) {
            if (!free[a]) continue;
            index[m] = a;
            std::size_t col = 0;
            for (std::size_t b = 0; b < K; ++b) {
                if (!free[b]) continue;
                system[m][col++] = H[a][b];
            }
            system[m][m] += std::clamp(H[a][a], 1e-6, 1e32) / radius;
            system[m][K] = -g[a];
            ++m;
        }
        if (m == 0) {
            result.converged = true;
            break;
        }
        // Gaussian elimination with partial pivoting on the m × m system.
        bool singular = false;
        for (std::size_t c = 0; c < m && !singular; ++c) {
            std::size_t pivot = c;
            for (std::size_t row = c + 1; row < m; ++row)
                if (std::abs(system[row][c]) > std::abs(system[pivot][c])) pivot = row;
            if (!(std::abs(system[pivot][c]) > 0)) {
                singular = true;
                break;
            }
            std::swap(system[c], system[pivot]);
            for (std::size_t row = c + 1; row < m; ++row) {
                const double factor = system[row][c] / system[c][c];
                for (std::size_t col = c; col < m; ++col) system[row][col] -= factor * system[c][col];
                system[row][K] -= factor * system[c][K];
            }
        }
        std::array<double, K> step{};
        if (!singular)
            for (std::size_t c = m; c-- > 0;) {
                double v = system[c][K];
                for (std::size_t col = c + 1; col < m; ++col) v -= system[c][col] * step[index[col]];
                step[index[c]] = v / system[c][c];
            }
        std::array<double, K> trial = x;
        double step_norm = 0, x_norm = 0;
        for (std::size_t j = 0; j < K; ++j) {
            trial[j] = std::clamp(x[j] + step[j], lower[j], upper[j]);
            step[j] = trial[j] - x[j];
            step_norm += step[j] * step[j];
            x_norm += x[j] * x[j];
        }
        step_norm = std::sqrt(step_norm), x_norm = std::sqrt(x_norm);
        if (!singular && step_norm <= S::kParameterTolerance * (x_norm + S::kParameterTolerance)) {
            result.converged = true;
            break;
        }
        // The model's decrease for the step taken (after clamping): −(g·δ + ½ δᵀ H δ).
        double predicted = 0;
        for (std::size_t a = 0; a < K; ++a) {
            double h = 0;
            for (std::size_t b = 0; b < K; ++b) h += H[a][b] * step[b];
            predicted -= g[a] * step[a] + 0.5 * step[a] * h;
        }
        const bool evaluated = !singular && f(trial.data(), r_trial.data(), J_trial.data());
        const double trial_cost = evaluated ? cost_of(r_trial) : std::numeric_limits<double>::quiet_NaN();
        const double actual = cost - trial_cost;
        const double rho = predicted > 0 ? actual / predicted : -1.0;
        if (std::isfinite(trial_cost) && rho > S::kMinRelativeDecrease) {
            x = trial, cost = trial_cost;
            std::swap(r, r_trial);
            std::swap(J, J_trial);
            result.x = x, result.cost = cost;
            radius = radius / std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * rho - 1.0, 3));
            decrease_factor = 2.0;
            if (std::abs(actual) <= S::kFunctionTolerance * cost) {
                result.converged = true;
                break;
            }
            if (!keep_going(iteration, cost, x)) {
                result.abandoned = true;
                break;
            }
        } else {
            radius /= decrease_factor;
            decrease_factor *= 2.0;
            if (radius < S::kMinRadius) {
                result.converged = true;
                break;
            }
        }
    }
    return result;
}

}  // namespace metalfit
