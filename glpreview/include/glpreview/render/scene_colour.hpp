// The colour space a scene renders in (its `space` key, default the role scene_linear) and the conversions into it
// (an environment image's `colorspace`): docs/scene.md, "Colour". A space the OCIO config lacks, or one that holds
// data, is an error of the scene naming the field.
#pragma once

#include <string>

#include "glpreview/io/image.hpp"
#include "glpreview/scene/scene.hpp"
#include "libfit/color/color_space.hpp"
#include "libfit/color/rgb_conversion.hpp"

namespace metalfit::glpreview {

// XYZ → the scene's space (the Fresnel curves and the fits). Throws InputError naming the scene's `space`.
ColorSpaceConverter scene_converter(const OcioConfigChoice& config, const std::string& space,
                                    const std::filesystem::path& scene_file);

// Pixels in `from` → the scene's space. Throws InputError naming `field` (or `space`, when the scene's is missing).
RgbConversion scene_space_conversion(const Scene& scene, const OcioConfigChoice& config, const std::string& from,
                                     const std::string& field);

// The scene's equirect environment image in the scene's space: read, then converted from its `colorspace` when it
// names one (before `intensity`, which the shaders and the CPU tracer apply). Throws InputError naming the file or
// the field.
Image read_environment_image(const Scene& scene, const OcioConfigChoice& config);

}  // namespace metalfit::glpreview
