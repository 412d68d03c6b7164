// Batch fitting streamed in input order (fit_materials_in_order) and the fit record written material by material
// (FitRecordStream): the order, the bound on the materials alive at once (the reorder window: counted, not timed),
// the first error in input order, and the streamed record byte for byte against fit_record on catalog materials.
#include <gtest/gtest.h>

#include "test_environment.hpp"
#include "test_support.hpp"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "libfit/base/errors.hpp"
#include "libfit/color/color_space.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/fit/budget.hpp"
#include "libfit/fit/fit_batch.hpp"
#include "libfit/fit/fit_record.hpp"
#include "libfit/fit/fit_record_stream.hpp"
#include "libfit/fit/model_cost.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/models/model.hpp"

namespace metalfit {
namespace test_fit_batch {

using namespace metalfit::test;

// Two cheap models: the batch's order and bounds do not depend on which.
MaterialFitRequest cheap_request() {
    return {SpectralOptions{}, ErrorSettings{}, {&find_model("schlick"), &find_model("lazanyi")}};
}

// `count` materials cycling through the catalog, renamed "m<i>", each loader counting its calls in `started`;
// `failing` (if < count) throws an InputError naming "m<failing>".
std::vector<std::function<Material()>> counted_loaders(std::size_t count, std::atomic<std::size_t>& started,
                                                       std::size_t failing = SIZE_MAX) {
    std::vector<Material> bases;
    for (const CatalogEntry& e : env().catalog.entries()) bases.push_back(load_material(env().catalog, e.id, ""));
    std::vector<std::function<Material()>> loaders;
    for (std::size_t i = 0; i < count; ++i)
        loaders.push_back([&started, base = bases[i % bases.size()], i, failing] {
            ++started;
            if (i == failing) throw InputError({"m" + std::to_string(i)}, "bad");
            Material m = base;
            m.id = "m" + std::to_string(i);
            return m;
        });
    return loaders;
}

TEST(FitBatch, HandsEveryFitOnInInputOrderWithAtMostTheWindowAlive) {
    for (const int threads : {1, 2, 3}) {
        constexpr std::size_t kCount = 24, kWindow = 3;
        std::atomic<std::size_t> started{0};
        std::size_t handed = 0, most_alive = 0;
        fit_materials_in_order(
            counted_loaders(kCount, started), env().colour(), cheap_request(), threads,
            [&](std::size_t index, MaterialFit&& fit) {
                EXPECT_EQ(index, handed) << threads << " threads";
                EXPECT_EQ(fit.material.id, "m" + std::to_string(index));
                EXPECT_EQ(fit.models.size(), 2u);
                // Loaded and not yet let go by the sink: this one and those started after it.
                most_alive = std::max(most_alive, started.load() - handed);
                ++handed;
            },
            {}, kWindow);
        EXPECT_EQ(handed, kCount) << threads << " threads";
        EXPECT_LE(most_alive, kWindow) << threads << " threads";
        EXPECT_GE(most_alive, 1u);
    }
}

TEST(FitBatch, SameFitsAsOneMaterialAtATime) {
    std::atomic<std::size_t> started{0};
    const auto loaders = counted_loaders(5, started);
    const std::vector<MaterialFit> batch = fit_materials(loaders, env().colour(), cheap_request(), 2);
    ASSERT_EQ(batch.size(), loaders.size());
    for (std::size_t i = 0; i < loaders.size(); ++i) {
        const MaterialFit alone = fit_material(loaders[i](), env().colorimetry, env().converter, cheap_request());
        EXPECT_EQ(batch[i].material.id, alone.material.id);
        for (std::size_t m = 0; m < alone.models.size(); ++m)
            EXPECT_EQ(model_record(batch[i].models[m]).dump(), model_record(alone.models[m]).dump()) << i;
    }
}

TEST(FitBatch, StopsAtTheFirstErrorInInputOrderAfterHandingOnEveryMaterialBeforeIt) {
    std::atomic<std::size_t> started{0};
    std::vector<std::size_t> handed;
    try {
        fit_materials_in_order(
            counted_loaders(20, started, 7), env().colour(), cheap_request(), 2,
            [&](std::size_t index, MaterialFit&&) { handed.push_back(index); }, {}, 4);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_TRUE(Contains(e.what(), "m7"));
    }
    ASSERT_EQ(handed.size(), 7u);
    for (std::size_t i = 0; i < handed.size(); ++i) EXPECT_EQ(handed[i], i);
    EXPECT_LE(started.load(), 7u + 4u);  // nothing started beyond the window past the failure
}

TEST(FitBatch, AnErrorOfTheSinkStopsTheBatch) {
    std::atomic<std::size_t> started{0};
    std::size_t calls = 0;
    EXPECT_THROW(fit_materials_in_order(
                     counted_loaders(20, started), env().colour(), cheap_request(), 2,
                     [&](std::size_t index, MaterialFit&&) {
                         ++calls;
                         if (index == 3) throw std::runtime_error("disk full");
                     },
                     {}, 4),
                 std::runtime_error);
    EXPECT_EQ(calls, 4u);
    EXPECT_LE(started.load(), 3u + 4u);
}

// ---------------------------------------------------------------------------------------------------------------
// The streamed record against fit_record, byte for byte.

FitRecordContext context() {
    return {kShipped,        env().converter.space(), Observer::cie1931_2deg,
            Illuminant::D65, SpectralOptions{},       ErrorSettings{}};
}

std::string streamed(const std::vector<MaterialFit>& fits, const FitRecordContext& c,
                     const std::vector<BudgetChoice>* budgets = nullptr) {
    std::string text;
    std::size_t pieces = 0;
    FitRecordStream stream(c, [&](std::string_view piece) {
        text += piece;
        ++pieces;
    });
    for (std::size_t i = 0; i < fits.size(); ++i) stream.add(fits[i], budgets ? &(*budgets)[i] : nullptr);
    stream.finish();
    EXPECT_GE(pieces, fits.size() + 1);  // written as it goes, not at the end
    return text;
}

std::vector<MaterialFit> catalog_fits(const std::vector<std::string>& ids) {
    std::vector<MaterialFit> fits;
    for (const std::string& id : ids)
        fits.push_back(
            fit_material(load_material(env().catalog, id, ""), env().colorimetry, env().converter, cheap_request()));
    return fits;
}

TEST(FitRecordStream, SameTextAsTheWholeRecord) {
    const std::vector<MaterialFit> fits = catalog_fits({"Au", "Al", "Cu", "Ag"});
    EXPECT_EQ(streamed(fits, context()), fit_record(fits, context()).dump(2));
    EXPECT_EQ(streamed({fits[0]}, context()), fit_record({fits[0]}, context()).dump(2));
    EXPECT_EQ(streamed({}, context()), fit_record({}, context()).dump(2));
}

TEST(FitRecordStream, SameTextWithBudgetsAndConstraints) {
    const std::vector<MaterialFit> fits = catalog_fits({"Au", "Al", "Cu"});
    std::vector<BudgetChoice> budgets;
    for (const MaterialFit& f : fits)
        budgets.push_back(choose_model(f.models, builtin_cost_table(), parse_budget("1%", BudgetMetric::rel_rms)));
    FitRecordContext constrained = context();
    constrained.constraints.gamut_fit = true;
    EXPECT_EQ(streamed(fits, constrained, &budgets), fit_record(fits, constrained, &budgets).dump(2));
    const std::vector<BudgetChoice> none;
    EXPECT_EQ(streamed({}, context(), &none), fit_record({}, context(), &none).dump(2));
}

TEST(FitRecordStream, AMaterialNamedTwiceIsWrittenOnceAsTheWholeRecordKeepsIt) {
    const std::vector<MaterialFit> fits = catalog_fits({"Cu", "Au"});
    const std::vector<MaterialFit> twice{fits[0], fits[1], fits[0]};
    EXPECT_EQ(streamed(twice, context()), fit_record(twice, context()).dump(2));
}

}  // namespace test_fit_batch
}  // namespace metalfit
