#include "libfit/color/color_space.hpp"

#include <OpenColorIO/OpenColorIO.h>

#include <cmath>
#include <cstdlib>

#include "color/ocio_config_load.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/utf8.hpp"
#include "libfit/color/ocio_config_contents.hpp"

namespace OCIO = OCIO_NAMESPACE;

namespace metalfit {

struct ColorSpaceConverter::Impl {
    OCIO::ConstConfigRcPtr config;
    OCIO::ConstCPUProcessorRcPtr cpu;
    OCIO::ConstCPUProcessorRcPtr inverse;
};

namespace {

const auto describe = detail::describe_ocio_config;  // every message here names the config so

}  // namespace

OcioConfigChoice choose_ocio_config(const std::optional<std::filesystem::path>& explicit_config,
                                    const std::filesystem::path& data_dir, const std::string& explicit_origin) {
    OcioConfigChoice choice{data_dir / "ocio" / "config.ocio", "metalfit default"};
    if (const char* env = std::getenv("OCIO"); env != nullptr && *env != '\0')
        choice = {env, "$OCIO"};
    else if (explicit_config)
        choice = {*explicit_config, explicit_origin};
    // The config's path is written into records and messages (UTF-8).
    if (const auto problem = find_invalid_utf8(choice.path.native()))
        throw ColorConfigError(describe(choice) + ": the path is not UTF-8 (" + problem->reason + ")");
    return choice;
}

ColorSpaceConverter::ColorSpaceConverter(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}
ColorSpaceConverter::~ColorSpaceConverter() = default;
ColorSpaceConverter::ColorSpaceConverter(const ColorSpaceConverter&) = default;
ColorSpaceConverter& ColorSpaceConverter::operator=(const ColorSpaceConverter&) = default;
ColorSpaceConverter::ColorSpaceConverter(ColorSpaceConverter&&) noexcept = default;
ColorSpaceConverter& ColorSpaceConverter::operator=(ColorSpaceConverter&&) noexcept = default;

ColorSpaceConverter ColorSpaceConverter::create(const OcioConfigChoice& choice, const std::string& target,
                                                const std::string& xyz_space_name) {
    auto impl = std::make_shared<Impl>();
    impl->config = detail::load_ocio_config(choice);
    const auto& config = impl->config;
    const auto what_exists = [&choice] {
        const OcioConfigContents contents = read_ocio_config_contents(choice);
        return " (colour spaces: " + contents.space_names() + "; roles: " + contents.role_names() + ")";
    };
    const auto xyz = xyz_space_name.empty() ? (config->hasRole(kXyzRole) ? config->getColorSpace(kXyzRole) : nullptr)
                                            : config->getColorSpace(xyz_space_name.c_str());
    if (!xyz) {
        if (xyz_space_name.empty())
            throw ColorConfigError(describe(choice) + " has no role '" + kXyzRole +
                                   "' (needed to find CIE XYZ D65; name the XYZ colour space with --xyz-space)" +
                                   what_exists());
        throw ColorConfigError(describe(choice) + " has no colour space or role '" + xyz_space_name + "' for CIE XYZ" +
                               what_exists());
    }
    const std::string xyz_space = xyz->getName();
    const std::string wanted = target.empty() ? kSceneLinearRole : target;
    const auto target_space =
        target.empty() && !config->hasRole(kSceneLinearRole) ? nullptr : config->getColorSpace(wanted.c_str());
    if (!target_space) {
        if (target.empty())
            throw ColorConfigError(describe(choice) + " has no role '" + kSceneLinearRole +
                                   "' (name the target colour space)" + what_exists());
        throw ColorConfigError(describe(choice) + " has no colour space or role '" + wanted + "'" + what_exists());
    }
    for (const std::string& name : {xyz_space, std::string(target_space->getName())})
        if (const auto problem = find_invalid_utf8(name))
            throw ColorConfigError(describe(choice) + ": colour space name is not UTF-8 (" + problem->reason +
                                   "): " + name);
    if (target_space->isData())
        throw ColorConfigError(describe(choice) + ": colour space '" + target_space->getName() +
                               "' holds data, not colour (isdata): name a scene-linear colour space");
    try {
        impl->cpu = config->getProcessor(xyz_space.c_str(), target_space->getName())->getDefaultCPUProcessor();
        impl->inverse = config->getProcessor(target_space->getName(), xyz_space.c_str())->getDefaultCPUProcessor();
    } catch (const OCIO::Exception& e) {
        throw ColorConfigError(describe(choice) + ": no transform from '" + xyz_space + "' to '" +
                               target_space->getName() + "': " + e.what());
    }
    ColorSpaceConverter converter(impl);
    converter.config_ = choice;
    converter.space_ = target_space->getName();
    converter.xyz_space_ = xyz_space;

    // Reflectance ratios need a linear space: check additivity and scaling on a few XYZ values. They are divided by
    // the perfect reflector's RGB, so the first probe (about the D65 white) must give finite positive channels, and
    // every value must be finite (a matrix near the double maximum gives inf in OCIO's float32, then NaN ratios).
    const XYZ probes[] = {{0.9, 1.0, 1.1}, {0.2, 0.1, 0.05}, {0.05, 0.1, 0.4}};
    for (const XYZ& p : probes) {
        const RGB full = converter(p);
        const RGB half = converter({p.X * 0.5, p.Y * 0.5, p.Z * 0.5});
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(full[c]) || !std::isfinite(half[c]) || (&p == probes && !(full[c] > 0.0)))
                throw ColorConfigError(
                    describe(choice) + ": colour space '" + converter.space_ +
                    "' gives a non-finite RGB, or a non-positive one for the white (its transform is degenerate)");
        for (int c = 0; c < 3; ++c)
            if (std::abs(full[c] - 2.0 * half[c]) > 1e-4 * (1.0 + std::abs(full[c])))
                throw ColorConfigError(describe(choice) + ": colour space '" + converter.space_ +
                                       "' is not linear (reflectance curves need a scene-linear space)");
    }
    return converter;
}

