#include "color/ocio_config_load.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "base/yaml_structure.hpp"
#include "color/shipped_ocio_config.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/input_file.hpp"
#include "libfit/base/text.hpp"
#include "libfit/base/utf8.hpp"
#include "libfit/color/ocio_config_loads.hpp"

namespace OCIO = OCIO_NAMESPACE;

namespace metalfit::detail {
namespace {

// Every transform reachable from `transform` that is not a group (group transforms opened, 64 levels at most).
void each_leaf_transform(const OCIO::ConstTransformRcPtr& transform,
                         const std::function<void(const OCIO::ConstTransformRcPtr&)>& visit, int depth = 0) {
    if (!transform || depth > 64) return;
    if (const auto group = OCIO::DynamicPtrCast<const OCIO::GroupTransform>(transform)) {
        for (int i = 0; i < group->getNumTransforms(); ++i)
            each_leaf_transform(group->getTransform(i), visit, depth + 1);
        return;
    }
    visit(transform);
}

// The colour spaces a transform refers to by name (through groups), as the config resolves them (roles, aliases).
void referenced_spaces(const OCIO::ConstConfigRcPtr& config, const OCIO::ConstTransformRcPtr& transform,
                       std::set<std::string>& out) {
    const auto add = [&](const char* name) {
        if (name == nullptr || *name == '\0') return;
        if (const auto space = config->getColorSpace(name)) out.insert(space->getName());
    };
    each_leaf_transform(transform, [&](const OCIO::ConstTransformRcPtr& leaf) {
        if (const auto cs = OCIO::DynamicPtrCast<const OCIO::ColorSpaceTransform>(leaf)) {
            add(cs->getSrc());
            add(cs->getDst());
        } else if (const auto look = OCIO::DynamicPtrCast<const OCIO::LookTransform>(leaf)) {
            add(look->getSrc());
            add(look->getDst());
        } else if (const auto view = OCIO::DynamicPtrCast<const OCIO::DisplayViewTransform>(leaf)) {
            add(view->getSrc());
        }
    });
}

// Every transform the config defines, with what holds it ("colour space 'x'", "look 'y'", ...).
void each_transform(const OCIO::Config& config,
                    const std::function<void(const OCIO::ConstTransformRcPtr&, const std::string&)>& visit) {
    const int spaces = config.getNumColorSpaces(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL);
    for (int i = 0; i < spaces; ++i) {
        const char* name = config.getColorSpaceNameByIndex(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL, i);
        const auto space = config.getColorSpace(name);
        if (!space) continue;
        for (const auto direction : {OCIO::COLORSPACE_DIR_TO_REFERENCE, OCIO::COLORSPACE_DIR_FROM_REFERENCE})
            visit(space->getTransform(direction), std::string("colour space '") + name + "'");
    }
    for (int i = 0; i < config.getNumLooks(); ++i) {
        const char* name = config.getLookNameByIndex(i);
        if (const auto look = config.getLook(name)) {
            visit(look->getTransform(), std::string("look '") + name + "'");
            visit(look->getInverseTransform(), std::string("look '") + name + "'");
        }
    }
    for (int i = 0; i < config.getNumViewTransforms(); ++i) {
        const char* name = config.getViewTransformNameByIndex(i);
        if (const auto view = config.getViewTransform(name))
            for (const auto direction : {OCIO::VIEWTRANSFORM_DIR_TO_REFERENCE, OCIO::VIEWTRANSFORM_DIR_FROM_REFERENCE})
                visit(view->getTransform(direction), std::string("view transform '") + name + "'");
    }
    for (int i = 0; i < config.getNumNamedTransforms(OCIO::NAMEDTRANSFORM_ALL); ++i) {
        const char* name = config.getNamedTransformNameByIndex(OCIO::NAMEDTRANSFORM_ALL, i);
        if (const auto named = config.getNamedTransform(name))
            for (const auto direction : {OCIO::TRANSFORM_DIR_FORWARD, OCIO::TRANSFORM_DIR_INVERSE})
                visit(named->getTransform(direction), std::string("named transform '") + name + "'");
    }
}

// Empty when the LUT `src` of a file transform resolves to a regular file within the size limit; else why not.
std::string lut_problem(const OCIO::Config& config, const char* src, std::string& resolved) {
    try {
        resolved = config.getCurrentContext()->resolveFileLocation(src);
    } catch (const OCIO::Exception&) {
        resolved = src;
        return "not found (in the config's search path)";
    }
    struct stat st {};
    if (::stat(resolved.c_str(), &st) != 0) return "not found";
    if (!S_ISREG(st.st_mode)) return "not a regular file (OCIO would read it without end)";
    if (static_cast<unsigned long long>(st.st_size) > kMaxInputFileBytes)
        return "the file is " + std::to_string(st.st_size) + " bytes; the limit is " +
               std::to_string(kMaxInputFileBytes >> 20) + " MiB";
    return {};
}

// The configs made in this process, by absolute path, with the bytes they were made from.
struct LoadedConfigs {
    std::mutex mutex;
    std::map<std::filesystem::path, std::pair<std::string, OCIO::ConstConfigRcPtr>> by_path;
    OcioConfigLoads counts;
};

LoadedConfigs& loaded_configs() {
    static LoadedConfigs loaded;
    return loaded;
}

}  // namespace

std::string describe_ocio_config(const OcioConfigChoice& choice) {
    return "OCIO config " + choice.path.string() + " (" + choice.origin + ")";
}

OCIO::ConstConfigRcPtr load_ocio_config(const OcioConfigChoice& choice, const std::string& context) {
    const std::string described = context.empty() ? describe_ocio_config(choice) : context;
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
    // Once per process and file: the same bytes at the same path give the Config already made (its processors, which
    // OCIO caches inside it, included). A file changed since is made again.
    std::error_code absolute_error;
    std::filesystem::path key = std::filesystem::absolute(choice.path, absolute_error);
    if (absolute_error) key = choice.path;
    LoadedConfigs& loaded = loaded_configs();
    {
        const std::lock_guard lock(loaded.mutex);
        if (const auto found = loaded.by_path.find(key); found != loaded.by_path.end() && found->second.first == text) {
            ++loaded.counts.reused;
            return found->second.second;
        }
    }
    // metalfit's own config, byte for byte: built through OCIO's API, without YAML. The same Config as the parse, which
    // passes every check below (test OcioConfigLoads.ShippedConfigBuiltEqualsParsed).
    if (text == shipped_ocio_config_text()) {
        OCIO::ConstConfigRcPtr config = build_shipped_ocio_config(key.parent_path());
        const std::lock_guard lock(loaded.mutex);
        ++loaded.counts.shipped_built;
        loaded.by_path[key] = {std::move(text), config};
        return config;
    }
    // The YAML's shape (depth, nodes, aliases: base/yaml_structure) and the number of entries, before OCIO reads it.
    // OCIO then opens the path again (so that its working folder and search path are the file's): the file could be
    // swapped in between only by someone who can write it anyway.
    try {
        const YamlShape shape = check_yaml_structure(text, choice.path);
        // OCIO's loading is quadratic in its entries (4,000 colour spaces take 2 s, 9,000 take 22 s): each colour
        // space, look, view transform or named transform is a tagged node, or an alias standing for one.
        std::size_t entries = shape.aliases;
        for (const char* tag : {"!<ColorSpace>", "!<Look>", "!<ViewTransform>", "!<NamedTransform>"})
            for (std::size_t at = text.find(tag); at != std::string::npos; at = text.find(tag, at + 1)) ++entries;
        if (entries > kMaxOcioEntries)
            throw InputError({choice.path}, "more than " + std::to_string(kMaxOcioEntries) +
                                                " colour spaces, looks, view "
                                                "transforms, named transforms and aliases (" +
                                                std::to_string(entries) + ")");
    } catch (const InputError& e) {
        throw ColorConfigError(described + ": cannot be loaded: " + e.what());
    }
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
    // Every LUT a file transform names: a regular file within the size limit that the search path finds (OCIO would
    // read /dev/zero or a FIFO without end).
    each_transform(*config, [&](const OCIO::ConstTransformRcPtr& transform, const std::string& holder) {
        each_leaf_transform(transform, [&](const OCIO::ConstTransformRcPtr& leaf) {
            const auto file = OCIO::DynamicPtrCast<const OCIO::FileTransform>(leaf);
            if (!file) return;
            const char* src = file->getSrc();
            std::string resolved;
            if (const std::string problem = lut_problem(*config, src ? src : "", resolved); !problem.empty())
                throw ColorConfigError(described + ": " + holder + ": file transform " + resolved + ": " + problem);
        });
    });
    const std::lock_guard lock(loaded.mutex);
    ++loaded.counts.parsed;
    loaded.by_path[key] = {std::move(text), config};
    return config;
}

}  // namespace metalfit::detail

namespace metalfit {

OcioConfigLoads ocio_config_loads() {
    detail::LoadedConfigs& loaded = detail::loaded_configs();
    const std::lock_guard lock(loaded.mutex);
    return loaded.counts;
}

std::string serialized_ocio_config(const OcioConfigChoice& choice) {
    std::ostringstream out;
    detail::load_ocio_config(choice)->serialize(out);
    return out.str();
}

}  // namespace metalfit
