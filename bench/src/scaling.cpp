#include "metalfit_bench/scaling.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <memory>
#include <mutex>
#include <random>
#include <stdexcept>

#include "libfit/base/errors.hpp"
#include "libfit/base/number_text.hpp"
#include "libfit/color/display_transform.hpp"
#include "libfit/export/export.hpp"
#include "libfit/export/export_stream.hpp"
#include "libfit/fit/fit_batch.hpp"
#include "libfit/fit/fit_record_stream.hpp"
#include "libfit/fit/model_cost.hpp"
#include "libfit/io/csv.hpp"
#include "libfit/models/model.hpp"
#include "libfit/report/model_costs.hpp"
#include "libfit/report/report_stream.hpp"
#include "libfit/report/sphere_renders.hpp"
#include "metalfit_bench/machine.hpp"
#include "metalfit_bench/nk_database.hpp"
#include "metalfit_bench/subprocess.hpp"

namespace metalfit::bench {

namespace {

// A uniform number in [−1, 1] from 53 bits of the generator (std::uniform_real_distribution is not the same on
// every standard library).
double symmetric_unit(std::mt19937_64& generator) {
    return 2.0 * static_cast<double>(generator() >> 11) * 0x1p-53 - 1.0;
}

SpectralCurve scaled(const SpectralCurve& curve, double factor) {
    const Spectrum* table = curve.tabulated();
    if (!table) return curve;
    std::vector<SpectrumSample> samples;
    for (std::size_t i = 0; i < table->size(); ++i)
        samples.push_back({table->wavelengths()[i], table->values()[i] * factor});
    return Spectrum(std::move(samples));
}

double process_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double thread_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::string join_models(const std::vector<std::string>& models) {
    std::string text;
    for (const std::string& m : models) text += (text.empty() ? "" : ",") + m;
    return text;
}

// A folder of its own under $TMPDIR for an export or report cell's output, removed with everything in it.
struct ScratchFolder {
    std::filesystem::path path;
    ScratchFolder() {
        std::random_device random;
        path = std::filesystem::temp_directory_path() /
               ("metalfit-scaling-" + std::to_string(::getpid()) + "-" + std::to_string(random()));
        if (!std::filesystem::create_directory(path))
            throw std::runtime_error("scaling: cannot make the folder " + path.string());
    }
    ~ScratchFolder() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;
};

// A material's n and k at its tabulated wavelengths as a CSV table `metalfit` reads back (wavelength in µm, n, k;
// 17 significant digits: the same doubles). The n and k of a synthetic material share the base table's wavelengths.
void write_nk_table(const std::filesystem::path& file, const Material& m) {
    const Spectrum* n = m.index.n.tabulated();
    const Spectrum* k = m.index.k.tabulated();
    if (!n || !k || !std::ranges::equal(n->wavelengths(), k->wavelengths()))
        throw std::runtime_error("scaling: " + m.id + ": n and k are not one table");
    std::string text = "wl,n,k\n";
    for (std::size_t i = 0; i < n->size(); ++i)
        text += significant_text(n->wavelengths()[i] / 1000.0, 17) + "," + significant_text(n->values()[i], 17) + "," +
                significant_text(k->values()[i], 17) + "\n";
    std::FILE* out = std::fopen(file.c_str(), "w");
    if (!out) throw std::runtime_error("scaling: cannot write " + file.string());
    const bool written = std::fputs(text.c_str(), out) >= 0;
    if (std::fclose(out) != 0 || !written) throw std::runtime_error("scaling: cannot write " + file.string());
}

}  // namespace

std::vector<std::function<Material()>> synthetic_materials(const Catalog& catalog, std::size_t count,
                                                           std::uint64_t seed) {
    // The catalog's tables are read once and shared by the loaders (a few hundred kB in all).
    auto bases = std::make_shared<std::vector<Material>>();
    for (const CatalogEntry& entry : catalog.entries()) bases->push_back(load_material(catalog, entry.id, ""));
    if (bases->empty()) throw std::runtime_error("synthetic materials: the catalog is empty");
    std::vector<std::function<Material()>> loaders;
    for (std::size_t i = 0; i < count; ++i)
        loaders.push_back([bases, i, seed] {
            std::mt19937_64 generator(seed + i);
            Material m = (*bases)[i % bases->size()];
            const double n_factor = 1.0 + 0.1 * symmetric_unit(generator),
                         k_factor = 1.0 + 0.1 * symmetric_unit(generator);
            m.index.n = scaled(m.index.n, n_factor);
            m.index.k = scaled(m.index.k, k_factor);
            m.id = "synthetic-" + std::to_string(i) + "-" + m.id;
            return m;
        });
    return loaders;
}

namespace {

// The fits of `loaders` as `metalfit fit|export|report --all` runs them (`mode`), measured (the cell's size and threads
// set by the caller).
ScalingCell measure_fits(const Environment& env, const std::vector<std::function<Material()>>& materials, int threads,
                         const std::vector<std::string>& models, ScalingMode mode) {
    std::vector<const Model*> chosen;
    for (const std::string& id : models) chosen.push_back(&find_model(id));
    // Each loader's thread CPU summed (the loaders run on every worker thread).
    std::mutex setup_mutex;
    double setup_cpu = 0;
    std::vector<std::function<Material()>> loaders;
    for (const std::function<Material()>& load : materials)
        loaders.push_back([&load, &setup_mutex, &setup_cpu] {
            const double t0 = thread_cpu_seconds();
            Material m = load();
            const double spent = thread_cpu_seconds() - t0;
            const std::lock_guard lock(setup_mutex);
            setup_cpu += spent;
            return m;
        });
    const MaterialFitRequest request{env.spectral, env.error, chosen};
    const BatchColour colour{env.config, env.colorimetry, env.converter};
    // The record as `metalfit fit --all --json` streams it, its text counted and let go.
    const FitRecordContext context{env.config,      env.converter.space(), Observer::cie1931_2deg,
                                   Illuminant::D65, env.spectral,          env.error};
    std::size_t record_bytes = 0;
    double record_cpu = 0;
    ScalingCell cell;
    BatchStatistics statistics;
    const double cpu0 = process_cpu_seconds();
    const auto wall0 = std::chrono::steady_clock::now();
    // Each material handed on in input order, `hand` timed as the record's CPU.
    const auto timed = [&](const std::function<void(const MaterialFit&)>& hand) {
        return [&, hand](std::size_t, MaterialFit&& fit) {
            cell.fits += fit.models.size();
            const double t0 = thread_cpu_seconds();
            hand(fit);
            record_cpu += thread_cpu_seconds() - t0;
        };
    };
    if (mode == ScalingMode::fit) {
        // Streamed, as `metalfit fit --all` runs: each fit counted, written and let go in input order.
        FitRecordStream record(context, [&record_bytes](std::string_view text) { record_bytes += text.size(); });
        fit_materials_in_order(loaders, colour, request, threads,
                               timed([&](const MaterialFit& fit) { record.add(fit); }), {}, 0, &statistics);
        record.finish();
    } else {
        const ScratchFolder scratch;
        const std::filesystem::path out = scratch.path / "out";
        if (mode == ScalingMode::export_) {
            // As `metalfit export --all --format all --model LIST` runs (cmd_export.cpp).
            ExportRequest export_request{{}, chosen};
            for (const auto& format : kExportFormatNames.names) export_request.formats.push_back(format.value);
            const std::string materialx_space = materialx_colorspace(context.config, context.space);
            leave_out_formats_the_space_cannot_carry(export_request, context.space, materialx_space);
            const MaterialFitRequest fit_request{env.spectral, env.error, models_to_fit(export_request)};
            ExportStream stream(out, context, export_request, materialx_space);
            fit_materials_for_export(loaders, colour, fit_request, export_request, threads,
                                     timed([&](const MaterialFit& fit) { stream.add(fit); }));
            const double t0 = thread_cpu_seconds();
            stream.finish([](const std::string&) {});
            record_cpu += thread_cpu_seconds() - t0;
        } else {
            // As `metalfit report --all --renders off --model LIST` runs (cmd_report.cpp): the recommendation's
            // default tolerance and target, the built-in cost table. report-renders: `--renders on`, the materials
            // rendered first by one glpreview (as cmd_report.cpp runs it), from CSV tables of them (glpreview reads
            // files, not the synthetic materials in this process).
            const Tolerance tolerance;
            MaterialFitRequest report_request = request;
            report_request.constraints.f0_tolerance = tolerance.f0_err;
            const DisplayTransform display = DisplayTransform::create(env.config);
            const CostTable table = builtin_cost_table();
            const CostAndBudget cost = report_costs({}, table, std::nullopt);
            SphereRenders renders{std::nullopt, "--renders off"};
            if (mode == ScalingMode::report_renders) {
                SphereRenderRequest render{glpreview_beside_this_program(),
                                           env.catalog.data_dir() / "scenes" / "sheet.json",
                                           {},
                                           {},
                                           {},
                                           {},
                                           models,
                                           env.catalog.data_dir(),
                                           env.config};
                const std::filesystem::path tables = scratch.path / "tables";
                std::filesystem::create_directory(tables);
                for (const std::function<Material()>& load : materials) {
                    const Material m = load();
                    render.materials.push_back((tables / (m.id + ".csv")).string());
                    render.ids.push_back(m.id);
                    write_nk_table(render.materials.back(), m);
                }
                const auto renders0 = std::chrono::steady_clock::now();
                renders = render_spheres(render, RenderMode::on);
                cell.renders_wall_s =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - renders0).count();
                rusage children{};
                getrusage(RUSAGE_CHILDREN, &children);
                cell.renders_peak_mib = static_cast<double>(children.ru_maxrss) / 1024.0;  // kB on Linux
            }
            FitRecordContext report_context = context;
            report_context.constraints = report_request.constraints;
            const ReportInputs inputs{report_context, env.colorimetry, env.converter, display, env.catalog,
                                      cost,           renders,         true};
            ReportStream stream(out, inputs, table, std::nullopt, tolerance, ExportFormat::glsl);
            fit_materials_in_order(loaders, colour, report_request, threads,
                                   timed([&](const MaterialFit& fit) { stream.add(fit); }));
            const double t0 = thread_cpu_seconds();
            stream.finish();
            record_cpu += thread_cpu_seconds() - t0;
        }
        for (const auto& entry : std::filesystem::recursive_directory_iterator(out))
            if (entry.is_regular_file()) record_bytes += entry.file_size();
    }
    cell.setup_cpu_s = setup_cpu;
    cell.record_cpu_s = record_cpu;
    cell.record_mib = static_cast<double>(record_bytes) / (1024.0 * 1024.0);
    cell.window_wait_s = statistics.window_wait_s;
    cell.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    cell.cpu_s = process_cpu_seconds() - cpu0;
    cell.materials = materials.size();
    cell.threads = threads;
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    cell.peak_mib = static_cast<double>(usage.ru_maxrss) / 1024.0;  // kB on Linux
    return cell;
}

}  // namespace

