#include "base/yaml_structure.hpp"

#include <string>
#include <unordered_map>
#include <vector>

#include "libfit/base/errors.hpp"

namespace metalfit::detail {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }
bool ends_token(char c) { return is_blank(c) || c == '\n' || c == ',' || c == '[' || c == ']' || c == '{' || c == '}'; }

// An anchor (&name) and how many bytes its node spans, with what the aliases inside it add; it is open until the
// scan leaves its node (an over-estimate: the node ends no later than where the scan closes it).
struct Anchor {
    std::size_t start = 0;
    std::size_t weight = 0;
    int flow = 0;         // flow depth where it was written
    int line_indent = 0;  // indentation of its line (block context)
    bool open = true;
};

class Scan {
public:
    Scan(std::string_view text, const std::filesystem::path& file) : text_(text), file_(file) {}

    void run() {
        const std::size_t n = text_.size();
        bool line_start = true, value_start = true;
        while (i_ < n) {
            if (line_start) {
                line_start = false;
                value_start = true;
                if (begin_line()) continue;
            }
            const char c = text_[i_];
            if (c == '\n') {
                ++line_;
                line_start = true;
                ++i_;
            } else if (is_blank(c)) {
                ++i_;
            } else if (c == '#' && (i_ == 0 || is_blank(text_[i_ - 1]) || text_[i_ - 1] == '\n')) {
                skip_to_line_end();
            } else if ((c == '[' || c == '{') && (flow_ > 0 || value_start)) {
                ++flow_;
                count_node();
                check_depth();
                ++i_;
                value_start = true;
            } else if ((c == ']' || c == '}') && flow_ > 0) {
                --flow_;
                ++i_;
                close_anchors([&](const Anchor& a) { return a.flow > flow_; });
                value_start = false;
            } else if (c == ',' && flow_ > 0) {
                count_node();
                close_anchors([&](const Anchor& a) { return a.flow == flow_; });
                ++i_;
                value_start = true;
            } else if (c == ':' && (i_ + 1 == n || ends_token(text_[i_ + 1]))) {
                count_node();
                ++i_;
                value_start = true;
            } else if (value_start && (c == '"' || c == '\'')) {
                skip_quoted(c);
                value_start = false;
            } else if (value_start && c == '!') {  // a tag (OCIO's !<ColorSpace>): the node follows
                while (i_ < n && !is_blank(text_[i_]) && text_[i_] != '\n') ++i_;
            } else if (value_start && c == '&') {
                anchor(token_after_indicator());
            } else if (value_start && c == '*') {
                alias(token_after_indicator());
                value_start = false;
            } else if (value_start && flow_ == 0 && (c == '|' || c == '>')) {
                block_scalar();
            } else {
                ++i_;
                value_start = false;
            }
        }
    }

    YamlShape shape() const { return {nodes_, aliases_}; }

private:
    [[noreturn]] void fail(const std::string& why) const { throw InputError({file_, line_}, why); }

    void check_depth() const {
        if (static_cast<int>(indents_.size()) + flow_ > kMaxYamlDepth)
            fail("YAML nested deeper than " + std::to_string(kMaxYamlDepth) + " levels (refused before parsing)");
    }
    void count_node() {
        if (++nodes_ > kMaxYamlNodes)
            fail("more than " + std::to_string(kMaxYamlNodes) + " YAML nodes (refused before parsing)");
    }
    void skip_to_line_end() {
        while (i_ < text_.size() && text_[i_] != '\n') ++i_;
    }

    // The start of a line: indentation (block levels), the end of a block scalar, "- " and "? " entries. True when the
    // whole line was consumed (part of a block scalar).
    bool begin_line() {
        const std::size_t n = text_.size();
        std::size_t j = i_;
        while (j < n && text_[j] == ' ') ++j;
        const int indent = static_cast<int>(j - i_);
        std::size_t k = j;
        while (k < n && is_blank(text_[k])) ++k;
        const bool blank = k == n || text_[k] == '\n' || text_[k] == '#';
        if (flow_ > 0) {
            i_ = j;
            return false;
        }
        if (block_parent_ >= 0 && (blank || indent > block_parent_)) {
            skip_to_line_end();
            return true;
        }
        block_parent_ = -1;
        i_ = j;
        if (blank) return false;
        close_anchors([&](const Anchor& a) { return a.line_indent >= indent; });
        line_indent_ = indent;
        while (!indents_.empty() && indents_.back() > indent) indents_.pop_back();
        if (indents_.empty() || indents_.back() < indent) indents_.push_back(indent);
        check_depth();
        // "- - x": each entry indicator opens a level at its column + 2.
        while (i_ < n && (text_[i_] == '-' || text_[i_] == '?') &&
               (i_ + 1 == n || is_blank(text_[i_ + 1]) || text_[i_ + 1] == '\n')) {
            const int column = static_cast<int>(i_ - (j - static_cast<std::size_t>(indent))) + 2;
            count_node();
            if (indents_.back() < column) indents_.push_back(column);
            check_depth();
            ++i_;
            while (i_ < n && text_[i_] == ' ') ++i_;
        }
        return false;
    }

