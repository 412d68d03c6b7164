#include "libfit/color/rgb_conversion.hpp"

#include <OpenColorIO/OpenColorIO.h>

#include "color/ocio_config_load.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/color/ocio_config_contents.hpp"

namespace OCIO = OCIO_NAMESPACE;

namespace metalfit {

struct RgbConversion::Impl {
    OCIO::ConstCPUProcessorRcPtr processor;
};

RgbConversion RgbConversion::create(const OcioConfigChoice& choice, const std::string& from, const std::string& to) {
    const OCIO::ConstConfigRcPtr config = detail::load_ocio_config(choice);
    const auto resolve = [&](const std::string& name) {
        const auto space = config->getColorSpace(name.c_str());
        if (!space) {
            const OcioConfigContents contents = read_ocio_config_contents(choice);
            throw ColorConfigError(choice.path.string() + " has no colour space or role '" + name +
                                   "' (colour spaces: " + contents.space_names() + "; roles: " + contents.role_names() +
                                   ")");
        }
        if (space->isData())
            throw ColorConfigError(choice.path.string() + ": colour space '" + space->getName() +
                                   "' holds data, not colour");
        return std::string(space->getName());
    };
    const std::string source = resolve(from), target = resolve(to);
    if (source == target) return RgbConversion(nullptr, source, target);
    try {
        auto impl = std::make_unique<Impl>();
        impl->processor = config->getProcessor(source.c_str(), target.c_str())->getDefaultCPUProcessor();
        return RgbConversion(std::move(impl), source, target);
    } catch (const OCIO::Exception& e) {
        throw ColorConfigError(choice.path.string() + ": no conversion from '" + source + "' to '" + target +
                               "': " + e.what());
    }
}

void RgbConversion::apply(std::span<float> rgb) const {
    if (!impl_ || rgb.empty()) return;
    OCIO::PackedImageDesc desc(rgb.data(), static_cast<long>(rgb.size() / 3), 1, 3);
    impl_->processor->apply(desc);
}

RgbConversion::RgbConversion(std::unique_ptr<Impl> impl, std::string from, std::string to)
    : impl_(std::move(impl)), from_(std::move(from)), to_(std::move(to)) {}
RgbConversion::~RgbConversion() = default;
RgbConversion::RgbConversion(RgbConversion&&) noexcept = default;
RgbConversion& RgbConversion::operator=(RgbConversion&&) noexcept = default;

}  // namespace metalfit
