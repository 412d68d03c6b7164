#include "libfit/color/color_difference.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace metalfit {

namespace {

constexpr double kEpsilon = 216.0 / 24389.0;  // (6/29)³
constexpr double kKappa = 24389.0 / 27.0;     // (29/3)³

double lab_f(double t) { return t > kEpsilon ? std::cbrt(t) : (kKappa * t + 16.0) / 116.0; }

constexpr double kDegree = std::numbers::pi / 180.0;
// cos and sin of the angles in T (eq. 15), and cos 116° (where the rotation term is left out); the doubles nearest
// them (computed with cosl, sinl in long double).
constexpr double kCos30 = 0.8660254037844386, kSin30 = 0.5;
constexpr double kCos6 = 0.99452189536827329, kSin6 = 0.10452846326765347;
constexpr double kCos63 = 0.4539904997395468, kSin63 = 0.8910065241883679;
constexpr double kCos116 = -0.4383711467890774;

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

// What the hues enter ΔE00 through: ΔH' (eq. 10) and the mean hue h̄' (eq. 14), as its cosine and sine and, where it
// is known, in degrees.
struct HueTerms {
    double dH = 0.0;
    double cos_mean = 1.0, sin_mean = 0.0;
    double mean_degrees = std::numeric_limits<double>::quiet_NaN();
};

// By the angles, as Sharma et al. write it: used for their edge cases, C1'·C2' = 0 (Δh' = 0, h̄' = h1' + h2') and hues
// exactly opposite (Δh' = ±180° by the sign of h2' − h1'), and for chromas far outside colours' range.
HueTerms hue_terms_by_angles(double a1p, double b1, double a2p, double b2, double C_product) {
    const double h1p = hue_deg(b1, a1p), h2p = hue_deg(b2, a2p);
    double dhp = 0.0, hp_mean = h1p + h2p;
    if (C_product != 0.0) {
        dhp = h2p - h1p;
        if (dhp > 180.0)
            dhp -= 360.0;
        else if (dhp < -180.0)
            dhp += 360.0;
        if (std::abs(h1p - h2p) <= 180.0)
            hp_mean = 0.5 * (h1p + h2p);
        else if (h1p + h2p < 360.0)
            hp_mean = 0.5 * (h1p + h2p + 360.0);
        else
            hp_mean = 0.5 * (h1p + h2p - 360.0);
    }
    return {2.0 * std::sqrt(C_product) * std::sin(0.5 * dhp * kDegree), std::cos(hp_mean * kDegree),
            std::sin(hp_mean * kDegree), hp_mean};
}

// By the vectors (a', b) themselves, the same quantities without an angle. With P = C1'C2', dot = a1'a2' + b1b2 =
// P cos Δh' and cross = a1'b2 − b1a2' = P sin Δh' (|Δh'| < 180°, the short way round as eq. 9 takes it):
// ΔH' = 2√P sin(Δh'/2) = cross·√(2 / (P + dot)) where dot > 0 (1 − cos Δh' = sin²Δh' / (1 + cos Δh'), no
// cancellation), sign(cross)·√(2 (P − dot)) otherwise. h̄', the mean the short way round (eq. 14), is the direction
// of the bisector of the two hues: C2'(a1', b1) + C1'(a2', b2), or where they are 90° or more apart (that sum
// cancels) the chord C1'(a2', b2) − C2'(a1', b1) turned by 90° towards the shorter arc. Requires cross ≠ 0 or dot > 0.
HueTerms hue_terms_by_vectors(double a1p, double b1, double C1p, double a2p, double b2, double C2p, double C_product,
                              double dot, double cross) {
    HueTerms t;
    double x = 0.0, y = 0.0;
    if (dot > 0.0) {
        t.dH = cross * std::sqrt(2.0 / (C_product + dot));
        x = C2p * a1p + C1p * a2p;
        y = C2p * b1 + C1p * b2;
    } else {
        const double side = cross > 0.0 ? 1.0 : -1.0;
        t.dH = side * std::sqrt(2.0 * (C_product - dot));
        x = side * (C1p * b2 - C2p * b1);
        y = -side * (C1p * a2p - C2p * a1p);
    }
    const double length = std::sqrt(x * x + y * y);
    t.cos_mean = x / length;
    t.sin_mean = y / length;
    return t;
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

    // Eqs. 2–5: a' rescaled to lift neutrals' chroma, then C'.
    const double C1 = std::sqrt(c1.a * c1.a + c1.b * c1.b), C2 = std::sqrt(c2.a * c2.a + c2.b * c2.b);
    const double C_mean7 = pow7(0.5 * (C1 + C2));
    const double G = 0.5 * (1.0 - std::sqrt(C_mean7 / (C_mean7 + k25_7)));
    const double a1p = (1.0 + G) * c1.a, a2p = (1.0 + G) * c2.a;
    const double C1p = std::sqrt(a1p * a1p + c1.b * c1.b), C2p = std::sqrt(a2p * a2p + c2.b * c2.b);

    // Eqs. 8–10 and 14: differences, and the hue terms (by the vectors; by the angles at the edge cases).
    const double dLp = c2.L - c1.L;
    const double dCp = C2p - C1p;
    const double C_product = C1p * C2p;
    const double dot = a1p * a2p + c1.b * c2.b, cross = a1p * c2.b - c1.b * a2p;
    const bool by_vectors = C_product > 1e-100 && C_product < 1e100 && (cross != 0.0 || dot > 0.0);
    const HueTerms hue_terms = by_vectors ? hue_terms_by_vectors(a1p, c1.b, C1p, a2p, c2.b, C2p, C_product, dot, cross)
                                          : hue_terms_by_angles(a1p, c1.b, a2p, c2.b, C_product);

    // Eqs. 12–13, 15–20: means and weighting functions. T's cosines of multiples of h̄' follow from cos h̄', sin h̄'
    // (double, triple and quadruple angles).
    const double c = hue_terms.cos_mean, s = hue_terms.sin_mean;
    const double cos2 = c * c - s * s, sin2 = 2.0 * s * c;
    const double cos3 = cos2 * c - sin2 * s, sin3 = sin2 * c + cos2 * s;
    const double cos4 = cos2 * cos2 - sin2 * sin2, sin4 = 2.0 * sin2 * cos2;
    const double T = 1.0 - 0.17 * (c * kCos30 + s * kSin30) + 0.24 * cos2 + 0.32 * (cos3 * kCos6 - sin3 * kSin6) -
                     0.20 * (cos4 * kCos63 + sin4 * kSin63);
    const double L_mean = 0.5 * (c1.L + c2.L);
    const double Cp_mean = 0.5 * (C1p + C2p);
    const double L_offset2 = (L_mean - 50.0) * (L_mean - 50.0);
    const double S_L = 1.0 + 0.015 * L_offset2 / std::sqrt(20.0 + L_offset2);
    const double S_C = 1.0 + 0.045 * Cp_mean;
    const double S_H = 1.0 + 0.015 * Cp_mean * T;
    const double lightness = dLp / S_L, chroma = dCp / S_C, hue = hue_terms.dH / S_H;
    const double sum = lightness * lightness + chroma * chroma + hue * hue;

    // Eq. 21, the rotation term R_T·chroma·hue: |R_T| ≤ 2 sin 2Δθ with Δθ = 30° exp(−((h̄' − 275°)/25°)²). Where that
    // exponent exceeds 40 (h̄' in [0°, 116.9°]) the term is below 1.05 e^-40 · sum = 4.5e-18 · sum, under a twentieth
    // of an ulp of sum: it is left out there, and with it the angle h̄' itself.
    double mean_degrees = hue_terms.mean_degrees;
    if (std::isnan(mean_degrees)) {
        if ((s > 0.0 && c > kCos116) || (s == 0.0 && c > 0.0)) return std::sqrt(sum);
        mean_degrees = std::atan2(s, c) / kDegree;
        if (mean_degrees < 0.0) mean_degrees += 360.0;
    }
    const double hue_offset = (mean_degrees - 275.0) / 25.0;
    if (hue_offset * hue_offset > 40.0) return std::sqrt(sum);
    const double d_theta = 30.0 * std::exp(-hue_offset * hue_offset);
    const double Cp_mean7 = pow7(Cp_mean);
    const double R_C = 2.0 * std::sqrt(Cp_mean7 / (Cp_mean7 + k25_7));
    const double R_T = -std::sin(2.0 * d_theta * kDegree) * R_C;
    return std::sqrt(sum + R_T * chroma * hue);
}

}  // namespace metalfit
