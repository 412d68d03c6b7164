// Pixels from one colour space of the OCIO config to another (an environment image tagged with its own space into
// the space a scene renders in). The OCIO processor is built once; the same space both sides is the identity.
#pragma once

#include <memory>
#include <span>
#include <string>

#include "libfit/color/color_space.hpp"

namespace metalfit {

class RgbConversion {
public:
    // `from`, `to`: colour spaces or roles of the config. Throws ColorConfigError naming the config and the space that
    // is missing, or one that holds data (isdata), not colour.
    static RgbConversion create(const OcioConfigChoice& config, const std::string& from, const std::string& to);
    // Interleaved RGB, in place.
    void apply(std::span<float> rgb) const;
    bool identity() const { return !impl_; }
    const std::string& from() const { return from_; }  // the config's names (a role resolved)
    const std::string& to() const { return to_; }

    ~RgbConversion();
    RgbConversion(RgbConversion&&) noexcept;
    RgbConversion& operator=(RgbConversion&&) noexcept;

private:
    struct Impl;
    RgbConversion(std::unique_ptr<Impl> impl, std::string from, std::string to);
    std::unique_ptr<Impl> impl_;
    std::string from_, to_;
};

}  // namespace metalfit
