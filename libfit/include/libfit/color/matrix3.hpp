// A 3×3 matrix of doubles acting on XYZ (chromatic adaptation, cone spaces). Row-major; small and exact enough
// for colorimetry (libfit does not use Eigen, see libfit/CMakeLists.txt).
#pragma once

#include <array>

#include "libfit/color/color.hpp"

namespace metalfit {

struct Matrix3 {
    std::array<std::array<double, 3>, 3> m{};

    static constexpr Matrix3 identity() { return {{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}}; }
    static constexpr Matrix3 diagonal(double a, double b, double c) { return {{{{a, 0, 0}, {0, b, 0}, {0, 0, c}}}}; }

    constexpr double operator()(int row, int col) const { return m[row][col]; }
    constexpr XYZ operator*(const XYZ& v) const {
        return {m[0][0] * v.X + m[0][1] * v.Y + m[0][2] * v.Z, m[1][0] * v.X + m[1][1] * v.Y + m[1][2] * v.Z,
                m[2][0] * v.X + m[2][1] * v.Y + m[2][2] * v.Z};
    }
    constexpr Matrix3 operator*(const Matrix3& b) const {
        Matrix3 r;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) r.m[i][j] = m[i][0] * b.m[0][j] + m[i][1] * b.m[1][j] + m[i][2] * b.m[2][j];
        return r;
    }
    friend constexpr bool operator==(const Matrix3&, const Matrix3&) = default;
};

// The inverse by the adjugate; throws std::domain_error for a singular matrix.
Matrix3 inverse(const Matrix3& a);

}  // namespace metalfit
