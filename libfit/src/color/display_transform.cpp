#include "libfit/color/display_transform.hpp"

#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <cmath>

#include "libfit/base/errors.hpp"

namespace OCIO = OCIO_NAMESPACE;

namespace metalfit {

struct DisplayTransform::Impl {
    OCIO::ConstCPUProcessorRcPtr processor;
};

DisplayTransform DisplayTransform::create(const OcioConfigChoice& choice, const std::string& source) {
    const std::string src = source.empty() ? OCIO::ROLE_SCENE_LINEAR : source;
    try {
        auto config = OCIO::Config::CreateFromFile(choice.path.string().c_str());
        const char* display = config->getDefaultDisplay();
        const char* view = config->getDefaultView(display);
        auto transform = OCIO::DisplayViewTransform::Create();
        transform->setSrc(src.c_str());
        transform->setDisplay(display);
        transform->setView(view);
        auto processor = config->getProcessor(transform);
        auto impl = std::make_unique<Impl>();
        impl->processor = processor->getDefaultCPUProcessor();
        const auto source_space = config->getColorSpace(src.c_str());
        return DisplayTransform(std::move(impl), std::string(source_space ? source_space->getName() : src) + " → " +
                                                     display + " / " + view);
    } catch (const OCIO::Exception& e) {
        throw ColorConfigError(choice.path.string() + ": no display transform from " + src + ": " + e.what());
    }
}

DisplayTransform::DisplayTransform(std::unique_ptr<Impl> impl, std::string description)
    : impl_(std::move(impl)), description_(std::move(description)) {}
DisplayTransform::~DisplayTransform() = default;
DisplayTransform::DisplayTransform(DisplayTransform&&) noexcept = default;
DisplayTransform& DisplayTransform::operator=(DisplayTransform&&) noexcept = default;

std::vector<unsigned char> DisplayTransform::apply(std::span<const float> rgb, int width, int height) const {
    std::vector<float> pixels(rgb.begin(), rgb.end());
    OCIO::PackedImageDesc desc(pixels.data(), width, height, 3);
    impl_->processor->apply(desc);
    std::vector<unsigned char> out(pixels.size());
    for (std::size_t i = 0; i < pixels.size(); ++i)
        out[i] = static_cast<unsigned char>(std::lround(std::clamp(pixels[i], 0.0f, 1.0f) * 255.0f));
    return out;
}

}  // namespace metalfit
