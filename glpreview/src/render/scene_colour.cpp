#include "glpreview/render/scene_colour.hpp"

#include "glpreview/io/image_io.hpp"
#include "glpreview/scene/confined_file.hpp"
#include "libfit/base/errors.hpp"

namespace metalfit::glpreview {

ColorSpaceConverter scene_converter(const OcioConfigChoice& config, const std::string& space,
                                    const std::filesystem::path& scene_file) {
    try {
        return ColorSpaceConverter::create(config, space);
    } catch (const ColorConfigError& e) {
        if (space.empty()) throw;  // the config's own problem (no scene_linear role), not the scene's
        throw InputError(InputLocation(scene_file, 0, "space"), e.what());
    }
}

RgbConversion scene_space_conversion(const Scene& scene, const OcioConfigChoice& config, const std::string& from,
                                     const std::string& field) {
    const std::string to = scene.space.empty() ? std::string("scene_linear") : scene.space;
    try {
        RgbConversion::create(config, to, to);  // the scene's own space first, so that its error names `space`
    } catch (const ColorConfigError& e) {
        throw InputError(InputLocation(scene.file, 0, scene.space.empty() ? field : "space"), e.what());
    }
    try {
        return RgbConversion::create(config, from, to);
    } catch (const ColorConfigError& e) {
        throw InputError(InputLocation(scene.file, 0, field), e.what());
    }
}

Image read_environment_image(const Scene& scene, const OcioConfigChoice& config) {
    // Opened once, checked on its descriptor and read through it; its errors name the scene and the field. The
    // scene already resolved the file against its folder (a path relative to the working folder when the scene's
    // is): made absolute here, so that ConfinedFile does not resolve it against the scene's folder a second time.
    const ConfinedFile file =
        ConfinedFile::open(scene, std::filesystem::absolute(scene.environment.equirect.file), "environment.file");
    Image pixels;
    try {
        pixels = read_image(file.path());
    } catch (const InputError& e) {
        throw InputError(InputLocation(scene.file, 0, "environment.file"), file.in_original_terms(e.what()));
    }
    if (!scene.environment.equirect.colorspace.empty())
        scene_space_conversion(scene, config, scene.environment.equirect.colorspace, "environment.colorspace")
            .apply(pixels.rgb);
    return pixels;
}

}  // namespace metalfit::glpreview
