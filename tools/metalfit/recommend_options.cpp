#include "recommend_options.hpp"

#include <cmath>
#include <cstdlib>

#include "libfit/base/errors.hpp"
#include "libfit/fit/budget.hpp"

namespace metalfit::cli {

std::optional<Tolerance> RecommendOptions::tolerance() const {
    target_format();
    if (!recommend) return std::nullopt;
    Tolerance t;
    t.rel_rms = parse_fraction_limit("--max-rel-rms", max_rel_rms);
    t.f0_err = parse_fraction_limit("--max-f0-error", max_f0_error);
    char* end = nullptr;
    t.de2000_max = max_de2000.empty() ? std::nan("") : std::strtod(max_de2000.c_str(), &end);
    if (max_de2000.empty() || end != max_de2000.c_str() + max_de2000.size() || !std::isfinite(t.de2000_max) ||
        t.de2000_max < 0)
        throw UsageError("--max-de2000 '" + max_de2000 + "': give a number >= 0 (units of Delta E, e.g. 1)");
    return t;
}

ExportFormat RecommendOptions::target_format() const { return parse_recommend_target(target); }

void RecommendOptions::constrain(FitConstraints& constraints) const {
    const auto t = tolerance();
    if (t && !constraints.f0_tolerance && !constraints.pin_f0 && !constraints.gamut_fit)
        constraints.f0_tolerance = t->f0_err;
}

void add_recommend_options(CLI::App& app, RecommendOptions& o, bool with_flag) {
    const std::string what = with_flag ? "--recommend" : "the recommendation";
    if (with_flag)
        app.add_flag("--recommend", o.recommend,
                     "Per material, the cheapest model for --target meeting every --max-* limit, its constants and why "
                     "the cheaper ones fail (fitted under --f0-tolerance = --max-f0-error)");
    app.add_option("--target", o.target,
                   "Consumer of " + what +
                       ": glsl, hlsl, mtlx, openpbr, gltf, cpp, blender, msl or wgsl (default: glsl)");
    app.add_option("--max-rel-rms", o.max_rel_rms, what + ": worst-channel rel_rms limit (default: 0.5%)");
    app.add_option("--max-f0-error", o.max_f0_error,
                   what + ": worst-channel |F0 error| limit, also held by the fits (default: 0.5%)");
    app.add_option("--max-de2000", o.max_de2000, what + ": worst Delta E 2000 limit (default: 1)");
}

}  // namespace metalfit::cli
