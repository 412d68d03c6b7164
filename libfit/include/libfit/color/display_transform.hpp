// The display transform through OpenColorIO: scene-linear RGB → the config's default display and view, quantised
// to 8 bits (the only place where metalfit makes display-referred values; everything else stays linear).
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "libfit/color/color_space.hpp"

namespace metalfit {

// scene_linear (or another colour space of the config) → the config's default display and view (metalfit's config:
// sRGB, Un-tone-mapped). The OCIO processor is built once.
class DisplayTransform {
public:
    // `source`: a colour space or role of the config; empty: the role scene_linear. Throws ColorConfigError naming
    // the config.
    static DisplayTransform create(const OcioConfigChoice& config, const std::string& source = {});
    // 8-bit display-referred RGB of interleaved scene-linear RGB pixels (width × height, rows kept as given):
    // each value clamped to [0, 1] after the transform and rounded to the nearest of 0 … 255.
    std::vector<unsigned char> apply(std::span<const float> rgb, int width, int height) const;
    const std::string& description() const { return description_; }  // "Linear Rec.709 (sRGB) → sRGB - Display / Un-tone-mapped"

    ~DisplayTransform();
    DisplayTransform(DisplayTransform&&) noexcept;
    DisplayTransform& operator=(DisplayTransform&&) noexcept;

private:
    struct Impl;
    explicit DisplayTransform(std::unique_ptr<Impl> impl, std::string description);
    std::unique_ptr<Impl> impl_;
    std::string description_;
};

}  // namespace metalfit
