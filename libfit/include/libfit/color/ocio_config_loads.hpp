// How this process made its OCIO configs: each config file is read by OCIO once per process and its Config object
// (with OCIO's processor cache inside it) shared by every converter made from it; metalfit's own config
// (data/ocio/config.ocio, byte for byte) is built through OCIO's API instead of parsed. For tests and measurements.
#pragma once

#include <cstddef>
#include <string>

#include "libfit/color/color_space.hpp"

namespace metalfit {

struct OcioConfigLoads {
    std::size_t parsed = 0;         // configs OCIO read from their file (Config::CreateFromFile)
    std::size_t shipped_built = 0;  // configs that held the shipped bytes, built without YAML
    std::size_t reused = 0;         // loads answered by a config already made in this process (same file, same bytes)
};

// The counts since the process started.
OcioConfigLoads ocio_config_loads();

// OCIO's serialisation (Config::serialize) of the config metalfit uses for `choice` (loaded as every converter loads
// it): what tells a built config from a parsed one, if anything.
std::string serialized_ocio_config(const OcioConfigChoice& choice);

}  // namespace metalfit
