#include "libfit/color/ocio_config_contents.hpp"

#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>

#include "libfit/base/errors.hpp"
#include "libfit/base/text.hpp"
#include "color/ocio_config_file.hpp"

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
    const OCIO::ConstConfigRcPtr config = load_ocio_config(choice);
    OcioConfigContents contents{choice, {}, {}};
    for (int i = 0; i < config->getNumColorSpaces(); ++i) {
        const auto space = config->getColorSpace(config->getColorSpaceNameByIndex(i));
        OcioColorSpaceEntry entry{space->getName(), space->getFamily(), {}, space->isData()};
        for (std::size_t a = 0; a < space->getNumAliases(); ++a) entry.aliases.emplace_back(space->getAlias(a));
        contents.spaces.push_back(std::move(entry));
    }
    for (int i = 0; i < config->getNumRoles(); ++i)
        contents.roles.push_back({config->getRoleName(i), config->getRoleColorSpace(i)});
    std::sort(contents.roles.begin(), contents.roles.end(),
              [](const OcioRole& a, const OcioRole& b) { return a.role < b.role; });
    return contents;
}

}  // namespace metalfit
