#include "libfit/fit/model_cost.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

#include "libfit/base/errors.hpp"
#include "libfit/base/record_path.hpp"

namespace metalfit {

namespace {

// SPIR-V arithmetic + transcendental instructions per model (metalfit bench's "SPIR-V ops": glslangValidator -V -Os on
// the bench's fragment shader around Model::glsl_source()). Regenerate with `build/bin/metalfit bench --quick --json`
// (rows[].spirv_ops); test_bench_spirv.cpp (BuiltInCostTableIsTheBenchCount) recounts them.
const ModelCost kSpirvOps[] = {
    {"schlick", 7},
    {"lazanyi", 13},
    {"lazanyi-comp", 18},
    {"f82-tint", 19},
    {"conductor-rgb", 35},
    {"gulbrandsen", 51},
    {"schlick-comp-linear", 12},
    {"schlick-comp", 11},
    {"schlick-comp-general", 8},
    {"rational", 9},
};

}  // namespace

std::optional<double> CostTable::cost_of(std::string_view model) const {
    for (const ModelCost& c : costs)
        if (c.model == model) return c.cost;
    return std::nullopt;
}

CostTable builtin_cost_table() {
    CostTable table{
        "built-in: SPIR-V ops per model (glslangValidator -V -Os, as metalfit bench counts them)", "SPIR-V ops", {}};
    for (const ModelCost& c : kSpirvOps) table.costs.push_back(c);
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
    if (!j.is_object() || !j.contains("schema") || j["schema"] != "metalfit.bench/1")
        throw InputError({file, 0, "schema"},
                         "not a metalfit bench report (expected \"metalfit.bench/1\" from `metalfit bench --json`)");
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
