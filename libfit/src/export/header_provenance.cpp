#include "export/header_provenance.hpp"

#include "libfit/base/text.hpp"
#include "libfit/base/version.hpp"

namespace metalfit::detail {

std::vector<std::string> header_provenance_lines(const Material& m, const FitRecordContext& r) {
    std::vector<std::string> lines;
    lines.push_back("data source: " + m.source + " (" + m.provenance.format + ", " +
                    m.provenance.file.filename().string() + ", sha256 " + m.provenance.sha256 + ")");
    const std::string reference = one_line(m.provenance.references);
    lines.push_back("reference: " + (reference.empty() ? std::string("none given") : reference));
    if (!m.provenance.note.empty()) lines.push_back("caveat: " + one_line(m.provenance.note));
    lines.push_back("colour space: " + r.space + " (OCIO " + r.config.origin + "); " + to_string(r.illuminant) + ", " +
                    to_string(r.observer) + ", R_c(mu) white balanced to the perfect reflector");
    lines.push_back("colour convention: " + to_string(r.convention) +
                    "; chromatic adaptation: " + describe_adaptation(r.adaptation, r.adapted, r.illuminant));
    for (const std::string& warning : m.warnings) lines.push_back("DATA WARNING: " + warning);
    return lines;
}

nlohmann::ordered_json material_identity_json(std::string_view schema, const Material& material,
                                              const FitRecordContext& record, std::string_view model) {
    return {{"schema", schema},
            {"metalfit_version", METALFIT_VERSION},
            {"material", material.id},
            {"name", material.name},
            {"source", material.source},
            {"provenance", header_provenance_lines(material, record)},
            {"color_space", record.space},
            {"model", model}};
}

}  // namespace metalfit::detail
