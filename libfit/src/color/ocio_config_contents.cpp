#include "libfit/color/ocio_config_contents.hpp"

#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>

#include "color/ocio_config_load.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/text.hpp"
#include "libfit/base/utf8.hpp"

namespace OCIO = OCIO_NAMESPACE;

namespace metalfit {

std::string OcioConfigContents::space_names() const {
    std::vector<std::string> names;
    for (const OcioColorSpaceEntry& s : spaces) names.push_back(s.name);
    return join(names);
}

std::string OcioConfigContents::role_names() const {
    std::vector<std::string> names;
    for (const OcioRole& r : roles) names.push_back(r.role + " → " + r.space);
    return join(names);
}

OcioConfigContents read_ocio_config_contents(const OcioConfigChoice& choice) {
    const OCIO::ConstConfigRcPtr config = detail::load_ocio_config(choice);
    OcioConfigContents contents{choice, {}, {}};
    // Names, families, aliases and roles reach `metalfit spaces --json` and records: UTF-8 (utf8.hpp) or refused.
    const auto text = [&choice](const char* value, const std::string& field) {
        std::string s = value == nullptr ? "" : value;
        if (const auto problem = find_invalid_utf8(s))
            throw ColorConfigError(detail::describe_ocio_config(choice) + ": " + field + " is not UTF-8 (" +
                                   problem->reason + "): " + s);
        return s;
    };
    for (int i = 0; i < config->getNumColorSpaces(); ++i) {
        const auto space = config->getColorSpace(config->getColorSpaceNameByIndex(i));
        const std::string name = text(space->getName(), "the name of colour space " + std::to_string(i + 1));
        OcioColorSpaceEntry entry{
            name, text(space->getFamily(), "colour space '" + name + "': family"), {}, space->isData()};
        for (std::size_t a = 0; a < space->getNumAliases(); ++a)
            entry.aliases.push_back(text(space->getAlias(a), "colour space '" + name + "': aliases"));
        contents.spaces.push_back(std::move(entry));
    }
    for (int i = 0; i < config->getNumRoles(); ++i) {
        const std::string role = text(config->getRoleName(i), "role " + std::to_string(i + 1));
        contents.roles.push_back({role, text(config->getRoleColorSpace(i), "role '" + role + "'")});
    }
    std::sort(contents.roles.begin(), contents.roles.end(),
              [](const OcioRole& a, const OcioRole& b) { return a.role < b.role; });
    return contents;
}

}  // namespace metalfit
