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
// What the display's 8-bit values encode, measured through OCIO (the display/view's colour space → the role
// cie_xyz_d65_interchange), not guessed from names: what a PNG's colour chunks can truthfully say.
struct DisplayEncoding {
    enum class Kind {
        srgb,   // Rec.709 primaries, D65 white and the IEC 61966-2-1 (sRGB) curve
        gamma,  // Rec.709 primaries, D65 white and a pure power curve: decoded = encoded^gamma
        other,  // anything else (other primaries, a curve of another shape, no XYZ role): nothing to tag
    };
    Kind kind = Kind::other;
    double gamma = 0;           // kind == gamma
    std::string display_space;  // the colour space of the config's default display and view
    std::string why;            // kind == other: what did not match
};

class DisplayTransform {
public:
    // `source`: a colour space or role of the config; empty: the role scene_linear. Throws ColorConfigError naming
    // the config.
    static DisplayTransform create(const OcioConfigChoice& config, const std::string& source = {});
    // 8-bit display-referred RGB of interleaved scene-linear RGB pixels (width × height, rows kept as given):
    // each value clamped to [0, 1] after the transform and rounded to the nearest of 0 … 255.
    std::vector<unsigned char> apply(std::span<const float> rgb, int width, int height) const;
    const std::string& description() const {
        return description_;
    }  // "Linear Rec.709 (sRGB) → sRGB - Display / Un-tone-mapped"
    const DisplayEncoding& encoding() const { return encoding_; }

    ~DisplayTransform();
    DisplayTransform(DisplayTransform&&) noexcept;
    DisplayTransform& operator=(DisplayTransform&&) noexcept;

private:
    struct Impl;
    explicit DisplayTransform(std::unique_ptr<Impl> impl, std::string description, DisplayEncoding encoding);
    std::unique_ptr<Impl> impl_;
    std::string description_;
    DisplayEncoding encoding_;
};

}  // namespace metalfit
