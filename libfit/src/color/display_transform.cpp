#include "libfit/color/display_transform.hpp"

#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "color/ocio_config_load.hpp"
#include "libfit/base/errors.hpp"

namespace OCIO = OCIO_NAMESPACE;

namespace metalfit {

struct DisplayTransform::Impl {
    OCIO::ConstCPUProcessorRcPtr processor;
};

namespace {

double srgb_decode(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }

// The encoded RGB `rgb` of `display_space`, as CIE XYZ.
std::array<float, 3> display_xyz(const OCIO::ConstCPUProcessorRcPtr& to_xyz, std::array<float, 3> rgb) {
    to_xyz->applyRGB(rgb.data());
    return rgb;
}

// Measures the display colour space: its primaries and white (encoded (1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 1) →
// xy, any curve through 0 and 1 keeps them) against Rec.709 / D65 within 5e-4, then its curve on the grey axis
// (Y / Y_white at 15 encoded values) against the sRGB curve, else a power law fitted at 0.5, within 1e-3.
DisplayEncoding measure_encoding(const OCIO::ConstConfigRcPtr& config, const char* display, const char* view) {
    DisplayEncoding e;
    const char* named = config->getDisplayViewColorSpaceName(display, view);
    e.display_space =
        (named == nullptr || *named == 0 || std::string(named) == OCIO::OCIO_VIEW_USE_DISPLAY_NAME) ? display : named;
    if (!config->getColorSpace("cie_xyz_d65_interchange")) {
        e.why = "the config has no role cie_xyz_d65_interchange to measure the display with";
        return e;
    }
    OCIO::ConstCPUProcessorRcPtr to_xyz;
    try {
        to_xyz = config->getProcessor(e.display_space.c_str(), "cie_xyz_d65_interchange")->getDefaultCPUProcessor();
    } catch (const OCIO::Exception& error) {
        e.why = std::string("no transform from the display to CIE XYZ: ") + error.what();
        return e;
    }
    constexpr double kRec709[4][2] = {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}, {0.3127, 0.3290}};
    const std::array<float, 3> probes[4] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    for (int i = 0; i < 4; ++i) {
        const auto c = display_xyz(to_xyz, probes[i]);
        const double sum = double(c[0]) + c[1] + c[2];
        if (!(sum > 0) || std::abs(c[0] / sum - kRec709[i][0]) > 5e-4 || std::abs(c[1] / sum - kRec709[i][1]) > 5e-4) {
            e.why = "primaries or white are not Rec.709 / D65";
            return e;
        }
    }
    const double white = display_xyz(to_xyz, {1, 1, 1})[1];
    const auto decoded = [&](double v) {
        const float f = static_cast<float>(v);
        return display_xyz(to_xyz, {f, f, f})[1] / white;
    };
    const double gamma = std::log(decoded(0.5)) / std::log(0.5);
    bool srgb = true, power = std::isfinite(gamma) && gamma > 0;
    for (int i = 1; i < 16; ++i) {
        const double v = i / 16.0, y = decoded(v);
        srgb = srgb && std::abs(y - srgb_decode(v)) < 1e-3;
        power = power && std::abs(y - std::pow(v, gamma)) < 1e-3;
    }
    if (srgb)
        e.kind = DisplayEncoding::Kind::srgb;
    else if (power)
        e.kind = DisplayEncoding::Kind::gamma, e.gamma = gamma;
    else
        e.why = "the curve is neither the sRGB curve nor a power law";
    return e;
}

}  // namespace

DisplayTransform DisplayTransform::create(const OcioConfigChoice& choice, const std::string& source) {
    const std::string src = source.empty() ? OCIO::ROLE_SCENE_LINEAR : source;
    try {
        const auto config =
            detail::load_ocio_config(choice, choice.path.string() + ": no display transform from " + src);
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
        return DisplayTransform(
            std::move(impl), std::string(source_space ? source_space->getName() : src) + " → " + display + " / " + view,
            measure_encoding(config, display, view));
    } catch (const OCIO::Exception& e) {
        throw ColorConfigError(choice.path.string() + ": no display transform from " + src + ": " + e.what());
    }
}

DisplayTransform::DisplayTransform(std::unique_ptr<Impl> impl, std::string description, DisplayEncoding encoding)
    : impl_(std::move(impl)), description_(std::move(description)), encoding_(std::move(encoding)) {}
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
