// The metalfit subcommands: each registers its options on a CLI11 app and runs over libfit.
#pragma once

#include <CLI/CLI.hpp>

#include <array>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace metalfit {
struct MaterialFit;
}

namespace metalfit::cli {

// Options every subcommand shares.
struct GlobalOptions {
    std::filesystem::path data_dir;                    // built-in database
    std::optional<std::filesystem::path> ocio_config;  // --ocio-config ($OCIO wins when set)
};

// Each registers its options on the subcommand's app and returns the function that runs it once the command line is
// parsed (one per cmd_<name>.cpp).
std::function<void()> add_list_command(CLI::App& app, const GlobalOptions& global);
std::function<void()> add_show_command(CLI::App& app, const GlobalOptions& global);
std::function<void()> add_fit_command(CLI::App& app, const GlobalOptions& global);
std::function<void()> add_models_command(CLI::App& app, const GlobalOptions& global);
std::function<void()> add_bench_command(CLI::App& app, const GlobalOptions& global);
std::function<void()> add_export_command(CLI::App& app, const GlobalOptions& global);
std::function<void()> add_spaces_command(CLI::App& app, const GlobalOptions& global);
std::function<void()> add_report_command(CLI::App& app, const GlobalOptions& global);
std::function<void()> add_table_command(CLI::App& app, const GlobalOptions& global);

// The subcommands, in the order --help lists them: the one list main() registers, runs and names in the message
// about an unknown command.
struct Command {
    std::string_view name;
    std::string_view description;
    std::function<void()> (*add)(CLI::App& app, const GlobalOptions& global);
    std::string_view example;  // the arguments after `metalfit`, shown at the end of its --help (runs as written)
};
inline constexpr std::array<Command, 9> kCommands{{
    {"list", "List the built-in materials", &add_list_command, "list --json"},
    {"show", "Reference reflectance of one material (F0, F82, R at a few angles)", &add_show_command,
     "show Au --space ACEScg"},
    {"fit", "Fit cheap Fresnel models (closed forms and Ceres) to one material or --all", &add_fit_command,
     "fit Au,Cu --model f82-tint,schlick-comp"},
    {"models", "The Fresnel models: parameters, bounds and GLSL", &add_models_command, "models --json"},
    {"bench", "What accuracy costs: model evaluation, fit, SPIR-V and GPU timings against accuracy", &add_bench_command,
     "bench --quick"},
    {"export", "Write shader-ready constants: JSON, GLSL, HLSL, MSL, WGSL, MaterialX, OpenPBR, C++, glTF",
     &add_export_command, "export Au --model f82-tint --format glsl,mtlx -o out/export"},
    {"spaces", "The OCIO config in use: its colour spaces (which can be --space) and roles", &add_spaces_command,
     "spaces"},
    {"report", "HTML report (catalog and material pages, report.json, charts, renders) of the fits",
     &add_report_command, "report Au,Cu --renders off -o report"},
    {"table", "F0 and F82 tint of every catalog metal: linear, 8-bit and hex, with source and caveat",
     &add_table_command, "table Ti --film TiO2 --thickness 0:300:20nm"},
}};

// `metalfit report --fail-above`: the report was written, and `count` channels are above the limit (each already
// printed on stderr). main() exits with exit_fail_above (docs/cli.md).
inline constexpr int exit_fail_above = 6;
struct FailAbove {
    std::size_t count = 0;
};

// Prints to stdout (`output` empty or "-"), else writes atomically to the file `output`.
void emit(const std::string& text, const std::filesystem::path& output);

// The registered model ids, comma-separated (for --model's help).
std::string model_ids();

// The names of a libfit enum table (libfit/base/enum_names.hpp), in its order, for CLI::IsMember: an option accepts
// exactly the names libfit parses and prints.
template <typename Table>
std::vector<std::string> names_of(const Table& table) {
    std::vector<std::string> names;
    for (const auto& entry : table.names) names.emplace_back(entry.name);
    return names;
}

// "metalfit: warning: ..." on stderr.
void warn(const std::string& message);

// One line per model and channel whose fit refused something (FitResult::refused: --pin F0 against a bound, every
// start ending with a pole): "Au: gulbrandsen: red: --pin F0 refused: …". fit and export print them as warnings.
std::vector<std::string> refusal_warnings(const MaterialFit& fit);

// v with `digits` decimals for human-readable tables; "-" for NaN (an undefined metric).
std::string fixed(double v, int digits = 5);

// The first word of the command line that is neither an option nor the value of one of `options_with_values`
// (empty if none): the command a user typed, for the message about an unknown one.
std::string first_command_word(int argc, char** argv, std::initializer_list<std::string_view> options_with_values);

}  // namespace metalfit::cli
