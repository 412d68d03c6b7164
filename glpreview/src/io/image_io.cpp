#include "glpreview/io/image_io.hpp"

#include <OpenImageIO/imageio.h>
#include <stdlib.h>
#include <sys/stat.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <system_error>

#include "libfit/base/errors.hpp"

namespace metalfit::glpreview {
namespace {

// Writes pixels of `format` through OpenImageIO into a new private folder beside `file` (mkdtemp: a name nobody can
// plant a link at), then renames the image over `file` and removes the folder.
void write_pixels(const std::filesystem::path& file, const OIIO::ImageSpec& spec, OIIO::TypeDesc format, const void* pixels) {
    const std::filesystem::path dir = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
    std::string pattern = (dir / ("." + file.filename().string().substr(0, 200) + ".partial-XXXXXX")).string();
    if (::mkdtemp(pattern.data()) == nullptr)
        throw InputError(InputLocation(file), "cannot write the image: directory " + dir.string() + " is not writable");
    const std::filesystem::path staging = pattern;
    const std::filesystem::path temporary = staging / file.filename();
    auto fail = [&](const std::string& why) {
        std::error_code ignored;
        std::filesystem::remove_all(staging, ignored);
        throw InputError(InputLocation(file), "cannot write the image: " + why);
    };
    auto out = OIIO::ImageOutput::create(file.string());
    if (!out) fail(OIIO::geterror());
    if (!out->open(temporary.string(), spec)) fail(out->geterror());
    if (!out->write_image(format, pixels)) fail(out->geterror());
    if (!out->close()) fail(out->geterror());
    std::error_code error;
    std::filesystem::rename(temporary, file, error);
    if (error) fail(error.message());
    std::filesystem::remove(staging, error);
}

// Opens an image for reading after checking what a header can claim: a regular file (a FIFO or /dev/zero would hang
// or never end) and dimensions within kMaxInputImageSide and kMaxInputImagePixels, before any pixel is allocated.
std::unique_ptr<OIIO::ImageInput> open_checked(const std::filesystem::path& file) {
    struct stat st {};
    if (::stat(file.c_str(), &st) != 0) throw InputError(InputLocation(file), "cannot read the image: no such file");
    if (!S_ISREG(st.st_mode)) throw InputError(InputLocation(file), "cannot read the image: not a regular file");
    std::unique_ptr<OIIO::ImageInput> in;
    try {
        in = OIIO::ImageInput::open(file.string());
    } catch (const std::exception& e) {
        throw InputError(InputLocation(file), std::string("cannot read the image: ") + e.what());
    }
    if (!in) throw InputError(InputLocation(file), "cannot read the image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.width > kMaxInputImageSide || spec.height > kMaxInputImageSide ||
        static_cast<long long>(spec.width) * spec.height > kMaxInputImagePixels || spec.depth > 1 || spec.nchannels < 1 ||
        spec.nchannels > 64)
        throw InputError(InputLocation(file), "image dimensions " + std::to_string(spec.width) + " x " +
                                                  std::to_string(spec.height) + " x " + std::to_string(spec.nchannels) +
                                                  " channels are outside the limits (sides up to " +
                                                  std::to_string(kMaxInputImageSide) + ", " + std::to_string(kMaxInputImagePixels) +
                                                  " pixels, 64 channels)");
    return in;
}

// The EXR header's capture date (OpenImageIO's "DateTime", written as OpenEXR's `capDate`): the time given by
// $SOURCE_DATE_EPOCH (reproducible-builds.org's convention: seconds since 1970 UTC) when it is set, so that a rerun
// writes the same bytes; else OpenImageIO's own (the time of writing).
void set_capture_date(OIIO::ImageSpec& spec) {
    const char* epoch = std::getenv("SOURCE_DATE_EPOCH");
    if (epoch == nullptr) return;
    const std::string_view text(epoch);
    long long seconds = -1;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), seconds);
    std::tm utc{};
    const std::time_t t = static_cast<std::time_t>(seconds);
    if (error != std::errc() || end != text.data() + text.size() || seconds < 0 || ::gmtime_r(&t, &utc) == nullptr)
        throw UsageError("SOURCE_DATE_EPOCH: expected seconds since 1970-01-01 UTC, a non-negative integer (got '" +
                         std::string(text.substr(0, 40)) + "')");
    char date[32];
    std::strftime(date, sizeof date, "%Y:%m:%d %H:%M:%S", &utc);
    spec.attribute("DateTime", date);
}

}  // namespace