RGB ColorSpaceConverter::operator()(const XYZ& xyz) const {
    float pixel[3] = {static_cast<float>(xyz.X), static_cast<float>(xyz.Y), static_cast<float>(xyz.Z)};
    impl_->cpu->applyRGB(pixel);
    return {pixel[0], pixel[1], pixel[2]};
}

XYZ ColorSpaceConverter::to_xyz(const RGB& rgb) const {
    float pixel[3] = {static_cast<float>(rgb.r), static_cast<float>(rgb.g), static_cast<float>(rgb.b)};
    impl_->inverse->applyRGB(pixel);
    return {pixel[0], pixel[1], pixel[2]};
}

std::vector<XYZ> ColorSpaceConverter::to_xyz(std::span<const RGB> rgb) const {
    std::vector<float> pixels(3 * rgb.size());
    for (std::size_t i = 0; i < rgb.size(); ++i) {
        pixels[3 * i] = static_cast<float>(rgb[i].r);
        pixels[3 * i + 1] = static_cast<float>(rgb[i].g);
        pixels[3 * i + 2] = static_cast<float>(rgb[i].b);
    }
    if (!rgb.empty()) {
        OCIO::PackedImageDesc image(pixels.data(), static_cast<long>(rgb.size()), 1, 3);
        impl_->inverse->apply(image);
    }
    std::vector<XYZ> xyz;
    xyz.reserve(rgb.size());
    for (std::size_t i = 0; i < rgb.size(); ++i) xyz.emplace_back(pixels[3 * i], pixels[3 * i + 1], pixels[3 * i + 2]);
    return xyz;
}

std::vector<std::string> ColorSpaceConverter::available_spaces() const {
    std::vector<std::string> names;
    const auto& config = impl_->config;
    for (int i = 0; i < config->getNumColorSpaces(); ++i) names.emplace_back(config->getColorSpaceNameByIndex(i));
    return names;
}

}  // namespace metalfit
