// The Pareto front of cost against error (bench/pareto.hpp) and its marking on report rows.
#include <gtest/gtest.h>

#include <cmath>

#include "metalfit_bench/bench_report.hpp"
#include "metalfit_bench/pareto.hpp"

namespace test_bench_pareto {

using namespace metalfit::bench;

TEST(Pareto, DominatedPointsAreOffTheFront) {
    // cost, error: a cheap inaccurate, a middle one, a dominated one (slower and less accurate than b), an exact one.
    const std::vector<ParetoPoint> p{{0.1, 0.10}, {0.5, 0.01}, {0.8, 0.02}, {10, 0.0}};
    EXPECT_EQ(pareto_front(p), (std::vector<bool>{true, true, false, true}));
    EXPECT_TRUE(dominates(p[1], p[2]));
    EXPECT_FALSE(dominates(p[2], p[1]));
    EXPECT_FALSE(dominates(p[0], p[1]));  // cheaper but less accurate: a trade-off
}

TEST(Pareto, TiesWithinToleranceDoNotDominate) {
    const ParetoTolerance t{0.10, 0.05, 1e-5};
    // 5 % slower, same error: a tie in both, neither dominates, both stay on the front.
    const std::vector<ParetoPoint> tie{{1.00, 0.01}, {1.05, 0.01}};
    EXPECT_EQ(pareto_front(tie, t), (std::vector<bool>{true, true}));
    // 30 % slower with the same error: dominated.
    const std::vector<ParetoPoint> slower{{1.00, 0.01}, {1.30, 0.01}};
    EXPECT_EQ(pareto_front(slower, t), (std::vector<bool>{true, false}));
    // Same cost, error 3 % apart: a tie; 20 % apart: dominated.
    EXPECT_FALSE(dominates({1, 0.0100}, {1, 0.0103}, t));
    EXPECT_TRUE(dominates({1, 0.0100}, {1, 0.0120}, t));
    // Below the absolute floor errors tie (0.0002 % against 0.0001 %).
    EXPECT_FALSE(dominates({1, 1e-6}, {1, 2e-6}, t));
}

TEST(Pareto, NanPointsAreNeitherOnTheFrontNorDominating) {
    const std::vector<ParetoPoint> p{{NAN, 0.0}, {1.0, 0.5}};
    EXPECT_EQ(pareto_front(p), (std::vector<bool>{false, true}));
}

CostRow row(const std::string& id, const std::string& kind, double ratio, double error,
            std::optional<double> shader = {}) {
    CostRow r;
    r.id = id;
    r.kind = kind;
    r.ratio_scalar.median = ratio;
    r.median_rel_rms = error;
    r.shader_ratio = shader;
    return r;
}

TEST(Pareto, ReportRowsAreMarkedAmongModelsAndAmongAllRows) {
    std::vector<CostRow> rows{row("fast", "model", 0.1, 0.10, 0.3),             // on both model fronts
                              row("same-but-slower", "model", 0.5, 0.10, 0.4),  // dominated by fast
                              row("accurate", "model", 1.0, 0.001, 1.0),        // on the model fronts
                              row("lut", "lut", 0.1, 0.0001),                   // dominates every model on the CPU
                              row("exact", "exact", 1000, 0.0)};                // the only exact row
    mark_pareto_fronts(rows, ParetoTolerance{});
    EXPECT_TRUE(rows[0].front_models.cpu);
    EXPECT_FALSE(rows[1].front_models.cpu);
    EXPECT_TRUE(rows[2].front_models.cpu);
    EXPECT_FALSE(rows[3].front_models.cpu);  // not a model
    EXPECT_EQ(rows[0].front_models.gpu, true);
    EXPECT_EQ(rows[1].front_models.gpu, false);
    EXPECT_EQ(rows[3].front_models.gpu, std::nullopt);
    EXPECT_FALSE(rows[0].front_all.cpu);
    EXPECT_FALSE(rows[2].front_all.cpu);
    EXPECT_TRUE(rows[3].front_all.cpu);
    EXPECT_TRUE(rows[4].front_all.cpu);
    EXPECT_EQ(rows[4].front_all.gpu, std::nullopt);  // no shader figure
    EXPECT_EQ(rows[2].front_all.gpu, true);          // the LUT has no shader figure here: only models compete
}

}  // namespace test_bench_pareto
