// Which method a rough sphere is rendered with (issue 36 item 4; docs/preview.md, "Choosing the glossy method"):
// `prefiltered` or `localized`, chosen from the sphere's roughness and a table measured in the shipped rooms
// (data/glossy-choice.json, made by scripts/measure-glossy-choice.py; embedded at build time), or as the scene asks.
//
// The rule, from the table's rows (one per measured roughness: how many spheres each method won against the
// Monte-Carlo reference, and the ratio localized / prefiltered of their RMSEs):
// - `auto` (the default) renders localized at and above the lowest measured roughness from which on, at every
//   measured roughness, localized won at least kLocalizedMajority of the spheres and its median RMSE ratio is below
//   1; below that, and when there is no such roughness, prefiltered. Localized costs 25-140x the prefiltered frame:
//   auto takes it where it wins clearly (three spheres in four), so that rooms not measured are likely to agree;
// - `localized` asked for below the lowest measured roughness from which on localized's RMSE was never more than
//   kLocalizedWorstRatio times prefiltered's on any measured sphere ("fails": its lobe is narrower than the area
//   lights and the sum breaks up) falls back to prefiltered, and the scene gets a warning saying so; `prefiltered`
//   is always honoured.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

inline constexpr double kLocalizedMajority = 0.75;
inline constexpr double kLocalizedWorstRatio = 4.0;

// One measured roughness of the table.
struct GlossyChoiceRow {
    double roughness = 0;
    int spheres = 0;                           // spheres measured (every room's) at this roughness
    int localized_wins = 0;                    // of them, where localized's RMSE was below prefiltered's
    double median_ratio = 0, worst_ratio = 0;  // localized RMSE / prefiltered RMSE over those spheres
};

struct GlossyChoiceTable {
    std::vector<GlossyChoiceRow> rows;  // by increasing roughness
    std::string command;                // the command that measured it
    // Derived by the rule above (nullopt: never).
    std::optional<double> localized_from;        // auto picks localized at or above this roughness
    std::optional<double> localized_works_from;  // localized asked for below this falls back to prefiltered
};

// Reads a table (the JSON of scripts/measure-glossy-choice.py) and derives its thresholds; throws InputError naming
// `name` and the field.
GlossyChoiceTable parse_glossy_choice_table(const std::string& json_text, const std::string& name);
// The table glpreview was built with (data/glossy-choice.json).
const GlossyChoiceTable& glossy_choice_table();

struct GlossyChoice {
    GlossyMethod method = GlossyMethod::prefiltered;
    bool fell_back = false;  // localized was asked for where it fails: rendered prefiltered
    std::string reason;      // one line: why this method (--explain, the fallback's warning)
};
GlossyChoice choose_glossy_method(double roughness, GlossyRequest request,
                                  const GlossyChoiceTable& table = glossy_choice_table());

// `glpreview --glossy-as-asked` (for measuring the table: scripts/measure-glossy-choice.py): every rough sphere that
// asked for `localized` is rendered localized, also where the table says it fails; its fallback warning goes.
void honour_glossy_requests(Scene& scene);

}  // namespace metalfit::glpreview
