// Colour conventions: presets of observer, illuminant and chromatic adaptation that reproduce published metal
// tables (docs/colour.md, "Conventions"). White handling is the same in all of them: R_c = RGB_c(F) / RGB_c(white).
#pragma once

#include <string>
#include <string_view>

#include "libfit/base/enum_names.hpp"
#include "libfit/color/chromatic_adaptation.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/color/illuminant.hpp"

namespace metalfit {

enum class Convention {
    metalfit,         // CIE 1931 2°, D65, Bradford (the identity for D65)
    adobe,            // Adobe's metal-colors table (peterkutz/metal-colors): CIE 2015 2°, D65, no adaptation
    physicallybased,  // physicallybased.info: CIE 1931 2°; D65 for D65 spaces, D60 for the ACES spaces; Bradford
};
inline constexpr EnumNames kConventionNames{
    "convention", KnownNamesWording::expected,
    std::array{EnumName<Convention>{Convention::metalfit, "metalfit"}, EnumName<Convention>{Convention::adobe, "adobe"},
               EnumName<Convention>{Convention::physicallybased, "physicallybased"}}};

Convention parse_convention(std::string_view s);  // "metalfit" | "adobe" | "physicallybased"; UsageError
std::string to_string(Convention c);

struct ColourConvention {
    Observer observer;
    Illuminant illuminant;
    Adaptation adaptation;
};

// The preset for a target colour space (the resolved OCIO name): physicallybased integrates the ACES spaces
// (names starting with "ACES") under D60, every other space under D65.
ColourConvention convention_preset(Convention c, std::string_view space);

}  // namespace metalfit
