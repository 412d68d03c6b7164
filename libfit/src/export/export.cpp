// The export core: parameter choice, gamut policy, re-evaluated metrics, the shared comment header, and writing a set
// of files as one unit. The formats live in export_<format>.cpp.
#include "libfit/export/export.hpp"

#include "libfit/color/ocio_config_contents.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include "export/export_formats.hpp"
#include "export/header_provenance.hpp"
#include "libfit/base/atomic_file.hpp"
#include "libfit/base/staged_folder.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/names.hpp"
#include "libfit/base/version.hpp"
#include "libfit/color/ocio_config_contents.hpp"
#include "libfit/models/registry.hpp"

namespace metalfit {

namespace {

constexpr std::array<ExportFormat, 7> kFormats{ExportFormat::json, ExportFormat::glsl, ExportFormat::hlsl,
                                               ExportFormat::mtlx, ExportFormat::openpbr, ExportFormat::cpp,
                                               ExportFormat::gltf};

std::string figure(double v) {
    if (std::isnan(v)) return "undefined";
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}

std::string figures(const PerChannel& v) { return figure(v[0]) + ", " + figure(v[1]) + ", " + figure(v[2]); }

// Applies the gamut policy to the colour parameters; returns one note per parameter that was outside [0, 1].
std::vector<std::string> apply_gamut(const Model& model, ModelParameters& params, GamutPolicy policy) {
    std::vector<std::string> notes;
    const auto parameters = model.parameters();
    for (std::size_t i = 0; i < parameters.size(); ++i) {
        if (parameters[i].kind != ParameterKind::colour) continue;  // the gamut policy applies to colours only
        const std::string name(parameters[i].name);
        const RGB colour = params.parameter(i);
        std::string outside;
        double max = 0;
        for (int c = 0; c < 3; ++c) {
            const double v = colour[c];
            max = std::max(max, v);
            if (v > 1.0 || v < 0.0) outside += (outside.empty() ? "" : ", ") + std::string(kChannelNames[c]) + " " + detail::number(v);
        }
        if (outside.empty()) continue;
        switch (policy) {
            case GamutPolicy::keep:
                notes.push_back(name + " outside [0, 1] (" + outside + "): kept");
                break;
            case GamutPolicy::clip:
                params.set_parameter(i, {std::clamp(colour.r, 0.0, 1.0), std::clamp(colour.g, 0.0, 1.0), std::clamp(colour.b, 0.0, 1.0)});
                notes.push_back(name + " outside [0, 1] (" + outside + "): clipped to [0, 1]");
                break;
            case GamutPolicy::scale:
                for (int c = 0; c < 3; ++c) params[c][i] = std::max(0.0, max > 1.0 ? colour[c] / max : colour[c]);
                notes.push_back(name + " outside [0, 1] (" + outside + "): " +
                                (max > 1.0 ? "scaled by 1/" + detail::number(max) : std::string("negative values set to 0")));
                break;
        }
    }
    return notes;
}

}  // namespace

std::string to_string(ExportFormat format) {
    switch (format) {
        case ExportFormat::json: return "json";
        case ExportFormat::glsl: return "glsl";
        case ExportFormat::hlsl: return "hlsl";
        case ExportFormat::mtlx: return "mtlx";
        case ExportFormat::openpbr: return "openpbr";
        case ExportFormat::cpp: return "cpp";
        case ExportFormat::gltf: return "gltf";
    }
    return "?";
}

std::vector<ExportFormat> parse_export_formats(std::string_view list) {
    if (list == "all") return {kFormats.begin(), kFormats.end()};
    std::vector<ExportFormat> formats;
    while (!list.empty()) {
        const auto comma = list.find(',');
        const std::string_view name = list.substr(0, comma);
        const auto it = std::find_if(kFormats.begin(), kFormats.end(), [&](ExportFormat f) { return to_string(f) == name; });
        if (it == kFormats.end())
            throw UsageError("unknown export format '" + std::string(name) + "' (known: json, glsl, hlsl, mtlx, openpbr, cpp, gltf, or all)");
        if (std::find(formats.begin(), formats.end(), *it) == formats.end()) formats.push_back(*it);
        list = comma == std::string_view::npos ? std::string_view{} : list.substr(comma + 1);
    }
    if (formats.empty()) throw UsageError("empty export format list (known: json, glsl, hlsl, mtlx, openpbr, cpp, gltf, or all)");
    return formats;
}

ParameterSource parse_parameter_source(const std::string& text) {
    if (text == "fit") return ParameterSource::fit;
    if (text == "closed") return ParameterSource::closed;
    throw UsageError("unknown parameter source '" + text + "' (fit or closed)");
}

GamutPolicy parse_gamut_policy(const std::string& text) {
    if (text == "keep") return GamutPolicy::keep;
    if (text == "clip") return GamutPolicy::clip;
    if (text == "scale") return GamutPolicy::scale;
    throw UsageError("unknown gamut policy '" + text + "' (keep, clip or scale)");
}

std::string to_string(GamutPolicy policy) {
    switch (policy) {
        case GamutPolicy::keep: return "keep";
        case GamutPolicy::clip: return "clip";
        case GamutPolicy::scale: return "scale";
    }
    return "?";
}

WrittenParameters written_parameters(const ModelResult& result, const SampledReference& reference,
                                     ParameterSource source, GamutPolicy gamut, const std::string& material_id) {
    const Model& model = *result.model;
    WrittenParameters w;
    w.model = &model;
    if (source == ParameterSource::fit) {
        w.origin = "fit";
        w.params = result.fit.value.params;
    } else {
        if (!result.best_closed) {
            std::string reasons;
            for (const ClosedFormResult& form : result.closed_forms)
                reasons += (reasons.empty() ? "" : "; ") + form.id + ": " + form.undefined;
            throw UsageError(material_id + ": " + std::string(model.id()) + ": no closed form is defined (" + reasons +
                             "); export the fitted parameters instead");
        }
        const ClosedFormResult& best = result.closed_forms[*result.best_closed];
        w.origin = "closed " + best.id;
        w.params = best.value->params;
    }
    w.gamut = apply_gamut(model, w.params, gamut);
    w.metrics = compute_metrics(model, w.params, reference);
    return w;
}

const Model& expressible_stand_in() { return model_of<StandInModel>(); }

std::vector<const Model*> models_to_fit(const ExportRequest& request) {
    std::vector<const Model*> models = request.models;
    const auto wants = [&](ExportFormat f) {
        return std::find(request.formats.begin(), request.formats.end(), f) != request.formats.end();
    };
    bool needs_stand_in = false;
    for (const Model* m : request.models) {
        if (wants(ExportFormat::openpbr) && !m->is_f82_tint_curve()) needs_stand_in = true;
        if (wants(ExportFormat::mtlx) && m->materialx_form() == MaterialxForm::stand_in) needs_stand_in = true;
    }
    const Model* stand_in = &expressible_stand_in();
    if (needs_stand_in && std::find(models.begin(), models.end(), stand_in) == models.end()) models.push_back(stand_in);
    return models;
}

namespace detail {

std::string file_stem(std::string_view id_prefix, const std::string& material_id, std::string_view model_id) {
    std::string s = std::string(id_prefix) + "_" + material_id + "_" + std::string(model_id);
    for (char& ch : s) ch = std::isalnum(static_cast<unsigned char>(ch)) ? static_cast<char>(std::tolower(static_cast<unsigned char>(ch))) : '_';
    return s;
}

std::string constant_stem(std::string_view id_prefix, const std::string& material_id, std::string_view model_id) {
    std::string s = file_stem(id_prefix, material_id, model_id);
    for (char& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    return s;
}

std::string cpp_index_name(std::string_view id_prefix) { return std::string(id_prefix) + "_materials"; }
std::string cpp_index_path(std::string_view id_prefix) { return "cpp/" + cpp_index_name(id_prefix) + ".hpp"; }

std::string number(double v) {
    char text[40];
    const auto end = std::to_chars(text, text + sizeof text, v).ptr;  // shortest text that reads back as v
    std::string s(text, end);
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
    return s;
}

std::string shader_number(double v) {
    char text[40];
    const float f = static_cast<float>(v);
    const auto end = std::to_chars(text, text + sizeof text, f).ptr;  // shortest text that reads back as f (<= 9 digits)
    std::string s(text, end);
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
    return s;
}

std::string half_precision_note(const WrittenParameters& written, std::string_view prefix) {
    // Half precision (binary16, mediump on most GPUs) holds |x| <= 65504 with an 11-bit significand. What the model
    // functions compute beyond their constants: n, k (ParameterKind::index) are squared (k², 4n²k²); Gulbrandsen's
    // r, g become n, k through 1 / (1 − √r) and 1 / (1 − r), infinite once r rounds to 1.
    constexpr double kHalfMax = 65504.0, kHalfEpsilon = 1.0 / 2048.0;
    const auto short_number = [](double v) {
        char text[32];
        std::snprintf(text, sizeof text, "%.6g", v);
        return std::string(text);
    };
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
            const std::string which = std::string(parameters[i].name) + " " + kChannelNames[c] + " = " + short_number(v[c]);
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
                unsafe(std::string("k² or 4n²k² of ") + kChannelNames[c] + " reaches " + short_number(squares) + ", beyond 65504");
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

std::string channel_list(const ModelParameters& params, std::size_t index) {
    const RGB v = params.parameter(index);
    return number(v.r) + ", " + number(v.g) + ", " + number(v.b);
}

std::string shader_channel_list(const ModelParameters& params, std::size_t index) {
    const RGB v = params.parameter(index);
    return shader_number(v.r) + ", " + shader_number(v.g) + ", " + shader_number(v.b);
}

std::string comment_header(const MaterialExport& material, const WrittenParameters& written,
                           const ExportContext& context, std::string_view prefix, std::string_view extra) {
    const Material& m = material.fit->material;
    const FitRecordContext& r = context.record;
    const Metrics& e = written.metrics;
    std::ostringstream s;
    // Every line as data (names, file names and references come from inputs): no line break, control or
    // direction-changing character, no backslash that would continue a line comment (libfit/base/names.hpp).
    const auto line = [&](const std::string& text) { s << prefix << comment_text(text) << "\n"; };
    line("metalfit " METALFIT_VERSION " export: " + m.name + " (" + m.id + ")");
    for (const std::string& provenance : header_provenance_lines(m, r)) line(provenance);
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
    line("error of these parameters against R_c (R, G, B; " + std::to_string(r.error.nodes) +
         " Gauss-Legendre nodes on [0, 1], " + to_string(r.error.weight) + " weight; maxima over mu = i/1024 and the nodes):");
    line("  rel_rms     = " + figures(e.rel_rms));
    line("  abs_rms     = " + figures(e.abs_rms));
    line("  max_rel     = " + figures(e.max_rel));
    line("  max_abs     = " + figures(e.max_abs));
    line("  albedo_err  = " + figures(e.albedo_err));
    line("  de2000_mean = " + figure(e.de2000_mean));
    line("  de2000_max  = " + figure(e.de2000_max));
    return s.str();
}

std::optional<WrittenParameters> as_f82_tint(const WrittenParameters& written, const SampledReference& reference) {
    const Model& model = *written.model;
    if (&model == &expressible_stand_in()) return written;
    if (!model.is_f82_tint_curve()) return std::nullopt;
    WrittenParameters w = written;
    w.model = &expressible_stand_in();
    bool tint_one = true;
    for (int c = 0; c < 3; ++c) {
        w.params[c] = *model.f82_tint_of(written.params[c]);
        tint_one = tint_one && w.params[c][1] == 1.0;
    }
    w.origin = written.origin + " of " + std::string(model.id()) + ", written as " + std::string(w.model->id()) +
               (tint_one ? " with tint 1" : "") + " (the same curve)";
    w.metrics = compute_metrics(*w.model, w.params, reference);
    return w;
}

std::string untagged_materialx_warning(const std::string& ocio_space) {
    return "WARNING: colours are in " + ocio_space +
           ", for which MaterialX has no colour-space name: the document carries no colorspace and consumers read its "
           "colours as their working space (export in Linear Rec.709, ACEScg, Linear P3-D65 or Linear AdobeRGB for a "
           "tagged document)";
}

}  // namespace detail

std::string parse_id_prefix(const std::string& text) {
    // Keywords and reserved words of C++20, GLSL 4.60 / ES 3.00 and HLSL (Shader Model 6) that match the pattern.
    static const std::set<std::string_view> reserved{
        "alignas", "alignof", "and", "and_eq", "asm", "auto", "bitand", "bitor", "bool", "break", "case", "catch",
        "char", "char8_t", "char16_t", "char32_t", "class", "compl", "concept", "const", "consteval", "constexpr",
        "constinit", "const_cast", "continue", "co_await", "co_return", "co_yield", "decltype", "default", "delete",
        "do", "double", "dynamic_cast", "else", "enum", "explicit", "export", "extern", "false", "float", "for",
        "friend", "goto", "if", "inline", "int", "long", "mutable", "namespace", "new", "noexcept", "not", "not_eq",
        "nullptr", "operator", "or", "or_eq", "private", "protected", "public", "register", "reinterpret_cast",
        "requires", "return", "short", "signed", "sizeof", "static", "static_assert", "static_cast", "struct",
        "switch", "template", "this", "thread_local", "throw", "true", "try", "typedef", "typeid", "typename",
        "union", "unsigned", "using", "virtual", "void", "volatile", "wchar_t", "while", "xor", "xor_eq",
        // GLSL
        "attribute", "uniform", "varying", "buffer", "shared", "coherent", "restrict", "readonly", "writeonly",
        "layout", "centroid", "flat", "smooth", "noperspective", "patch", "sample", "subroutine", "in", "out",
        "inout", "invariant", "precise", "discard", "uint", "lowp", "mediump", "highp", "precision", "vec2", "vec3",
        "vec4", "ivec2", "ivec3", "ivec4", "uvec2", "uvec3", "uvec4", "bvec2", "bvec3", "bvec4", "dvec2", "dvec3",
        "dvec4", "mat2", "mat3", "mat4", "common", "partition", "active", "filter", "input", "output",
        "superp", "fixed", "half", "hvec2", "hvec3", "hvec4", "fvec2", "fvec3", "fvec4", "cast", "interface",
        "noinline", "external", "resource",
        // HLSL
        "bool2", "bool3", "bool4", "cbuffer", "tbuffer", "column_major", "row_major", "compile",
        "dword", "float2", "float3", "float4", "groupshared", "half2", "half3", "half4", "int2", "int3", "int4",
        "line", "lineadj", "linear", "matrix", "nointerpolation", "packoffset", "pass", "pixelfragment", "point",
        "sampler", "sampler_state", "snorm", "stateblock", "technique", "texture", "triangle", "triangleadj",
        "unorm", "vector", "vertexfragment", "min16float", "min10float", "min16int", "min12int",
        "min16uint", "uint2", "uint3", "uint4"};
    const auto fail = [&](const std::string& why) -> std::string {
        throw UsageError("--id-prefix '" + text + "': " + why);
    };
    if (text.empty() || text.size() > 31 || !(text[0] >= 'a' && text[0] <= 'z') ||
        !std::all_of(text.begin(), text.end(), [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'; }))
        return fail("expected [a-z][a-z0-9_]{0,30} (a lower-case letter, then up to 30 letters, digits or '_')");
    if (text.find("__") != std::string::npos || text.back() == '_')
        return fail("the identifiers would hold \"__\", which C++ and GLSL reserve");
    if (text == "gl") return fail("GLSL reserves identifiers starting with gl_");
    if (reserved.contains(text)) return fail("a C++, GLSL or HLSL keyword");
    return text;
}

double parse_roughness(const std::string& text) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{} || end != text.data() + text.size() || !(value >= 0.0 && value <= 1.0))
        throw UsageError("--roughness '" + text + "': expected a number in [0, 1] (OpenPBR's specular_roughness)");
    return value;
}

std::string materialx_colorspace(const OcioConfigChoice& config, const std::string& ocio_space) {
    // MaterialX 1.39's linear colour spaces, each with the names OCIO configs (the builtin studio and CG configs,
    // ACES 1.x, metalfit's own) give the same space or list as aliases.
    static const std::vector<std::pair<std::string, std::vector<std::string>>> known{
        {"lin_rec709", {"lin_rec709", "Linear Rec.709 (sRGB)", "Linear Rec.709", "lin_srgb", "lin_rec709_srgb",
                        "Utility - Linear - sRGB", "Utility - Linear - Rec.709", "scene-linear Rec.709-sRGB"}},
        {"acescg", {"acescg", "lin_ap1", "ACES - ACEScg", "lin_ap1_scene"}},
        {"lin_displayp3", {"lin_displayp3", "Linear P3-D65", "lin_p3d65", "Utility - Linear - P3-D65"}},
        {"lin_adobergb", {"lin_adobergb", "Linear AdobeRGB", "Linear Adobe RGB (1998)"}},
    };
    std::vector<std::string> names{ocio_space};
    try {
        for (const OcioColorSpaceEntry& s : read_ocio_config_contents(config).spaces)
            if (s.name == ocio_space) names.insert(names.end(), s.aliases.begin(), s.aliases.end());
    } catch (const ColorConfigError&) {
        // The config was read to fit; if it cannot be read now, match by the space's name alone.
    }
    const auto same = [](const std::string& a, const std::string& b) {
        return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
                   return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
               });
    };
    for (const auto& [materialx_name, spellings] : known)
        for (const std::string& name : names)
            for (const std::string& spelling : spellings)
                if (same(name, spelling)) return materialx_name;
    return {};
}

std::vector<std::string> export_warnings(const FitRecordContext& context, const ExportRequest& request,
                                         const std::string& materialx_space) {
    std::vector<std::string> warnings;
    const bool materialx = std::any_of(request.formats.begin(), request.formats.end(), [](ExportFormat f) {
        return f == ExportFormat::mtlx || f == ExportFormat::openpbr;
    });
    if (materialx && materialx_space.empty())
        warnings.push_back(detail::untagged_materialx_warning(context.space));
    return warnings;
}

namespace detail {
}  // namespace detail

std::vector<ExportFile> export_files(const std::vector<MaterialFit>& fits, const FitRecordContext& context,
                                     const ExportRequest& request, const std::string& materialx_space) {
    using detail::ModelExport;
    require_export_space(request, context.space, materialx_space);
    const Model& stand_in_model = expressible_stand_in();
    std::vector<detail::MaterialExport> materials;
    for (const MaterialFit& fit : fits) {
        if (!fit.reference) throw std::logic_error("export: fit of " + fit.material.id + " has no sampled reference");
        detail::MaterialExport m{&fit, {}};
        const auto result_of = [&](const Model* model) -> const ModelResult& {
            for (const ModelResult& r : fit.models)
                if (r.model == model) return r;
            throw std::logic_error("export: " + fit.material.id + " was not fitted with " + std::string(model->id()));
        };
        const auto needed = models_to_fit(request);
        const bool has_stand_in = std::find(needed.begin(), needed.end(), &stand_in_model) != needed.end();
        std::optional<WrittenParameters> stand_in;
        if (has_stand_in)
            stand_in = written_parameters(result_of(&stand_in_model), *fit.reference, request.source, request.gamut,
                                          fit.material.id);
        for (const Model* model : request.models) {
            ModelExport e{written_parameters(result_of(model), *fit.reference, request.source, request.gamut, fit.material.id),
                          std::nullopt};
            if (!detail::as_f82_tint(e.written, *fit.reference)) e.stand_in = stand_in;
            m.models.push_back(std::move(e));
        }
        materials.push_back(std::move(m));
    }
    const detail::ExportContext ctx{context, request, materialx_space};
    std::vector<ExportFile> files;
    for (ExportFormat format : request.formats) {
        std::vector<ExportFile> more;
        switch (format) {
            case ExportFormat::json: more = detail::export_json(materials, ctx); break;
            case ExportFormat::glsl: more = detail::export_glsl(materials, ctx); break;
            case ExportFormat::hlsl: more = detail::export_hlsl(materials, ctx); break;
            case ExportFormat::mtlx: more = detail::export_mtlx(materials, ctx); break;
            case ExportFormat::openpbr: more = detail::export_openpbr(materials, ctx); break;
            case ExportFormat::cpp: more = detail::export_cpp(materials, ctx); break;
            case ExportFormat::gltf: more = detail::export_gltf(materials, ctx); break;
        }
        for (ExportFile& f : more) files.push_back(std::move(f));
    }
    std::set<std::filesystem::path> seen;
    for (const ExportFile& f : files)
        if (!seen.insert(f.path).second)
            throw UsageError("export: two materials would write the same file " + f.path.string() +
                             " (their ids differ only in punctuation or case)");
    return files;
}

namespace {

// The registered models whose functions a shared model file defines ("vec3 metalfit_schlick(", "float3 …").
std::vector<const Model*> models_defined_in(std::string_view text) {
    std::vector<const Model*> models;
    for (const Model* m : all_models()) {
        const std::string name = std::string(m->glsl_function()) + "(";
        if (text.find("vec3 " + name) != std::string_view::npos || text.find("float3 " + name) != std::string_view::npos)
            models.push_back(m);
    }
    return models;
}

// The index files of a second export into a folder: merged with what is there, so that no entry is lost.
std::string merge_index(const std::filesystem::path& dir, const std::filesystem::path& relative, const std::string& existing,
                        const std::string& mine) {
    const std::string name = relative.generic_string();
    try {
        if (name == "metalfit_export.json") return detail::merge_json_record(existing, mine);
        if (name.starts_with("cpp/") && name.ends_with("_materials.hpp")) {  // cpp_index_path of the export's prefix
            const std::string prefix = name.substr(4, name.size() - 4 - std::string_view("_materials.hpp").size());
            std::vector<detail::CppIndexEntry> entries = detail::parse_cpp_materials_index(existing);
            for (const detail::CppIndexEntry& e : detail::parse_cpp_materials_index(mine)) {
                const auto same = std::find_if(entries.begin(), entries.end(),
                                               [&](const detail::CppIndexEntry& x) { return x.include == e.include; });
                if (same != entries.end()) *same = e;
                else entries.push_back(e);
            }
            return detail::cpp_materials_index(entries, prefix);
        }
        if (name == "glsl/metalfit_models.glsl" || name == "hlsl/metalfit_models.hlsl" || name == "cpp/metalfit_models.hpp") {
            std::vector<const Model*> models = models_defined_in(existing);
            const std::vector<const Model*> now = models_defined_in(mine);
            if (std::all_of(models.begin(), models.end(), [&](const Model* m) {
                    return std::find(now.begin(), now.end(), m) != now.end();
                }))
                return mine;
            std::vector<const Model*> all;  // registry order
            for (const Model* m : all_models())
                if (std::find(models.begin(), models.end(), m) != models.end() || std::find(now.begin(), now.end(), m) != now.end())
                    all.push_back(m);
            if (name.starts_with("glsl/")) return detail::glsl_models_file(all);
            if (name.starts_with("hlsl/")) return detail::hlsl_models_file(all);
            return detail::cpp_models_file(all);
        }
    } catch (const std::invalid_argument& e) {
        throw InputError({dir / relative}, std::string("cannot add this export to the folder: ") + e.what() +
                                               "; export into another folder or remove this one");
    }
    return mine;
}

}  // namespace

void write_export(const std::filesystem::path& dir, const std::vector<ExportFile>& files) {
    std::vector<OutputFile> outputs;
    outputs.reserve(files.size());
    for (const ExportFile& f : files) outputs.push_back({f.path, f.contents});
    update_folder_as_unit(dir, outputs, [&](const std::filesystem::path& relative, const std::string& existing, const std::string& mine) {
        return merge_index(dir, relative, existing, mine);
    });
}

}  // namespace metalfit
