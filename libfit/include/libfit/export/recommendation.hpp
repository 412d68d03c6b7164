// The recommendation: for one material and one consumer (--target glsl|hlsl|mtlx|openpbr|gltf|cpp), the cheapest model
// whose fit meets a tolerance on rel_rms, F0 error and ΔE2000 together (budget.hpp's choose_model, the one definition
// of "the cheapest model meeting a tolerance"), with its constants in the target's own syntax and, for every cheaper
// model, why it fails. `metalfit fit --recommend` and `metalfit table --recommend` print it.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "libfit/export/export.hpp"
#include "libfit/fit/budget.hpp"
#include "libfit/fit/fit.hpp"
#include "libfit/fit/model_cost.hpp"

namespace metalfit {

// What the user tolerates, every limit in every channel: worst-channel rel_rms and |err_f0| (fractions), worst ΔE2000.
struct Tolerance {
    double rel_rms = 0.005;
    double f0_err = 0.005;
    double de2000_max = 1.0;
};
// The tolerance as budgets, in this order: rel_rms, f0_err, de2000_max (the first orders ties in choose_model).
Budgets tolerance_budgets(const Tolerance& tolerance);
// "rel_rms <= 0.5 %, f0_err <= 0.5 %, de2000_max <= 1"
std::string tolerance_text(const Tolerance& tolerance);

// The consumers a recommendation is for: every export format but json. UsageError naming --target otherwise.
ExportFormat parse_recommend_target(const std::string& text);
// Why `target` does not render `model` as the model itself ("" when it does): MaterialX writes the models without a
// node of their own (lazanyi-comp, the compensated Schlick families, rational) as a stand-in, OpenPBR evaluates only F82-tint curves, a glTF viewer draws Schlick from baseColorFactor whatever the
// extras say (the format registry's stand-in rule, plus glTF's core BRDF).
std::string target_refuses(ExportFormat target, const Model& model);
// The constants of `params` (one model's) as the target writes them, lines ready to paste: GLSL/HLSL/C++ constants
// named after the parameters, MaterialX inputs of the model's node, OpenPBR's base_color/specular_color, glTF's
// baseColorFactor.
std::string target_constants(ExportFormat target, const Model& model, const ModelParameters& params);

struct Recommendation {
    std::string material;  // the material's id
    ExportFormat target = ExportFormat::glsl;
    Tolerance tolerance;
    BudgetChoice choice;    // chosen: the recommended model, or nullptr when no model meets the tolerance
    std::string constants;  // target_constants of the chosen model's fit ("" when none)
    // One line per model cheaper than the chosen one (every model when none is chosen): "schlick: rel_rms 21.8 % >
    // 0.5 % (G, by 21.3 %)".
    std::vector<std::string> cheaper;

    // The lines a terminal shows: the model (or that none meets), its constants, then the cheaper models' reasons.
    std::string text() const;
};

Recommendation recommend(const MaterialFit& fit, const CostTable& costs, const Tolerance& tolerance,
                         ExportFormat target);

// {"target", "tolerance": {rel_rms, f0_err, de2000_max}, "chosen": id or null, "constants": text or null, "cost_table",
// "cost_unit", "candidates": [{"model", "cost", "values": {metric: value}, "qualifies", "reason"}]} (schemas/fit).
nlohmann::ordered_json recommendation_record(const Recommendation& recommendation);

// `metalfit table --recommend`: one row per material (material, model or "none", its worst-channel rel_rms and
// |F0 error| in %, ΔE2000 max, and the next cheaper model with why it fails), as Markdown, CSV or JSON (an array of
// {"material", …recommendation_record}).
std::string recommendation_table_markdown(const std::vector<Recommendation>& rows);
std::string recommendation_table_csv(const std::vector<Recommendation>& rows);
nlohmann::ordered_json recommendation_table_json(const std::vector<Recommendation>& rows);

}  // namespace metalfit
