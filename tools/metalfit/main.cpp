// metalfit: measured metal n,k → shader-ready Fresnel constants. A thin layer over libfit.
// Exit codes (docs/cli.md): 0 ok, 1 internal error, 2 usage, 3 bad input file, 4 colour configuration,
// 6 `report --fail-above` found channels above the limit (the report is written).
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string_view>
#include <cstdio>
#include <iostream>

#include "commands.hpp"
#include "libfit/base/atomic_file.hpp"
#include "libfit/base/data_dir.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/library_logging.hpp"
#include "libfit/base/utf8.hpp"
#include "libfit/base/version.hpp"
#include "libfit/models/model.hpp"

namespace metalfit::cli {

void emit(const std::string& text, const std::filesystem::path& output) {
    if (output.empty() || output == "-") std::cout << text << std::flush;
    else write_file_atomically(output, text);
}

std::string model_ids() {
    std::string ids;
    for (const Model* m : all_models()) ids += (ids.empty() ? "" : ", ") + std::string(m->id());
    return ids;
}

void warn(const std::string& message) { std::cerr << "metalfit: warning: " << sanitised_message(message) << "\n"; }

std::string fixed(double v, int digits) {
    if (std::isnan(v)) return "-";
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", digits, v);
    return text;
}

// The first word of the command line that is neither an option nor an option's value: the command a user typed.
std::string first_command_word(int argc, char** argv, std::initializer_list<std::string_view> options_with_values) {
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (arg.empty() || arg[0] != '-') return std::string(arg);
        if (std::find(options_with_values.begin(), options_with_values.end(), arg) != options_with_values.end()) ++i;
    }
    return {};
}

}  // namespace metalfit::cli

namespace {

int run_metalfit(int argc, char** argv) {
    using namespace metalfit;
    constexpr int ok = exit_ok, usage = exit_usage;

    CLI::App app{"metalfit: fit shader Fresnel models to measured spectral n,k of metals"};
    app.set_version_flag("--version", std::string("metalfit ") + METALFIT_VERSION);
    app.require_subcommand(1);
    app.option_defaults()->always_capture_default();  // --help shows every default (subcommands inherit this)
    app.fallthrough();
    cli::GlobalOptions global{default_data_dir(), std::nullopt};
    app.add_option("--data-dir", global.data_dir, "Built-in database folder (default: $METALFIT_DATA, else ../share/metalfit beside the executable, else the source tree's data/)")
        ->check(CLI::ExistingDirectory);
    app.add_option("--ocio-config", global.ocio_config, "OCIO config to use when $OCIO is not set (default: data/ocio/config.ocio)");

    std::function<void()> run;
    auto& list = *app.add_subcommand("list", "List the built-in materials");
    auto run_list = cli::add_list_command(list, global);
    auto& show = *app.add_subcommand("show", "Reference reflectance of one material (F0, F82, R at a few angles)");
    auto run_show = cli::add_show_command(show, global);
    auto& fit = *app.add_subcommand("fit", "Fit cheap Fresnel models (closed forms and Ceres) to one material or --all");
    auto run_fit = cli::add_fit_command(fit, global);
    auto& models = *app.add_subcommand("models", "The Fresnel models: parameters, bounds and GLSL");
    auto run_models = cli::add_models_command(models, global);
    auto& bench = *app.add_subcommand("bench", "What accuracy costs: model evaluation, fit, SPIR-V and GPU timings against accuracy");
#if METALFIT_HAVE_BENCH
    auto run_bench = cli::add_bench_command(bench, global);
#else
    bench.allow_extras()->fallthrough(false);
    const auto run_bench = [] {
        throw UsageError("bench: this metalfit was built without the bench (configure with -DMETALFIT_BUILD_BENCH=ON)");
    };
#endif
    auto& export_ = *app.add_subcommand("export", "Write shader-ready constants: JSON, GLSL, HLSL, MaterialX, OpenPBR, C++");
    auto run_export = cli::add_export_command(export_, global);
    auto& spaces = *app.add_subcommand("spaces", "The OCIO config in use: its colour spaces (which can be --space) and roles");
    auto run_spaces = cli::add_spaces_command(spaces, global);
    auto& report = *app.add_subcommand("report", "HTML report (catalog and material pages, report.json, charts, renders) of the fits");
    auto run_report = cli::add_report_command(report, global);
    auto& table = *app.add_subcommand("table", "F0 and F82 tint of every catalog metal: linear, 8-bit and hex, with source and caveat");
    auto run_table = cli::add_table_command(table, global);

    try {
        require_utf8_arguments(argc, argv);  // before any value becomes a name, label or path (docs/cli.md)
    } catch (...) {
        return report_current_exception("metalfit");
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // CLI11 says "A subcommand is required" for a mistyped one too: name the word and the commands instead.
        if (app.get_subcommands().empty())
            if (const std::string word = cli::first_command_word(argc, argv, {"--data-dir", "--ocio-config"}); !word.empty()) {
                std::string known;
                for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
                    known += (known.empty() ? "" : ", ") + sub->get_name();
                std::fprintf(stderr, "metalfit: unknown command '%s' (commands: %s; --help for more)\n", word.c_str(), known.c_str());
                return usage;
            }
        const int code = app.exit(e);
        return code == 0 ? ok : usage;
    }
    try {
        if (list.parsed()) run_list();
        if (show.parsed()) run_show();
        if (fit.parsed()) run_fit();
        if (models.parsed()) run_models();
        if (bench.parsed()) run_bench();
        if (export_.parsed()) run_export();
        if (spaces.parsed()) run_spaces();
        if (report.parsed()) run_report();
        if (table.parsed()) run_table();
        return ok;
    } catch (const cli::FailAbove&) {
        return cli::exit_fail_above;
    } catch (...) {
        return report_current_exception("metalfit");
    }
}

}  // namespace

int main(int argc, char** argv) {
    metalfit::route_library_logging("metalfit");
    return metalfit::finish_standard_output("metalfit", run_metalfit(argc, argv));
}
