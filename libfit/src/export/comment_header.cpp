// The comment header every text export starts with (material, provenance, model, parameters, error figures), and
// the half-precision note of the shader exports.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "export/export_formats.hpp"
#include "export/header_provenance.hpp"
#include "libfit/base/names.hpp"
#include "libfit/base/number_text.hpp"
#include "libfit/base/version.hpp"

namespace metalfit::detail {

namespace {

std::string figure(double v) { return std::isnan(v) ? "undefined" : significant_text(v, 6); }

std::string figures(const PerChannel& v) { return figure(v[0]) + ", " + figure(v[1]) + ", " + figure(v[2]); }

}  // namespace

std::string half_precision_note(const WrittenParameters& written, std::string_view prefix) {
    // Half precision (binary16, mediump on most GPUs) holds |x| <= 65504 with an 11-bit significand. What the model
    // functions compute beyond their constants: n, k (ParameterKind::index) are squared (k², 4n²k²); Gulbrandsen's
    // r, g become n, k through 1 / (1 − √r) and 1 / (1 − r), infinite once r rounds to 1.
    constexpr double kHalfMax = 65504.0, kHalfEpsilon = 1.0 / 2048.0;
    const auto short_number = [](double v) { return significant_text(v, 6); };
    const auto parameters = written.model->parameters();
    std::vector<std::string> bounds;
    std::string verdict;
    const auto unsafe = [&](const std::string& why) {
        if (verdict.empty()) verdict = "NOT safe: " + why + "; use highp";
    };
    std::vector<std::size_t> index;
    for (std::size_t i = 0; i < parameters.size(); ++i) {
        if (parameters[i].kind == ParameterKind::index) index.push_back(i);
        const RGB v = written.params.parameter(i);
        for (int c = 0; c < 3; ++c) {
            const std::string which =
                std::string(parameters[i].name) + " " + kChannelNames[c] + " = " + short_number(v[c]);
            if (std::abs(v[c]) > kHalfMax) unsafe(which + " is beyond 65504");
            if (parameters[i].upper > parameters[i].lower && v[c] >= parameters[i].upper * (1.0 - 1e-9))
                bounds.push_back(which + " is the fit's upper bound (the fit runs it there to come close to F0 > 1)");
            if (parameters[i].upper > parameters[i].lower && v[c] <= parameters[i].lower * (1.0 + 1e-9))
                bounds.push_back(which + " is the fit's lower bound");
        }
    }
    for (int c = 0; c < 3; ++c) {
        if (index.size() == 2) {
            const double n = written.params[c][index[0]], k = written.params[c][index[1]];
            const double squares = std::max(k * k, 4.0 * n * n * k * k);
            if (squares > kHalfMax)
                unsafe(std::string("k² or 4n²k² of ") + kChannelNames[c] + " reaches " + short_number(squares) +
                       ", beyond 65504");
        }
        if (written.model->materialx_form() == MaterialxForm::artistic_ior && 1.0 - written.params[c][0] < kHalfEpsilon)
            unsafe(std::string("r ") + kChannelNames[c] + " = " + short_number(written.params[c][0]) +
                   " rounds to 1 in half, and 1 / (1 - r) is infinite");
    }
    if (verdict.empty())
        verdict = "in range (constants and intermediates below 65504), but half's 11-bit significand (4.9e-4 relative) "
                  "adds to the errors above";
    std::string text = std::string(prefix) + "half precision (16-bit float, mediump): " + verdict + "\n";
    for (const std::string& b : bounds) text += std::string(prefix) + "  " + b + "\n";
    return text;
}

std::vector<ColourOutOfRange> colours_out_of_range(const MaterialExport& material, const WrittenParameters& written,
                                                   std::string_view model, std::span<const std::string_view> names) {
    std::vector<ColourOutOfRange> out;
    const auto parameters = written.model->parameters();
    for (std::size_t i = 0; i < parameters.size(); ++i) {
        if (parameters[i].kind != ParameterKind::colour) continue;
        const RGB v = written.params.parameter(i);
        for (int c = 0; c < 3; ++c)
            if (!(v[c] >= 0.0 && v[c] <= 1.0))
                out.push_back({material.fit->material.id, std::string(model),
                               std::string(i < names.size() ? names[i] : parameters[i].name), c, v[c]});
    }
    return out;
}

std::string comment_header(const MaterialExport& material, const WrittenParameters& written,
                           const ExportContext& context, std::string_view prefix, std::string_view extra,
                           bool base_of_layers) {
    const Material& m = material.fit->material;
    const FitRecordContext& r = context.record;
    const Metrics& e = written.metrics;
    std::ostringstream s;
    // Every line as data (names, file names and references come from inputs): no line break, control or
    // direction-changing character, no backslash that would continue a line comment (libfit/base/names.hpp).
    const auto line = [&](const std::string& text) { s << prefix << comment_text(text) << "\n"; };
    line("metalfit " METALFIT_VERSION " export: " + m.name + " (" + m.id + ")");
    for (const std::string& provenance : header_provenance_lines(m, r, base_of_layers)) line(provenance);
    line("model: " + std::string(written.model->id()) + " - " + std::string(written.model->title()));
    if (!extra.empty()) {
        std::string_view rest = extra;
        while (!rest.empty()) {
            const auto nl = rest.find('\n');
            line(std::string(rest.substr(0, nl)));
            rest = nl == std::string_view::npos ? std::string_view{} : rest.substr(nl + 1);
        }
    }
    line("parameters: " + written.origin + "; gamut policy: " + to_string(context.request.gamut));
    for (const std::string& note : written.gamut) line("OUT OF GAMUT: " + note);
    for (const ColourOutOfRange& o : colours_out_of_range(material, written, written.model->id()))
        line("OUT OF RANGE: " + o.parameter + " " + kChannelNames[o.channel] + " = " + number(o.value) +
             " outside [0, 1], written as it is (a consumer may clip it; --gamut clip or scale, or --gamut-fit)");
    line(std::string("error of these parameters against ") + (base_of_layers ? "the bare metal's " : "") +
         "R_c (R, G, B; " + std::to_string(r.error.nodes) + " Gauss-Legendre nodes on [0, 1], " +
         to_string(r.error.weight) + " weight; maxima over mu = i/1024 and the nodes):");
    line("  rel_rms     = " + figures(e.rel_rms));
    line("  abs_rms     = " + figures(e.abs_rms));
    line("  max_rel     = " + figures(e.max_rel));
    line("  max_abs     = " + figures(e.max_abs));
    line("  albedo_err  = " + figures(e.albedo_err));
    line("  de2000_mean = " + figure(e.de2000_mean));
    line("  de2000_max  = " + figure(e.de2000_max));
    return s.str();
}

}  // namespace metalfit::detail
