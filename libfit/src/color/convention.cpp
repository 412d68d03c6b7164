#include "libfit/color/convention.hpp"

#include "libfit/base/errors.hpp"

namespace metalfit {

Convention parse_convention(std::string_view s) { return kConventionNames.parse(s); }

std::string to_string(Convention c) { return std::string(kConventionNames.name(c)); }

ColourConvention convention_preset(Convention c, std::string_view space) {
    switch (c) {
        case Convention::adobe: return {Observer::cie2015_2deg, Illuminant::D65, Adaptation::none};
        case Convention::physicallybased:
            return {Observer::cie1931_2deg, space.starts_with("ACES") ? Illuminant::parse("D60") : Illuminant::D65,
                    Adaptation::bradford};
        case Convention::metalfit: break;
    }
    return {Observer::cie1931_2deg, Illuminant::D65, Adaptation::bradford};
}

}  // namespace metalfit
