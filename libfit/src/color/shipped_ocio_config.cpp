#include "color/shipped_ocio_config.hpp"

#include <initializer_list>
#include <string>

#include "shipped_ocio_config_bytes.hpp"

namespace OCIO = OCIO_NAMESPACE;

namespace metalfit::detail {
namespace {

OCIO::TransformRcPtr builtin(const char* style, bool inverse = false) {
    auto t = OCIO::BuiltinTransform::Create();
    t->setStyle(style);
    if (inverse) t->setDirection(OCIO::TRANSFORM_DIR_INVERSE);
    return t;
}

OCIO::TransformRcPtr matrix(const std::initializer_list<double>& rows3x3) {
    double m44[16] = {};
    int i = 0;
    for (const double v : rows3x3) {
        m44[(i / 3) * 4 + i % 3] = v;
        ++i;
    }
    m44[15] = 1.0;
    auto t = OCIO::MatrixTransform::Create();
    t->setMatrix(m44);
    return t;
}

OCIO::TransformRcPtr exponent(double value) {
    auto t = OCIO::ExponentTransform::Create();
    const double v[4] = {value, value, value, 1.0};
    t->setValue(v);
    return t;
}

OCIO::TransformRcPtr srgb_curve() {
    auto t = OCIO::ExponentWithLinearTransform::Create();
    const double gamma[4] = {2.4, 2.4, 2.4, 1.0}, offset[4] = {0.055, 0.055, 0.055, 0.0};
    t->setGamma(gamma);
    t->setOffset(offset);
    return t;
}

OCIO::TransformRcPtr to_aces(const char* src) {
    auto t = OCIO::ColorSpaceTransform::Create();
    t->setSrc(src);
    t->setDst("ACES2065-1");
    return t;
}

OCIO::TransformRcPtr group(const std::initializer_list<OCIO::TransformRcPtr>& children) {
    auto g = OCIO::GroupTransform::Create();
    for (const auto& child : children) g->appendTransform(child);
    return g;
}

struct Space {
    const char* name;
    std::initializer_list<const char*> aliases;
    const char* family;
    const char* description;
    bool data;
    const char* encoding;
    OCIO::TransformRcPtr transform;  // to the scene reference, or from the display reference (display spaces)
};

void add_space(OCIO::Config& config, OCIO::ReferenceSpaceType reference, const Space& s) {
    auto space = OCIO::ColorSpace::Create(reference);
    space->setName(s.name);
    for (const char* alias : s.aliases) space->addAlias(alias);
    space->setFamily(s.family);
    space->setDescription(s.description);
    space->setIsData(s.data);
    space->setEncoding(s.encoding);
    if (s.transform)
        space->setTransform(s.transform, reference == OCIO::REFERENCE_SPACE_DISPLAY
                                             ? OCIO::COLORSPACE_DIR_FROM_REFERENCE
                                             : OCIO::COLORSPACE_DIR_TO_REFERENCE);
    config.addColorSpace(space);
}

}  // namespace

std::string_view shipped_ocio_config_text() { return kShippedOcioConfigText; }

// Mirrors scripts/make-ocio-config.py, key by key, in the file's order.
OCIO::ConstConfigRcPtr build_shipped_ocio_config(const std::filesystem::path& folder) {
    const auto config = OCIO::Config::Create();
    config->setMajorVersion(2);
    config->setMinorVersion(1);
    config->setName("metalfit-config-v2");
    config->setDescription(
        "metalfit's own config, built from OpenColorIO 2.1 BuiltinTransforms (ACES CG config conventions):\n"
        "scene reference ACES2065-1, display reference CIE-XYZ-D65. Linear P3-D65, Linear Rec.2020 and Linear "
        "AdobeRGB use\n"
        "matrices derived from their primaries and the D65 white (0.3127, 0.3290). Every colour-space name of "
        "MaterialX 1.39\n"
        "(srgb_texture, lin_rec709, lin_srgb, g22_rec709, g18_rec709, rec709_display, acescg, lin_ap1, g22_ap1,\n"
        "srgb_displayp3, lin_displayp3, adobergb, lin_adobergb) is a space or an alias here.\n");
    config->setEnvironmentMode(OCIO::ENV_ENVIRONMENT_LOAD_PREDEFINED);
    config->setSearchPath("");
    config->setStrictParsingEnabled(true);
    const double luma[3] = {0.2126, 0.7152, 0.0722};
    config->setDefaultLumaCoefs(luma);
    for (const auto& [role, space] :
         std::initializer_list<std::pair<const char*, const char*>>{{"aces_interchange", "ACES2065-1"},
                                                                    {"cie_xyz_d65_interchange", "CIE-XYZ-D65"},
                                                                    {"color_picking", "sRGB - Texture"},
                                                                    {"color_timing", "ACEScct"},
                                                                    {"compositing_linear", "ACEScg"},
                                                                    {"compositing_log", "ACEScct"},
                                                                    {"data", "Raw"},
                                                                    {"matte_paint", "sRGB - Texture"},
                                                                    {"reference", "ACES2065-1"},
                                                                    {"default", "Linear Rec.709 (sRGB)"},
                                                                    {"rendering", "Linear Rec.709 (sRGB)"},
                                                                    {"scene_linear", "Linear Rec.709 (sRGB)"},
                                                                    {"texture_paint", "sRGB - Texture"}})
        config->setRole(role, space);
    config->addSharedView("Un-tone-mapped", "Un-tone-mapped", OCIO::OCIO_VIEW_USE_DISPLAY_NAME, nullptr, nullptr,
                          nullptr);
    config->addDisplaySharedView("sRGB - Display", "Un-tone-mapped");
    config->addDisplayView("sRGB - Display", "Raw", "Raw", nullptr);
    config->setActiveDisplays("sRGB - Display");
    config->setActiveViews("Un-tone-mapped, Raw");

    auto view = OCIO::ViewTransform::Create(OCIO::REFERENCE_SPACE_SCENE);
    view->setName("Un-tone-mapped");
    view->setDescription("Scene-linear values shown as they are (no tone mapping); clips above 1.");
    view->setTransform(builtin("UTILITY - ACES-AP0_to_CIE-XYZ-D65_BFD"), OCIO::VIEWTRANSFORM_DIR_FROM_REFERENCE);
    config->addViewTransform(view);
    config->setDefaultViewTransformName("Un-tone-mapped");

    add_space(*config, OCIO::REFERENCE_SPACE_DISPLAY,
              {"CIE-XYZ-D65",
               {"cie_xyz_d65"},
               "",
               "CIE XYZ with the D65 white, the display connection space (OCIO v2 display reference).",
               false,
               "display-linear",
               nullptr});
    add_space(*config, OCIO::REFERENCE_SPACE_DISPLAY,
              {"sRGB - Display",
               {"srgb_display"},
               "Display",
               "sRGB display (piecewise sRGB EOTF, Rec.709 primaries, D65), for 8-bit images.",
               false,
               "sdr-video",
               builtin("DISPLAY - CIE-XYZ-D65_to_sRGB")});

    const auto scene = [&config](const Space& s) { add_space(*config, OCIO::REFERENCE_SPACE_SCENE, s); };
    scene({"ACES2065-1",
           {"aces2065_1", "ACES - ACES2065-1", "lin_ap0"},
           "ACES",
           "The Academy Color Encoding System reference colour space (AP0 primaries, ACES white).",
           false,
           "scene-linear",
           nullptr});
    scene({"ACEScg",
           {"ACES - ACEScg", "lin_ap1"},
           "ACES",
           "ACEScg (AP1 primaries, ACES white), linear.",
           false,
           "scene-linear",
           builtin("ACEScg_to_ACES2065-1")});
    scene({"ACEScct",
           {"ACES - ACEScct", "acescct_ap1"},
           "ACES",
           "ACEScct, the logarithmic grading encoding of ACEScg (not linear).",
           false,
           "log",
           builtin("ACEScct_to_ACES2065-1")});
    scene({"Linear Rec.709 (sRGB)",
           {"lin_rec709_srgb", "lin_rec709", "lin_srgb", "Utility - Linear - sRGB"},
           "Utility",
           "Linear Rec.709 primaries with the D65 white (linear sRGB).",
           false,
           "scene-linear",
           group({builtin("UTILITY - ACES-AP1_to_LINEAR-REC709_BFD", true), builtin("ACEScg_to_ACES2065-1")})});
    scene({"Linear P3-D65",
           {"lin_p3d65", "lin_displayp3", "Utility - Linear - P3-D65"},
           "Utility",
           "Linear P3 primaries with the D65 white (Display P3 without its transfer function).",
           false,
           "scene-linear",
           group({matrix({0.486570948648216, 0.265667693169093, 0.198217285234362, 0.228974564069749, 0.691738521836506,
                          0.079286914093745, -0.0, 0.045113381858903, 1.043944368900976}),
                  builtin("UTILITY - ACES-AP0_to_CIE-XYZ-D65_BFD", true)})});
    scene({"Linear Rec.2020",
           {"lin_rec2020", "Utility - Linear - Rec.2020"},
           "Utility",
           "Linear Rec.2020 primaries with the D65 white.",
           false,
           "scene-linear",
           group({matrix({0.636958048301291, 0.144616903586208, 0.168880975164172, 0.262700212011267, 0.677998071518871,
                          0.059301716469862, 0.0, 0.028072693049087, 1.060985057710791}),
                  builtin("UTILITY - ACES-AP0_to_CIE-XYZ-D65_BFD", true)})});
    scene({"sRGB - Texture",
           {"srgb_tx", "srgb_texture"},
           "Utility",
           "sRGB-encoded texture (piecewise sRGB curve, Rec.709 primaries, D65).",
           false,
           "sdr-video",
           group({srgb_curve(), builtin("UTILITY - ACES-AP1_to_LINEAR-REC709_BFD", true),
                  builtin("ACEScg_to_ACES2065-1")})});
    scene({"Linear AdobeRGB",
           {"lin_adobergb"},
           "Utility",
           "Linear Adobe RGB (1998) primaries with the D65 white.",
           false,
           "scene-linear",
           group({matrix({0.576669042910131, 0.185558237906546, 0.188228646234995, 0.297344975250536, 0.627363566255466,
                          0.075291458493998, 0.027031361386412, 0.070688852535827, 0.991337536837639}),
                  builtin("UTILITY - ACES-AP0_to_CIE-XYZ-D65_BFD", true)})});
    scene({"Gamma 2.2 Rec.709",
           {"g22_rec709"},
           "Utility",
           "Rec.709 primaries, D65, encoded with a pure 2.2 power (MaterialX g22_rec709).",
           false,
           "sdr-video",
           group({exponent(2.2), to_aces("Linear Rec.709 (sRGB)")})});
    scene({"Gamma 1.8 Rec.709",
           {"g18_rec709"},
           "Utility",
           "Rec.709 primaries, D65, encoded with a pure 1.8 power (MaterialX g18_rec709).",
           false,
           "sdr-video",
           group({exponent(1.8), to_aces("Linear Rec.709 (sRGB)")})});
    scene({"Gamma 2.4 Rec.709",
           {"rec709_display", "g24_rec709"},
           "Utility",
           "Rec.709 primaries, D65, encoded with a pure 2.4 power (MaterialX rec709_display).",
           false,
           "sdr-video",
           group({exponent(2.4), to_aces("Linear Rec.709 (sRGB)")})});
    scene({"Gamma 2.2 AP1",
           {"g22_ap1"},
           "Utility",
           "ACEScg primaries (AP1, ACES white) encoded with a pure 2.2 power (MaterialX g22_ap1).",
           false,
           "sdr-video",
           group({exponent(2.2), to_aces("ACEScg")})});
    scene({"sRGB Encoded P3-D65",
           {"srgb_displayp3", "srgb_p3d65"},
           "Utility",
           "Display P3 (P3 primaries, D65, the piecewise sRGB curve), MaterialX srgb_displayp3.",
           false,
           "sdr-video",
           group({srgb_curve(), to_aces("Linear P3-D65")})});
    scene({"AdobeRGB",
           {"adobergb", "g22_adobergb"},
           "Utility",
           "Adobe RGB (1998) (its primaries, D65, the power 563/256), MaterialX adobergb.",
           false,
           "sdr-video",
           group({exponent(2.19921875), to_aces("Linear AdobeRGB")})});
    scene({"Raw", {"raw", "Utility - Raw"}, "Utility", "Data, not colour (never converted).", true, "data", nullptr});

    config->setWorkingDir(folder.c_str());
    return config;
}

}  // namespace metalfit::detail
