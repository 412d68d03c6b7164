#include "libfit/fit/oxide_chart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <sstream>

#include "libfit/base/errors.hpp"
#include "libfit/base/number_text.hpp"
#include "libfit/base/record_path.hpp"
#include "libfit/base/text.hpp"
#include "libfit/base/version.hpp"
#include "libfit/color/color_difference.hpp"
#include "libfit/reference/reference_curve.hpp"
#include "libfit/spectral/complex_index.hpp"

namespace metalfit {
namespace {

using Json = nlohmann::ordered_json;

// "%.6g", as the chart's thicknesses and indices are written.
std::string number(double v) { return significant_text(v, 6); }

Material constant_film(double n) {
    Material m;
    m.id = number(n);
    m.name = "n = " + number(n);
    m.source = "constant";
    m.index = ComplexIndex{SpectralCurve(ConstantSpectrum{n}), SpectralCurve(ConstantSpectrum{0.0})};
    m.provenance.format = "constant";
    m.provenance.data_type = "constant n, k = 0";
    return m;
}

Material with_film(const Material& metal, const LayerMaterial& film, double d, const std::optional<ClearCoat>& coat) {
    Material m = metal;
    auto stack = std::make_shared<LayerStack>();
    stack->film = ThinFilm{film, d};
    stack->coat = coat;
    m.layers = std::move(stack);
    return m;
}

std::string fixed4(double v) { return fixed_text(v, 4); }

ChartDifference difference(const OxideChart& chart, double OxideChartRow::*member) {
    ChartDifference d;
    if (!chart.versus_index || chart.rows.empty()) return d;
    for (const OxideChartRow& r : chart.rows) {
        d.mean += r.*member;
        if (r.*member > d.max) d.max = r.*member, d.max_thickness_nm = r.thickness_nm;
    }
    d.mean /= static_cast<double>(chart.rows.size());
    return d;
}

}  // namespace

std::vector<double> parse_thickness_range(std::string_view text) {
    const InputLocation where{"--thickness " + std::string(text)};
    std::string_view body = trim(text);
    double scale = 0;
    for (const auto& [unit, s] :
         {std::pair<std::string_view, double>{"nm", 1.0}, {"um", 1000.0}, {"µm", 1000.0}, {"μm", 1000.0}})
        if (body.size() > unit.size() && body.substr(body.size() - unit.size()) == unit) {
            body = body.substr(0, body.size() - unit.size());
            scale = s;
            break;
        }
    if (scale == 0)
        throw UsageError("--thickness " + std::string(text) +
                         ": give FIRST:LAST:STEP with a unit (0:300:10nm) or one "
                         "thickness (80nm)");
    std::vector<double> parts;
    for (std::size_t start = 0;;) {
        const std::size_t colon = body.find(':', start);
        const auto value = whole_number(body.substr(start, colon == std::string_view::npos ? colon : colon - start));
        if (!value)
            throw UsageError("--thickness " + std::string(text) +
                             ": not numbers FIRST:LAST:STEP with a unit (0:300:10nm) or one thickness (80nm)");
        parts.push_back(*value * scale);
        if (colon == std::string_view::npos) break;
        start = colon + 1;
    }
    if (parts.size() != 1 && parts.size() != 3)
        throw UsageError("--thickness " + std::string(text) + ": give FIRST:LAST:STEP (0:300:10nm) or one thickness");
    for (std::size_t i = 0; i < std::min<std::size_t>(parts.size(), 2); ++i)  // FIRST and LAST; STEP below
        if (const std::string problem = film_thickness_problem(parts[i]); !problem.empty())
            throw InputError(where, problem);
    if (parts.size() == 1) return {parts[0]};
    const double first = parts[0], last = parts[1], step = parts[2];
    if (!std::isfinite(step) || step <= 0)
        throw InputError(where, "step " + number(step) + " nm is not a positive finite number");
    if (last < first) throw InputError(where, "LAST " + number(last) + " nm is below FIRST " + number(first) + " nm");
    const double count = std::floor((last - first) / step * (1 + 1e-12)) + 1;
    if (count > static_cast<double>(kMaxChartRows))
        throw InputError(where, number(count) + " thicknesses: at most " + std::to_string(kMaxChartRows) +
                                    " (a coarser step)");
    std::vector<double> values;
    for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i)
        values.push_back(std::min(last, first + static_cast<double>(i) * step));
    return values;
}

