// `metalfit bench`: everything measured in one run, and its renderings (text tables, JSON, Markdown page).
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "libfit/base/interleaved_timer.hpp"
#include "metalfit_bench/catalog_accuracy.hpp"
#include "metalfit_bench/glpreview_results.hpp"
#include "metalfit_bench/layers.hpp"
#include "metalfit_bench/machine.hpp"
#include "metalfit_bench/pareto.hpp"
#include "metalfit_bench/spirv_cost.hpp"

namespace metalfit::bench {

struct BenchOptions {
    bool quick = false;
    std::string material = "Au";  // the material whose fitted parameters the evaluation and convergence use
    std::filesystem::path data_dir;
    std::optional<std::filesystem::path> ocio_config;
    std::filesystem::path glpreview;                   // empty: the GPU sections are skipped
    std::optional<std::filesystem::path> glslang;      // glslangValidator; empty: the SPIR-V section is skipped
    std::string command_line;                          // for the report's header
    std::function<void(const std::string&)> progress;  // one line per phase (stderr), if given
};

// One row of the main table: a model, the exact forms or a LUT.
struct CostRow {
    std::string id;
    std::string kind;  // "model", "exact", "lut"
    std::string description;
    std::optional<int> params_per_channel;
    double median_rel_rms = 0;  // catalog, worst channel, as libfit/fit/catalog_summary
    double worst_rel_rms = 0;
    std::string accuracy_source;  // where the accuracy comes from
    double ns_scalar = 0;         // per evaluation (3 channels), median over rounds
    double ns_array = 0;
    Ratio ratio_scalar, ratio_array;     // to conductor-rgb, same run
    std::optional<double> fit_ms;        // fit_model() per material, median over the catalog
    std::optional<int> spirv_ops;        // arithmetic + transcendental + texture
    std::optional<double> shader_ratio;  // glpreview ms per frame / conductor-rgb's
    // Pareto fronts of (cost, median rel_rms): among the models only (the issue's "no model both slower and less
    // accurate than another"; false for the other rows) and among all rows (the LUTs and exact forms included).
    // cpu: on the scalar ratio; gpu: on the shader ratio, empty without a shader figure.
    struct Front {
        bool cpu = false;
        std::optional<bool> gpu;
    };
    Front front_models, front_all;
};

struct ConvergenceRow {
    int nodes = 0;
    double integration_ms = 0;           // the spectral reference at the N nodes (N × 471 wavelengths + OCIO)
    std::vector<double> rel_rms_change;  // per model (all_models() order): |rms(N) − rms(ref)| / rms(ref)
};

struct BenchReport {
    std::string command_line;
    Machine machine;
    bool quick = false;
    std::string material;
    TimingOptions timing;
    ParetoTolerance tolerance;
    std::size_t catalog_materials = 0;
    std::vector<CostRow> rows;
    std::string spirv_validator;  // path, or empty when skipped
    std::string spirv_skipped;    // why, when skipped
    std::vector<SpirvRow> spirv;
    int convergence_reference_nodes = 0;
    std::vector<std::string> convergence_models;
    std::vector<ConvergenceRow> convergence;
    std::optional<LayersBench> layers;  // the stacks' cost (metalfit_bench/layers.hpp)
    GpuSection<ShaderBench> shaders;
    GpuSection<LocalizationBench> localization;
    double seconds = 0;  // wall time of the whole run
};

// Runs every measurement. Throws what libfit throws for a bad data folder or OCIO config.
BenchReport run_bench(const BenchOptions& options);

// Marks front_models and front_all on the rows (used by run_bench; exposed for tests).
void mark_pareto_fronts(std::vector<CostRow>& rows, const ParetoTolerance& tolerance);

// The thesis's Table 3.2 (relative time of a shader evaluation, exact Fresnel = 100 %) next to this run.
struct ThesisComparison {
    std::string model;
    double thesis_percent = 0;
    std::optional<double> cpu_scalar_percent, cpu_array_percent, spirv_percent, shader_percent;
};
std::vector<ThesisComparison> thesis_comparison(const BenchReport& report);

// Schema "metalfit.bench/1" (docs/cli.md).
nlohmann::json to_json(const BenchReport& report);
// The tables as printed by `metalfit bench`.
std::string to_text(const BenchReport& report);
// The page docs/accuracy-vs-cost.md. `previous` is the page being replaced (may be empty): the text between
// kReadingBegin and kReadingEnd in it is kept.
std::string to_markdown(const BenchReport& report, const std::string& previous);

inline constexpr const char* kReadingBegin = "<!-- metalfit-bench: hand-written reading (kept on regeneration) -->";
inline constexpr const char* kReadingEnd = "<!-- metalfit-bench: end of hand-written reading -->";

}  // namespace metalfit::bench
