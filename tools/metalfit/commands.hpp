// The metalfit subcommands: each registers its options on a CLI11 app and runs over libfit.
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <functional>
#include <optional>
#include <initializer_list>
#include <string>
#include <string_view>

namespace metalfit::cli {

// Options every subcommand shares.
struct GlobalOptions {
    std::filesystem::path data_dir;                    // built-in database
    std::optional<std::filesystem::path> ocio_config;  // --ocio-config ($OCIO wins when set)
};

// Each returns the function that runs the subcommand once the command line is parsed.
std::function<void()> add_list_command(CLI::App& app, const GlobalOptions& global);
std::function<void()> add_show_command(CLI::App& app, const GlobalOptions& global);
std::function<void()> add_fit_command(CLI::App& app, const GlobalOptions& global);
std::function<void()> add_models_command(CLI::App& app, const GlobalOptions& global);
std::function<void()> add_bench_command(CLI::App& app, const GlobalOptions& global);
std::function<void()> add_export_command(CLI::App& app, const GlobalOptions& global);
std::function<void()> add_spaces_command(CLI::App& app, const GlobalOptions& global);
std::function<void()> add_report_command(CLI::App& app, const GlobalOptions& global);
std::function<void()> add_table_command(CLI::App& app, const GlobalOptions& global);

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

// "metalfit: warning: ..." on stderr.
void warn(const std::string& message);

// v with `digits` decimals for human-readable tables; "-" for NaN (an undefined metric).
std::string fixed(double v, int digits = 5);

// The first word of the command line that is neither an option nor the value of one of `options_with_values`
// (empty if none): the command a user typed, for the message about an unknown one.
std::string first_command_word(int argc, char** argv, std::initializer_list<std::string_view> options_with_values);

}  // namespace metalfit::cli
