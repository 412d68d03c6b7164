#include "libfit/export/recommendation.hpp"

#include <cmath>

#include "export/format_registry.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/number_text.hpp"

namespace metalfit {

namespace {

using Json = nlohmann::ordered_json;

// Nine significant digits: a float's value survives the paste (float has 24 bits, 9 digits round-trip it).
std::string number(double x) { return significant_text(x, 9); }

std::string triple(const RGB& v, const std::string& separator = ", ") {
    return number(v.r) + separator + number(v.g) + separator + number(v.b);
}

std::string percent(double fraction) { return significant_text(100 * fraction, 3) + " %"; }

}  // namespace

Budgets tolerance_budgets(const Tolerance& t) {
    return {
        {t.rel_rms, BudgetMetric::rel_rms}, {t.f0_err, BudgetMetric::f0_err}, {t.de2000_max, BudgetMetric::de2000_max}};
}

std::string tolerance_text(const Tolerance& tolerance) {
    std::string text;
    for (const Budget& b : tolerance_budgets(tolerance)) text += (text.empty() ? "" : ", ") + budget_text(b);
    return text;
}

ExportFormat parse_recommend_target(const std::string& text) {
    for (const auto& entry : kExportFormatNames.names)
        if (entry.value != ExportFormat::json && entry.name == text) return entry.value;
    throw UsageError("--target '" + text + "': one of glsl, hlsl, mtlx, openpbr, gltf, cpp, blender, msl, wgsl");
}

std::string target_refuses(ExportFormat target, const Model& model) {
    if (target == ExportFormat::gltf)
        return model.id() == "schlick"
                   ? ""
                   : "a glTF viewer renders Schlick from baseColorFactor, not " + std::string(model.id());
    if (detail::needs_stand_in(detail::format_entry(target), model))
        return to_string(target) + " cannot express " + std::string(model.id()) + " (it writes a stand-in)";
    return "";
}

std::string target_constants(ExportFormat target, const Model& model, const ModelParameters& params) {
    const auto parameters = model.parameters();
    std::string text;
    const auto each = [&](auto&& line) {
        for (std::size_t i = 0; i < parameters.size(); ++i)
            text += line(std::string(parameters[i].name), params.parameter(i));
    };
    const auto f82 = [&]() -> std::pair<RGB, RGB> {
        RGB F0, tint;
        for (int c = 0; c < 3; ++c) {
            const auto ft = model.f82_tint_of(params[c]);
            if (!ft) throw std::logic_error(std::string(model.id()) + " is not an F82-tint curve");
            F0[c] = (*ft)[0], tint[c] = (*ft)[1];
        }
        return {F0, tint};
    };
    switch (target) {
        case ExportFormat::glsl:
            each(
                [](const std::string& n, const RGB& v) { return "const vec3 " + n + " = vec3(" + triple(v) + ");\n"; });
            text += "// F = " + std::string(model.glsl_function()) + "(";
            for (std::size_t i = 0; i < parameters.size(); ++i) text += std::string(parameters[i].name) + ", ";
            text += "mu);  // glsl/metalfit_models.glsl\n";
            break;
        case ExportFormat::hlsl:
            each([](const std::string& n, const RGB& v) {
                return "static const float3 " + n + " = float3(" + triple(v) + ");\n";
            });
            text += "// F = " + std::string(model.glsl_function()) + "(";
            for (std::size_t i = 0; i < parameters.size(); ++i) text += std::string(parameters[i].name) + ", ";
            text += "mu);  // hlsl/metalfit_models.hlsl\n";
            break;
        case ExportFormat::msl:
            each([](const std::string& n, const RGB& v) {
                return "constant float3 " + n + " = float3(" + triple(v) + ");\n";
            });
            text += "// F = " + std::string(model.glsl_function()) + "(";
            for (std::size_t i = 0; i < parameters.size(); ++i) text += std::string(parameters[i].name) + ", ";
            text += "mu);  // msl/metalfit_models.metal (copy the constants into locals first)\n";
            break;
        case ExportFormat::wgsl:
            each([](const std::string& n, const RGB& v) { return "const " + n + " = vec3f(" + triple(v) + ");\n"; });
            text += "// F = " + std::string(model.glsl_function()) + "(";
            for (std::size_t i = 0; i < parameters.size(); ++i) text += std::string(parameters[i].name) + ", ";
            text += "mu);  // wgsl/metalfit_models.wgsl\n";
            break;
        case ExportFormat::cpp:
            each([](const std::string& n, const RGB& v) {
                return "constexpr std::array<float, 3> " + n + "{" + triple(v) + "};\n";
            });
            break;
        case ExportFormat::mtlx:
            switch (model.materialx_form()) {
                case MaterialxForm::conductor_bsdf:
                    text += "<conductor_bsdf>: <input name=\"ior\" type=\"color3\" value=\"" +
                            triple(params.parameter(0)) + "\" /> <input name=\"extinction\" type=\"color3\" value=\"" +
                            triple(params.parameter(1)) + "\" />\n";
                    break;
                case MaterialxForm::artistic_ior:
                    text += "<artistic_ior>: <input name=\"reflectivity\" type=\"color3\" value=\"" +
                            triple(params.parameter(0)) + "\" /> <input name=\"edge_color\" type=\"color3\" value=\"" +
                            triple(params.parameter(1)) + "\" />\n";
                    break;
                case MaterialxForm::generalized_schlick: {
                    const auto [F0, tint] = f82();
                    text += "<generalized_schlick_bsdf>: <input name=\"color0\" type=\"color3\" value=\"" + triple(F0) +
                            "\" /> <input name=\"color82\" type=\"color3\" value=\"" + triple(tint) + "\" />\n";
                    break;
                }
                case MaterialxForm::stand_in: break;
            }
            break;
        case ExportFormat::openpbr: {
            const auto [F0, tint] = f82();
            text += "base_metalness = 1\nbase_color = " + triple(F0) + "\nspecular_color = " + triple(tint) + "\n";
            break;
        }
        case ExportFormat::gltf:
            text += "\"pbrMetallicRoughness\": {\"baseColorFactor\": [" + triple(params.parameter(0)) +
                    ", 1.0], \"metallicFactor\": 1.0}\n";
            break;
        case ExportFormat::blender: {
            const auto [F0, tint] = f82();
            text += "Metallic BSDF (Blender >= 4.3), fresnel_type 'F82': Base Color = " + triple(F0) +
                    ", Edge Tint = " + triple(tint) + "\n";
            break;
        }
        case ExportFormat::json: break;
    }
    return text;
}

Recommendation recommend(const MaterialFit& fit, const CostTable& costs, const Tolerance& tolerance,
                         ExportFormat target) {
    Recommendation r;
    r.material = fit.material.id;
    r.target = target;
    r.tolerance = tolerance;
    r.choice = choose_model(fit.models, costs, tolerance_budgets(tolerance),
                            [target](const Model& model) { return target_refuses(target, model); });
    for (const BudgetCandidate& c : r.choice.candidates) {
        if (c.model == r.choice.chosen) break;
        r.cheaper.push_back(std::string(c.model->id()) + ": " + c.reason);
    }
    if (r.choice.chosen)
        for (const ModelResult& m : fit.models)
            if (m.model == r.choice.chosen) r.constants = target_constants(target, *m.model, m.fit.value.params);
    return r;
}

std::string Recommendation::text() const {
    std::string s = "  recommended for " + to_string(target) + ": ";
    const BudgetCandidate* chosen = nullptr;
    for (const BudgetCandidate& c : choice.candidates)
        if (c.model == choice.chosen) chosen = &c;
    if (chosen)
        s += std::string(chosen->model->id()) + " (rel_rms " + percent(chosen->values[0]) + ", |F0 error| " +
             percent(chosen->values[1]) + ", ΔE2000 max " + significant_text(chosen->values[2], 3) + ")\n";
    else
        s += "no model meets the tolerance\n";
    s += "    tolerance: " + tolerance_text(tolerance) + " in every channel; cost table: " + choice.cost_source + "\n";
    for (std::size_t start = 0; start < constants.size();) {
        const std::size_t end = constants.find('\n', start);
        s += "    " + constants.substr(start, end - start) + "\n";
        start = end == std::string::npos ? constants.size() : end + 1;
    }
    if (!cheaper.empty()) s += chosen ? "  cheaper models fail:\n" : "  every model fails:\n";
    for (const std::string& line : cheaper) s += "    " + line + "\n";
    return s;
}

Json recommendation_record(const Recommendation& r) {
    Json candidates = Json::array();
    for (const BudgetCandidate& c : r.choice.candidates) {
        Json values = Json::object();
        for (std::size_t i = 0; i < r.choice.budgets.size(); ++i)
            values[to_string(r.choice.budgets[i].metric)] = std::isnan(c.values[i]) ? Json(nullptr) : Json(c.values[i]);
        candidates.push_back({{"model", c.model->id()},
                              {"cost", c.cost ? Json(*c.cost) : Json(nullptr)},
                              {"values", values},
                              {"qualifies", c.qualifies},
                              {"reason", c.reason.empty() ? Json(nullptr) : Json(c.reason)}});
    }
    return {
        {"target", to_string(r.target)},
        {"tolerance",
         {{"rel_rms", r.tolerance.rel_rms}, {"f0_err", r.tolerance.f0_err}, {"de2000_max", r.tolerance.de2000_max}}},
        {"chosen", r.choice.chosen ? Json(r.choice.chosen->id()) : Json(nullptr)},
        {"constants", r.constants.empty() ? Json(nullptr) : Json(r.constants)},
        {"cost_table", r.choice.cost_source},
        {"cost_unit", r.choice.cost_unit},
        {"candidates", candidates}};
}

namespace {

struct TableCells {
    std::string model, rel_rms, f0_err, de2000, cheaper;
};

TableCells cells(const Recommendation& r) {
    TableCells t{"none", "", "", "", ""};
    if (r.choice.chosen)
        for (const BudgetCandidate& c : r.choice.candidates)
            if (c.model == r.choice.chosen) {
                t.model = std::string(c.model->id());
                t.rel_rms = significant_text(100 * c.values[0], 3);
                t.f0_err = significant_text(100 * c.values[1], 3);
                t.de2000 = significant_text(c.values[2], 3);
            }
    if (!r.cheaper.empty()) t.cheaper = r.cheaper.back();
    return t;
}

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return out + "\"";
}

}  // namespace

