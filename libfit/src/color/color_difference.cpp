#include "libfit/color/color_difference.hpp"

#include <cmath>
#include <numbers>

namespace metalfit {

namespace {

constexpr double kEpsilon = 216.0 / 24389.0;  // (6/29)³
constexpr double kKappa = 24389.0 / 27.0;     // (29/3)³

double lab_f(double t) { return t > kEpsilon ? std::cbrt(t) : (kKappa * t + 16.0) / 116.0; }

constexpr double kDegree = std::numbers::pi / 180.0;

double sin_deg(double degrees) { return std::sin(degrees * kDegree); }
double cos_deg(double degrees) { return std::cos(degrees * kDegree); }

// Hue angle in [0°, 360°); 0 for the achromatic a' = b = 0 (eq. 4).
double hue_deg(double b, double a_prime) {
    if (a_prime == 0.0 && b == 0.0) return 0.0;
    const double h = std::atan2(b, a_prime) / kDegree;
    return h < 0.0 ? h + 360.0 : h;
}

double pow7(double x) {
    const double x2 = x * x, x3 = x2 * x;
    return x3 * x3 * x;
}

}  // namespace

Lab xyz_to_lab(const XYZ& xyz, const XYZ& white) {
    const double fx = lab_f(xyz.X / white.X);
    const double fy = lab_f(xyz.Y / white.Y);
    const double fz = lab_f(xyz.Z / white.Z);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

double ciede2000(const Lab& reference, const Lab& sample) {
    const Lab& c1 = reference;
    const Lab& c2 = sample;
    constexpr double k25_7 = 6103515625.0;  // 25⁷

    // Eqs. 2–5: a' rescaled to lift neutrals' chroma, then C' and h'.
    const double C1 = std::hypot(c1.a, c1.b), C2 = std::hypot(c2.a, c2.b);
    const double C_mean7 = pow7(0.5 * (C1 + C2));
    const double G = 0.5 * (1.0 - std::sqrt(C_mean7 / (C_mean7 + k25_7)));
    const double a1p = (1.0 + G) * c1.a, a2p = (1.0 + G) * c2.a;
    const double C1p = std::hypot(a1p, c1.b), C2p = std::hypot(a2p, c2.b);
    const double h1p = hue_deg(c1.b, a1p), h2p = hue_deg(c2.b, a2p);

    // Eqs. 8–11: differences.
    const double dLp = c2.L - c1.L;
    const double dCp = C2p - C1p;
    const double C_product = C1p * C2p;
    double dhp = 0.0;
    if (C_product != 0.0) {
        dhp = h2p - h1p;
        if (dhp > 180.0)
            dhp -= 360.0;
        else if (dhp < -180.0)
            dhp += 360.0;
    }
    const double dHp = 2.0 * std::sqrt(C_product) * sin_deg(0.5 * dhp);

    // Eqs. 12–14: means, with the hue mean taken the short way round the circle.
    const double L_mean = 0.5 * (c1.L + c2.L);
    const double Cp_mean = 0.5 * (C1p + C2p);
    double hp_mean = h1p + h2p;
    if (C_product != 0.0) {
        if (std::abs(h1p - h2p) <= 180.0)
            hp_mean = 0.5 * (h1p + h2p);
        else if (h1p + h2p < 360.0)
            hp_mean = 0.5 * (h1p + h2p + 360.0);
        else
            hp_mean = 0.5 * (h1p + h2p - 360.0);
    }

    // Eqs. 15–21: weighting functions and the rotation term.
    const double T = 1.0 - 0.17 * cos_deg(hp_mean - 30.0) + 0.24 * cos_deg(2.0 * hp_mean) +
                     0.32 * cos_deg(3.0 * hp_mean + 6.0) - 0.20 * cos_deg(4.0 * hp_mean - 63.0);
    const double hue_offset = (hp_mean - 275.0) / 25.0;
    const double d_theta = 30.0 * std::exp(-hue_offset * hue_offset);
    const double Cp_mean7 = pow7(Cp_mean);
    const double R_C = 2.0 * std::sqrt(Cp_mean7 / (Cp_mean7 + k25_7));
    const double L_offset2 = (L_mean - 50.0) * (L_mean - 50.0);
    const double S_L = 1.0 + 0.015 * L_offset2 / std::sqrt(20.0 + L_offset2);
    const double S_C = 1.0 + 0.045 * Cp_mean;
    const double S_H = 1.0 + 0.015 * Cp_mean * T;
    const double R_T = -sin_deg(2.0 * d_theta) * R_C;

    const double lightness = dLp / S_L, chroma = dCp / S_C, hue = dHp / S_H;
    return std::sqrt(lightness * lightness + chroma * chroma + hue * hue + R_T * chroma * hue);
}

}  // namespace metalfit
