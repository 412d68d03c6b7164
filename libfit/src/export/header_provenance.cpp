#include "export/header_provenance.hpp"

#include "libfit/base/number_text.hpp"
#include "libfit/base/record_path.hpp"
#include "libfit/base/text.hpp"
#include "libfit/base/version.hpp"
#include "libfit/io/layer_stack.hpp"

namespace metalfit::detail {

std::vector<std::string> header_provenance_lines(const Material& m, const FitRecordContext& r, bool base_of_layers) {
    std::vector<std::string> lines;
    lines.push_back("data source: " + m.source + " (" + m.provenance.format + ", " +
                    record_path(m.provenance.file, r.data_dir) + ", sha256 " + m.provenance.sha256 + ")");
    const std::string reference = one_line(m.provenance.references);
    lines.push_back("reference: " + (reference.empty() ? std::string("none given") : reference));
    if (!m.provenance.note.empty()) lines.push_back("caveat: " + one_line(m.provenance.note));
    if (m.layers && !m.layers->empty()) {
        // The whole stack: the constants reproduce the layered curve, not the bare metal's.
        lines.push_back("stack: " + one_line(describe_stack(m)) +
                        (base_of_layers ? "; the base parameters fit the bare " + one_line(m.name) +
                                              "'s reflectance, the layers are this format's own (docs/export.md, "
                                              "Layered exports)"
                                        : std::string("; the parameters fit the stack's reflectance (docs/colour.md, "
                                                      "Layered metals)")));
        if (m.layers->coat)
            lines.push_back("coat layer: " + one_line(describe(*m.layers->coat)) + "; " +
                            describe_layer_index(layer_index_summary(m.layers->coat->material)));
        if (m.layers->film)
            lines.push_back("film layer: " + one_line(describe(*m.layers->film)) + " (" +
                            significant_text(m.layers->film->thickness_nm / 1000.0, 6) + " um); " +
                            describe_layer_index(layer_index_summary(m.layers->film->material)));
        const auto layer = [&lines, &r](const char* what, const LayerMaterial& l) {
            if (l.source == "constant") return;
            lines.push_back(std::string(what) + " data: " + l.id + " (" + l.source + ", " +
                            record_path(l.provenance.file, r.data_dir) + ", sha256 " + l.provenance.sha256 + ")");
        };
        if (m.layers->coat) layer("coat", m.layers->coat->material);
        if (m.layers->film) layer("film", m.layers->film->material);
    }
    lines.push_back("colour space: " + r.space + " (OCIO " + r.config.origin + "); " + to_string(r.illuminant) + ", " +
                    to_string(r.observer) + ", R_c(mu) white balanced to the perfect reflector");
    lines.push_back("colour convention: " + to_string(r.convention) +
                    "; chromatic adaptation: " + describe_adaptation(r.adaptation, r.adapted, r.illuminant));
    for (const std::string& warning : m.warnings) lines.push_back("DATA WARNING: " + warning);
    return lines;
}

nlohmann::ordered_json material_identity_json(std::string_view schema, const Material& material,
                                              const FitRecordContext& record, std::string_view model,
                                              bool base_of_layers) {
    return {{"schema", schema},
            {"metalfit_version", METALFIT_VERSION},
            {"material", material.id},
            {"name", material.name},
            {"source", material.source},
            {"provenance", header_provenance_lines(material, record, base_of_layers)},
            {"color_space", record.space},
            {"model", model}};
}

}  // namespace metalfit::detail
