#include "libfit/io/refractiveindex.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

#include "base/parse_number.hpp"
#include "base/yaml_structure.hpp"
#include "io/unphysical_rows.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/file_digest.hpp"
#include "libfit/base/input_file.hpp"
#include "libfit/base/number_text.hpp"
#include "libfit/base/utf8.hpp"

namespace metalfit {
namespace {

constexpr const char* kSupportedTypes = "tabulated nk, tabulated n, tabulated k, formula 1, formula 2";

// The file's text; InputError naming the line of the first byte that is not UTF-8 (yaml-cpp would stop on some
// with an exception that names no file, and pass overlong forms, surrogates and code points above U+10FFFF on).
std::string read_text(const std::filesystem::path& file) {
    std::string text = read_input_file(file);
    if (const auto problem = find_invalid_utf8(text))
        throw InputError({file, problem->line}, problem->reason + " (a YAML file is UTF-8 text)");
    if (const auto nul = text.find('\0'); nul != std::string::npos)
        throw InputError({file, 1 + static_cast<int>(std::count(
                                        text.begin(), text.begin() + static_cast<std::ptrdiff_t>(nul), '\n'))},
                         "a NUL byte (not a text file)");
    return text;
}

std::vector<std::string> split_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// The rows of a tabulated block (n or k) and the block's field, for messages.
struct Rows {
    std::vector<SpectrumSample> samples;
    std::string field;
};

class Reader {
public:
    explicit Reader(std::filesystem::path file)
        : file_(std::move(file)), text_(read_text(file_)), lines_(split_lines(text_)) {}

    Material read() {
        YAML::Node root;
        detail::check_yaml_structure(text_, file_);  // depth, node count, aliases: before yaml-cpp spends on them
        try {
            root = YAML::Load(text_);
        } catch (const YAML::ParserException& e) {
            throw InputError({file_, e.mark.line + 1}, "invalid YAML: " + e.msg);
        } catch (const YAML::Exception& e) {
            throw InputError({file_}, std::string("cannot read YAML: ") + e.what());
        }
        if (!root.IsMap())
            throw InputError({file_, 1}, "not a refractiveindex.info file (expected a mapping with DATA)");

        Material m;
        m.provenance.file = file_;
        m.provenance.format = "refractiveindex.info YAML";
        m.provenance.references = text(root, "REFERENCES");
        m.provenance.comments = text(root, "COMMENTS");
        read_conditions(root, m.provenance);

        const YAML::Node data = root["DATA"];
        if (!data) throw InputError({file_, 0, "DATA"}, "missing (a refractiveindex.info file needs a DATA list)");
        if (!data.IsSequence() || data.size() == 0)
            throw InputError({file_, line_of(data), "DATA"}, "expected a non-empty list of data blocks");

        // Tabulated blocks are read into rows first: rows no material has, far outside the visible range, are dropped
        // from there outward before the curves are made (or refused: unphysical_rows.hpp).
        std::optional<SpectralCurve> n, k;
        std::optional<Rows> n_rows, k_rows;
        std::vector<std::string> types;
        for (std::size_t i = 0; i < data.size(); ++i) {
            const std::string where = "DATA[" + std::to_string(i) + "]";
            const YAML::Node block = data[i];
            if (!block.IsMap() || !block["type"])
                throw InputError({file_, line_of(block), where + ".type"}, "missing data type");
            const std::string type = scalar(block["type"], where + ".type");
            types.push_back(type);
            const auto claim = [&](bool taken, const char* what) {
                if (taken) throw InputError({file_, line_of(block), where}, std::string("second ") + what + " block");
            };
            if (type == "tabulated nk") {
                claim(n || n_rows, "n");
                claim(k || k_rows, "k");
                auto [nn, kk] = tabulated(block, where, 2);
                n_rows.emplace(std::move(nn));
                k_rows.emplace(std::move(kk));
            } else if (type == "tabulated n") {
                claim(n || n_rows, "n");
                n_rows.emplace(tabulated(block, where, 1).first);
            } else if (type == "tabulated k") {
                claim(k || k_rows, "k");
                k_rows.emplace(tabulated(block, where, 1, /*is_k=*/true).first);
            } else if (type == "formula 1" || type == "formula 2") {
                claim(n || n_rows, "n");
                n.emplace(formula(block, where, type == "formula 1"));
            } else {
                throw InputError({file_, line_of(block["type"]), where + ".type"},
                                 "unsupported data type '" + type + "' (supported: " + kSupportedTypes + ")");
            }
        }
        std::vector<SpectrumSample> no_rows;
        const detail::UnphysicalTrim trim = detail::drop_unphysical_ends(
            unphysical_, n_rows ? n_rows->samples : no_rows, k_rows ? k_rows->samples : no_rows, 1e-3, "\xc2\xb5m");
        std::erase_if(small_n_, [&](const detail::SmallN& row) { return !trim.n.keeps(row.nm); });
        m.warnings.insert(m.warnings.end(), trim.warnings.begin(), trim.warnings.end());
        // Repeated wavelengths, one warning per block (a "tabulated nk" block: the larger count of its n and k).
        std::vector<std::pair<std::string, std::size_t>> conflicts;
        for (auto [rows, curve] : {std::pair{&n_rows, &n}, std::pair{&k_rows, &k}}) {
            if (!*rows) continue;
            Spectrum values(std::move((*rows)->samples));
            const std::size_t count = values.conflicting_duplicates();
            if (!conflicts.empty() && conflicts.back().first == (*rows)->field)
                conflicts.back().second = std::max(conflicts.back().second, count);
            else
                conflicts.emplace_back((*rows)->field, count);
            curve->emplace(std::move(values));
        }
        for (const auto& [field, count] : conflicts)
            if (count > 0)
                warnings_.push_back(file_.string() + ": " + field + ": " + std::to_string(count) +
                                    " repeated wavelength(s) with different values: their mean is used");
        if (!n) throw InputError({file_, line_of(data), "DATA"}, "no n data (only k)");
        // A "tabulated n" row with n near 0 is |n + ik| near 0 where k is too there (no k data: k = 0 everywhere).
        detail::check_small_n(small_n_,
                              [&](double nm) { return k ? (*k)(nm, Interpolation::linear, OutOfRange::clamp) : 0.0; });
        if (!k) {
            m.warnings.push_back(file_.string() + ": no k data (" + types.front() + " only): k = 0 assumed");
            k.emplace(ConstantSpectrum{0.0});
        }
        std::string joined;
        for (const auto& t : types) joined += (joined.empty() ? "" : " + ") + t;
        m.provenance.data_type = joined;
        m.provenance.sha256 = sha256_bytes(text_);
        m.index = ComplexIndex{std::move(*n), std::move(*k)};
        m.id = m.name = file_.stem().string();
        m.source = file_.filename().string();
        m.warnings.insert(m.warnings.end(), warnings_.begin(), warnings_.end());
        return m;
    }

private:
    int line_of(const YAML::Node& node) const { return node && node.Mark().line >= 0 ? node.Mark().line + 1 : 0; }

