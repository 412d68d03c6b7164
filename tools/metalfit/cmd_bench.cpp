// metalfit bench: what accuracy costs in time. A thin layer over the bench library (bench/): it parses the options,
// finds glslangValidator and glpreview, runs the measurements and prints (or writes) the report.
#include <unistd.h>

#include <fstream>
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "libfit/base/atomic_file.hpp"
#include "libfit/base/errors.hpp"
#include "metalfit_bench/bench_report.hpp"
#include "metalfit_bench/environment.hpp"
#include "metalfit_bench/model_costs.hpp"
#include "metalfit_bench/scaling.hpp"
#include "metalfit_bench/subprocess.hpp"

namespace metalfit::cli {
namespace {

struct BenchCommandOptions {
    bool quick = false;
    bool json = false;
    std::filesystem::path markdown;
    std::filesystem::path output;
    std::string material = "Au";
    std::optional<std::filesystem::path> glpreview;
    // --scaling: the scaling table instead of the report.
    // --model-costs: the measured cost table instead of the report.
    bool model_costs = false;
    bool scaling = false;
    std::vector<std::size_t> scaling_sizes;
    std::vector<int> scaling_threads;
    std::string scaling_models;
    // --scaling-database: the database's cells (alone, or after the synthetic ones with --scaling).
    std::optional<std::filesystem::path> scaling_database;
    std::string scaling_mode = "fit";
    // The hidden children of --scaling and --scaling-database: one cell measured in this process.
    std::optional<std::size_t> scaling_cell;
    std::optional<std::filesystem::path> scaling_database_cell;
    int threads = 1;
};

std::vector<std::string> split_models(const std::string& list) {
    std::vector<std::string> ids;
    for (const Model* m : parse_model_list(list)) ids.emplace_back(m->id());
    return ids;
}

void run_scaling_command(const BenchCommandOptions& o, const GlobalOptions& global) {
    if (o.scaling_cell) {
        const bench::Environment env = bench::Environment::load(global.data_dir, global.ocio_config);
        emit(bench::to_json(bench::measure_scaling_cell(env, *o.scaling_cell, o.threads, split_models(o.scaling_models),
                                                        bench::kScalingModeNames.parse(o.scaling_mode)))
                     .dump() +
                 "\n",
             o.output);
        return;
    }
    if (o.scaling_database_cell) {
        const bench::Environment env = bench::Environment::load(global.data_dir, global.ocio_config);
        emit(bench::to_json(
                 bench::measure_database_cell(env, *o.scaling_database_cell, o.threads, split_models(o.scaling_models)))
                     .dump() +
                 "\n",
             o.output);
        return;
    }
    bench::ScalingOptions options;
    options.metalfit = std::filesystem::read_symlink("/proc/self/exe");
    options.data_dir = global.data_dir;
    options.ocio_config = global.ocio_config;
    if (!o.scaling_sizes.empty()) options.sizes = o.scaling_sizes;
    if (!o.scaling_threads.empty()) options.threads = o.scaling_threads;
    if (!o.scaling_models.empty()) options.models = split_models(o.scaling_models);
    options.mode = bench::kScalingModeNames.parse(o.scaling_mode);
    options.command_line = "metalfit bench --scaling";
    if (o.scaling_database) {
        std::error_code error;
        if (!std::filesystem::is_directory(*o.scaling_database, error))
            throw UsageError("--scaling-database: " + o.scaling_database->string() +
                             " is not a folder (a refractiveindex.info database folder, such as data/nk)");
        options.database = o.scaling_database;
        options.command_line = o.scaling ? "metalfit bench --scaling --scaling-database " + o.scaling_database->string()
                                         : "metalfit bench --scaling-database " + o.scaling_database->string();
        if (!o.scaling) options.sizes.clear();  // the database alone
    }
    if (isatty(STDERR_FILENO))
        options.progress = [](const std::string& line) { std::cerr << "metalfit bench: " << line << "\n"; };
    const bench::ScalingTable table = bench::run_scaling(options);
    emit(o.json ? bench::to_json(table).dump(2) + "\n" : bench::to_text(table), o.output);
}

std::string read_if_exists(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    if (in) text << in.rdbuf();
    return text.str();
}

void run_model_costs_command(const BenchCommandOptions& o, const GlobalOptions& global) {
    bench::ModelCostsOptions options;
    options.material = o.material;
    options.data_dir = global.data_dir;
    options.ocio_config = global.ocio_config;
    options.glpreview = o.glpreview ? *o.glpreview : bench::executable_dir() / "glpreview";
    options.glslang = bench::find_on_path("glslangValidator");
    if (o.quick) options.cpu_rounds = 9;
    options.command_line = "metalfit bench --model-costs" + std::string(o.quick ? " --quick" : "") +
                           (o.json ? " --json" : "") + (o.material != "Au" ? " --material " + o.material : "");
    if (isatty(STDERR_FILENO))
        options.progress = [](const std::string& line) { std::cerr << "metalfit bench: " << line << "\n"; };
    bench::ModelCosts costs;
    try {
        costs = bench::measure_model_costs(options);
    } catch (const std::runtime_error& e) {
        throw UsageError(std::string("bench --model-costs: ") + e.what());
    }
    if (o.json) std::cerr << bench::to_text(costs);
    emit(o.json ? bench::to_json(costs).dump(2) + "\n" : bench::to_text(costs), o.output);
}

void run_bench_command(const BenchCommandOptions& o, const GlobalOptions& global) {
    if (o.scaling || o.scaling_cell || o.scaling_database || o.scaling_database_cell)
        return run_scaling_command(o, global);
    if (o.model_costs) return run_model_costs_command(o, global);
    bench::BenchOptions options;
    options.quick = o.quick;
    options.material = o.material;
    options.data_dir = global.data_dir;
    options.ocio_config = global.ocio_config;
    options.glpreview = o.glpreview ? *o.glpreview : bench::executable_dir() / "glpreview";
    options.glslang = bench::find_on_path("glslangValidator");
    options.command_line = "metalfit bench" + std::string(o.quick ? " --quick" : "") +
                           (o.material != "Au" ? " --material " + o.material : "") +
                           (o.markdown.empty() ? "" : " --markdown " + o.markdown.string());
    if (isatty(STDERR_FILENO))
        options.progress = [](const std::string& line) { std::cerr << "metalfit bench: " << line << "\n"; };

    const bench::BenchReport report = bench::run_bench(options);
    if (!o.markdown.empty()) write_file_atomically(o.markdown, bench::to_markdown(report, read_if_exists(o.markdown)));
    emit(o.json ? bench::to_json(report).dump(2) + "\n" : bench::to_text(report), o.output);
}

}  // namespace

std::function<void()> add_bench_command(CLI::App& app, const GlobalOptions& global) {
    auto o = std::make_shared<BenchCommandOptions>();
    app.add_flag("--quick", o->quick, "Fewer timing rounds (well under a minute); glpreview gets --quick too");
    app.add_flag("--json", o->json, "Print the report as JSON (schema metalfit.bench/1, docs/cli.md)");
    app.add_option("--markdown", o->markdown,
                   "Also write the report as a Markdown page (keeps its hand-written reading)");
    app.add_option("--material", o->material,
                   "Material whose fitted parameters the evaluation timings use (default: Au)");
    app.add_option("--glpreview", o->glpreview,
                   "The glpreview executable for the GPU sections (default: next to metalfit)");
    app.add_option("-o,--output", o->output, "Write to this file instead of stdout (- for stdout)");
    app.add_flag("--model-costs", o->model_costs,
                 "Only the measured cost table (data/model-costs.json): each model on llvmpipe and in the CPU "
                 "array loop as ratios to conductor-rgb, SPIR-V counts, rank correlations");
    app.add_flag(
        "--scaling", o->scaling,
        "Only the scaling table: fit on 1, 29, 300, 3000 synthetic materials (catalog tables, n and k perturbed) on "
        "1 and 2 threads: wall, CPU, peak memory, fits per CPU second (minutes)");
    app.add_option("--scaling-sizes", o->scaling_sizes, "Material counts of --scaling (default: 1,29,300,3000)")
        ->delimiter(',')
        ->check(CLI::PositiveNumber);
    app.add_option("--scaling-threads", o->scaling_threads, "Thread counts of --scaling (default: 1,2)")
        ->delimiter(',')
        ->check(CLI::PositiveNumber);
    app.add_option("--scaling-models", o->scaling_models,
                   "Models of --scaling, comma-separated, or all (default: the first six, "
                   "schlick,lazanyi,lazanyi-comp,f82-tint,conductor-rgb,gulbrandsen)");
    app.add_option("--scaling-database", o->scaling_database,
                   "Fit every metal nk file of a refractiveindex.info database folder (data/nk, a clone's "
                   "database/data): one cell per thread count; alone, or after --scaling's")
        ->type_name("FOLDER");
    app.add_option("--scaling-mode", o->scaling_mode,
                   "What --scaling runs: fit (fit --all --json), export (export --all --format all) or report "
                   "(report --all --renders off)");
    app.add_option("--scaling-cell", o->scaling_cell)->group("");                    // the child of --scaling
    app.add_option("--scaling-database-cell", o->scaling_database_cell)->group("");  // the child of --scaling-database
    app.add_option("--threads", o->threads)->group("")->check(CLI::PositiveNumber);
    return [o, &global] { run_bench_command(*o, global); };
}

}  // namespace metalfit::cli
