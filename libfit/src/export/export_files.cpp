// The export core: the fits of a request become the written parameters of each material and model, and each
// requested format (format_registry) writes its files from them.
#include <algorithm>
#include <functional>
#include <memory>
#include <set>
#include <stdexcept>

#include "export/export_formats.hpp"
#include "export/format_registry.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/export/consumer_curve.hpp"

namespace metalfit {

std::vector<const Model*> models_to_fit(const ExportRequest& request) {
    std::vector<const Model*> models = request.models;
    bool needs_stand_in = false;
    for (const Model* m : request.models)
        for (ExportFormat format : request.formats)
            needs_stand_in = needs_stand_in || detail::needs_stand_in(detail::format_entry(format), *m);
    const Model* stand_in = &expressible_stand_in();
    if (needs_stand_in && std::find(models.begin(), models.end(), stand_in) == models.end()) models.push_back(stand_in);
    return models;
}

std::vector<std::string> export_warnings(const FitRecordContext& context, const ExportRequest& request,
                                         const std::string& materialx_space) {
    std::vector<std::string> warnings;
    const bool materialx = std::any_of(request.formats.begin(), request.formats.end(),
                                       [](ExportFormat f) { return detail::format_entry(f).materialx_document; });
    if (materialx && materialx_space.empty()) warnings.push_back(detail::untagged_materialx_warning(context.space));
    return warnings;
}

namespace {

// The requested formats that cannot carry the export's colour space (glTF outside linear Rec.709).
std::vector<ExportFormat> formats_outside_their_space(const std::vector<ExportFormat>& formats,
                                                      const std::string& materialx_space) {
    std::vector<ExportFormat> outside;
    for (ExportFormat f : formats)
        if (detail::format_entry(f).linear_rec709_only && materialx_space != "lin_rec709") outside.push_back(f);
    return outside;
}

}  // namespace

void require_export_space(const ExportRequest& request, const std::string& space, const std::string& materialx_space) {
    if (formats_outside_their_space(request.formats, materialx_space).empty()) return;
    std::string others;
    for (const detail::ExportFormatEntry& f : detail::export_format_entries())
        if (!f.linear_rec709_only) others += (others.empty() ? "" : ",") + to_string(f.format);
    throw UsageError(
        "export --format gltf: glTF 2.0's colours are linear Rec.709 (sRGB primaries) and a .gltf cannot name another "
        "space, but this export is in '" +
        space +
        "'; export glTF with --space 'Linear Rec.709 (sRGB)' (the default), "
        "or list the other formats (" +
        others + ") instead of all");
}

std::string leave_out_formats_the_space_cannot_carry(ExportRequest& request, const std::string& space,
                                                     const std::string& materialx_space) {
    const std::vector<ExportFormat> outside = formats_outside_their_space(request.formats, materialx_space);
    if (outside.empty()) return {};
    std::erase_if(request.formats,
                  [&](ExportFormat f) { return std::find(outside.begin(), outside.end(), f) != outside.end(); });
    return "--format all: glTF left out: glTF 2.0's colours are linear Rec.709 and a .gltf cannot name '" + space +
           "' (export it with --space 'Linear Rec.709 (sRGB)')";
}

bool needs_bare_metal_fits(const ExportRequest& request) {
    return std::any_of(request.formats.begin(), request.formats.end(),
                       [](ExportFormat f) { return detail::format_entry(f).layers_over_bare_metal; });
}

void attach_bare_metal_fits(std::vector<MaterialFit>& fits, const BatchColour& colour,
                            const MaterialFitRequest& request, int jobs) {
    std::vector<std::size_t> layered;
    std::vector<std::function<Material()>> loaders;
    for (std::size_t i = 0; i < fits.size(); ++i)
        if (fits[i].material.layers && !fits[i].material.layers->empty()) {
            layered.push_back(i);
            loaders.push_back([material = fits[i].material]() mutable {
                material.layers = nullptr;
                return material;
            });
        }
    if (loaders.empty()) return;
    std::vector<MaterialFit> bare = fit_materials(loaders, colour, request, jobs);
    for (std::size_t j = 0; j < layered.size(); ++j)
        fits[layered[j]].bare_metal = std::make_shared<const MaterialFit>(std::move(bare[j]));
}

detail::MaterialExport detail::material_export(const MaterialFit& fit, const ExportRequest& request) {
    using detail::ModelExport;
    const Model& stand_in_model = expressible_stand_in();
    if (!fit.reference) throw std::logic_error("export: fit of " + fit.material.id + " has no sampled reference");
    detail::MaterialExport m{&fit, {}, nullptr};
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
        ModelExport e{
            written_parameters(result_of(model), *fit.reference, request.source, request.gamut, fit.material.id),
            std::nullopt};
        if (!detail::as_f82_tint(e.written, *fit.reference)) e.stand_in = stand_in;
        m.models.push_back(std::move(e));
    }
    return m;
}

