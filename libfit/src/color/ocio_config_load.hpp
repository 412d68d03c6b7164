// Internal: the one way libfit loads an OCIO config (color_space, rgb_conversion, display_transform,
// ocio_config_contents), with the checks OCIO itself does not make.
#pragma once

#include <OpenColorIO/OpenColorIO.h>

#include <cstddef>

#include "libfit/color/color_space.hpp"

namespace metalfit::detail {

// The most colour spaces, looks, view transforms and named transforms (with the aliases that could stand for them)
// a config may hold: OCIO 2.1 loads them in quadratic time (2,000 in about 0.5 s on this project's machines).
inline constexpr std::size_t kMaxOcioEntries = 2000;

// "OCIO config <path> (<origin>)": how every message about a config names it.
std::string describe_ocio_config(const OcioConfigChoice& choice);

// Reads a config under the limits of every other input (docs/colour.md, "Limits"): refuses a config that is not a
// regular file within the input size limit (input_file.hpp), not UTF-8, whose YAML fails check_yaml_structure or that
// holds more than kMaxOcioEntries entries; then OCIO::Config::CreateFromFile; then refuses a config in which a colour
// space's transforms refer back to it through ColorSpaceTransforms, LookTransforms or DisplayViewTransforms (directly
// or through other spaces): OCIO follows such a cycle without end and the process dies of a stack overflow (SIGSEGV) in
// getProcessor. ColorConfigError naming the config and the spaces of the cycle; and refuses a file transform (a LUT)
// that the search path does not find as a regular file of at most the input size limit (naming the LUT); a config OCIO
// cannot load is "cannot be loaded: <OCIO's reason>". Messages start with `context`, by default "OCIO config <path>
// (<origin>)". Once per process and file (libfit/color/ocio_config_loads.hpp): a later call for the same path whose
// bytes are unchanged returns the same Config, and a file holding exactly data/ocio/config.ocio's bytes is built
// through OCIO's API (shipped_ocio_config.hpp) instead of parsed.
OCIO_NAMESPACE::ConstConfigRcPtr load_ocio_config(const OcioConfigChoice& choice, const std::string& context = {});

}  // namespace metalfit::detail
