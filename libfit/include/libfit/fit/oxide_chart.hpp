// The oxide colour chart (`metalfit table METAL --film FILM --thickness 0:300:10nm [--versus 2.488]`): per film
// thickness the stack's F0 = R(1) and F82 = R(1/7) colours, linear in the working space and as 8-bit display values /
// hex, and, with a constant film index to compare (physicallybased.info's "Titanium (Anodized)" uses 2.488), the
// colours of that film next to them and the CIEDE2000 difference between the two. docs/colour.md, "The oxide colour
// chart".
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "libfit/fit/metal_table.hpp"
#include "libfit/io/layer_stack.hpp"

namespace metalfit {

// The most rows a chart has (0:2000:1nm).
inline constexpr std::size_t kMaxChartRows = 2001;

// "FIRST:LAST:STEP" with one unit at the end ("0:300:10nm", "0:0.3:0.01um") or one thickness ("80nm").
// Not a number, or no unit: UsageError; a thickness negative, not finite or beyond 2 µm, a step ≤ 0 or not finite,
// LAST < FIRST, or more than kMaxChartRows rows: InputError naming `--thickness TEXT` (exit 3, nothing written).
std::vector<double> parse_thickness_range(std::string_view text);

// A constant film index to compare (`--versus 2.488`): not a number: UsageError; not finite or not in (0, 1e6]:
// InputError.
double parse_versus_index(std::string_view text);

struct ChartColour {
    RGB linear;  // white balanced, in the working space
    Display8 display{};
};

struct OxideChartRow {
    double thickness_nm = 0;
    ChartColour f0, f82;
    std::optional<ChartColour> versus_f0, versus_f82;  // the constant-index film of the same thickness
    double de2000_f0 = 0, de2000_f82 = 0;              // between the two (0 without --versus)
};

struct OxideChart {
    std::string description;       // "titanium under a TiO2 (Siefke) film of 0–300 nm"
    nlohmann::ordered_json stack;  // the metal's and the layers' provenance (film thickness left out)
    std::string metal_id, space, display;
    std::optional<double> versus_index;
    std::vector<OxideChartRow> rows;
};

// What a chart is made of: the bare metal, the film's material and an optional coat over the film.
struct OxideChartInputs {
    Material metal;  // bare (its layers are replaced)
    LayerMaterial film;
    std::optional<ClearCoat> coat;
    std::vector<double> thicknesses_nm;
    std::optional<double> versus_index;
    std::filesystem::path data_dir;  // the database: the record names files relative to it (base/record_path.hpp)
};

// The chart; the ΔE2000 in CIELAB of the XYZ before the colour space, white = the perfect reflector (as the fit's
// metrics). Throws InputError when the film or coat does not cover the colour range (as --film does).
OxideChart oxide_chart(const OxideChartInputs& inputs, const MetalTableColour& colour);

// ΔE2000 over the rows with --versus: mean and max (and the thickness of the max), for F0 and F82.
struct ChartDifference {
    double mean = 0, max = 0, max_thickness_nm = 0;
};
ChartDifference chart_difference_f0(const OxideChart& chart);
ChartDifference chart_difference_f82(const OxideChart& chart);

// The renderings of `--format`: one row per thickness.
std::string oxide_chart_markdown(const OxideChart& chart);
std::string oxide_chart_csv(const OxideChart& chart);
std::string oxide_chart_html(const OxideChart& chart);             // a standalone page of swatches
nlohmann::ordered_json oxide_chart_json(const OxideChart& chart);  // schemas/oxide-chart.schema.json

}  // namespace metalfit