double parse_versus_index(std::string_view text) {
    const auto n = whole_number(text);
    if (!n) throw UsageError("--versus " + std::string(text) + ": give a constant film index (2.488)");
    if (!std::isfinite(*n) || *n <= 0.0 || *n > 1e6)
        throw InputError({"--versus " + std::string(text)},
                         "index " + number(*n) + " is not a finite number in (0, 1e6]");
    return *n;
}

OxideChart oxide_chart(const OxideChartInputs& in, const MetalTableColour& colour) {
    OxideChart chart;
    chart.metal_id = in.metal.id;
    chart.space = colour.working.space();
    chart.display = colour.display.description();
    chart.versus_index = in.versus_index;
    const double first = in.thicknesses_nm.empty() ? 0 : in.thicknesses_nm.front();
    const double last = in.thicknesses_nm.empty() ? 0 : in.thicknesses_nm.back();
    {
        Material described = with_film(in.metal, in.film, first, in.coat);
        std::string text = describe_stack(described);
        const std::string one = " film of " + number(first) + " nm";
        if (first != last)
            if (const std::size_t at = text.rfind(one); at != std::string::npos)
                text.replace(at, one.size(), " film of " + number(first) + "–" + number(last) + " nm");
        chart.description = text;
        chart.stack = stack_record(described, in.data_dir);
        chart.stack["description"] = text;
        chart.stack["film"].erase("thickness_nm");
        chart.stack["metal"] = {{"material", in.metal.id},
                                {"name", in.metal.name},
                                {"source", in.metal.source},
                                {"file", record_path(in.metal.provenance.file, in.data_dir)},
                                {"sha256", in.metal.provenance.sha256},
                                {"reference", in.metal.provenance.references}};
    }
    const XYZ white = colour.colorimetry.white();
    const Material versus_film = in.versus_index ? constant_film(*in.versus_index) : Material{};
    std::vector<RGB> scene;  // F0, F82 (and the versus ones) of every row, in scene_linear, for one display call
    for (const double d : in.thicknesses_nm) {
        OxideChartRow row;
        row.thickness_nm = d;
        const Material m = with_film(in.metal, in.film, d, in.coat);
        const ReferenceCurve working(m, colour.colorimetry, colour.working, colour.spectral);
        const ReferenceCurve scene_curve(m, colour.colorimetry, colour.scene_linear, colour.spectral);
        row.f0.linear = working(1.0);
        row.f82.linear = working(kMuF82);
        scene.push_back(scene_curve(1.0));
        scene.push_back(scene_curve(kMuF82));
        if (in.versus_index) {
            const Material v = with_film(in.metal, versus_film, d, in.coat);
            const ReferenceCurve versus(v, colour.colorimetry, colour.working, colour.spectral);
            const ReferenceCurve versus_scene(v, colour.colorimetry, colour.scene_linear, colour.spectral);
            row.versus_f0 = ChartColour{versus(1.0), {}};
            row.versus_f82 = ChartColour{versus(kMuF82), {}};
            scene.push_back(versus_scene(1.0));
            scene.push_back(versus_scene(kMuF82));
            row.de2000_f0 = ciede2000(xyz_to_lab(working.xyz(1.0), white), xyz_to_lab(versus.xyz(1.0), white));
            row.de2000_f82 = ciede2000(xyz_to_lab(working.xyz(kMuF82), white), xyz_to_lab(versus.xyz(kMuF82), white));
        }
        chart.rows.push_back(row);
    }
    const std::vector<Display8> display = display_colours(scene, colour.display);
    const std::size_t per_row = in.versus_index ? 4 : 2;
    for (std::size_t i = 0; i < chart.rows.size(); ++i) {
        OxideChartRow& r = chart.rows[i];
        r.f0.display = display[per_row * i];
        r.f82.display = display[per_row * i + 1];
        if (in.versus_index) {
            r.versus_f0->display = display[per_row * i + 2];
            r.versus_f82->display = display[per_row * i + 3];
        }
    }
    return chart;
}

