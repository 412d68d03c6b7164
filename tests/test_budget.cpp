// The cheapest model for an error budget (libfit/fit/budget, model_cost): choose_model on hand-made fits and cost
// tables (ties, models without a cost, "none qualifies"), the budget parser, and reading a bench report.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include <nlohmann/json.hpp>

#include "libfit/base/errors.hpp"
#include "libfit/base/sample_statistics.hpp"
#include "libfit/fit/budget.hpp"
#include "libfit/fit/model_cost.hpp"
#include "libfit/models/registry.hpp"
#include "test_support.hpp"

namespace metalfit {
namespace test_budget {

using namespace metalfit::test;

// A fit of `model` whose worst channel has the given rel_rms (the others lower), max_rel twice that, ΔE `de`.
ModelResult result(const std::string& model, double rel, double de = 1.0) {
    ModelResult r;
    r.model = &find_model(model);
    r.fit.value.metrics.rel_rms = {rel / 2, rel, rel / 3};
    r.fit.value.metrics.max_rel = {rel, 2 * rel, rel};
    r.fit.value.metrics.de2000_max = de;
    return r;
}

CostTable table(std::vector<ModelCost> costs) { return {"hand-made", "units", std::move(costs)}; }

TEST(Budget, PicksTheCheapestModelMeetingTheBudgetInEveryChannel) {
    const std::vector<ModelResult> fits{result("schlick", 0.02), result("f82-tint", 0.008), result("rational", 0.004),
                                        result("conductor-rgb", 0.001)};
    const CostTable costs = table({{"schlick", 10}, {"f82-tint", 20}, {"rational", 15}, {"conductor-rgb", 40}});
    const BudgetChoice one = choose_model(fits, costs, {0.01, BudgetMetric::rel_rms});
    ASSERT_NE(one.chosen, nullptr);
    EXPECT_EQ(one.chosen->id(), "rational");                   // cheaper than f82-tint, which also qualifies
    EXPECT_EQ(one.candidates.front().model->id(), "schlick");  // cheapest first
    EXPECT_FALSE(one.candidates.front().qualifies);
    EXPECT_TRUE(Contains(one.candidates.front().reason, "rel_rms 2 % > 1 %")) << one.candidates.front().reason;
    // A tighter budget: only the most expensive one.
    EXPECT_EQ(choose_model(fits, costs, {0.002, BudgetMetric::rel_rms}).chosen->id(), "conductor-rgb");
    // The worst channel decides, not the mean: rational's channels are 0.2, 0.4, 0.13 %.
    EXPECT_EQ(choose_model(fits, costs, {0.0039, BudgetMetric::rel_rms}).chosen->id(), "conductor-rgb");
    EXPECT_EQ(choose_model(fits, costs, {0.004, BudgetMetric::rel_rms}).chosen->id(), "rational");  // limit inclusive
    // Another metric: max_rel is twice the worst rel_rms here.
    EXPECT_EQ(choose_model(fits, costs, {0.01, BudgetMetric::max_rel}).chosen->id(), "rational");
    EXPECT_EQ(choose_model(fits, costs, {0.015, BudgetMetric::max_rel}).chosen->id(), "rational");
    EXPECT_EQ(choose_model(fits, costs, {0.0075, BudgetMetric::max_rel}).chosen->id(), "conductor-rgb");
}

TEST(Budget, TiesInCostGoToTheMoreAccurateModelThenToTheInputOrder) {
    const CostTable costs = table({{"schlick", 10}, {"f82-tint", 10}, {"rational", 10}});
    const std::vector<ModelResult> fits{result("schlick", 0.004), result("f82-tint", 0.003), result("rational", 0.003)};
    const BudgetChoice c = choose_model(fits, costs, {0.005, BudgetMetric::rel_rms});
    EXPECT_EQ(c.chosen->id(), "f82-tint");  // 0.3 % beats 0.4 % at the same cost; f82-tint before rational in the input
    EXPECT_EQ(c.candidates[0].model->id(), "f82-tint");
    EXPECT_EQ(c.candidates[1].model->id(), "rational");
    EXPECT_EQ(c.candidates[2].model->id(), "schlick");
}

TEST(Budget, NoneQualifiesSaysWhyForEveryModel) {
    const std::vector<ModelResult> fits{result("schlick", 0.02), result("f82-tint", 0.011), result("rational", 0.001)};
    // rational would qualify but has no cost in the table.
    const BudgetChoice c =
        choose_model(fits, table({{"schlick", 10}, {"f82-tint", 20}}), {0.005, BudgetMetric::rel_rms});
    EXPECT_EQ(c.chosen, nullptr);
    ASSERT_EQ(c.candidates.size(), 3u);
    EXPECT_EQ(c.candidates.back().model->id(), "rational");  // no cost: last
    EXPECT_TRUE(Contains(c.candidates.back().reason, "no cost for rational")) << c.candidates.back().reason;
    for (const BudgetCandidate& k : c.candidates) {
        EXPECT_FALSE(k.qualifies);
        EXPECT_FALSE(k.reason.empty());
    }
    EXPECT_TRUE(Contains(c.summary(), "none qualifies")) << c.summary();
    // An undefined metric never qualifies.
    ModelResult undefined = result("schlick", 0.001);
    undefined.fit.value.metrics.rel_rms[1] = std::numeric_limits<double>::quiet_NaN();
    const BudgetChoice u = choose_model({undefined}, table({{"schlick", 1}}), {0.5, BudgetMetric::rel_rms});
    EXPECT_EQ(u.chosen, nullptr);
    EXPECT_TRUE(Contains(u.candidates[0].reason, "undefined"));
    // ΔE budgets compare the worst ΔE2000.
    const BudgetChoice de = choose_model({result("schlick", 0.1, 0.8), result("f82-tint", 0.1, 0.3)},
                                         table({{"schlick", 1}, {"f82-tint", 2}}), {0.5, BudgetMetric::de2000_max});
    EXPECT_EQ(de.chosen->id(), "f82-tint");
}

TEST(Budget, ParsesPercentagesFractionsAndDeltaE) {
    EXPECT_DOUBLE_EQ(parse_budget("0.5%", BudgetMetric::rel_rms).limit, 0.005);
    EXPECT_DOUBLE_EQ(parse_budget("0.005", BudgetMetric::max_rel).limit, 0.005);
    EXPECT_DOUBLE_EQ(parse_budget("1.5", BudgetMetric::de2000_max).limit, 1.5);
    for (const char* bad : {"", "%", "abc", "-1%", "0.5%%", "nan", "inf", "1e999"})
        EXPECT_THROW(parse_budget(bad, BudgetMetric::rel_rms), UsageError) << bad;
    EXPECT_THROW(parse_budget("1%", BudgetMetric::de2000_max), UsageError);
    EXPECT_THROW(parse_budget_metric("abs_rms"), UsageError);
    EXPECT_EQ(budget_text({0.005, BudgetMetric::rel_rms}), "rel_rms <= 0.5 %");
}

// The built-in table is data/model-costs.json's measured llvmpipe column (issue 29): it covers exactly the registry,
// conductor-rgb is its own baseline (1), every cost is the file's ratio, inside its quartiles; the file's rank
// correlations are those of its own columns (recomputed here); schlick (7 SPIR-V ops, no root) is cheaper than the
// exact form, which rounds two complex square roots per channel.
TEST(ModelCost, TheBuiltInTableIsTheMeasuredFileAndCoversTheRegistry) {
    const CostTable t = builtin_cost_table();
    EXPECT_TRUE(Contains(t.source, "data/model-costs.json")) << t.source;
    EXPECT_TRUE(Contains(t.unit, "llvmpipe")) << t.unit;
    EXPECT_EQ(t.costs.size(), all_models().size());
    for (const Model* m : all_models()) EXPECT_TRUE(t.cost_of(m->id())) << m->id() << " is not in the cost table";
    for (const ModelCost& c : t.costs) EXPECT_NO_THROW(find_model(c.model)) << c.model << " is not a model";
    EXPECT_EQ(*t.cost_of("conductor-rgb"), 1.0);
    EXPECT_FALSE(t.cost_of("no-such-model"));

    std::ifstream in(kData / "model-costs.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j["schema"], "metalfit.model-costs/1");
    EXPECT_EQ(j["cost"], "llvmpipe");
    std::vector<double> gpu, cpu, ops, weighted;
    for (const auto& m : j["models"]) {
        const std::string id = m["model"];
        const double ratio = m["llvmpipe"]["ratio"];
        EXPECT_EQ(*t.cost_of(id), ratio) << id;
        for (const char* column : {"llvmpipe", "cpu_array"}) {
            const auto& c = m[column];
            EXPECT_GE(c["noise"].get<double>(), 0) << id << " " << column;
            EXPECT_LE(c["quartiles"][0].get<double>(), c["ratio"].get<double>()) << id << " " << column;
            EXPECT_GE(c["quartiles"][1].get<double>(), c["ratio"].get<double>()) << id << " " << column;
        }
        gpu.push_back(ratio);
        cpu.push_back(m["cpu_array"]["ratio"]);
        ops.push_back(m["spirv_ops"]);
        weighted.push_back(m["spirv_weighted"]);
    }
    const auto& rho = j["spearman"];
    EXPECT_NEAR(rho["spirv_weighted_vs_llvmpipe"].get<double>(), spearman(weighted, gpu), 1e-12);
    EXPECT_NEAR(rho["spirv_weighted_vs_cpu_array"].get<double>(), spearman(weighted, cpu), 1e-12);
    EXPECT_NEAR(rho["spirv_ops_vs_llvmpipe"].get<double>(), spearman(ops, gpu), 1e-12);
    EXPECT_NEAR(rho["spirv_ops_vs_cpu_array"].get<double>(), spearman(ops, cpu), 1e-12);
    EXPECT_NEAR(rho["cpu_array_vs_llvmpipe"].get<double>(), spearman(cpu, gpu), 1e-12);
    EXPECT_LT(*t.cost_of("schlick"), *t.cost_of("conductor-rgb"));
}

TEST(ModelCost, ReadsAModelCostsDocumentAsCostsAndRefusesABrokenOne) {
    const TempDir temp;
    const auto file = temp.write("costs.json", R"({"schema": "metalfit.model-costs/1", "cost": "cpu_array", "models": [
        {"model": "schlick", "llvmpipe": {"ratio": 0.1}, "cpu_array": {"ratio": 0.2}},
        {"model": "f82-tint", "llvmpipe": {"ratio": 0.6}, "cpu_array": {"ratio": 0.3}}]})");
    const CostTable t = cost_table_from_bench_json(file);
    EXPECT_DOUBLE_EQ(*t.cost_of("f82-tint"), 0.3);
    EXPECT_TRUE(Contains(t.unit, "CPU array")) << t.unit;
    const auto bad =
        temp.write("bad-costs.json", R"({"schema": "metalfit.model-costs/1", "cost": "llvmpipe", "models": [
        {"model": "schlick", "llvmpipe": {"ratio": -1}}]})");
    try {
        cost_table_from_bench_json(bad);
        ADD_FAILURE() << "accepted a negative cost";
    } catch (const InputError& e) {
        EXPECT_TRUE(Contains(e.what(), "models[0].llvmpipe.ratio")) << e.what();
    }
}

