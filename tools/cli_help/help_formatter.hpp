// --help within 100 columns (docs/cli.md): CLI11's formatter with every option's and subcommand's description broken
// at spaces so that the description column ends by column 100 (CLI11 2.1 prints a description on one line however
// long). Used by metalfit and glpreview: `app.formatter(std::make_shared<metalfit::cli_help::HelpFormatter>())`
// before the subcommands are added (they inherit it).
#pragma once

#include <CLI/CLI.hpp>

#include <cstddef>
#include <sstream>
#include <string>

namespace metalfit::cli_help {

inline constexpr std::size_t kHelpColumns = 100;

// Columns of UTF-8 text: its code points (every character the help uses is one column wide).
inline std::size_t columns(const std::string& text) {
    std::size_t n = 0;
    for (const char c : text) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    return n;
}

// `text` broken at spaces into lines of at most `width` columns (a longer word stays whole on its own line); the
// text's own line breaks are kept.
inline std::string wrapped(const std::string& text, std::size_t width) {
    std::string out, line, word;
    const auto end_line = [&] {
        out += line;
        line.clear();
    };
    const auto add_word = [&] {
        if (word.empty()) return;
        if (!line.empty() && columns(line) + 1 + columns(word) > width) {
            end_line();
            out += '\n';
        }
        line += (line.empty() ? "" : " ") + word;
        word.clear();
    };
    for (const char c : text) {
        if (c == ' ') {
            add_word();
        } else if (c == '\n') {
            add_word();
            end_line();
            out += '\n';
        } else {
            word += c;
        }
    }
    add_word();
    end_line();
    return out;
}

class HelpFormatter : public CLI::Formatter {
public:
    std::string make_option_desc(const CLI::Option* option) const override {
        return wrapped(CLI::Formatter::make_option_desc(option), kHelpColumns - get_column_width());
    }
    std::string make_subcommand(const CLI::App* sub) const override {
        std::stringstream out;
        CLI::detail::format_help(out, sub->get_display_name(true),
                                 wrapped(sub->get_description(), kHelpColumns - get_column_width()),
                                 get_column_width());
        return out.str();
    }
};

}  // namespace metalfit::cli_help