std::vector<std::string> out_of_range_lines(const std::vector<ExportFile>& files) {
    std::vector<std::string> lines;
    for (const ExportFile& f : files)
        for (const ColourOutOfRange& o : f.out_of_range)
            lines.push_back("export: " + f.path.generic_string() + ": " + o.parameter + " " + kChannelNames[o.channel] +
                            " = " + detail::number(o.value) + " outside [0, 1] (" + o.material + ", " + o.model +
                            "; a consumer may clip it: --gamut clip|scale or --gamut-fit)");
    return lines;
}

std::vector<std::vector<ExportFile>> detail::export_files_by_format(const std::vector<MaterialFit>& fits,
                                                                    const FitRecordContext& context,
                                                                    const ExportRequest& request,
                                                                    const std::string& materialx_space) {
    require_export_space(request, context.space, materialx_space);
    std::vector<detail::MaterialExport> materials;
    for (const MaterialFit& fit : fits) {
        detail::MaterialExport m = detail::material_export(fit, request);
        if (fit.material.layers && !fit.material.layers->empty() && needs_bare_metal_fits(request)) {
            if (!fit.bare_metal)
                throw std::logic_error("export: layered " + fit.material.id +
                                       " has no bare-metal fit (attach_bare_metal_fits)");
            m.bare_metal =
                std::make_shared<const detail::MaterialExport>(detail::material_export(*fit.bare_metal, request));
        }
        materials.push_back(std::move(m));
    }
    const detail::ExportContext ctx{context, request, materialx_space};
    std::vector<std::vector<ExportFile>> by_format;
    for (ExportFormat format : request.formats) by_format.push_back(detail::format_entry(format).write(materials, ctx));
    // Every colour written outside [0, 1], by any format: in the export record, per material and model, each with the
    // file that writes it (the header of each text file says the same; out_of_range_lines gives stderr's lines).
    ExportFile* record = nullptr;
    for (std::vector<ExportFile>& files : by_format)
        for (ExportFile& f : files)
            if (f.path == "metalfit_export.json") record = &f;
    if (record) {
        nlohmann::ordered_json j = nlohmann::ordered_json::parse(record->contents);
        for (const MaterialFit& fit : fits)
            for (const Model* model : request.models) {
                nlohmann::ordered_json list = nlohmann::ordered_json::array();
                for (const std::vector<ExportFile>& files : by_format)
                    for (const ExportFile& f : files)
                        for (const ColourOutOfRange& o : f.out_of_range)
                            if (o.material == fit.material.id && o.model == model->id())
                                list.push_back({{"file", f.path.generic_string()},
                                                {"parameter", o.parameter},
                                                {"channel", kChannelNames[o.channel]},
                                                {"value", o.value}});
                j["materials"][fit.material.id]["models"][std::string(model->id())]["export"]["out_of_range"] = list;
            }
        // What each requested format's consumer renders for each model, with that curve's error figures.
        for (const detail::MaterialExport& m : materials)
            for (const detail::ModelExport& e : m.models) {
                nlohmann::ordered_json consumers = nlohmann::ordered_json::object();
                for (const ConsumerCurve& c : detail::consumer_curves(m, e, request))
                    consumers[to_string(c.format)] = consumer_curve_record(c);
                j["materials"][m.fit->material.id]["models"][std::string(e.written.model->id())]["export"]
                 ["consumers"] = consumers;
            }
        record->contents = j.dump(2) + "\n";
    }
    return by_format;
}

std::vector<ExportFile> export_files(const std::vector<MaterialFit>& fits, const FitRecordContext& context,
                                     const ExportRequest& request, const std::string& materialx_space) {
    std::vector<ExportFile> files;
    for (std::vector<ExportFile>& more : detail::export_files_by_format(fits, context, request, materialx_space))
        for (ExportFile& f : more) files.push_back(std::move(f));
    std::set<std::filesystem::path> seen;
    for (const ExportFile& f : files)
        if (!seen.insert(f.path).second)
            throw UsageError("export: two materials would write the same file " + f.path.string() +
                             " (their ids differ only in punctuation or case)");
    return files;
}

}  // namespace metalfit
