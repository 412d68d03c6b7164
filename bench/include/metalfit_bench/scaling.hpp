// The scaling table of `metalfit bench --scaling`: `fit` on synthetic material sets of growing size (the catalog's
// tables with n and k perturbed, deterministic) on 1 and 2 threads: wall, CPU and peak memory, each cell in a
// process of its own (peak resident memory is a process's), and the fit throughput (materials × models per CPU second);
// and the whole database: every metal nk file of a refractiveindex.info database folder (nk_database.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "libfit/base/enum_names.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/io/material.hpp"
#include "metalfit_bench/environment.hpp"

namespace metalfit::bench {

inline constexpr std::uint64_t kScalingSeed = 20261201;

// `count` synthetic materials: material i is catalog entry i mod E (its primary table) with n and k each scaled by a
// factor 1 + 0.1 u, u uniform in [−1, 1] from a generator seeded with seed + i (the same set on every machine; a
// curve given by a formula or a constant is kept as it is). Loaded on demand, as `fit --all` loads its files.
std::vector<std::function<Material()>> synthetic_materials(const Catalog& catalog, std::size_t count,
                                                           std::uint64_t seed = kScalingSeed);

// What a cell runs on the synthetic materials: `fit --all --json` (the record streamed, its text counted), `export
// --all --format all` (ExportStream into a scratch folder, removed after), `report --all --renders off`
// (ReportStream likewise) or `report --renders on` (the same, the materials written as CSV tables for glpreview,
// which renders them first as metalfit report runs it: render_spheres).
enum class ScalingMode { fit, export_, report, report_renders };
inline constexpr EnumNames kScalingModeNames{
    "--scaling-mode", KnownNamesWording::alternatives,
    std::array{EnumName<ScalingMode>{ScalingMode::fit, "fit"}, EnumName<ScalingMode>{ScalingMode::export_, "export"},
               EnumName<ScalingMode>{ScalingMode::report, "report"},
               EnumName<ScalingMode>{ScalingMode::report_renders, "report-renders"}}};

// One cell: what the child process measured.
struct ScalingCell {
    std::size_t materials = 0;
    int threads = 0;
    std::size_t fits = 0;  // material × model fits done (materials × models when every fit ran)
    double wall_s = 0;     // the fits (fit_materials), wall clock
    double cpu_s = 0;      // the fits, process CPU (user + system, every thread)
    double peak_mib = 0;   // peak resident memory of the whole process (ru_maxrss)
    // Where the CPU and wall go besides the fits, measured inside the same run: the synthetic materials' set-up (their
    // loaders, thread CPU), the fit record streamed material by material as `fit --all --json` writes it (thread CPU;
    // its text counted, not kept), and the wall time threads waited at the reorder window (summed over the threads).
    double setup_cpu_s = 0;
    double record_cpu_s = 0;
    double record_mib = 0;  // fit: the record's size; export, report: the folder's
    double window_wait_s = 0;
    // A database cell (`source` "database"): the folder's scan, the files fitted being `materials`; set-up CPU is then
    // the files' loading during the fits, and the scan's own CPU (every file read and classified once before) apart.
    std::string source = "synthetic";
    std::filesystem::path folder;
    std::size_t files = 0, skipped_not_nk = 0, skipped_unreadable = 0, skipped_outside_visible = 0,
                skipped_not_metal = 0;
    double scan_cpu_s = 0;
    // report-renders: glpreview's run (the child process render_spheres starts), wall clock and peak resident memory
    // (the cell's children's ru_maxrss); peak_mib stays the cell's own process.
    double renders_wall_s = 0;
    double renders_peak_mib = 0;
};

// Fits `materials` synthetic materials with `models` on `threads` threads in this process and measures it
// (`metalfit bench --scaling-cell`, the child of run_scaling).
ScalingCell measure_scaling_cell(const Environment& env, std::size_t materials, int threads,
                                 const std::vector<std::string>& models, ScalingMode mode = ScalingMode::fit);
// Fits every metal nk file of `folder` (scan_nk_database) with `models` on `threads` threads in this process and
// measures it (`metalfit bench --scaling-database-cell`, the child of run_scaling). Throws InputError for a folder
// that is not one.
ScalingCell measure_database_cell(const Environment& env, const std::filesystem::path& folder, int threads,
                                  const std::vector<std::string>& models);
nlohmann::json to_json(const ScalingCell& cell);
ScalingCell scaling_cell_from_json(const nlohmann::json& j);

struct ScalingOptions {
    std::filesystem::path metalfit;  // the executable the cells run in (this one)
    std::filesystem::path data_dir;
    std::optional<std::filesystem::path> ocio_config;
    std::vector<std::size_t> sizes{1, 29, 300, 3000};  // none: no synthetic cells
    std::optional<std::filesystem::path> database;     // a database folder: one more cell per thread count
    std::vector<int> threads{1, 2};
    std::vector<std::string> models{"schlick", "lazanyi", "lazanyi-comp", "f82-tint", "conductor-rgb", "gulbrandsen"};
    ScalingMode mode = ScalingMode::fit;
    std::string command_line;
    std::function<void(const std::string&)> progress;
};

struct ScalingTable {
    std::vector<std::string> models;
    ScalingMode mode = ScalingMode::fit;
    std::uint64_t seed = kScalingSeed;
    std::vector<ScalingCell> cells;  // sizes × threads, in that order, then the database's cells (threads)
    std::string machine;             // CPU model, cores
    std::string command_line;
    // Fit throughput, materials × models per CPU second, of the largest 1-thread cell (its CPU time includes the
    // reference curves every material needs).
    double fits_per_cpu_second() const;
};

// Runs every cell as `metalfit bench --scaling-cell N --threads T --scaling-models LIST` (a database's as
// `--scaling-database-cell FOLDER`) and collects them. Throws std::runtime_error naming the cell when a child fails.
ScalingTable run_scaling(const ScalingOptions& options);

nlohmann::json to_json(const ScalingTable& table);  // schema metalfit.bench-scaling/1 (docs/cli.md)
std::string to_text(const ScalingTable& table);

}  // namespace metalfit::bench