std::string recommendation_table_markdown(const std::vector<Recommendation>& rows) {
    std::string s;
    if (!rows.empty())
        s += "Recommended for " + to_string(rows.front().target) + ": " + tolerance_text(rows.front().tolerance) +
             "; cost table: " + rows.front().choice.cost_source + "\n\n";
    s += "| material | model | rel_rms % | \\|F0 error\\| % | ΔE2000 max | next cheaper model: why it fails |\n";
    s += "|---|---|---|---|---|---|\n";
    for (const Recommendation& r : rows) {
        const TableCells t = cells(r);
        std::string cheaper = t.cheaper;
        for (std::size_t i = 0; (i = cheaper.find('|', i)) != std::string::npos; i += 2) cheaper.insert(i, "\\");
        s += "| " + r.material + " | " + t.model + " | " + t.rel_rms + " | " + t.f0_err + " | " + t.de2000 + " | " +
             cheaper + " |\n";
    }
    return s;
}

std::string recommendation_table_csv(const std::vector<Recommendation>& rows) {
    std::string s = "material,target,model,rel_rms_percent,f0_err_percent,de2000_max,next_cheaper_fails\n";
    for (const Recommendation& r : rows) {
        const TableCells t = cells(r);
        s += csv_field(r.material) + "," + to_string(r.target) + "," + t.model + "," + t.rel_rms + "," + t.f0_err +
             "," + t.de2000 + "," + csv_field(t.cheaper) + "\n";
    }
    return s;
}

Json recommendation_table_json(const std::vector<Recommendation>& rows) {
    Json out = Json::array();
    for (const Recommendation& r : rows) {
        Json row = Json::object();
        row["material"] = r.material;
        const Json record = recommendation_record(r);
        for (auto it = record.begin(); it != record.end(); ++it) row[it.key()] = *it;
        out.push_back(std::move(row));
    }
    return out;
}

}  // namespace metalfit
