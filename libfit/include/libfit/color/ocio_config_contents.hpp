// What an OCIO config holds: its colour spaces (with family, aliases, whether they are data) and its roles, for
// `metalfit spaces` and for error messages that name what exists instead of only what is missing.
#pragma once

#include <string>
#include <vector>

#include "libfit/color/color_space.hpp"

namespace metalfit {

struct OcioColorSpaceEntry {
    std::string name;
    std::string family;
    std::vector<std::string> aliases;
    bool is_data = false;  // OCIO's isdata: values that are not colours (Raw, normals); never a reflectance target
};

struct OcioRole {
    std::string role;   // e.g. "scene_linear"
    std::string space;  // the colour space it names
};

struct OcioConfigContents {
    OcioConfigChoice config;
    std::vector<OcioColorSpaceEntry> spaces;  // in the config's order
    std::vector<OcioRole> roles;              // sorted by role name

    // "Linear Rec.709 (sRGB), ACEScg, ..." and "scene_linear → Linear Rec.709 (sRGB), ...": one line each.
    std::string space_names() const;
    std::string role_names() const;
};

// Throws ColorConfigError naming the config when it cannot be loaded.
OcioConfigContents read_ocio_config_contents(const OcioConfigChoice& config);

}  // namespace metalfit
