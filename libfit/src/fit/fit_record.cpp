#include "libfit/fit/fit_record.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "libfit/base/file_digest.hpp"
#include "libfit/base/record_path.hpp"
#include "libfit/base/version.hpp"
#include "libfit/io/layer_stack.hpp"

namespace metalfit {

namespace {

using Json = nlohmann::ordered_json;

Json per_channel(const PerChannel& v) { return Json::array({v[0], v[1], v[2]}); }
Json rgb_json(const RGB& v) { return Json::array({v.r, v.g, v.b}); }

Json params_json(const Model& model, const ModelParameters& params) {
    Json j = Json::object();
    const auto parameters = model.parameters();
    for (std::size_t i = 0; i < parameters.size(); ++i)
        j[std::string(parameters[i].name)] = rgb_json(params.parameter(i));
    return j;
}

Json solver_json(const FitResult& fit) {
    Json start = Json::array(), iterations = Json::array(), termination = Json::array(), initial = Json::array(),
         final_cost = Json::array(), starts = Json::array(), fallback = Json::array();
    for (int c = 0; c < 3; ++c) {
        const SolverSummary& s = fit.solver[c];
        start.push_back(s.start);
        iterations.push_back(s.iterations);
        termination.push_back(s.termination);
        initial.push_back(s.initial_cost);
        final_cost.push_back(s.final_cost);
        starts.push_back(s.starts);
        fallback.push_back(fit.fallback[c].empty() ? Json(nullptr) : Json(fit.fallback[c]));
    }
    // One method for the three channels (the same model and constraints); a summary without one (no parameter free,
    // no start: SolverSummary's defaults) is the plain solve's.
    const std::string& method = fit.solver[0].method;
    return {{"solver", method.empty() ? std::string(kCeresSolve) : method},
            {"start", start},
            {"iterations", iterations},
            {"termination", termination},
            {"initial_cost", initial},
            {"final_cost", final_cost},
            {"starts", starts},
            {"fallback_to_closed", fallback}};
}

Json data_provenance(const Material& material, const std::filesystem::path& data_dir) {
    const Provenance& p = material.provenance;
    Json data = {{"file", record_path(p.file, data_dir)},
                 {"sha256", p.sha256},
                 {"format", p.format},
                 {"data_type", p.data_type},
                 {"reference", p.references},
                 {"note", p.note}};
    // Only for a layered material (a film, a coat), so that bare records keep their keys.
    if (material.layers && !material.layers->empty()) data["stack"] = stack_record(material, data_dir);
    return data;
}

}  // namespace

Json metrics_record(const Metrics& m) {
    return {{"rel_rms", per_channel(m.rel_rms)},      {"abs_rms", per_channel(m.abs_rms)},
            {"max_rel", per_channel(m.max_rel)},      {"max_abs", per_channel(m.max_abs)},
            {"de2000_mean", m.de2000_mean},           {"de2000_max", m.de2000_max},
            {"albedo_err", per_channel(m.albedo_err)}};
}

// params, metrics (exactly the seven keys of docs/fitting.md, "Definitions") and where the maxima are.
Json evaluated_record(const Model& model, const EvaluatedParameters& value) {
    const Metrics& m = value.metrics;
    return {{"params", params_json(model, value.params)},
            {"metrics", metrics_record(m)},
            {"err_f0", per_channel(m.err_f0)},
            {"metrics_at_mu",
             {{"max_rel", per_channel(m.max_rel_mu)},
              {"max_abs", per_channel(m.max_abs_mu)},
              {"de2000_max", m.de2000_max_mu}}}};
}

Json model_record(const ModelResult& result) {
    const Model& model = *result.model;
    Json names = Json::array();
    for (const Parameter& p : model.parameters()) names.push_back(p.name);

    Json forms = Json::object();
    std::string all_undefined;
    for (const ClosedFormResult& form : result.closed_forms) {
        Json j = {{"description", form.description}};
        if (form.value) {
            j.update(evaluated_record(model, *form.value));
            if (!form.outside_bounds.empty()) j["outside_bounds"] = form.outside_bounds;
        } else {
            j["undefined"] = form.undefined;
            all_undefined += (all_undefined.empty() ? "" : "; ") + form.id + ": " + form.undefined;
        }
        forms[form.id] = std::move(j);
    }
    Json closed;
    if (result.best_closed) {
        const ClosedFormResult& best = result.closed_forms[*result.best_closed];
        closed = {{"form", best.id}};
        closed.update(evaluated_record(model, *best.value));
    } else {
        closed = {{"undefined", all_undefined}};
    }
    Json fit = evaluated_record(model, result.fit.value);
    fit["solver"] = solver_json(result.fit);
    // Only where the model cannot represent the data within its bounds (older records had no such key).
    if (std::any_of(result.fit.unrepresentable.begin(), result.fit.unrepresentable.end(),
                    [](const std::string& u) { return !u.empty(); })) {
        Json unrepresentable = Json::array();
        for (const std::string& u : result.fit.unrepresentable)
            unrepresentable.push_back(u.empty() ? Json(nullptr) : Json(u));
        fit["unrepresentable"] = unrepresentable;
    }
    // Only where the fit refused something for a channel (--pin F0 against a bound, every start ending with a pole).
    if (std::any_of(result.fit.refused.begin(), result.fit.refused.end(),
                    [](const std::string& r) { return !r.empty(); })) {
        Json refused = Json::array();
        for (const std::string& r : result.fit.refused) refused.push_back(r.empty() ? Json(nullptr) : Json(r));
        fit["refused"] = refused;
    }
    // Only where a channel's fit ends on a bound of the model (issue 29 item 4): which parameter, which bound.
    std::array<std::string, 3> on_bound;
    for (int c = 0; c < 3; ++c) on_bound[c] = at_bound(model, result.fit.value.params[c]);
    if (std::any_of(on_bound.begin(), on_bound.end(), [](const std::string& b) { return !b.empty(); })) {
        Json at = Json::array();
        for (const std::string& b : on_bound) at.push_back(b.empty() ? Json(nullptr) : Json(b));
        fit["at_bound"] = at;
    }
    return {{"title", model.title()}, {"parameters", names}, {"closed", closed}, {"closed_forms", forms}, {"fit", fit}};
}

Json budget_record(const BudgetChoice& choice) {
    Json candidates = Json::array();
    for (const BudgetCandidate& c : choice.candidates)
        candidates.push_back({{"model", c.model->id()},
                              {"cost", c.cost ? Json(*c.cost) : Json(nullptr)},
                              {"value", c.value},
                              {"qualifies", c.qualifies},
                              {"reason", c.reason.empty() ? Json(nullptr) : Json(c.reason)}});
    return {{"metric", to_string(choice.budget.metric)},
            {"limit", choice.budget.limit},
            {"cost_table", choice.cost_source},
            {"cost_unit", choice.cost_unit},
            {"chosen", choice.chosen ? Json(choice.chosen->id()) : Json(nullptr)},
            {"summary", choice.summary()},
            {"candidates", candidates}};
}

Json material_record(const MaterialFit& m, const std::filesystem::path& data_dir, const BudgetChoice* budget,
                     const Json* recommendation) {
    Json out_of_gamut = Json::array();
    for (int c = 0; c < 3; ++c)
        if (m.F0[c] > 1.0 || m.F0[c] < 0.0) out_of_gamut.push_back(kChannelNames[c]);
    Json models = Json::object();
    for (const ModelResult& r : m.models) models[std::string(r.model->id())] = model_record(r);
    Json record = {{"name", m.material.name},
                   {"source", m.material.source},
                   {"data", data_provenance(m.material, data_dir)},
                   {"F0", rgb_json(m.F0)},
                   {"out_of_gamut_F0", out_of_gamut},
                   {"white_raw_rgb", rgb_json(m.raw_white)},
                   {"warnings", record_messages(m.material.warnings, m.material.provenance.file, data_dir)},
                   {"models", models}};
    if (budget) record["budget"] = budget_record(*budget);
    if (recommendation) record["recommendation"] = *recommendation;
    return record;
}

Json fit_record_without_materials(const FitRecordContext& context, const BudgetChoice* first_budget) {
    const ErrorSettings& e = context.error;
    Json record = {{"schema", kFitRecordSchema},
                   {"provenance",
                    {{"metalfit_version", METALFIT_VERSION},
                     {"cmf", to_string(context.observer)},
                     {"illuminant", to_string(context.illuminant)},
                     {"adaptation", to_string(context.adaptation)},
                     {"adapted", context.adapted},
                     {"convention", to_string(context.convention)},
                     {"ocio_config",
                      {{"file", record_path(context.config.path, context.data_dir)},
                       {"origin", context.config.origin},
                       {"sha256", sha256_file(context.config.path)}}},
                     {"color_space", context.space},
                     {"interpolation", to_string(context.spectral.interpolation)},
                     {"out_of_range", to_string(context.spectral.out_of_range)},
                     {"white_balance", "R_c = RGB_c(F) / RGB_c(perfect reflector)"},
                     {"nodes", e.nodes},
                     {"quadrature", "Gauss-Legendre on [0, 1]"},
                     {"max_grid", kDenseIntervals + 1},
                     {"metric", to_string(e.metric)},
                     {"weight", to_string(e.weight)}}},
                   {"materials", Json::object()}};
    // Only when a constraint is on, so that unconstrained records keep their keys.
    if (context.constraints.pin_f0) record["provenance"]["constraints"]["pin_f0"] = true;
    if (context.constraints.gamut_fit) record["provenance"]["constraints"]["gamut_fit"] = true;
    if (context.constraints.f0_tolerance)
        record["provenance"]["constraints"]["f0_tolerance"] = *context.constraints.f0_tolerance;
    if (first_budget)
        record["provenance"]["budget"] = {{"metric", to_string(first_budget->budget.metric)},
                                          {"limit", first_budget->budget.limit},
                                          {"cost_table", first_budget->cost_source}};
    return record;
}

Json fit_record(const std::vector<MaterialFit>& materials, const FitRecordContext& context,
                const std::vector<BudgetChoice>* budgets) {
    if (budgets && budgets->size() != materials.size())
        throw std::logic_error("fit_record: one budget choice per material");
    Json record = fit_record_without_materials(context, budgets && !budgets->empty() ? &budgets->front() : nullptr);
    Json& materials_json = record["materials"];
    for (std::size_t index = 0; index < materials.size(); ++index)
        materials_json[materials[index].material.id] =
            material_record(materials[index], context.data_dir, budgets ? &(*budgets)[index] : nullptr);
    return record;
}

}  // namespace metalfit
