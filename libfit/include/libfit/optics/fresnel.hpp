// Exact Fresnel reflectance at a planar interface from vacuum (or air, n = 1) into a medium with
// complex index η = n + i k. μ = cos θ of the angle of incidence.
#pragma once

#include <complex>

namespace metalfit {

struct FresnelReflectance {
    double s = 0.0;  // perpendicular (TE) polarisation, |r_s|²
    double p = 0.0;  // parallel (TM) polarisation, |r_p|²
    double unpolarized() const { return 0.5 * (s + p); }
};

// Complex form in double precision (pbrt-v4's FrComplex): cos θt = sqrt(1 − (1 − μ²)/η²) on the
// principal branch. Valid for conductors (k > 0) and dielectrics (k = 0), including n < 1, where
// total internal reflection gives 1. μ is clamped to [0, 1]; F(μ = 0) = 1 for every η ≠ 1, and
// η = 1 (no interface) reflects nothing at every μ.
FresnelReflectance fresnel_reflectance(double mu, std::complex<double> eta);

// Unpolarised reflectance, (F_s + F_p) / 2.
inline double fresnel(double mu, std::complex<double> eta) { return fresnel_reflectance(mu, eta).unpolarized(); }

// Normal incidence: ((n − 1)² + k²) / ((n + 1)² + k²).
double fresnel_normal_incidence(std::complex<double> eta);

}  // namespace metalfit
