// The colour options shared by every subcommand that computes reference curves (show, fit, ...).
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "commands.hpp"
#include "libfit/color/color_space.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/color/convention.hpp"
#include "libfit/fit/fit_batch.hpp"
#include "libfit/fit/fit_record.hpp"
#include "libfit/reference/reference_curve.hpp"

namespace metalfit::cli {

// --cmf, --illuminant and --adaptation override the convention's preset; unset, they come from --convention.
struct ColourOptions {
    std::string space;      // empty: role scene_linear
    std::string xyz_space;  // empty: role cie_xyz_d65_interchange
    std::string convention = "metalfit";
    std::optional<std::string> cmf;
    std::optional<std::string> illuminant;
    std::optional<std::string> adaptation;
    std::string interpolation = "linear";
    bool extrapolate = false;
};

void add_colour_options(CLI::App& app, ColourOptions& options);

// What the options resolve to: the OCIO config in use, the colorimetry, the converter and the spectral options.
struct ColourSetup {
    OcioConfigChoice config;
    Colorimetry colorimetry;
    ColorSpaceConverter converter;
    SpectralOptions spectral;
    Convention convention;
    std::filesystem::path data_dir;  // the database: records name its files relative to it (base/record_path.hpp)

    // The colour pipeline of a batch fit (fit_materials), referring to this setup.
    BatchColour batch() const { return {config, colorimetry, converter}; }
    // The provenance of records and exports made with this setup.
    FitRecordContext record_context(const ErrorSettings& error) const {
        return {config,
                converter.space(),
                colorimetry.observer(),
                colorimetry.illuminant(),
                spectral,
                error,
                colorimetry.adaptation(),
                colorimetry.adapted(),
                convention,
                {},
                data_dir};
    }
};

// Warns when --ocio-config is overridden by $OCIO.
ColourSetup resolve_colour_options(const ColourOptions& options, const GlobalOptions& global);

}  // namespace metalfit::cli