ScalingCell measure_scaling_cell(const Environment& env, std::size_t materials, int threads,
                                 const std::vector<std::string>& models, ScalingMode mode) {
    return measure_fits(env, synthetic_materials(env.catalog, materials), threads, models, mode);
}

ScalingCell measure_database_cell(const Environment& env, const std::filesystem::path& folder, int threads,
                                  const std::vector<std::string>& models) {
    const NkDatabaseScan scan = scan_nk_database(folder);
    // Each file loaded again when its fit comes (as `fit` loads its files): the scan keeps none of them.
    std::vector<std::function<Material()>> loaders;
    for (const std::filesystem::path& file : scan.metal_files)
        loaders.push_back([file, folder] {
            Material m = load_nk_file(file);
            m.id = std::filesystem::relative(file, folder).replace_extension().generic_string();
            return m;
        });
    ScalingCell cell = measure_fits(env, loaders, threads, models, ScalingMode::fit);
    cell.source = "database";
    cell.folder = folder;
    cell.files = scan.files;
    cell.skipped_not_nk = scan.not_nk;
    cell.skipped_unreadable = scan.unreadable;
    cell.skipped_outside_visible = scan.outside_visible;
    cell.skipped_not_metal = scan.not_metal;
    cell.scan_cpu_s = scan.cpu_s;
    return cell;
}