ChartDifference chart_difference_f0(const OxideChart& chart) { return difference(chart, &OxideChartRow::de2000_f0); }
ChartDifference chart_difference_f82(const OxideChart& chart) { return difference(chart, &OxideChartRow::de2000_f82); }

std::string oxide_chart_markdown(const OxideChart& chart) {
    std::ostringstream s;
    s << chart.description << ". F0 = R(1) and F82 = R(1/7) (the reflectance at 82°, not the tint), linear "
      << chart.space << "; hex through " << chart.display << " (clamped to [0, 1]).";
    if (chart.versus_index)
        s << " Beside them a film of constant index " << number(*chart.versus_index)
          << " (k = 0) of the same thickness, and the CIEDE2000 between the two.";
    s << "\n\n| d (nm) | F0 (linear) | F0 hex | F82 (linear) | F82 hex |";
    if (chart.versus_index)
        s << " F0 hex, n = " << number(*chart.versus_index) << " | F82 hex, n = " << number(*chart.versus_index)
          << " | ΔE00 F0 | ΔE00 F82 |";
    s << "\n|---|---|---|---|---|" << (chart.versus_index ? "---|---|---|---|" : "") << "\n";
    const auto triple = [](const RGB& v) { return fixed4(v.r) + ", " + fixed4(v.g) + ", " + fixed4(v.b); };
    for (const OxideChartRow& r : chart.rows) {
        s << "| " << number(r.thickness_nm) << " | " << triple(r.f0.linear) << " | `" << hex(r.f0.display) << "` | "
          << triple(r.f82.linear) << " | `" << hex(r.f82.display) << "` |";
        if (chart.versus_index)
            s << " `" << hex(r.versus_f0->display) << "` | `" << hex(r.versus_f82->display) << "` | "
              << fixed_text(r.de2000_f0, 2) << " | " << fixed_text(r.de2000_f82, 2) << " |";
        s << "\n";
    }
    if (chart.versus_index) {
        const ChartDifference f0 = chart_difference_f0(chart), f82 = chart_difference_f82(chart);
        s << "\nΔE00 against n = " << number(*chart.versus_index) << ": F0 mean " << fixed_text(f0.mean, 2) << ", max "
          << fixed_text(f0.max, 2) << " at " << number(f0.max_thickness_nm) << " nm; F82 mean "
          << fixed_text(f82.mean, 2) << ", max " << fixed_text(f82.max, 2) << " at " << number(f82.max_thickness_nm)
          << " nm\n";
    }
    return s.str();
}

std::string oxide_chart_csv(const OxideChart& chart) {
    std::ostringstream s;
    s << "thickness_nm,F0_r,F0_g,F0_b,F0_hex,F82_r,F82_g,F82_b,F82_hex";
    if (chart.versus_index)
        s << ",versus_index,versus_F0_r,versus_F0_g,versus_F0_b,versus_F0_hex,versus_F82_r,versus_F82_g,versus_F82_b,"
             "versus_F82_hex,de2000_F0,de2000_F82";
    s << "\n";
    for (const OxideChartRow& r : chart.rows) {
        s << shortest_text(r.thickness_nm);
        const auto colour = [&s](const ChartColour& c) {
            for (int k = 0; k < 3; ++k) s << ',' << shortest_text(c.linear[k]);
            s << ',' << hex(c.display);
        };
        colour(r.f0);
        colour(r.f82);
        if (chart.versus_index) {
            s << ',' << shortest_text(*chart.versus_index);
            colour(*r.versus_f0);
            colour(*r.versus_f82);
            s << ',' << shortest_text(r.de2000_f0) << ',' << shortest_text(r.de2000_f82);
        }
        s << "\n";
    }
    return s.str();
}

