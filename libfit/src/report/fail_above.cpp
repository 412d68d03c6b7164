#include "libfit/report/fail_above.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "libfit/base/errors.hpp"
#include "libfit/base/number_text.hpp"

namespace metalfit {
namespace {

std::string percent(double fraction) { return significant_text(100 * fraction, 4) + " %"; }

}  // namespace

double parse_relative_limit(const std::string& text, const std::string& option) {
    const bool is_percent = !text.empty() && text.back() == '%';
    const std::string number = is_percent ? text.substr(0, text.size() - 1) : text;
    char* end = nullptr;
    const double value = number.empty() ? NAN : std::strtod(number.c_str(), &end);
    if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(value) || value <= 0)
        throw UsageError(option + ": expected a positive fraction or percentage, e.g. 0.005 or 0.5% (got '" + text +
                         "')");
    return is_percent ? value / 100 : value;
}

std::vector<std::string> channels_above(const std::vector<MaterialFit>& fits, double limit) {
    std::vector<std::string> lines;
    for (const MaterialFit& fit : fits)
        for (std::string& line : channels_above(fit, limit)) lines.push_back(std::move(line));
    return lines;
}

std::vector<std::string> channels_above(const MaterialFit& fit, double limit) {
    std::vector<std::string> lines;
    for (const ModelResult& r : fit.models)
        for (int c = 0; c < 3; ++c) {
            const double v = r.fit.value.metrics.rel_rms[c];
            if (std::isnan(v) || v > limit)
                lines.push_back(fit.material.id + ": " + std::string(r.model->id()) + ": " + kChannelNames[c] +
                                ": fitted rel_rms " + (std::isnan(v) ? std::string("undefined") : percent(v)) + " > " +
                                percent(limit));
        }
    return lines;
}

}  // namespace metalfit
