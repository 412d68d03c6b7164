// `export --all` and `report --all` written material by material (ExportStream, ReportStream): the folders are byte
// for byte what export_files + write_export and report_files + write_report_folder write for the same fits — with a
// layered finish (its bare metal fitted on the batch's threads), into a folder an earlier export left (its shared
// files merged), and with the same refusal of two materials writing one file. The memory bound is measured in
// test_bench_scaling.cpp.
#include <gtest/gtest.h>

#include "test_environment.hpp"
#include "test_support.hpp"

#include <map>
#include <string>
#include <vector>

#include "libfit/base/errors.hpp"
#include "libfit/color/color_space.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/color/display_transform.hpp"
#include "libfit/export/export.hpp"
#include "libfit/export/export_stream.hpp"
#include "libfit/fit/fit_batch.hpp"
#include "libfit/fit/model_cost.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/io/finishes.hpp"
#include "libfit/models/model.hpp"
#include "libfit/report/model_costs.hpp"
#include "libfit/report/report.hpp"
#include "libfit/report/report_stream.hpp"

namespace metalfit {
namespace test_streamed_outputs {

namespace fs = std::filesystem;
using namespace metalfit::test;

// Catalog metals and a layered finish (anodized titanium: a film over the metal).
std::vector<std::function<Material()>> loaders(const std::vector<std::string>& names) {
    std::vector<std::function<Material()>> out;
    for (const std::string& name : names)
        out.push_back([name] {
            if (std::optional<Material> finish = load_finish_named(env().catalog, name)) return *finish;
            return load_material(env().catalog, name, "");
        });
    return out;
}

// Every regular file below `dir`, by relative path.
std::map<std::string, std::string> tree(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(dir))
        if (entry.is_regular_file()) files[fs::relative(entry.path(), dir).generic_string()] = read_file(entry.path());
    return files;
}

void expect_same_trees(const fs::path& whole, const fs::path& streamed) {
    const auto a = tree(whole), b = tree(streamed);
    EXPECT_GT(a.size(), 0u);
    for (const auto& [path, contents] : a) {
        const auto it = b.find(path);
        if (it == b.end()) {
            ADD_FAILURE() << path << " missing from the streamed folder";
            continue;
        }
        EXPECT_TRUE(it->second == contents)
            << path << " differs (" << contents.size() << " / " << it->second.size() << " bytes)";
    }
    for (const auto& [path, contents] : b) EXPECT_TRUE(a.count(path)) << path << " only in the streamed folder";
}

ExportRequest every_format(const std::vector<std::string>& models) {
    ExportRequest request;
    for (const auto& format : kExportFormatNames.names) request.formats.push_back(format.value);
    for (const std::string& m : models) request.models.push_back(&find_model(m));
    return request;
}

// Exports `names` both ways into `whole` and `streamed`; returns the out_of_range lines of each.
std::pair<std::vector<std::string>, std::vector<std::string>> export_both(const std::vector<std::string>& names,
                                                                          const ExportRequest& request,
                                                                          const fs::path& whole,
                                                                          const fs::path& streamed) {
    const FitRecordContext context = env().context();
    const std::string space = materialx_colorspace(context.config, context.space);
    const MaterialFitRequest fit_request{SpectralOptions{}, ErrorSettings{}, models_to_fit(request)};
    std::vector<MaterialFit> fits = fit_materials(loaders(names), env().colour(), fit_request, 2);
    if (needs_bare_metal_fits(request)) attach_bare_metal_fits(fits, env().colour(), fit_request, 2);
    const std::vector<ExportFile> files = export_files(fits, context, request, space);
    write_export(whole, files);
    ExportStream stream(streamed, context, request, space);
    fit_materials_for_export(loaders(names), env().colour(), fit_request, request, 2,
                             [&](std::size_t, MaterialFit&& fit) { stream.add(fit); });
    std::vector<std::string> streamed_lines;
    stream.finish([&](const std::string& line) { streamed_lines.push_back(line); });
    return {out_of_range_lines(files), streamed_lines};
}

TEST(ExportStream, WritesTheFolderExportFilesWritesWithALayeredFinish) {
    TempDir tmp;
    const auto [whole, streamed] = export_both({"Au", "anodized-ti-80nm", "Cu", "Cu85Zn15"},
                                               every_format({"f82-tint", "conductor-rgb", "lazanyi-comp"}),
                                               tmp.path() / "whole", tmp.path() / "streamed");
    expect_same_trees(tmp.path() / "whole", tmp.path() / "streamed");
    EXPECT_EQ(streamed, whole);   // stderr's lines, in export_files's order
    EXPECT_FALSE(whole.empty());  // Cu85Zn15's f82-tint tint is above 1: the order of the lines is exercised
}

TEST(ExportStream, MergesTheSharedFilesOfAnEarlierExportAsWriteExportDoes) {
    TempDir tmp;
    const ExportRequest earlier = every_format({"schlick"});
    for (const char* dir : {"whole", "streamed"}) {
        const FitRecordContext context = env().context();
        const MaterialFitRequest fit_request{SpectralOptions{}, ErrorSettings{}, models_to_fit(earlier)};
        const std::vector<MaterialFit> fits = fit_materials(loaders({"Ag", "Au"}), env().colour(), fit_request, 1);
        write_export(tmp.path() / dir,
                     export_files(fits, context, earlier, materialx_colorspace(context.config, context.space)));
    }
    export_both({"Au", "Cu"}, every_format({"f82-tint"}), tmp.path() / "whole", tmp.path() / "streamed");
    expect_same_trees(tmp.path() / "whole", tmp.path() / "streamed");
    // The record holds Ag from the first export, Au with both models, Cu.
    const auto record = nlohmann::json::parse(read_file(tmp.path() / "streamed" / "metalfit_export.json"));
    EXPECT_TRUE(record["materials"].contains("Ag"));
    EXPECT_TRUE(record["materials"]["Au"]["models"].contains("schlick"));
    EXPECT_TRUE(record["materials"]["Au"]["models"].contains("f82-tint"));
}

TEST(ExportStream, RefusesTwoMaterialsWritingOneFileAsExportFilesDoesAndLeavesTheFolderAlone) {
    TempDir tmp;
    const ExportRequest request = every_format({"schlick"});
    const FitRecordContext context = env().context();
    const std::string space = materialx_colorspace(context.config, context.space);
    const MaterialFitRequest fit_request{SpectralOptions{}, ErrorSettings{}, models_to_fit(request)};
    std::vector<MaterialFit> fits = fit_materials(loaders({"Au", "Cu"}), env().colour(), fit_request, 1);
    fits[1].material.id = "AU";  // another id, the same file stem
    std::string whole_error, streamed_error;
    try {
        export_files(fits, context, request, space);
    } catch (const UsageError& e) {
        whole_error = e.what();
    }
    {
        ExportStream stream(tmp.path() / "out", context, request, space);
        stream.add(fits[0]);
        try {
            stream.add(fits[1]);
        } catch (const UsageError& e) {
            streamed_error = e.what();
        }
    }
    EXPECT_NE(whole_error, "");
    EXPECT_EQ(streamed_error, whole_error);
    EXPECT_FALSE(fs::exists(tmp.path() / "out"));  // an unfinished stream writes nothing
}

TEST(ReportStream, WritesTheFolderReportFilesWrites) {
    TempDir tmp;
    const FitRecordContext context = env().context();
    const DisplayTransform display = DisplayTransform::create(kShipped);
    const CostTable table = builtin_cost_table();
    const std::optional<Budget> budget = Budget{0.01, BudgetMetric::rel_rms};
    const Tolerance tolerance;
    const SphereRenders renders{std::nullopt, "--renders off"};
    const MaterialFitRequest request{SpectralOptions{},
                                     ErrorSettings{},
                                     {&find_model("schlick"), &find_model("f82-tint"), &find_model("gulbrandsen")}};
    const std::vector<std::string> names{"Au", "anodized-ti-80nm", "Cu"};
    const std::vector<MaterialFit> fits = fit_materials(loaders(names), env().colour(), request, 2);
    const CostAndBudget cost = report_costs(fits, table, budget, tolerance, ExportFormat::glsl);
    write_report_folder(tmp.path() / "whole", report_files(fits, {context, env().colorimetry, env().converter, display,
                                                                  env().catalog, cost, renders, true}));
    const CostAndBudget costs_only = report_costs({}, table, budget);
    const ReportInputs inputs{context,       env().colorimetry, env().converter, display,
                              env().catalog, costs_only,        renders,         true};
    ReportStream stream(tmp.path() / "streamed", inputs, table, budget, tolerance, ExportFormat::glsl);
    fit_materials_in_order(loaders(names), env().colour(), request, 2,
                           [&](std::size_t, MaterialFit&& fit) { stream.add(fit); });
    stream.finish();
    expect_same_trees(tmp.path() / "whole", tmp.path() / "streamed");
}

TEST(ReportStream, RefusesAMaterialNamedTwiceAsReportFilesDoes) {
    TempDir tmp;
    const FitRecordContext context = env().context();
    const DisplayTransform display = DisplayTransform::create(kShipped);
    const CostTable table = builtin_cost_table();
    const CostAndBudget cost = report_costs({}, table, std::nullopt);
    const SphereRenders renders{std::nullopt, "--renders off"};
    const ReportInputs inputs{context, env().colorimetry, env().converter, display, env().catalog, cost, renders, true};
    const MaterialFitRequest request{SpectralOptions{}, ErrorSettings{}, {&find_model("schlick")}};
    const std::vector<MaterialFit> fits = fit_materials(loaders({"Au", "Au"}), env().colour(), request, 1);
    std::string whole_error, streamed_error;
    try {
        report_files(fits, inputs);
    } catch (const UsageError& e) {
        whole_error = e.what();
    }
    {
        ReportStream stream(tmp.path() / "out", inputs, table, std::nullopt, Tolerance{}, ExportFormat::glsl);
        stream.add(fits[0]);
        try {
            stream.add(fits[1]);
        } catch (const UsageError& e) {
            streamed_error = e.what();
        }
    }
    EXPECT_NE(whole_error, "");
    EXPECT_EQ(streamed_error, whole_error);
    EXPECT_FALSE(fs::exists(tmp.path() / "out"));
}

}  // namespace test_streamed_outputs
}  // namespace metalfit