TEST(ModelCost, ReadsABenchReportPreferringGpuRatios) {
    const TempDir temp;
    const auto& dir = temp.path();
    const auto write = [&](const std::string& name, const std::string& text) { return temp.write(name, text); };
    const auto gpu = write("gpu.json", R"({"schema": "metalfit.bench/1", "rows": [
        {"id": "schlick", "kind": "model", "ratio_scalar": 0.2, "shader_ratio": 0.5},
        {"id": "f82-tint", "kind": "model", "ratio_scalar": 0.3, "shader_ratio": 0.6},
        {"id": "lut-64", "kind": "lut", "ratio_scalar": 0.1, "shader_ratio": null}]})");
    const CostTable g = cost_table_from_bench_json(gpu);
    EXPECT_EQ(g.costs.size(), 2u);
    EXPECT_DOUBLE_EQ(*g.cost_of("schlick"), 0.5);
    EXPECT_TRUE(Contains(g.source, "GPU"));
    const auto cpu = write("cpu.json", R"({"schema": "metalfit.bench/1", "rows": [
        {"id": "schlick", "kind": "model", "ratio_scalar": 0.2, "shader_ratio": 0.5},
        {"id": "f82-tint", "kind": "model", "ratio_scalar": 0.3, "shader_ratio": null}]})");
    const CostTable c = cost_table_from_bench_json(cpu);
    EXPECT_DOUBLE_EQ(*c.cost_of("f82-tint"), 0.3);  // not every model has a GPU ratio: CPU for all
    EXPECT_TRUE(Contains(c.source, "CPU"));
    const auto bad_schema = write("bad.json", R"({"schema": "metalfit.fit/1", "rows": []})");
    try {
        cost_table_from_bench_json(bad_schema);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_TRUE(StartsWith(e.what(), bad_schema.string())) << e.what();
        EXPECT_TRUE(Contains(e.what(), "schema")) << e.what();
    }
    EXPECT_THROW(cost_table_from_bench_json(write("neg.json", R"({"schema": "metalfit.bench/1", "rows": [
        {"id": "schlick", "kind": "model", "ratio_scalar": -1, "shader_ratio": null}]})")),
                 InputError);
    EXPECT_THROW(cost_table_from_bench_json(write("broken.json", "{")), InputError);
    EXPECT_THROW(cost_table_from_bench_json(dir / "missing.json"), InputError);
}

}  // namespace test_budget
}  // namespace metalfit
