// XYZ → RGB working spaces through OpenColorIO.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "libfit/color/color.hpp"

namespace metalfit {

// Which OCIO config is in use and why: "$OCIO", "--ocio-config" or "metalfit default".
struct OcioConfigChoice {
    std::filesystem::path path;
    std::string origin;
};

// $OCIO if set (origin "$OCIO"), else `explicit_config` if given (origin `explicit_origin`: the caller names where it
// came from, e.g. its command-line option), else <data_dir>/ocio/config.ocio (origin "metalfit default").
OcioConfigChoice choose_ocio_config(const std::optional<std::filesystem::path>& explicit_config,
                                    const std::filesystem::path& data_dir,
                                    const std::string& explicit_origin = "explicit");

// The role through which XYZ is found, and the default target role.
inline constexpr const char* kXyzRole = "cie_xyz_d65_interchange";
inline constexpr const char* kSceneLinearRole = "scene_linear";

// Converts CIE XYZ (D65) to one colour space of a config. The OCIO processor is built once.
// OCIO evaluates in float32: expect about 1e-7 relative error.
class ColorSpaceConverter {
public:
    // target: a colour space name, alias or role; empty means the role scene_linear. xyz_space: the colour space that
    // holds CIE XYZ (D65); empty means the role cie_xyz_d65_interchange (OCIO v1 and ACES 1.2 configs lack it).
    // Throws ColorConfigError naming the config when it cannot be read, lacks the XYZ space or the target (listing
    // the spaces and roles it has), or the target holds data (Raw) or is not linear (reflectance curves need a
    // scene-linear space).
    static ColorSpaceConverter create(const OcioConfigChoice& config, const std::string& target = {},
                                      const std::string& xyz_space = {});

    RGB operator()(const XYZ& xyz) const;
    // The inverse, RGB of the target space → XYZ (for colour differences of model colours).
    XYZ to_xyz(const RGB& rgb) const;
    // The same for many colours in one OCIO apply over a packed image (how OCIO converts images): the values of to_xyz
    // one at a time, bit for bit (OCIO runs the same per-pixel operations either way; ColorSpace tests check it).
    std::vector<XYZ> to_xyz(std::span<const RGB> rgb) const;

    const std::string& space() const { return space_; }          // resolved colour space name
    const std::string& xyz_space() const { return xyz_space_; }  // the colour space XYZ is read from
    const OcioConfigChoice& config() const { return config_; }
    std::vector<std::string> available_spaces() const;

    ~ColorSpaceConverter();
    ColorSpaceConverter(const ColorSpaceConverter&);
    ColorSpaceConverter& operator=(const ColorSpaceConverter&);
    ColorSpaceConverter(ColorSpaceConverter&&) noexcept;
    ColorSpaceConverter& operator=(ColorSpaceConverter&&) noexcept;

private:
    struct Impl;
    explicit ColorSpaceConverter(std::shared_ptr<const Impl> impl);
    std::shared_ptr<const Impl> impl_;
    OcioConfigChoice config_;
    std::string space_;
    std::string xyz_space_;
};

}  // namespace metalfit
