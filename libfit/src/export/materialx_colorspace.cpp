// MaterialX's names of colour spaces: which OCIO spaces a MaterialX document can name, and what it says when it
// cannot.
#include <algorithm>
#include <cctype>

#include "export/export_formats.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/color/ocio_config_contents.hpp"

namespace metalfit {

std::string materialx_colorspace(const OcioConfigChoice& config, const std::string& ocio_space) {
    // MaterialX 1.39's linear colour spaces, each with the names OCIO configs (the builtin studio and CG configs,
    // ACES 1.x, metalfit's own) give the same space or list as aliases.
    static const std::vector<std::pair<std::string, std::vector<std::string>>> known{
        {"lin_rec709",
         {"lin_rec709", "Linear Rec.709 (sRGB)", "Linear Rec.709", "lin_srgb", "lin_rec709_srgb",
          "Utility - Linear - sRGB", "Utility - Linear - Rec.709", "scene-linear Rec.709-sRGB"}},
        {"acescg", {"acescg", "lin_ap1", "ACES - ACEScg", "lin_ap1_scene"}},
        {"lin_displayp3", {"lin_displayp3", "Linear P3-D65", "lin_p3d65", "Utility - Linear - P3-D65"}},
        {"lin_adobergb", {"lin_adobergb", "Linear AdobeRGB", "Linear Adobe RGB (1998)"}},
    };
    std::vector<std::string> names{ocio_space};
    try {
        for (const OcioColorSpaceEntry& s : read_ocio_config_contents(config).spaces)
            if (s.name == ocio_space) names.insert(names.end(), s.aliases.begin(), s.aliases.end());
    } catch (const ColorConfigError&) {
        // The config was read to fit; if it cannot be read now, match by the space's name alone.
    }
    const auto same = [](const std::string& a, const std::string& b) {
        return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
                   return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
               });
    };
    for (const auto& [materialx_name, spellings] : known)
        for (const std::string& name : names)
            for (const std::string& spelling : spellings)
                if (same(name, spelling)) return materialx_name;
    return {};
}

namespace detail {

std::string untagged_materialx_warning(const std::string& ocio_space) {
    return "WARNING: colours are in " + ocio_space +
           ", for which MaterialX has no colour-space name: the document carries no colorspace and consumers read its "
           "colours as their working space (export in Linear Rec.709, ACEScg, Linear P3-D65 or Linear AdobeRGB for a "
           "tagged document)";
}

}  // namespace detail
}  // namespace metalfit
