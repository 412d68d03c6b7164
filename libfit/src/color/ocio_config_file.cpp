#include "color/ocio_config_file.hpp"

#include <sys/stat.h>

#include <functional>

#include "base/yaml_structure.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/input_file.hpp"

namespace OCIO = OCIO_NAMESPACE;

namespace metalfit {
namespace {

std::string describe(const OcioConfigChoice& c) { return "OCIO config " + c.path.string() + " (" + c.origin + ")"; }

// Every file transform reachable from `transform` (inside group transforms too).
void each_file_transform(const OCIO::ConstTransformRcPtr& transform,
                         const std::function<void(const OCIO::FileTransform&)>& visit) {
    if (!transform) return;
    if (const auto file = OCIO::DynamicPtrCast<const OCIO::FileTransform>(transform)) visit(*file);
    if (const auto group = OCIO::DynamicPtrCast<const OCIO::GroupTransform>(transform))
        for (int i = 0; i < group->getNumTransforms(); ++i) each_file_transform(group->getTransform(i), visit);
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
        return "the file is " + std::to_string(st.st_size) + " bytes; the limit is " + std::to_string(kMaxInputFileBytes >> 20) + " MiB";
    return {};
}

}  // namespace

OCIO::ConstConfigRcPtr load_ocio_config(const OcioConfigChoice& choice) {
    try {
        // The same checks as every input (regular file, size), then the YAML's shape, before OCIO reads it. OCIO
        // then opens the path again (so that its working folder and search path are the file's): the file could be
        // swapped in between only by someone who can write it anyway.
        const std::string text = read_input_file(choice.path);
        const detail::YamlShape shape = detail::check_yaml_structure(text, choice.path);
        // OCIO's loading is quadratic in its entries (4,000 colour spaces take 2 s, 9,000 take 22 s): each colour
        // space, look, view transform or named transform is a tagged node, or an alias standing for one.
        std::size_t entries = shape.aliases;
        for (const char* tag : {"!<ColorSpace>", "!<Look>", "!<ViewTransform>", "!<NamedTransform>"})
            for (std::size_t at = text.find(tag); at != std::string::npos; at = text.find(tag, at + 1)) ++entries;
        if (entries > kMaxOcioEntries)
            throw InputError({choice.path}, "more than " + std::to_string(kMaxOcioEntries) + " colour spaces, looks, view "
                             "transforms, named transforms and aliases (" + std::to_string(entries) + ")");
    } catch (const InputError& e) {
        throw ColorConfigError(describe(choice) + ": cannot be loaded: " + e.what());
    }
    OCIO::ConstConfigRcPtr config;
    try {
        config = OCIO::Config::CreateFromFile(choice.path.c_str());
    } catch (const OCIO::Exception& e) {
        throw ColorConfigError(describe(choice) + ": cannot be loaded: " + e.what());
    }
    each_transform(*config, [&](const OCIO::ConstTransformRcPtr& transform, const std::string& holder) {
        each_file_transform(transform, [&](const OCIO::FileTransform& file) {
            const char* src = file.getSrc();
            std::string resolved;
            if (const std::string problem = lut_problem(*config, src ? src : "", resolved); !problem.empty())
                throw ColorConfigError(describe(choice) + ": " + holder + ": file transform " + resolved + ": " + problem);
        });
    });
    return config;
}

}  // namespace metalfit
