#include "libfit/fit/model_cost.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

#include "libfit/base/errors.hpp"
#include "libfit/base/record_path.hpp"
#include "model_costs_table.hpp"

namespace metalfit {

namespace {

// The cost column of a `metalfit bench --model-costs --json` document (schema metalfit.model-costs/1): its `cost`
// names the column ("llvmpipe" or "cpu_array"), each model row's `<column>.ratio` is the model's cost.
CostTable from_model_costs(const nlohmann::json& j, const std::filesystem::path& file, const std::string& name) {
    const auto where = [&](const std::string& field) { return InputLocation{file, 0, field}; };
    const auto cost = j.find("cost");
    if (cost == j.end() || !cost->is_string() || (*cost != "llvmpipe" && *cost != "cpu_array"))
        throw InputError(where("cost"), "expected \"llvmpipe\" or \"cpu_array\"");
    const std::string column = cost->get<std::string>();
    const auto models = j.find("models");
    if (models == j.end() || !models->is_array() || models->empty())
        throw InputError(where("models"), "expected a non-empty list");
    CostTable table;
    table.source =
        name + (column == "llvmpipe"
                    ? ": measured shader cost on llvmpipe, ratio to conductor-rgb (metalfit bench --model-costs)"
                    : ": measured CPU array-loop cost, ratio to conductor-rgb (metalfit bench --model-costs)");
    table.unit = column == "llvmpipe" ? "x conductor-rgb (llvmpipe)" : "x conductor-rgb (CPU array)";
    for (std::size_t i = 0; i < models->size(); ++i) {
        const auto& m = (*models)[i];
        const std::string at = "models[" + std::to_string(i) + "]";
        if (!m.is_object() || !m.contains("model") || !m["model"].is_string())
            throw InputError(where(at + ".model"), "expected a model id");
        const auto c = m.find(column);
        if (c == m.end() || !c->is_object() || !c->contains("ratio") || !(*c)["ratio"].is_number() ||
            !((*c)["ratio"].get<double>() > 0))
            throw InputError(where(at + "." + column + ".ratio"), "expected a positive number");
        table.costs.push_back({m["model"].get<std::string>(), (*c)["ratio"].get<double>()});
    }
    return table;
}

}  // namespace

std::optional<double> CostTable::cost_of(std::string_view model) const {
    for (const ModelCost& c : costs)
        if (c.model == model) return c.cost;
    return std::nullopt;
}

CostTable builtin_cost_table() {
    static const CostTable table = [] {
        const nlohmann::json j = nlohmann::json::parse(detail::kModelCostsTable);
        return from_model_costs(j, "data/model-costs.json", "built-in (data/model-costs.json)");
    }();
    return table;
}

CostTable cost_table_from_bench_json(const std::filesystem::path& file, const std::filesystem::path& data_dir) {
    std::ifstream in(file);
    if (!in) throw InputError({file}, "cannot open the bench report");
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(in);
    } catch (const nlohmann::json::parse_error& e) {
        throw InputError({file}, std::string("invalid JSON: ") + e.what());
    }
    if (j.is_object() && j.contains("schema") && j["schema"] == "metalfit.model-costs/1")
        return from_model_costs(j, file, record_path(file, data_dir));
    if (!j.is_object() || !j.contains("schema") || j["schema"] != "metalfit.bench/1")
        throw InputError({file, 0, "schema"}, "not a metalfit bench report (expected \"metalfit.bench/1\" from "
                                              "`metalfit bench --json` or \"metalfit.model-costs/1\")");
    const auto rows = j.find("rows");
    if (rows == j.end() || !rows->is_array()) throw InputError({file, 0, "rows"}, "expected a list");
    struct Row {
        std::string id;
        std::optional<double> gpu, cpu;
    };
    std::vector<Row> models;
    for (std::size_t i = 0; i < rows->size(); ++i) {
        const auto& r = (*rows)[i];
        const std::string where = "rows[" + std::to_string(i) + "]";
        if (!r.is_object() || !r.contains("id") || !r["id"].is_string() || !r.contains("kind") ||
            !r["kind"].is_string())
            throw InputError({file, 0, where}, "expected an object with string id and kind");
        if (r["kind"] != "model") continue;
        Row row{r["id"].get<std::string>(), {}, {}};
        const auto number = [&](const char* key) -> std::optional<double> {
            const auto v = r.find(key);
            if (v == r.end() || v->is_null()) return std::nullopt;
            if (!v->is_number() || !(v->get<double>() > 0))
                throw InputError({file, 0, where + "." + key}, "expected a positive number or null");
            return v->get<double>();
        };
        row.gpu = number("shader_ratio");
        row.cpu = number("ratio_scalar");
        models.push_back(std::move(row));
    }
    if (models.empty()) throw InputError({file, 0, "rows"}, "no model rows");
    const bool gpu = std::all_of(models.begin(), models.end(), [](const Row& r) { return r.gpu.has_value(); });
    CostTable table;
    table.source = record_path(file, data_dir) +
                   (gpu ? ": GPU shader ratio to conductor-rgb (metalfit bench)"
                        : ": CPU scalar ratio to conductor-rgb (metalfit bench; no GPU figures for every model)");
    table.unit = gpu ? "x conductor-rgb (GPU)" : "x conductor-rgb (CPU)";
    for (const Row& r : models) {
        const std::optional<double> cost = gpu ? r.gpu : r.cpu;
        if (!cost) throw InputError({file, 0, "rows." + r.id + ".ratio_scalar"}, "missing for model " + r.id);
        table.costs.push_back({r.id, *cost});
    }
    return table;
}

}  // namespace metalfit
