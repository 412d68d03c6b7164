// Internal: the one way libfit loads an OCIO config (color_space, rgb_conversion, display_transform,
// ocio_config_contents), with the checks OCIO itself does not make.
#pragma once

#include <OpenColorIO/OpenColorIO.h>

#include "libfit/color/color_space.hpp"

namespace metalfit::detail {

// Refuses a config that is not a regular file within the input size limit (input_file.hpp) or not UTF-8, then
// OCIO::Config::CreateFromFile, then refuses a config in which a colour space's transforms refer back to it through
// ColorSpaceTransforms, LookTransforms or DisplayViewTransforms (directly or through other spaces): OCIO follows such
// a cycle without end and the process dies of a stack overflow (SIGSEGV) in getProcessor. ColorConfigError naming
// the config and the spaces of the cycle; a config OCIO cannot load is "cannot be loaded: <OCIO's reason>". Messages
// start with `context`, by default "OCIO config <path> (<origin>)".
OCIO_NAMESPACE::ConstConfigRcPtr load_ocio_config(const OcioConfigChoice& choice, const std::string& context = {});

}  // namespace metalfit::detail
