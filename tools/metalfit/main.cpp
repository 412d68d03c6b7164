// metalfit: measured metal n,k → shader-ready Fresnel constants. A thin layer over libfit.
// Exit codes (docs/cli.md): 0 ok, 1 internal error, 2 usage, 3 bad input file, 4 colour configuration,
// 6 `report --fail-above` found channels above the limit (the report is written).
#include <cstdio>
#include <memory>

#include "commands.hpp"
#include "help_formatter.hpp"
#include "libfit/base/data_dir.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/library_logging.hpp"
#include "libfit/base/utf8.hpp"
#include "libfit/base/version.hpp"

namespace metalfit::cli {

#if !METALFIT_HAVE_BENCH
// Built without the bench library: `metalfit bench` stays a subcommand that says so (exit code 2), so scripts get a
// clear message rather than "unknown subcommand".
std::function<void()> add_bench_command(CLI::App& app, const GlobalOptions&) {
    app.allow_extras()->fallthrough(false);
    return [] {
        throw UsageError("bench: this metalfit was built without the bench (configure with -DMETALFIT_BUILD_BENCH=ON)");
    };
}
#endif

}  // namespace metalfit::cli

namespace {

int run_metalfit(int argc, char** argv) {
    using namespace metalfit;
    constexpr int ok = exit_ok, usage = exit_usage;

    CLI::App app{"metalfit: fit shader Fresnel models to measured spectral n,k of metals"};
    app.formatter(
        std::make_shared<metalfit::cli_help::HelpFormatter>());  // within 100 columns; the subcommands inherit it
    app.set_version_flag("--version", std::string("metalfit ") + METALFIT_VERSION);
    app.require_subcommand(1);
    app.option_defaults()->always_capture_default();  // --help shows every default (subcommands inherit this)
    app.fallthrough();
    cli::GlobalOptions global{default_data_dir(), std::nullopt};
    app.add_option(
           "--data-dir", global.data_dir,
           "Built-in database folder (default: $METALFIT_DATA, else ../share/metalfit beside the executable, else the source tree's data/)")
        ->check(CLI::ExistingDirectory);
    app.add_option("--ocio-config", global.ocio_config,
                   "OCIO config to use when $OCIO is not set (default: data/ocio/config.ocio)");

    // Each subcommand's app and the function that runs it once the command line is parsed (cli::kCommands).
    std::vector<std::pair<CLI::App*, std::function<void()>>> commands;
    for (const cli::Command& command : cli::kCommands) {
        CLI::App& sub = *app.add_subcommand(std::string(command.name), std::string(command.description));
        sub.footer("Example: metalfit " + std::string(command.example));
        commands.emplace_back(&sub, command.add(sub, global));
    }

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
            if (const std::string word = cli::first_command_word(argc, argv, {"--data-dir", "--ocio-config"});
                !word.empty()) {
                std::string known;
                for (const cli::Command& command : cli::kCommands)
                    known += (known.empty() ? "" : ", ") + std::string(command.name);
                std::fprintf(stderr, "metalfit: unknown command '%s' (commands: %s; --help for more)\n", word.c_str(),
                             known.c_str());
                return usage;
            }
        const int code = app.exit(e);
        return code == 0 ? ok : usage;
    }
    try {
        for (const auto& [sub, run] : commands)
            if (sub->parsed()) run();
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
