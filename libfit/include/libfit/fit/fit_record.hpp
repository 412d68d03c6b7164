// The fit record: the versioned JSON of `metalfit fit --json` (docs/fit-record.md), which exports read.
// Deterministic: the same inputs give byte-identical text (no times, no thread-dependent order).
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "libfit/color/color_space.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/color/convention.hpp"
#include "libfit/fit/budget.hpp"
#include "libfit/fit/fit.hpp"

namespace metalfit {

inline constexpr const char* kFitRecordSchema = "metalfit.fit/1";

// How the curves were made, for the record's provenance.
struct FitRecordContext {
    OcioConfigChoice config;
    std::string space;  // resolved colour space name
    Observer observer = Observer::cie1931_2deg;
    Illuminant illuminant = Illuminant::D65;
    SpectralOptions spectral;
    ErrorSettings error;
    Adaptation adaptation = Adaptation::bradford;  // as asked (docs/colour.md)
    bool adapted = false;                          // whether it changed anything (false for D65)
    Convention convention = Convention::metalfit;
    FitConstraints constraints = {};
    // The database the inputs came from: records name files relative to it (base/record_path.hpp), never absolutely.
    std::filesystem::path data_dir = {};
};

// `budgets`, when given, holds one choice per material (in the order of `materials`): each material's record then has
// a "budget" (budget_record) and the provenance the budget and its cost table.
nlohmann::ordered_json fit_record(const std::vector<MaterialFit>& materials, const FitRecordContext& context,
                                  const std::vector<BudgetChoice>* budgets = nullptr);

// The record with an empty "materials" object: schema and provenance, with the budget's provenance taken from
// `first_budget` (the first material's choice; every material has the same budget and cost table) when given.
nlohmann::ordered_json fit_record_without_materials(const FitRecordContext& context,
                                                    const BudgetChoice* first_budget = nullptr);

// One material's record (the value under materials.<id>): name, source, data, F0, ..., models, and its "budget"
// when `budget` is given.
// Its files are named by record_path against `data_dir` (the context's).
// `recommendation` (export/recommendation.hpp's record), when given, is written as its "recommendation".
nlohmann::ordered_json material_record(const MaterialFit& fit, const std::filesystem::path& data_dir,
                                       const BudgetChoice* budget = nullptr,
                                       const nlohmann::ordered_json* recommendation = nullptr);

// {"metric", "limit", "cost_table", "cost_unit", "chosen": id or null, "summary", "candidates": [{"model", "cost",
// "value", "qualifies", "reason"}]} (docs/fit-record.md).
nlohmann::ordered_json budget_record(const BudgetChoice& choice);

// {"params": {name: [r, g, b]}, "metrics": the seven keys of docs/fitting.md ("Definitions"), "metrics_at_mu": where the maxima are}:
// how every set of evaluated parameters (fit, closed form, exported values) appears in records.
nlohmann::ordered_json evaluated_record(const Model& model, const EvaluatedParameters& value);
// The seven metrics of docs/fitting.md ("Definitions") as the record writes them (also in the OpenPBR JSON and glTF extras).
nlohmann::ordered_json metrics_record(const Metrics& metrics);

// The JSON of one model's results (the value under materials.<id>.models.<model id>).
nlohmann::ordered_json model_record(const ModelResult& result);

}  // namespace metalfit
