// metalfit spaces: the OCIO config in use, its colour spaces (which can be a --space target) and its roles.
#include <nlohmann/json.hpp>

#include <sstream>

#include "commands.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/record_path.hpp"
#include "libfit/base/text.hpp"
#include "libfit/color/color_space.hpp"
#include "libfit/color/ocio_config_contents.hpp"

namespace metalfit::cli {
namespace {

struct SpacesOptions {
    bool json = false;
    std::string xyz_space;
    std::filesystem::path output;
};

// Whether `space` can hold reflectance curves (--space): the converter's own checks (not data, linear, reachable
// from XYZ); the reason when it cannot.
std::string target_refusal(const OcioConfigChoice& config, const std::string& space, const std::string& xyz_space) {
    try {
        ColorSpaceConverter::create(config, space, xyz_space);
        return {};
    } catch (const ColorConfigError& e) {
        const std::string message = e.what();
        const std::size_t colon = message.rfind(": ");
        return colon == std::string::npos ? message : message.substr(colon + 2);
    }
}

void run_spaces(const SpacesOptions& o, const GlobalOptions& global) {
    const OcioConfigChoice config = choose_ocio_config(global.ocio_config, global.data_dir, "--ocio-config");
    const OcioConfigContents contents = read_ocio_config_contents(config);
    nlohmann::ordered_json j;
    j["config"] = record_path(config.path, global.data_dir);
    j["origin"] = config.origin;
    j["spaces"] = nlohmann::ordered_json::array();
    for (const OcioColorSpaceEntry& s : contents.spaces) {
        const std::string refusal = s.is_data ? "holds data, not colour" : target_refusal(config, s.name, o.xyz_space);
        j["spaces"].push_back(
            {{"name", s.name},
             {"family", s.family},
             {"aliases", s.aliases},
             {"is_data", s.is_data},
             {"fit_target", refusal.empty()},
             {"why_not", refusal.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(refusal)}});
    }
    j["roles"] = nlohmann::ordered_json::object();
    for (const OcioRole& r : contents.roles) j["roles"][r.role] = r.space;
    if (o.json) {
        emit(j.dump(2) + "\n", o.output);
        return;
    }
    std::ostringstream out;
    out << "OCIO config " << config.path.string() << " (" << config.origin << ")\n";
    out << "colour spaces (* = usable as --space: linear colour reachable from XYZ):\n";
    for (const auto& s : j["spaces"]) {
        out << (s["fit_target"].get<bool>() ? "  * " : "    ") << s["name"].get<std::string>();
        const auto aliases = s["aliases"].get<std::vector<std::string>>();
        if (!aliases.empty()) out << "  (aliases: " << join(aliases) << ")";
        if (!s["why_not"].is_null()) out << "  — " << s["why_not"].get<std::string>();
        out << "\n";
    }
    out << "roles:\n";
    for (const OcioRole& r : contents.roles) out << "  " << r.role << " → " << r.space << "\n";
    emit(out.str(), o.output);
}

}  // namespace

std::function<void()> add_spaces_command(CLI::App& app, const GlobalOptions& global) {
    auto o = std::make_shared<SpacesOptions>();
    app.add_flag("--json", o->json, "Print JSON");
    app.add_option("--xyz-space", o->xyz_space,
                   "Colour space holding CIE XYZ D65 (default: the role cie_xyz_d65_interchange)");
    app.add_option("-o,--output", o->output, "Write to this file instead of stdout (- for stdout)");
    return [o, &global] { run_spaces(*o, global); };
}

}  // namespace metalfit::cli
