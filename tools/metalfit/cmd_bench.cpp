// metalfit bench: what accuracy costs in time. A thin layer over the bench library (bench/): it parses the options,
// finds glslangValidator and glpreview, runs the measurements and prints (or writes) the report.
#include <unistd.h>

#include <fstream>
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "libfit/base/atomic_file.hpp"
#include "metalfit_bench/bench_report.hpp"
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
};

std::string read_if_exists(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    if (in) text << in.rdbuf();
    return text.str();
}

void run_bench_command(const BenchCommandOptions& o, const GlobalOptions& global) {
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
    if (isatty(STDERR_FILENO)) options.progress = [](const std::string& line) { std::cerr << "metalfit bench: " << line << "\n"; };

    const bench::BenchReport report = bench::run_bench(options);
    if (!o.markdown.empty()) write_file_atomically(o.markdown, bench::to_markdown(report, read_if_exists(o.markdown)));
    emit(o.json ? bench::to_json(report).dump(2) + "\n" : bench::to_text(report), o.output);
}

}  // namespace

std::function<void()> add_bench_command(CLI::App& app, const GlobalOptions& global) {
    auto o = std::make_shared<BenchCommandOptions>();
    app.add_flag("--quick", o->quick, "Fewer timing rounds (well under a minute); glpreview gets --quick too");
    app.add_flag("--json", o->json, "Print the report as JSON (schema metalfit.bench/1, docs/cli.md)");
    app.add_option("--markdown", o->markdown, "Also write the report as a Markdown page (keeps its hand-written reading)");
    app.add_option("--material", o->material, "Material whose fitted parameters the evaluation timings use (default: Au)");
    app.add_option("--glpreview", o->glpreview, "The glpreview executable for the GPU sections (default: next to metalfit)");
    app.add_option("-o,--output", o->output, "Write to this file instead of stdout (- for stdout)");
    return [o, &global] { run_bench_command(*o, global); };
}

}  // namespace metalfit::cli