nlohmann::json to_json(const ScalingCell& c) {
    nlohmann::json j{{"materials", c.materials},
                     {"threads", c.threads},
                     {"fits", c.fits},
                     {"wall_s", c.wall_s},
                     {"cpu_s", c.cpu_s},
                     {"peak_mib", c.peak_mib},
                     {"setup_cpu_s", c.setup_cpu_s},
                     {"record_cpu_s", c.record_cpu_s},
                     {"record_mib", c.record_mib},
                     {"window_wait_s", c.window_wait_s},
                     {"source", c.source}};
    if (c.renders_wall_s > 0) j["renders"] = {{"wall_s", c.renders_wall_s}, {"peak_mib", c.renders_peak_mib}};
    if (c.source == "database")
        j["database"] = {{"folder", c.folder.string()},
                         {"files", c.files},
                         {"fitted", c.materials},
                         {"skipped",
                          {{"not_nk", c.skipped_not_nk},
                           {"unreadable", c.skipped_unreadable},
                           {"outside_visible", c.skipped_outside_visible},
                           {"not_metal", c.skipped_not_metal}}},
                         {"scan_cpu_s", c.scan_cpu_s}};
    return j;
}

ScalingCell scaling_cell_from_json(const nlohmann::json& j) {
    ScalingCell c;
    c.materials = j.at("materials").get<std::size_t>();
    c.threads = j.at("threads").get<int>();
    c.fits = j.at("fits").get<std::size_t>();
    c.wall_s = j.at("wall_s").get<double>();
    c.cpu_s = j.at("cpu_s").get<double>();
    c.peak_mib = j.at("peak_mib").get<double>();
    c.setup_cpu_s = j.at("setup_cpu_s").get<double>();
    c.record_cpu_s = j.at("record_cpu_s").get<double>();
    c.record_mib = j.at("record_mib").get<double>();
    c.window_wait_s = j.at("window_wait_s").get<double>();
    c.source = j.value("source", "synthetic");
    if (const auto r = j.find("renders"); r != j.end()) {
        c.renders_wall_s = r->at("wall_s").get<double>();
        c.renders_peak_mib = r->at("peak_mib").get<double>();
    }
    if (const auto d = j.find("database"); d != j.end()) {
        c.folder = d->at("folder").get<std::string>();
        c.files = d->at("files").get<std::size_t>();
        const nlohmann::json& skipped = d->at("skipped");
        c.skipped_not_nk = skipped.at("not_nk").get<std::size_t>();
        c.skipped_unreadable = skipped.at("unreadable").get<std::size_t>();
        c.skipped_outside_visible = skipped.at("outside_visible").get<std::size_t>();
        c.skipped_not_metal = skipped.at("not_metal").get<std::size_t>();
        c.scan_cpu_s = d->at("scan_cpu_s").get<double>();
    }
    return c;
}