nlohmann::ordered_json oxide_chart_json(const OxideChart& chart) {
    const auto colour = [](const ChartColour& c) {
        return Json{{"linear", {c.linear.r, c.linear.g, c.linear.b}},
                    {"display8", {c.display[0], c.display[1], c.display[2]}},
                    {"hex", hex(c.display)}};
    };
    Json rows = Json::array();
    for (const OxideChartRow& r : chart.rows) {
        Json row = {{"thickness_nm", r.thickness_nm}, {"F0", colour(r.f0)}, {"F82", colour(r.f82)}};
        if (chart.versus_index) {
            row["versus"] = {{"F0", colour(*r.versus_f0)}, {"F82", colour(*r.versus_f82)}};
            row["de2000"] = {{"F0", r.de2000_f0}, {"F82", r.de2000_f82}};
        }
        rows.push_back(std::move(row));
    }
    Json versus = nullptr;
    if (chart.versus_index) {
        const auto summary = [](const ChartDifference& d) {
            return Json{{"mean", d.mean}, {"max", d.max}, {"max_at_nm", d.max_thickness_nm}};
        };
        versus = {{"index", *chart.versus_index},
                  {"de2000_F0", summary(chart_difference_f0(chart))},
                  {"de2000_F82", summary(chart_difference_f82(chart))}};
    }
    return {{"schema", "metalfit.oxide-chart/1"},
            {"metalfit_version", METALFIT_VERSION},
            {"description", chart.description},
            {"stack", chart.stack},
            {"space", chart.space},
            {"display", chart.display},
            {"mu_f82", kMuF82},
            {"versus", versus},
            {"rows", rows}};
}

std::string oxide_chart_html(const OxideChart& chart) {
    std::ostringstream s;
    s << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << html_escaped(chart.description)
      << "</title>\n<style>body{font:14px sans-serif;margin:2em}table{border-collapse:collapse}"
         "td,th{padding:2px 8px;text-align:left}.sw{width:4em;height:1.6em}</style></head><body>\n<h1>"
      << html_escaped(chart.description)
      << "</h1>\n<p>F0 = R(1) and F82 = R(1/7) (the reflectance at 82°), swatches through "
      << html_escaped(chart.display) << "; linear values in " << html_escaped(chart.space) << ". metalfit "
      << METALFIT_VERSION << ".</p>\n";
    if (chart.versus_index) {
        const ChartDifference f0 = chart_difference_f0(chart), f82 = chart_difference_f82(chart);
        s << "<p>Beside them a film of constant index " << number(*chart.versus_index)
          << " (k = 0) of the same thickness. CIEDE2000 between the two: F0 mean " << fixed_text(f0.mean, 2) << ", max "
          << fixed_text(f0.max, 2) << " at " << number(f0.max_thickness_nm) << " nm; F82 mean "
          << fixed_text(f82.mean, 2) << ", max " << fixed_text(f82.max, 2) << " at " << number(f82.max_thickness_nm)
          << " nm.</p>\n";
    }
    s << "<table>\n<tr><th>d (nm)</th><th>F0</th><th>F82</th>";
    if (chart.versus_index)
        s << "<th>F0, n = " << number(*chart.versus_index) << "</th><th>F82, n = " << number(*chart.versus_index)
          << "</th><th>ΔE00 F0</th><th>ΔE00 F82</th>";
    s << "</tr>\n";
    const auto swatch = [&s](const ChartColour& c) {
        s << "<td><div class=\"sw\" style=\"background:" << hex(c.display) << "\" title=\"" << hex(c.display) << " ("
          << fixed4(c.linear.r) << ", " << fixed4(c.linear.g) << ", " << fixed4(c.linear.b) << ")\"></div></td>";
    };
    for (const OxideChartRow& r : chart.rows) {
        s << "<tr><td>" << number(r.thickness_nm) << "</td>";
        swatch(r.f0);
        swatch(r.f82);
        if (chart.versus_index) {
            swatch(*r.versus_f0);
            swatch(*r.versus_f82);
            s << "<td>" << fixed_text(r.de2000_f0, 2) << "</td><td>" << fixed_text(r.de2000_f82, 2) << "</td>";
        }
        s << "</tr>\n";
    }
    s << "</table>\n</body></html>\n";
    return s.str();
}

}  // namespace metalfit
