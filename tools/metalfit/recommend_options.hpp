// The options of the recommendation (fit, table, report): --recommend, --target and the tolerance's limits, resolved to
// libfit's Tolerance and target (export/recommendation.hpp).
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "libfit/export/recommendation.hpp"
#include "libfit/fit/fit.hpp"

namespace metalfit::cli {

struct RecommendOptions {
    bool recommend = false;
    std::string target = "glsl";
    std::string max_rel_rms = "0.5%";
    std::string max_f0_error = "0.5%";
    std::string max_de2000 = "1";

    // The tolerance when --recommend is given (UsageError naming the option of a bad limit), else empty; the target is
    // checked either way.
    std::optional<Tolerance> tolerance() const;
    ExportFormat target_format() const;
    // The recommendation's fits hold the F0 error it asks for: f0_tolerance = --max-f0-error unless the constraints
    // already hold F0 (--f0-tolerance, --pin F0) or the curve (--gamut-fit).
    void constrain(FitConstraints& constraints) const;
};

// --recommend (when `with_flag`; the report always recommends), --target, --max-rel-rms, --max-f0-error, --max-de2000.
void add_recommend_options(CLI::App& app, RecommendOptions& options, bool with_flag = true);

}  // namespace metalfit::cli