double ScalingTable::fits_per_cpu_second() const {
    const ScalingCell* largest = nullptr;
    for (const ScalingCell& c : cells)
        if (c.threads == 1 && (!largest || c.materials > largest->materials)) largest = &c;
    if (!largest || !(largest->cpu_s > 0)) return 0;
    return static_cast<double>(largest->fits) / largest->cpu_s;
}

ScalingTable run_scaling(const ScalingOptions& o) {
    ScalingTable table;
    table.models = o.models;
    table.mode = o.mode;
    table.machine = Machine::describe().one_line();
    table.command_line = o.command_line;
    const auto run_cell = [&](const std::vector<std::string>& cell_args, int threads, const std::string& what) {
        std::vector<std::string> args{"--data-dir", o.data_dir.string()};
        if (o.ocio_config) args.insert(args.end(), {"--ocio-config", o.ocio_config->string()});
        args.insert(args.end(), cell_args.begin(), cell_args.end());
        args.insert(args.end(), {"--threads", std::to_string(threads), "--scaling-models", join_models(o.models)});
        const std::string cell = what + " on " + std::to_string(threads) + " threads";
        if (o.progress) o.progress("scaling: " + cell);
        const ProcessResult r = run_process(o.metalfit, args);
        if (r.exit_code != 0) throw std::runtime_error("scaling cell " + cell + " failed: " + last_line(r.err));
        try {
            table.cells.push_back(scaling_cell_from_json(nlohmann::json::parse(r.out)));
        } catch (const nlohmann::json::exception& e) {
            throw std::runtime_error("scaling cell " + cell + ": unreadable output (" + e.what() + ")");
        }
    };
    for (std::size_t size : o.sizes)
        for (int threads : o.threads)
            run_cell({"bench", "--scaling-cell", std::to_string(size), "--scaling-mode",
                      std::string(kScalingModeNames.name(o.mode))},
                     threads, std::to_string(size) + " materials");
    if (o.database)
        for (int threads : o.threads)
            run_cell({"bench", "--scaling-database-cell", o.database->string()}, threads,
                     "the database " + o.database->string());
    return table;
}

