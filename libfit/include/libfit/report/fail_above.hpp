// The --fail-above gate of `metalfit report`: every material, model and channel whose fitted rel_rms is above a
// limit, one line each, for CI jobs that guard a material library.
#pragma once

#include <string>
#include <vector>

#include "libfit/fit/fit.hpp"

namespace metalfit {

// "0.5%" (a percentage) or "0.005" (a fraction) → 0.005; UsageError naming the option for anything else (or ≤ 0).
double parse_relative_limit(const std::string& text, const std::string& option);

// "Au: schlick: red: fitted rel_rms 1.234 % > 1 %" for each channel above `limit` (an undefined rel_rms is above
// any limit: "undefined"), in material, model, channel order.
std::vector<std::string> channels_above(const std::vector<MaterialFit>& fits, double limit);
// The same for one material.
std::vector<std::string> channels_above(const MaterialFit& fit, double limit);

}  // namespace metalfit
