#include "colour_options.hpp"

namespace metalfit::cli {

void add_colour_options(CLI::App& app, ColourOptions& o) {
    app.add_option("--space", o.space, "Target colour space or role of the OCIO config (default: role scene_linear)");
    app.add_option("--xyz-space", o.xyz_space,
                   "Colour space of the OCIO config holding CIE XYZ D65 (default: role cie_xyz_d65_interchange; for OCIO v1 / ACES 1.2 configs)");
    app.add_option("--cmf", o.cmf, "Colour matching functions")->check(CLI::IsMember({"1931", "1964"}));
    app.add_option("--illuminant", o.illuminant, "Illuminant")->check(CLI::IsMember({"D65", "A", "E"}));
    app.add_option("--interp", o.interpolation, "Interpolation of n and k")->check(CLI::IsMember({"linear", "pchip"}));
    app.add_flag("--extrapolate", o.extrapolate, "Hold end values outside the measured range (default: error)");
}

ColourSetup resolve_colour_options(const ColourOptions& o, const GlobalOptions& global) {
    auto config = choose_ocio_config(global.ocio_config, global.data_dir, "--ocio-config");
    if (global.ocio_config && config.origin == "$OCIO")
        warn("--ocio-config is ignored because $OCIO is set (" + config.path.string() + ")");
    const SpectralOptions spectral{o.interpolation == "pchip" ? Interpolation::pchip : Interpolation::linear,
                                   o.extrapolate ? OutOfRange::clamp : OutOfRange::error};
    auto colorimetry = Colorimetry::load(global.data_dir, parse_observer(o.cmf), parse_illuminant(o.illuminant));
    auto converter = ColorSpaceConverter::create(config, o.space, o.xyz_space);
    return {std::move(config), std::move(colorimetry), std::move(converter), spectral};
}

}  // namespace metalfit::cli