nlohmann::json to_json(const ScalingTable& t) {
    nlohmann::json cells = nlohmann::json::array();
    for (const ScalingCell& c : t.cells) cells.push_back(to_json(c));
    return {{"schema", "metalfit.bench-scaling/1"},
            {"command", t.command_line},
            {"machine", t.machine},
            {"mode", kScalingModeNames.name(t.mode)},
            {"models", t.models},
            {"seed", t.seed},
            {"cells", cells},
            {"fits_per_cpu_second", t.fits_per_cpu_second()}};
}

std::string to_text(const ScalingTable& t) {
    bool synthetic = false;
    for (const ScalingCell& c : t.cells) synthetic = synthetic || c.source != "database";
    std::string text =
        (synthetic ? "metalfit bench --scaling: " + std::string(kScalingModeNames.name(t.mode)) +
                         " on synthetic materials (catalog tables, n and k scaled by 1 ± 0.1, seed " +
                         std::to_string(t.seed) + ")"
                   : std::string("metalfit bench --scaling-database: fit every metal nk file of a database folder")) +
        ", models " + join_models(t.models) + "\n" + t.machine + "\n";
    // A Markdown row, each cell right-aligned in its column's width (what printf's "%<width>s" did).
    constexpr std::size_t kWidths[] = {9, 7, 9, 9, 9, 13, 11, 11, 12, 10, 13};
    const auto row = [&](const std::array<std::string, std::size(kWidths)>& cells) {
        std::string line = "|";
        for (std::size_t i = 0; i < cells.size(); ++i) line += " " + pad_left(cells[i], kWidths[i]) + " |";
        return line + "\n";
    };
    text += row({"materials", "threads", "wall s", "CPU s", "peak MiB", "fits / CPU s", "wall / mat", "set-up CPU s",
                 "record CPU s", "record MiB", "window wait s"});
    text += "|----------:|--------:|----------:|----------:|----------:|--------------:|------------:|------------:|"
            "-------------:|-----------:|--------------:|\n";
    for (const ScalingCell& c : t.cells)
        text += row(
            {std::to_string(c.materials), std::to_string(c.threads), fixed_text(c.wall_s, 3), fixed_text(c.cpu_s, 3),
             fixed_text(c.peak_mib, 1), fixed_text(c.cpu_s > 0 ? static_cast<double>(c.fits) / c.cpu_s : 0.0, 1),
             pad_left(fixed_text(c.materials ? 1e3 * c.wall_s / static_cast<double>(c.materials) : 0.0, 2), 8) + " ms",
             fixed_text(c.setup_cpu_s, 3), fixed_text(c.record_cpu_s, 3), fixed_text(c.record_mib, 1),
             fixed_text(c.window_wait_s, 3)});
    text += "fit throughput: " + fixed_text(t.fits_per_cpu_second(), 1) +
            " materials x models per CPU second (largest 1-thread cell)\n";
    const auto threads = [](const ScalingCell& c) {
        return std::to_string(c.threads) + (c.threads == 1 ? " thread" : " threads");
    };
    for (const ScalingCell& c : t.cells)
        if (c.renders_wall_s > 0)
            text += "renders (" + std::to_string(c.materials) + " materials, " + threads(c) +
                    "): glpreview --sheet-rows " + fixed_text(c.renders_wall_s, 1) + " s wall, peak " +
                    fixed_text(c.renders_peak_mib, 1) + " MiB\n";
    for (const ScalingCell& c : t.cells)
        if (c.source == "database")
            text += "database " + c.folder.string() + "\ndatabase (" + threads(c) + "): " + std::to_string(c.files) +
                    " files: " + std::to_string(c.materials) + " fitted; skipped " + std::to_string(c.skipped_not_nk) +
                    " not nk, " + std::to_string(c.skipped_unreadable) + " unreadable, " +
                    std::to_string(c.skipped_outside_visible) + " not covering 360-830 nm, " +
                    std::to_string(c.skipped_not_metal) + " not metal; scan " + fixed_text(c.scan_cpu_s, 3) +
                    " s CPU\n";
    return text;
}

}  // namespace metalfit::bench
