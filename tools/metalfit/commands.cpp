// What the subcommands share (commands.hpp): printing, warnings, the model ids, the command word. Also linked into
// the Python module (tools/python), whose functions print warnings the same way.
#include "commands.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <iostream>
#include <string_view>

#include "libfit/base/atomic_file.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/number_text.hpp"
#include "libfit/fit/fit.hpp"
#include "libfit/models/model.hpp"

namespace metalfit::cli {

void emit(const std::string& text, const std::filesystem::path& output) {
    if (output.empty() || output == "-")
        std::cout << text << std::flush;
    else
        write_file_atomically(output, text);
}

std::string model_ids() {
    std::string ids;
    for (const Model* m : all_models()) ids += (ids.empty() ? "" : ", ") + std::string(m->id());
    return ids;
}

std::vector<std::string> refusal_warnings(const MaterialFit& fit) {
    std::vector<std::string> lines;
    for (const ModelResult& r : fit.models)
        for (int c = 0; c < 3; ++c)
            if (!r.fit.refused[c].empty())
                lines.push_back(fit.material.id + ": " + std::string(r.model->id()) + ": " + kChannelNames[c] + ": " +
                                r.fit.refused[c]);
    return lines;
}

void warn(const std::string& message) { std::cerr << "metalfit: warning: " << sanitised_message(message) << "\n"; }

std::string fixed(double v, int digits) { return std::isnan(v) ? "-" : fixed_text(v, digits); }

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