    std::string scalar(const YAML::Node& node, const std::string& field) const {
        if (!node.IsScalar()) throw InputError({file_, line_of(node), field}, "expected a text value");
        return node.Scalar();
    }

    std::string text(const YAML::Node& root, const char* key) const {
        const YAML::Node node = root[key];
        if (!node) return {};
        std::string s = scalar(node, key);
        while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
        return s;
    }

    void read_conditions(const YAML::Node& root, Provenance& p) const {
        const YAML::Node c = root["CONDITIONS"];
        if (!c) return;
        if (!c.IsMap()) throw InputError({file_, line_of(c), "CONDITIONS"}, "expected a mapping");
        for (const auto& kv : c) {
            const std::string key = kv.first.Scalar();
            // Kept as written: `50e-9` is a string to YAML core-schema readers, a number to others.
            p.conditions[key] = kv.second.IsScalar() ? kv.second.Scalar() : YAML::Dump(kv.second);
        }
    }

    // Numbers of a field that is a space-separated string ("0.21 6.7") or a YAML list.
    std::vector<double> numbers(const YAML::Node& node, const std::string& field) const {
        const InputLocation where{file_, line_of(node), field};
        if (!node.IsSequence()) return detail::parse_row(detail::split_whitespace(scalar(node, field)), where);
        std::vector<std::string> items;
        for (const auto& item : node) items.push_back(scalar(item, field));
        return detail::parse_row(std::vector<std::string_view>(items.begin(), items.end()), where);
    }

    // The first file line of a scalar's contents: block scalars (| or >) start below their key.
    int first_content_line(const YAML::Node& node) const {
        const YAML::Mark mark = node.Mark();
        if (mark.line < 0 || static_cast<std::size_t>(mark.line) >= lines_.size()) return 0;
        const std::string& line = lines_[static_cast<std::size_t>(mark.line)];
        const std::size_t col = static_cast<std::size_t>(std::max(mark.column, 0));
        const bool block = col < line.size() && (line[col] == '|' || line[col] == '>');
        return mark.line + 1 + (block ? 1 : 0);
    }

