// Chromatic adaptation: the XYZ of a colour seen under one white, mapped to the corresponding colour under another
// (a von Kries transform: to a cone-like space, scale each channel by the ratio of the whites, back to XYZ).
#pragma once

#include <string>
#include <string_view>

#include "libfit/base/enum_names.hpp"
#include "libfit/color/color.hpp"
#include "libfit/color/matrix3.hpp"

namespace metalfit {

enum class Adaptation {
    bradford,       // Lam (1985) as in ICC v4 / Lindbloom: the sharpened cone space of the Bradford transform
    cat02,          // CIECAM02's CAT02 (CIE 159:2004), full adaptation (D = 1)
    von_kries_xyz,  // scaling X, Y, Z themselves ("XYZ scaling")
    none,           // no adaptation
};
inline constexpr EnumNames kAdaptationNames{"chromatic adaptation", KnownNamesWording::expected,
                                            std::array{EnumName<Adaptation>{Adaptation::bradford, "bradford"},
                                                       EnumName<Adaptation>{Adaptation::cat02, "cat02"},
                                                       EnumName<Adaptation>{Adaptation::von_kries_xyz, "von-kries-xyz"},
                                                       EnumName<Adaptation>{Adaptation::none, "none"}}};

Adaptation parse_adaptation(std::string_view s);  // "bradford" | "cat02" | "von-kries-xyz" | "none"; UsageError
std::string to_string(Adaptation a);              // the same names

// The cone-space matrix of a method (identity for von-kries-xyz and none).
Matrix3 cone_matrix(Adaptation a);

// M = C⁻¹ · diag(C·target / C·source) · C, so that M·source = target (exactly up to rounding). `none` and equal
// whites give the identity itself (not a product that is the identity up to rounding).
Matrix3 adaptation_matrix(Adaptation a, const XYZ& source_white, const XYZ& target_white);

// The XYZ (Y = 1) of a chromaticity x, y.
XYZ xyz_from_chromaticity(double x, double y);

}  // namespace metalfit