Image read_image(const std::filesystem::path& file) {
    auto in = open_checked(file);
    const OIIO::ImageSpec& spec = in->spec();
    const int channels = spec.nchannels;
    std::vector<float> pixels(static_cast<std::size_t>(spec.width) * spec.height * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()))
        throw InputError(InputLocation(file), "cannot read the image: " + in->geterror());
    Image image(spec.width, spec.height);
    for (std::size_t i = 0; i < static_cast<std::size_t>(spec.width) * spec.height; ++i)
        for (int c = 0; c < 3; ++c) image.rgb[3 * i + c] = pixels[i * channels + std::min(c, channels - 1)];
    for (float v : image.rgb)
        if (!std::isfinite(v) || v < 0) throw InputError(InputLocation(file), "pixels must be finite and non-negative radiance");
    return image;
}

void write_exr(const std::filesystem::path& file, const Image& image, const ExrColour* colour, const ExrMetadata& metadata) {
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::HALF);
    spec.channelnames = {"R", "G", "B"};
    spec.attribute("compression", "zip");
    set_capture_date(spec);
    if (colour) {
        const Chromaticities& c = colour->chromaticities;
        const float xy[8] = {static_cast<float>(c.red[0]),   static_cast<float>(c.red[1]),
                             static_cast<float>(c.green[0]), static_cast<float>(c.green[1]),
                             static_cast<float>(c.blue[0]),  static_cast<float>(c.blue[1]),
                             static_cast<float>(c.white[0]), static_cast<float>(c.white[1])};
        spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), xy);
        spec.attribute("colorSpace", colour->space);
    }
    for (const ExrAttribute& a : metadata) {
        if (const auto* text = std::get_if<std::string>(&a.value)) spec.attribute(a.name, *text);
        else if (const auto* f = std::get_if<float>(&a.value)) spec.attribute(a.name, *f);
        else spec.attribute(a.name, std::get<int>(a.value));
    }
    write_pixels(file, spec, OIIO::TypeDesc::FLOAT, image.rgb.data());
}

ExrMetadata read_image_metadata(const std::filesystem::path& file, const std::string& prefix) {
    auto in = open_checked(file);
    ExrMetadata out;
    for (const OIIO::ParamValue& p : in->spec().extra_attribs) {
        const std::string name = p.name().string();
        if (name.rfind(prefix, 0) != 0) continue;
        if (p.type() == OIIO::TypeDesc::STRING) out.push_back({name, std::string(p.get_ustring().string())});
        else if (p.type() == OIIO::TypeDesc::FLOAT) out.push_back({name, p.get_float()});
        else if (p.type() == OIIO::TypeDesc::INT) out.push_back({name, p.get_int()});
    }
    return out;
}

std::optional<ExrColour> read_exr_colour(const std::filesystem::path& file) {
    auto in = open_checked(file);
    const OIIO::ImageSpec& spec = in->spec();
    float xy[8];
    if (!spec.getattribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), xy)) return std::nullopt;
    return ExrColour{{{{xy[0], xy[1]}}, {{xy[2], xy[3]}}, {{xy[4], xy[5]}}, {{xy[6], xy[7]}}},
                     spec.get_string_attribute("colorSpace")};
}

void write_png(const std::filesystem::path& file, const Image& image, const DisplayTransform& display) {
    const std::vector<unsigned char> pixels = display.apply(image.rgb, image.width, image.height);
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
    // OpenImageIO's PNG writer turns "sRGB" into the sRGB chunk with gAMA 0.45455 and cHRM of Rec.709 / D65, and
    // "Gamma<g>" into gAMA 1/g. Another display (other primaries, another curve) gets no colour chunk: none would be true.
    const DisplayEncoding& encoding = display.encoding();
    if (encoding.kind == DisplayEncoding::Kind::srgb) spec.attribute("oiio:ColorSpace", "sRGB");
    else if (encoding.kind == DisplayEncoding::Kind::gamma)
        spec.attribute("oiio:ColorSpace", "Gamma" + std::to_string(encoding.gamma));
    write_pixels(file, spec, OIIO::TypeDesc::UINT8, pixels.data());
}

Png8 read_png8(const std::filesystem::path& file) {
    auto in = open_checked(file);
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.nchannels != 3) throw InputError(InputLocation(file), "expected an RGB image");
    Png8 png{spec.width, spec.height, std::vector<unsigned char>(static_cast<std::size_t>(spec.width) * spec.height * 3)};
    if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, png.rgb.data()))
        throw InputError(InputLocation(file), "cannot read the image: " + in->geterror());
    return png;
}

}  // namespace metalfit::glpreview