    // Rows "λ v1 [v2]" of a tabulated block; columns = number of values after λ. Rows with values outside the import
    // range go to unphysical_.
    std::pair<Rows, Rows> tabulated(const YAML::Node& block, const std::string& where, int columns, bool is_k = false) {
        const std::string field = where + ".data";
        const YAML::Node data = block["data"];
        if (!data) throw InputError({file_, line_of(block), field}, "missing");
        const std::string text = scalar(data, field);
        const int first_line = first_content_line(data);
        Rows first{{}, field}, second{{}, field};
        std::istringstream in(text);
        int row = 0, rows = 0;
        for (std::string line; std::getline(in, line); ++row) {
            const auto fields = detail::split_whitespace(line);
            if (fields.empty()) continue;
            const InputLocation here{file_, first_line > 0 ? first_line + row : 0, field};
            if (static_cast<int>(fields.size()) != columns + 1)
                throw InputError(here, "expected " + std::to_string(columns + 1) + " numbers per row, found " +
                                           std::to_string(fields.size()));
            const std::vector<double> v = detail::parse_row(fields, here);
            if (v[0] <= 0.0) throw InputError(here, "wavelength must be positive");
            const double nm = detail::wavelength_nm(v[0], 1000.0, fields[0], here);  // µm → nm
            if (rows >= static_cast<int>(kMaxTableRows))
                throw InputError(here, "more than " + std::to_string(kMaxTableRows) + " data rows (the limit)");
            ++rows;
            try {
                detail::check_optical_row(v, fields, columns == 2 ? "nk" : is_k ? "k" : "n", here);
                for (int c = 1; c <= columns; ++c) detail::check_index_limit(v[c], is_k || c == 2, fields[c], here);
                if (columns == 2) detail::check_index_modulus(v[1], v[2], here);
            } catch (const InputError& e) {
                unphysical_.push_back({nm, e, columns == 2 ? 3u : is_k ? 2u : 1u});
                continue;
            }
            if (columns == 1 && !is_k && v[1] < detail::kMinIndexModulus) {
                small_n_.push_back({here, nm, v[1]});
            }
            first.samples.push_back({nm, v[1]});
            if (columns == 2) second.samples.push_back({nm, v[2]});
        }
        if (rows == 0) throw InputError({file_, line_of(data), field}, "no data rows");
        return {std::move(first), std::move(second)};
    }

    SellmeierFormula formula(const YAML::Node& block, const std::string& where, bool squared) const {
        const YAML::Node range = block["wavelength_range"];
        const YAML::Node coefficients = block["coefficients"];
        if (!range) throw InputError({file_, line_of(block), where + ".wavelength_range"}, "missing");
        if (!coefficients) throw InputError({file_, line_of(block), where + ".coefficients"}, "missing");
        const auto r = numbers(range, where + ".wavelength_range");
        if (r.size() != 2 || !(r[0] > 0.0 && r[1] > r[0]))
            throw InputError({file_, line_of(range), where + ".wavelength_range"},
                             "expected two increasing positive wavelengths in µm");
        if (!(r[1] * 1000.0 <= 1e12))
            throw InputError({file_, line_of(range), where + ".wavelength_range"}, "wavelength out of range (µm)");
        auto c = numbers(coefficients, where + ".coefficients");
        if (c.empty()) throw InputError({file_, line_of(coefficients), where + ".coefficients"}, "no coefficients");
        SellmeierFormula f(squared ? SellmeierFormula::Form::squared_poles : SellmeierFormula::Form::linear_poles,
                           std::move(c), {r[0] * 1000.0, r[1] * 1000.0});
        // n within the import range (parse_number.hpp) at the range's ends and every nm of the visible range in it: a
        // pole, n² < 0 or coefficients near the double maximum would give NaN or inf reflectances downstream.
        const InputLocation here{file_, line_of(coefficients), where + ".coefficients"};
        const auto check = [&](double nm) {
            const double n = f(nm, OutOfRange::clamp);
            const std::string text = significant_text(n, 6) + " at " + significant_text(nm / 1000.0, 6) + " \xc2\xb5m";
            if (!(n >= detail::kMinIndexModulus))
                throw InputError(here, std::string("the formula gives n = ") + text +
                                           " (n\xc2\xb2 < 0, a pole or an overflow)");
            detail::check_index_limit(n, false, text, here);
        };
        check(r[0] * 1000.0);
        check(r[1] * 1000.0);
        for (double nm = std::ceil(std::max(r[0] * 1000.0, 360.0)); nm <= std::min(r[1] * 1000.0, 830.0); nm += 1.0)
            check(nm);
        return f;
    }

    std::filesystem::path file_;
    std::string text_;
    std::vector<std::string> lines_;  // to tell block scalars from plain ones
    std::vector<std::string> warnings_;
    std::vector<detail::SmallN> small_n_;            // rows of "tabulated n" blocks with n < 1e-6
    std::vector<detail::UnphysicalRow> unphysical_;  // rows outside the import range (unphysical_rows.hpp)
};

}  // namespace

Material load_refractiveindex_yaml(const std::filesystem::path& file) { return Reader(file).read(); }

}  // namespace metalfit
