#include "colour_options.hpp"

namespace metalfit::cli {

void add_colour_options(CLI::App& app, ColourOptions& o) {
    app.add_option("--space", o.space, "Target colour space or role of the OCIO config (default: role scene_linear)");
    app.add_option("--convention", o.convention,
                   "Preset of --cmf, --illuminant and --adaptation that reproduces a published table: metalfit "
                   "(1931, D65, bradford), adobe (2015-2, D65, none), physicallybased (1931; D60 for ACES spaces, "
                   "else D65; bradford) (default: metalfit)")
        ->check(CLI::IsMember(names_of(kConventionNames)));
    app.add_option(
        "--xyz-space", o.xyz_space,
        "Colour space of the OCIO config holding CIE XYZ D65 (default: role cie_xyz_d65_interchange; for OCIO v1 / ACES 1.2 configs)");
    app.add_option("--cmf", o.cmf,
                   "Colour matching functions: CIE 1931 2°, 1964 10°, 2015 2° or 10° (default: the convention's, 1931)")
        ->check(CLI::IsMember(names_of(kObserverNames)));
    app.add_option("--illuminant", o.illuminant,
                   "Illuminant: D65, D50, A (CIE tables), E, D55, D60, D75 or D<kelvin> (daylight from S0, S1, S2) "
                   "(default: the convention's, D65)");
    app.add_option("--adaptation", o.adaptation,
                   "Chromatic adaptation from the illuminant's white to D65's (not needed for D65) "
                   "(default: the convention's, bradford)")
        ->check(CLI::IsMember(names_of(kAdaptationNames)));
    app.add_option("--interp", o.interpolation, "Interpolation of n and k (default: linear)")
        ->check(CLI::IsMember(names_of(kInterpolationNames)));
    app.add_flag("--extrapolate", o.extrapolate, "Hold end values outside the measured range (default: error)");
}

ColourSetup resolve_colour_options(const ColourOptions& o, const GlobalOptions& global) {
    auto config = choose_ocio_config(global.ocio_config, global.data_dir, "--ocio-config");
    if (global.ocio_config && config.origin == "$OCIO")
        warn("--ocio-config is ignored because $OCIO is set (" + config.path.string() + ")");
    const SpectralOptions spectral{kInterpolationNames.parse(o.interpolation),
                                   o.extrapolate ? OutOfRange::clamp : OutOfRange::error};
    const Convention convention = parse_convention(o.convention);
    // Usage errors first: a wrong illuminant costs nothing.
    const std::optional<Illuminant> illuminant =
        o.illuminant ? std::optional(parse_illuminant(*o.illuminant)) : std::nullopt;
    auto converter = ColorSpaceConverter::create(config, o.space, o.xyz_space);
    const ColourConvention preset = convention_preset(convention, converter.space());
    auto colorimetry = Colorimetry::load(global.data_dir, o.cmf ? parse_observer(*o.cmf) : preset.observer,
                                         illuminant.value_or(preset.illuminant),
                                         o.adaptation ? parse_adaptation(*o.adaptation) : preset.adaptation);
    return {std::move(config), std::move(colorimetry), std::move(converter), spectral, convention, global.data_dir};
}

}  // namespace metalfit::cli
