#include "libfit/color/chromatic_adaptation.hpp"

#include <cmath>
#include <stdexcept>

#include "libfit/base/errors.hpp"

namespace metalfit {

Matrix3 inverse(const Matrix3& a) {
    const auto& m = a.m;
    const double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
    const double c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
    const double c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    const double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
    if (det == 0.0 || !std::isfinite(det)) throw std::domain_error("singular 3×3 matrix");
    Matrix3 r;
    r.m = {{{c00, m[0][2] * m[2][1] - m[0][1] * m[2][2], m[0][1] * m[1][2] - m[0][2] * m[1][1]},
            {c01, m[0][0] * m[2][2] - m[0][2] * m[2][0], m[0][2] * m[1][0] - m[0][0] * m[1][2]},
            {c02, m[0][1] * m[2][0] - m[0][0] * m[2][1], m[0][0] * m[1][1] - m[0][1] * m[1][0]}}};
    for (auto& row : r.m)
        for (double& v : row) v /= det;
    return r;
}

Adaptation parse_adaptation(std::string_view s) { return kAdaptationNames.parse(s); }

std::string to_string(Adaptation a) { return std::string(kAdaptationNames.name(a)); }

Matrix3 cone_matrix(Adaptation a) {
    switch (a) {
        case Adaptation::bradford:
            return {{{{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}}}};
        case Adaptation::cat02:
            return {{{{0.7328, 0.4296, -0.1624}, {-0.7036, 1.6975, 0.0061}, {0.0030, 0.0136, 0.9834}}}};
        case Adaptation::von_kries_xyz:
        case Adaptation::none: return Matrix3::identity();
    }
    return Matrix3::identity();
}

Matrix3 adaptation_matrix(Adaptation a, const XYZ& source_white, const XYZ& target_white) {
    if (a == Adaptation::none || source_white == target_white) return Matrix3::identity();
    const Matrix3 cone = cone_matrix(a);
    const XYZ s = cone * source_white, t = cone * target_white;
    if (a == Adaptation::von_kries_xyz) return Matrix3::diagonal(t.X / s.X, t.Y / s.Y, t.Z / s.Z);
    return inverse(cone) * (Matrix3::diagonal(t.X / s.X, t.Y / s.Y, t.Z / s.Z) * cone);
}

XYZ xyz_from_chromaticity(double x, double y) { return {x / y, 1.0, (1.0 - x - y) / y}; }

}  // namespace metalfit
