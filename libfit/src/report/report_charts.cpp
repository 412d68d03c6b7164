// The Vega-Lite specs of the report (rendered in the pages by vega-embed). The data of each chart are named
// datasets that the page script builds from report.json; the specs hold no numbers of their own.
#include "report/report_charts.hpp"

namespace metalfit::report_detail {
namespace {

using Json = nlohmann::ordered_json;

Json data(const char* name) { return {{"name", name}}; }

// The angle axis: θ in degrees (what artists think in) or μ = cos θ, chosen on the page.
Json angle_parameter() {
    return Json::array(
        {{{"name", "axis"},
          {"value", "θ (degrees)"},
          {"bind", {{"input", "radio"}, {"options", {"θ (degrees)", "μ = cos θ"}}, {"name", "x axis: "}}}}});
}
Json angle_transform() { return {{"calculate", "axis == 'μ = cos θ' ? datum.mu : datum.theta"}, {"as", "x"}}; }
Json angle_x() {
    return {{"field", "x"}, {"type", "quantitative"}, {"title", "θ (degrees) or μ = cos θ: choose below"}};
}
Json channel_facet() {
    return {{"field", "channel"}, {"type", "nominal"}, {"sort", {"red", "green", "blue"}}, {"title", nullptr}};
}
Json tooltip(std::initializer_list<std::pair<const char*, const char*>> fields) {
    Json t = Json::array();
    for (const auto& [field, type] : fields) t.push_back({{"field", field}, {"type", type}});
    return t;
}

Json material_charts() {
    Json charts = Json::object();
    charts["nk"] = {
        {"title", "measured n(λ) and k(λ); shaded: 360–830 nm, the range the colour is integrated over"},
        {"width", 560},
        {"height", 240},
        {"layer",
         {{{"data", data("visible")},
           {"mark", {{"type", "rect"}, {"color", "#888"}, {"opacity", 0.15}}},
           {"encoding", {{"x", {{"field", "from"}, {"type", "quantitative"}}}, {"x2", {{"field", "to"}}}}}},
          {{"data", data("nk")},
           {"mark", {{"type", "line"}, {"point", true}}},
           {"encoding",
            {{"x",
              {{"field", "nm"},
               {"type", "quantitative"},
               {"scale", {{"type", "log"}}},
               {"title", "wavelength (nm, log scale)"}}},
             {"y", {{"field", "value"}, {"type", "quantitative"}, {"title", "n, k"}}},
             {"color", {{"field", "quantity"}, {"type", "nominal"}, {"title", nullptr}}},
             {"tooltip", tooltip({{"quantity", "nominal"}, {"nm", "quantitative"}, {"value", "quantitative"}})}}}}}}};
    charts["spectral"] = {
        {"title", "exact spectral reflectance R(λ) at θ = 0°, 60°, 80°"},
        {"data", data("spectral")},
        {"width", 560},
        {"height", 240},
        {"mark", "line"},
        {"encoding",
         {{"x",
           {{"field", "nm"},
            {"type", "quantitative"},
            {"title", "wavelength (nm)"},
            {"scale", {{"domain", {360, 830}}}}}},
          {"y", {{"field", "R"}, {"type", "quantitative"}, {"title", "R(λ)"}}},
          {"color", {{"field", "angle"}, {"type", "nominal"}, {"title", "θ"}}},
          {"tooltip", tooltip({{"angle", "nominal"}, {"nm", "quantitative"}, {"R", "quantitative"}})}}}};
    const auto per_channel = [](const char* title, const char* dataset, const char* field, const char* y_title,
                                const char* series) {
        return Json{{"title", title},
                    {"data", data(dataset)},
                    {"params", angle_parameter()},
                    {"transform", Json::array({angle_transform()})},
                    {"facet", {{"column", channel_facet()}}},
                    {"spec",
                     {{"width", 250},
                      {"height", 220},
                      {"mark", {{"type", "line"}, {"clip", true}}},
                      {"encoding",
                       {{"x", angle_x()},
                        {"y", {{"field", field}, {"type", "quantitative"}, {"title", y_title}}},
                        {"color", {{"field", series}, {"type", "nominal"}, {"title", nullptr}}},
                        {"strokeDash",
                         {{"condition", {{"test", "datum.series == 'exact'"}, {"value", {1, 0}}}}, {"value", {5, 3}}}},
                        {"tooltip", tooltip({{series, "nominal"},
                                             {"theta", "quantitative"},
                                             {"mu", "quantitative"},
                                             {field, "quantitative"}})}}}}}};
    };
    charts["reflectance"] =
        per_channel("R_c per channel: exact (solid) and each fitted model", "reflectance", "R", "R_c", "series");
    charts["rel_error"] = per_channel("relative error (M − R) / R of each fitted model, in %", "rel_error",
                                      "rel_percent", "relative error (%)", "series");
    charts["de2000"] = {
        {"title", "ΔE2000 of each fitted model against the exact colour"},
        {"data", data("de2000")},
        {"params", angle_parameter()},
        {"transform", Json::array({angle_transform()})},
        {"width", 560},
        {"height", 240},
        {"mark", "line"},
        {"encoding",
         {{"x", angle_x()},
          {"y", {{"field", "de"}, {"type", "quantitative"}, {"title", "ΔE2000"}}},
          {"color", {{"field", "series"}, {"type", "nominal"}, {"title", nullptr}}},
          {"tooltip", tooltip({{"series", "nominal"}, {"theta", "quantitative"}, {"de", "quantitative"}})}}}};
    charts["stripes"] = {
        {"title", "colour at θ = 0…90° through the display transform: exact (top) above each fitted model"},
        {"data", data("stripes")},
        {"width", 560},
        {"height", {{"step", 22}}},
        {"mark", "rect"},
        {"encoding",
         {{"x",
           {{"field", "theta0"}, {"type", "quantitative"}, {"title", "θ (degrees)"}, {"scale", {{"domain", {0, 91}}}}}},
          {"x2", {{"field", "theta1"}}},
          {"y", {{"field", "row"}, {"type", "nominal"}, {"sort", nullptr}, {"title", nullptr}}},
          {"color", {{"field", "color"}, {"type", "nominal"}, {"scale", nullptr}}},
          {"tooltip", tooltip({{"row", "nominal"}, {"theta0", "quantitative"}, {"color", "nominal"}})}}}};
    return charts;
}

Json catalog_charts(bool with_costs) {
    Json charts = Json::object();
    charts["heatmap"] = {
        // The page sets the metric (rel_rms, |F0 error|, ΔE2000 max, max_rel: a menu above it) into "title" and the
        // legend's title and format; the outlined cell of each row is the material's recommendation.
        {"title", "worst-channel rel_rms of the fit, material × model (log colour scale; value in %)"},
        {"data", data("heatmap")},
        {"encoding",
         {{"x",
           {{"field", "model"},
            {"type", "nominal"},
            {"sort", nullptr},
            {"title", nullptr},
            {"axis", {{"orient", "top"}, {"labelAngle", -30}}}}},
          {"y", {{"field", "material"}, {"type", "nominal"}, {"sort", nullptr}, {"title", nullptr}}}}},
        {"layer",
         {{{"mark", {{"type", "rect"}, {"tooltip", true}}},
           {"encoding",
            {{"color",
              {{"field", "worst"},
               {"type", "quantitative"},
               {"scale", {{"type", "log"}, {"scheme", "viridis"}}},
               {"title", "rel_rms"},
               {"legend", {{"format", ".2~%"}}}}},
             {"tooltip", tooltip({{"material", "nominal"}, {"model", "nominal"}, {"label", "nominal"}})}}}},
          {{"transform", Json::array({{{"filter", "datum.recommended"}}})},
           {"mark", {{"type", "rect"}, {"fillOpacity", 0}, {"stroke", "#e4002b"}, {"strokeWidth", 3}}}},
          {{"mark", {{"type", "text"}, {"fontSize", 10}}},
           {"encoding",
            {{"text", {{"field", "label"}, {"type", "nominal"}}},
             {"color", {{"condition", {{"test", "datum.dark"}, {"value", "white"}}}, {"value", "black"}}}}}}}},
        {"width", {{"step", 86}}},
        {"height", {{"step", 24}}},
        {"config", {{"axis", {{"grid", false}}}}}};
    charts["swatches"] = {
        {"title", "F0 and F82 of every metal through the display transform"},
        {"data", data("swatches")},
        {"mark", {{"type", "rect"}, {"stroke", "#444"}, {"strokeWidth", 0.5}}},
        {"width", {{"step", 60}}},
        {"height", {{"step", 18}}},
        {"encoding",
         {{"x",
           {{"field", "which"},
            {"type", "nominal"},
            {"sort", {"F0", "F82"}},
            {"title", nullptr},
            {"axis", {{"orient", "top"}}}}},
          {"y", {{"field", "material"}, {"type", "nominal"}, {"sort", nullptr}, {"title", nullptr}}},
          {"color", {{"field", "color"}, {"type", "nominal"}, {"scale", nullptr}}},
          {"tooltip", tooltip({{"material", "nominal"}, {"which", "nominal"}, {"color", "nominal"}})}}}};
    if (with_costs)
        charts["pareto"] = {
            {"title", "error vs cost: median worst-channel rel_rms over the materials; the front joined"},
            {"width", 460},
            {"height", 280},
            {"layer",
             {{{"data", data("pareto_front")},
               {"mark", {{"type", "line"}, {"color", "#c33"}}},
               {"encoding",
                {{"x", {{"field", "cost"}, {"type", "quantitative"}, {"title", "cost"}}},
                 {"y", {{"field", "median"}, {"type", "quantitative"}, {"scale", {{"type", "log"}}}}}}}},
              {{"data", data("pareto")},
               {"mark", {{"type", "point"}, {"filled", true}, {"size", 70}}},
               {"encoding",
                {{"x", {{"field", "cost"}, {"type", "quantitative"}, {"title", "cost"}}},
                 {"y",
                  {{"field", "median"},
                   {"type", "quantitative"},
                   {"scale", {{"type", "log"}}},
                   {"title", "median worst-channel rel_rms"},
                   {"axis", {{"format", ".1%"}}}}},
                 {"color", {{"field", "on_front"}, {"type", "nominal"}, {"title", "Pareto front"}}},
                 {"tooltip", tooltip({{"model", "nominal"}, {"cost", "quantitative"}, {"median", "quantitative"}})}}}},
              {{"data", data("pareto")},
               {"mark", {{"type", "text"}, {"dx", 8}, {"align", "left"}}},
               {"encoding",
                {{"x", {{"field", "cost"}, {"type", "quantitative"}}},
                 {"y", {{"field", "median"}, {"type", "quantitative"}, {"scale", {{"type", "log"}}}}},
                 {"text", {{"field", "model"}}}}}}}}};
    return charts;
}

}  // namespace

Json chart_specs(bool with_costs) { return {{"catalog", catalog_charts(with_costs)}, {"material", material_charts()}}; }

}  // namespace metalfit::report_detail
