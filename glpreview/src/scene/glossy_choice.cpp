#include "glpreview/scene/glossy_choice.hpp"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "glossy_choice_table.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/number_text.hpp"

namespace metalfit::glpreview {
namespace {

using Json = nlohmann::json;

[[noreturn]] void fail(const std::string& name, const std::string& field, const std::string& message) {
    throw InputError({name, 0, field}, message);
}

template <typename T>
T number(const Json& row, const char* key, const std::string& name, const std::string& field) {
    if (!row.contains(key) || !row[key].is_number()) fail(name, field + "." + key, "expected a number");
    const double value = row[key].get<double>();
    if (!std::isfinite(value) || value < 0) fail(name, field + "." + key, "expected a finite number ≥ 0");
    return static_cast<T>(value);
}

// The lowest roughness of the rows from which on `holds` is true at every row above it.
template <typename Predicate>
std::optional<double> lowest_from_which_on(const std::vector<GlossyChoiceRow>& rows, Predicate holds) {
    std::optional<double> from;
    for (auto row = rows.rbegin(); row != rows.rend() && holds(*row); ++row) from = row->roughness;
    return from;
}

std::string roughness_text(double r) { return significant_text(r, 3); }

}  // namespace

GlossyChoiceTable parse_glossy_choice_table(const std::string& json_text, const std::string& name) {
    Json j;
    try {
        j = Json::parse(json_text);
    } catch (const Json::parse_error& e) {
        fail(name, "", std::string("not JSON: ") + e.what());
    }
    if (!j.is_object() || j.value("schema", "") != "metalfit.glossy-choice/1")
        fail(name, "schema", "expected \"metalfit.glossy-choice/1\"");
    if (!j.contains("rows") || !j["rows"].is_array() || j["rows"].empty())
        fail(name, "rows", "expected a non-empty array");
    GlossyChoiceTable table;
    table.command = j.value("command", "");
    for (std::size_t i = 0; i < j["rows"].size(); ++i) {
        const Json& row = j["rows"][i];
        const std::string field = "rows[" + std::to_string(i) + "]";
        GlossyChoiceRow r{number<double>(row, "roughness", name, field), number<int>(row, "spheres", name, field),
                          number<int>(row, "localized_wins", name, field),
                          number<double>(row, "median_ratio", name, field),
                          number<double>(row, "worst_ratio", name, field)};
        if (r.roughness <= 0 || r.roughness > 1) fail(name, field + ".roughness", "must be in (0, 1]");
        if (r.spheres < 1 || r.localized_wins > r.spheres)
            fail(name, field + ".localized_wins", "must be at most spheres (at least 1)");
        if (!table.rows.empty() && r.roughness <= table.rows.back().roughness)
            fail(name, field + ".roughness", "rows must be by increasing roughness");
        table.rows.push_back(r);
    }
    table.localized_from = lowest_from_which_on(table.rows, [](const GlossyChoiceRow& r) {
        return r.localized_wins >= kLocalizedMajority * r.spheres && r.median_ratio < 1;
    });
    table.localized_works_from = lowest_from_which_on(
        table.rows, [](const GlossyChoiceRow& r) { return r.worst_ratio <= kLocalizedWorstRatio; });
    return table;
}

const GlossyChoiceTable& glossy_choice_table() {
    static const GlossyChoiceTable table =
        parse_glossy_choice_table(std::string(detail::kGlossyChoiceTable), "data/glossy-choice.json");
    return table;
}

GlossyChoice choose_glossy_method(double roughness, GlossyRequest request, const GlossyChoiceTable& table) {
    const std::string at = "roughness " + roughness_text(roughness);
    switch (request) {
        case GlossyRequest::prefiltered: return {GlossyMethod::prefiltered, false, "asked for"};
        case GlossyRequest::localized:
            if (table.localized_works_from && roughness >= *table.localized_works_from)
                return {GlossyMethod::localized, false, "asked for"};
            return {GlossyMethod::prefiltered, true,
                    "'localized' fails at " + at + ": " +
                        (table.localized_works_from
                             ? "only from roughness " + roughness_text(*table.localized_works_from) +
                                   " on was its RMSE never above " + roughness_text(kLocalizedWorstRatio) +
                                   "x prefiltered's in the measured rooms"
                             : "its RMSE was above " + roughness_text(kLocalizedWorstRatio) +
                                   "x prefiltered's at every measured roughness") +
                        " (data/glossy-choice.json): rendered 'prefiltered'"};
        case GlossyRequest::automatic: break;
    }
    if (table.localized_from && roughness >= *table.localized_from)
        return {GlossyMethod::localized, false,
                "auto: " + at + " ≥ " + roughness_text(*table.localized_from) +
                    ", from where localized had the lower error on at least " +
                    significant_text(100 * kLocalizedMajority, 3) +
                    " % of the measured spheres (data/glossy-choice.json)"};
    return {GlossyMethod::prefiltered, false,
            "auto: " + at +
                (table.localized_from
                     ? " < " + roughness_text(*table.localized_from) + ", below which localized did not win on " +
                           significant_text(100 * kLocalizedMajority, 3) + " % of the measured spheres"
                     : ": localized never won on " + significant_text(100 * kLocalizedMajority, 3) +
                           " % of the measured spheres") +
                " (data/glossy-choice.json)"};
}

void honour_glossy_requests(Scene& scene) {
    for (Sphere& sphere : scene.spheres) {
        if (!sphere.rough() || sphere.glossy_request != GlossyRequest::localized) continue;
        const GlossyChoice choice = choose_glossy_method(sphere.roughness, sphere.glossy_request);
        sphere.glossy = GlossyMethod::localized;
        if (!choice.fell_back) continue;
        std::erase_if(scene.warnings, [&](const std::string& w) { return w.ends_with(": " + choice.reason); });
    }
}

}  // namespace metalfit::glpreview
