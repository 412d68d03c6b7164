// Internal: an OCIO config read under the limits of every other input (docs/colour.md, "Limits"): a regular file of
// at most kMaxInputFileBytes whose YAML passes check_yaml_structure, and whose file transforms (LUTs) name regular
// files of at most that size that OCIO's search path finds. OCIO itself would read /dev/zero or a FIFO forever and
// spend gigabytes on a deep or alias-expanded config.
#pragma once

#include <OpenColorIO/OpenColorIO.h>

#include <cstddef>

#include "libfit/color/color_space.hpp"

namespace metalfit {

// The most colour spaces, looks, view transforms and named transforms (with the aliases that could stand for them)
// a config may hold: OCIO 2.1 loads them in quadratic time (2,000 in about 0.5 s on this project's machines).
inline constexpr std::size_t kMaxOcioEntries = 2000;

// The config of `choice`; ColorConfigError (exit code 4), one line naming the config file (and the LUT file, for a
// file transform), when it is refused or OCIO cannot load it.
OCIO_NAMESPACE::ConstConfigRcPtr load_ocio_config(const OcioConfigChoice& choice);

}  // namespace metalfit
