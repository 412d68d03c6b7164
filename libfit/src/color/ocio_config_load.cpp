#include "color/ocio_config_load.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "libfit/base/errors.hpp"
#include "libfit/base/input_file.hpp"
#include "libfit/base/utf8.hpp"
#include "libfit/base/text.hpp"

namespace OCIO = OCIO_NAMESPACE;

namespace metalfit::detail {
namespace {

// The colour spaces a transform refers to by name (through groups), as the config resolves them (roles, aliases).
void referenced_spaces(const OCIO::ConstConfigRcPtr& config, const OCIO::ConstTransformRcPtr& transform,
                       std::set<std::string>& out, int depth = 0) {
    if (!transform || depth > 64) return;
    const auto add = [&](const char* name) {
        if (name == nullptr || *name == '\0') return;
        if (const auto space = config->getColorSpace(name)) out.insert(space->getName());
    };
    if (const auto group = OCIO::DynamicPtrCast<const OCIO::GroupTransform>(transform)) {
        for (int i = 0; i < group->getNumTransforms(); ++i) referenced_spaces(config, group->getTransform(i), out, depth + 1);
    } else if (const auto cs = OCIO::DynamicPtrCast<const OCIO::ColorSpaceTransform>(transform)) {
        add(cs->getSrc());
        add(cs->getDst());
    } else if (const auto look = OCIO::DynamicPtrCast<const OCIO::LookTransform>(transform)) {
        add(look->getSrc());
        add(look->getDst());
    } else if (const auto view = OCIO::DynamicPtrCast<const OCIO::DisplayViewTransform>(transform)) {
        add(view->getSrc());
    }
}

}  // namespace

OCIO::ConstConfigRcPtr load_ocio_config(const OcioConfigChoice& choice, const std::string& context) {
    const std::string described = context.empty() ? "OCIO config " + choice.path.string() + " (" + choice.origin + ")" : context;
    // UTF-8 throughout, as every text file metalfit reads (utf8.hpp): OCIO itself passes any bytes in names and
    // families on, and only warns about keys. Read as an input file (a regular file within its size limit).
    std::string text;
    try {
        text = read_input_file(choice.path);
    } catch (const InputError& e) {
        throw ColorConfigError(described + ": cannot be loaded: " + e.what());
    }
    if (const auto problem = find_invalid_utf8(text))
        throw ColorConfigError(described + ": line " + std::to_string(problem->line) + ": " + problem->reason +
                               " (an OCIO config is UTF-8 text)");
    OCIO::ConstConfigRcPtr config;
    try {
        config = OCIO::Config::CreateFromFile(choice.path.c_str());
    } catch (const OCIO::Exception& e) {
        throw ColorConfigError(described + ": cannot be loaded: " + e.what());
    }
    // The graph "space → spaces its transforms name", then a depth-first search for a cycle.
    std::map<std::string, std::set<std::string>> edges;
    for (int i = 0; i < config->getNumColorSpaces(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL); ++i) {
        const char* name = config->getColorSpaceNameByIndex(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL, i);
        const auto space = config->getColorSpace(name);
        if (!space) continue;
        auto& to = edges[space->getName()];
        referenced_spaces(config, space->getTransform(OCIO::COLORSPACE_DIR_TO_REFERENCE), to);
        referenced_spaces(config, space->getTransform(OCIO::COLORSPACE_DIR_FROM_REFERENCE), to);
    }
    enum class Mark { none, open, done };
    std::map<std::string, Mark> mark;
    std::vector<std::string> path;
    const std::function<void(const std::string&)> visit = [&](const std::string& space) {
        mark[space] = Mark::open;
        path.push_back(space);
        for (const std::string& next : edges[space]) {
            if (mark[next] == Mark::open) {
                std::vector<std::string> cycle(std::find(path.begin(), path.end(), next), path.end());
                cycle.push_back(next);
                throw ColorConfigError(described + ": colour space '" + next + "' converts to itself (" +
                                       join(cycle, " \xe2\x86\x92 ") +
                                       "): its transforms refer back to it, a cycle OCIO would follow without end");
            }
            if (mark[next] == Mark::none) visit(next);
        }
        path.pop_back();
        mark[space] = Mark::done;
    };
    for (const auto& [space, to] : edges)
        if (mark[space] == Mark::none) visit(space);
    return config;
}

}  // namespace metalfit::detail