    void skip_quoted(char quote) {
        const std::size_t n = text_.size();
        ++i_;
        while (i_ < n) {
            const char c = text_[i_];
            if (quote == '"' && c == '\\' && i_ + 1 < n) {
                if (text_[i_ + 1] == '\n') ++line_;
                i_ += 2;
            } else if (c == quote) {
                if (quote == '\'' && i_ + 1 < n && text_[i_ + 1] == '\'') {
                    i_ += 2;
                    continue;
                }
                ++i_;
                return;
            } else {
                if (c == '\n') ++line_;
                ++i_;
            }
        }
    }

    std::string token_after_indicator() {
        const std::size_t begin = ++i_;
        while (i_ < text_.size() && !ends_token(text_[i_])) ++i_;
        return std::string(text_.substr(begin, i_ - begin));
    }

    void anchor(std::string name) {
        if (name.empty()) return;
        count_node();
        Anchor a;
        a.start = i_;
        a.flow = flow_;
        a.line_indent = line_indent_;
        anchors_[name] = a;
        open_.push_back(std::move(name));
        if (open_.size() > static_cast<std::size_t>(kMaxYamlDepth))
            fail("more than " + std::to_string(kMaxYamlDepth) + " nested YAML anchors (refused before parsing)");
    }

    void alias(const std::string& name) {
        count_node();
        const auto found = anchors_.find(name);
        if (found == anchors_.end()) return;  // yaml-cpp reports the unknown anchor
        if (found->second.open) fail("alias *" + name + " inside the node its anchor marks (refused before parsing)");
        ++aliases_;
        const std::size_t weight = found->second.weight;
        alias_bytes_ += weight;
        for (const std::string& o : open_) anchors_[o].weight += weight;
        if (alias_bytes_ > kMaxYamlAliasBytes)
            fail("YAML aliases expand to more than " + std::to_string(kMaxYamlAliasBytes >> 20) +
                 " MiB (refused before parsing)");
    }

    template <class Predicate>
    void close_anchors(Predicate should_close) {
        for (std::size_t k = 0; k < open_.size();) {
            Anchor& a = anchors_[open_[k]];
            if (should_close(a)) {
                a.weight += i_ - a.start;
                a.open = false;
                open_.erase(open_.begin() + static_cast<std::ptrdiff_t>(k));
            } else {
                ++k;
            }
        }
    }

    // "|" or ">" with its indicators ending the line: the lines indented deeper than the current level are text.
    void block_scalar() {
        std::size_t j = i_ + 1;
        while (j < text_.size() && (text_[j] == '+' || text_[j] == '-' || (text_[j] >= '0' && text_[j] <= '9'))) ++j;
        while (j < text_.size() && is_blank(text_[j])) ++j;
        if (j == text_.size() || text_[j] == '\n' || text_[j] == '#')
            block_parent_ = indents_.empty() ? 0 : indents_.back();
        skip_to_line_end();
    }

    std::string_view text_;
    const std::filesystem::path& file_;
    std::size_t i_ = 0;
    int line_ = 1;
    int flow_ = 0;
    int line_indent_ = 0;
    int block_parent_ = -1;
    std::vector<int> indents_;
    std::size_t nodes_ = 0;
    std::size_t alias_bytes_ = 0;
    std::size_t aliases_ = 0;
    std::unordered_map<std::string, Anchor> anchors_;
    std::vector<std::string> open_;
};

}  // namespace

YamlShape check_yaml_structure(std::string_view text, const std::filesystem::path& file) {
    Scan scan(text, file);
    scan.run();
    return scan.shape();
}

}  // namespace metalfit::detail
