#include "libfit/color/convention.hpp"

#include "libfit/base/errors.hpp"

namespace metalfit {

Convention parse_convention(std::string_view s) {
    if (s == "metalfit") return Convention::metalfit;
    if (s == "adobe") return Convention::adobe;
    if (s == "physicallybased") return Convention::physicallybased;
    throw UsageError("unknown convention '" + std::string(s) + "' (expected metalfit, adobe or physicallybased)");
}

std::string to_string(Convention c) {
    switch (c) {
        case Convention::metalfit: return "metalfit";
        case Convention::adobe: return "adobe";
        case Convention::physicallybased: return "physicallybased";
    }
    return "?";
}

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
