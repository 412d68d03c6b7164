// Perceptual colour difference: CIE 1976 L*a*b* and CIEDE2000 ΔE₀₀ (the report's ΔE between a
// model's colour and the reference colour, white = perfect reflector).
#pragma once

#include "libfit/color/color.hpp"

namespace metalfit {

// CIE 1976 L*a*b*: L* = 100 for the white, a* and b* = 0 for any neutral.
struct Lab {
    double L = 0.0, a = 0.0, b = 0.0;
};

// CIE 1976 L*a*b* of xyz relative to the given white (CIE 15:2004): with t = X/Xn, Y/Yn, Z/Zn,
// f(t) = ∛t for t > ε, (κ t + 16) / 116 otherwise, ε = 216/24389, κ = 24389/27 (the exact
// rationals, so both branches meet at t = ε); L* = 116 f(Y/Yn) − 16, a* = 500 (f(X/Xn) − f(Y/Yn)),
// b* = 200 (f(Y/Yn) − f(Z/Zn)).
Lab xyz_to_lab(const XYZ& xyz, const XYZ& white);

// CIEDE2000 colour difference ΔE₀₀ (Sharma, Wu, Dalal 2005, eqs. 1–21), parametric factors
// kL = kC = kH = 1, hue angles in degrees. Follows the paper's edge cases: h' = 0 when a' = b = 0;
// Δh' = 0 and mean hue h1' + h2' when C1'·C2' = 0; Δh' wrapped by ±360° when |h2' − h1'| > 180°;
// the mean hue shifted by 360° (halved) when |h1' − h2'| > 180°. Symmetric in its arguments.
double ciede2000(const Lab& reference, const Lab& sample);

}  // namespace metalfit
