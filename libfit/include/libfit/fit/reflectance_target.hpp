// A measured reflectance as a fit target: rows of μ and white-balanced R, G, B in the working space (a goniometer's
// or another renderer's curve), linear between the rows. It has no spectrum and no complex index: its closed forms
// that sample η are undefined, the others and the fit work as for a spectral metal (fit/fit_target.hpp).
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "libfit/color/color_space.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/fit/fit_target.hpp"
#include "libfit/reference/sampled_reference.hpp"

namespace metalfit {

struct ReflectanceRow {
    double mu = 0;  // cos θ
    RGB value;      // R_c(μ), white balanced (R_c(0) = 1 for a physical interface)
};

class ReflectanceTarget final : public FitTarget {
public:
    // Rows with μ strictly increasing from exactly 0 to exactly 1 and finite values, in the space of `converter`
    // (whose perfect reflector, the colorimetry's white, is the white of the colours' L*a*b*). Throws InputError
    // naming `file` and the row (1-based) that breaks this.
    ReflectanceTarget(std::string id, std::filesystem::path file, std::vector<ReflectanceRow> rows,
                      const Colorimetry& colorimetry, const ColorSpaceConverter& converter, const ErrorSettings& error);

    std::shared_ptr<const SampledReference> reference() const override { return reference_; }
    RGB operator()(double mu) const override;
    std::string id() const override { return id_; }
    std::string describe() const override;
    InputLocation location() const override { return InputLocation(file_); }

    const std::vector<ReflectanceRow>& rows() const { return *rows_; }

private:
    std::string id_;
    std::filesystem::path file_;
    std::shared_ptr<const std::vector<ReflectanceRow>> rows_;  // shared with the sampled reference's curve
    std::shared_ptr<const SampledReference> reference_;
};

// R(μ) of the rows, linear between the two that bracket μ (μ clamped to [0, 1]).
RGB interpolate_reflectance(const std::vector<ReflectanceRow>& rows, double mu);

}  // namespace metalfit
