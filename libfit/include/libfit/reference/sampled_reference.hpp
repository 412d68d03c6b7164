// A reference curve sampled where the error integrals and maxima need it: at Gauss–Legendre nodes on [0, 1]
// (integrals) and on a uniform grid (maxima), with the colour of every sample for ΔE2000. The grid is sampled where it
// is asked for (the maxima look at it only where the nodes' errors come near their largest, fit/metrics.cpp), each
// point once.
#pragma once

#include <functional>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "libfit/base/enum_names.hpp"
#include "libfit/color/color.hpp"
#include "libfit/color/color_difference.hpp"
#include "libfit/reference/channel_target.hpp"
#include "libfit/reference/reference_curve.hpp"

namespace metalfit {

// Error metric minimised by the fit (docs/fitting.md, "Definitions"): relative or absolute difference to R_c.
enum class ErrorMetric { rel, abs };
// Angular weight w(μ) of the error integrals: 1 (uniform over the hemisphere) or 2μ (projected solid angle).
enum class AngularWeight { uniform, cosine };
inline constexpr EnumNames kErrorMetricNames{
    "error metric", KnownNamesWording::known,
    std::array{EnumName<ErrorMetric>{ErrorMetric::rel, "rel"}, EnumName<ErrorMetric>{ErrorMetric::abs, "abs"}}};
inline constexpr EnumNames kAngularWeightNames{"angular weight", KnownNamesWording::known,
                                               std::array{EnumName<AngularWeight>{AngularWeight::uniform, "uniform"},
                                                          EnumName<AngularWeight>{AngularWeight::cosine, "cosine"}}};

std::string to_string(ErrorMetric m);
std::string to_string(AngularWeight w);
ErrorMetric parse_error_metric(const std::string& text);      // "rel" | "abs", else UsageError
AngularWeight parse_angular_weight(const std::string& text);  // "uniform" | "cosine", else UsageError

struct ErrorSettings {
    int nodes = 128;
    ErrorMetric metric = ErrorMetric::rel;
    AngularWeight weight = AngularWeight::uniform;
};

// Uniform grid for maxima: μ = i / kDenseIntervals, i = 0 … kDenseIntervals (both ends included).
inline constexpr int kDenseIntervals = 1024;
// Below this many nodes, or where a channel of R comes below kNearZeroReference at a node or an end of the grid, the
// whole grid is sampled at once and the maxima scan all of it (the nodes too far apart to bracket the grid's maxima,
// or the relative error too steep between them).
inline constexpr int kFewestBracketingNodes = 64;
inline constexpr double kNearZeroReference = 0.01;

class SampledReference {
public:
    struct Sample {
        double mu = 0.0;
        double weight = 0.0;         // W_i w(μ_i): ∫ w f dμ ≈ Σ weight f (0 on the dense grid)
        double albedo_weight = 0.0;  // W_i 2μ_i: ∫ 2μ f dμ ≈ Σ albedo_weight f (0 on the dense grid)
        RGB value;                   // R_c(μ)
        Lab lab;                     // its colour, white = perfect reflector
    };

    // A white-balanced curve R_c(μ) at several μ at once (values equal to one μ at a time, bit for bit).
    using Curve = std::function<std::vector<RGB>(std::span<const double> mu)>;

    // The spectral reference curve (a bare metal or a layered stack): sampled through a copy of it.
    SampledReference(const ReferenceCurve& curve, const ErrorSettings& settings);
    // Any curve of white-balanced RGBs in the converter's space, where `raw_white` is the RGB of the perfect reflector
    // before white balance in that space (the white of the colours' L*a*b*): what a fit target without a spectrum
    // (fit/fit_target.hpp, a measured reflectance) samples.
    SampledReference(Curve curve, ColorSpaceConverter converter, RGB raw_white, const ErrorSettings& settings);

    std::span<const Sample> nodes() const { return nodes_; }
    // Grid point i (μ = i / kDenseIntervals). Sampled at construction: both ends (μ = 0 and 1), or every point where
    // whole_grid(); any other only after sample_grid has been asked for it.
    const Sample& grid(int i) const { return grid_[static_cast<std::size_t>(i)]; }
    const Sample& normal() const { return grid_.back(); }  // μ = 1
    // Samples the grid points among `indices` not sampled yet, in one batch (the values of one μ at a time, bit for
    // bit). Safe to call from several threads at once.
    void sample_grid(std::span<const int> indices) const;
    // Every grid point sampled at construction (few nodes, or R near 0: kFewestBracketingNodes, kNearZeroReference).
    bool whole_grid() const { return whole_grid_; }
    const ErrorSettings& settings() const { return settings_; }

    // L*a*b* of white-balanced RGBs of the curve's space (the perfect reflector (1, 1, 1) has L* = 100), through
    // the OCIO inverse of the curve's transform, in one OCIO apply (the values of one colour at a time, bit for bit).
    std::vector<Lab> lab(std::span<const RGB> balanced) const;

    // Why the relative metric is undefined (a channel of R_c is ≤ 0 somewhere on [0, 1]), if it is.
    const std::optional<std::string>& rel_undefined() const { return rel_undefined_; }

    // Channel c at the nodes as a least-squares target for settings().metric. Requires the metric to be defined.
    ChannelTarget target(int channel) const;

private:
    Curve curve_;  // for the grid points sampled later
    ColorSpaceConverter converter_;
    RGB raw_white_;
    XYZ white_;
    ErrorSettings settings_;
    std::vector<Sample> nodes_;
    mutable std::vector<Sample> grid_;        // kDenseIntervals + 1 points; written under grid_mutex_ only
    mutable std::vector<char> grid_sampled_;  // read and written under grid_mutex_ only
    mutable std::mutex grid_mutex_;
    bool whole_grid_ = false;
    std::optional<std::string> rel_undefined_;
};

}  // namespace metalfit
