#include "exr_file.hpp"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfChromaticitiesAttribute.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <Imath/half.h>

#include <array>
#include <charconv>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <string>

#include "glpreview/io/image_io.hpp"
#include "image_limits.hpp"
#include "libfit/base/errors.hpp"
#include "staged_write.hpp"

namespace metalfit::glpreview {
namespace {

// Opens an EXR for reading; OpenEXR's exceptions become InputError naming the file.
template <class Read>
auto with_exr(const std::filesystem::path& file, Read read) {
    if (const std::string problem = not_a_file_problem(file); !problem.empty()) throw InputError(InputLocation(file), problem);
    try {
        Imf::InputFile in(file.c_str());
        return read(in);
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError(InputLocation(file), std::string("cannot read the image: ") + e.what());
    }
}

// The EXR header's capture date (OpenEXR's `capDate`, "YYYY:MM:DD hh:mm:ss"): the time given by $SOURCE_DATE_EPOCH
// (reproducible-builds.org's convention: seconds since 1970 UTC, written as UTC) when it is set, so that a rerun
// writes the same bytes; else the local time of writing, as OpenImageIO wrote it.
void add_capture_date(Imf::Header& header) {
    const char* epoch = std::getenv("SOURCE_DATE_EPOCH");
    char date[32];
    if (epoch == nullptr) {
        const std::time_t now = std::time(nullptr);
        std::tm local{};
        if (::localtime_r(&now, &local) == nullptr) return;
        std::strftime(date, sizeof date, "%Y:%m:%d %H:%M:%S", &local);
        Imf::addCapDate(header, date);
        return;
    }
    const std::string_view text(epoch);
    long long seconds = -1;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), seconds);
    std::tm utc{};
    const std::time_t t = static_cast<std::time_t>(seconds);
    if (error != std::errc() || end != text.data() + text.size() || seconds < 0 || ::gmtime_r(&t, &utc) == nullptr)
        throw UsageError("SOURCE_DATE_EPOCH: expected seconds since 1970-01-01 UTC, a non-negative integer (got '" +
                         std::string(text.substr(0, 40)) + "')");
    std::strftime(date, sizeof date, "%Y:%m:%d %H:%M:%S", &utc);
    Imf::addCapDate(header, date);
}

}  // namespace

bool has_exr_signature(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::array<char, 4> magic{};
    return in.read(magic.data(), magic.size()) && magic == std::array<char, 4>{0x76, 0x2f, 0x31, 0x01};
}

Image read_exr(const std::filesystem::path& file) {
    return with_exr(file, [&](Imf::InputFile& in) {
        const Imath::Box2i window = in.header().dataWindow();
        const long long width = static_cast<long long>(window.max.x) - window.min.x + 1;
        const long long height = static_cast<long long>(window.max.y) - window.min.y + 1;
        const Imf::ChannelList& channels = in.header().channels();
        std::vector<std::string> names;
        for (auto c = channels.begin(); c != channels.end(); ++c) names.emplace_back(c.name());
        const std::string problem = dimensions_problem(width, height, static_cast<int>(names.size()));
        if (!problem.empty()) throw InputError(InputLocation(file), problem);
        std::array<std::string, 3> rgb;
        if (channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B")) rgb = {"R", "G", "B"};
        else
            for (std::size_t c = 0; c < 3; ++c) rgb[c] = names[std::min(c, names.size() - 1)];
        Image image(static_cast<int>(width), static_cast<int>(height));
        // The slices address the image's own pixels, offset so that the data window's corner lands on index 0.
        char* base = reinterpret_cast<char*>(image.rgb.data()) -
                     (static_cast<std::ptrdiff_t>(window.min.y) * width + window.min.x) * 3 * sizeof(float);
        Imf::FrameBuffer frame;
        for (std::size_t c = 0; c < 3; ++c)
            frame.insert(rgb[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), 3 * sizeof(float),
                                            static_cast<std::size_t>(width) * 3 * sizeof(float)));
        in.setFrameBuffer(frame);
        in.readPixels(window.min.y, window.max.y);
        return image;
    });
}

void write_exr(const std::filesystem::path& file, const Image& image, const ExrColour* colour, const ExrMetadata& metadata) {
    // The attributes OpenImageIO 2.4 wrote (the header's defaults, ZIP compression, half R G B, capDate,
    // chromaticities and colorSpace, then the metadata as string, float or int).
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const char* name : {"R", "G", "B"}) header.channels().insert(name, Imf::Channel(Imf::HALF));
    add_capture_date(header);
    if (colour) {
        const Chromaticities& c = colour->chromaticities;
        auto xy = [](const auto& p) { return Imath::V2f(static_cast<float>(p[0]), static_cast<float>(p[1])); };
        Imf::addChromaticities(header, Imf::Chromaticities(xy(c.red), xy(c.green), xy(c.blue), xy(c.white)));
        header.insert("colorSpace", Imf::StringAttribute(colour->space));
    }
    for (const ExrAttribute& a : metadata) {
        if (const auto* text = std::get_if<std::string>(&a.value)) header.insert(a.name, Imf::StringAttribute(*text));
        else if (const auto* f = std::get_if<float>(&a.value)) header.insert(a.name, Imf::FloatAttribute(*f));
        else header.insert(a.name, Imf::IntAttribute(std::get<int>(a.value)));
    }
    write_staged(file, [&](const std::filesystem::path& temporary) {
        Imf::OutputFile out(temporary.c_str(), header);
        // Each float rounded to the nearest half (Imath's conversion, as OpenImageIO's): OpenEXR writes what it is given.
        std::vector<Imath::half> halves(image.rgb.begin(), image.rgb.end());
        char* base = reinterpret_cast<char*>(halves.data());
        Imf::FrameBuffer frame;
        for (std::size_t c = 0; c < 3; ++c)
            frame.insert(std::string(1, "RGB"[c]), Imf::Slice(Imf::HALF, base + c * sizeof(Imath::half), 3 * sizeof(Imath::half),
                                                             static_cast<std::size_t>(image.width) * 3 * sizeof(Imath::half)));
        out.setFrameBuffer(frame);
        out.writePixels(image.height);
    });
}

ExrMetadata read_image_metadata(const std::filesystem::path& file, const std::string& prefix) {
    return with_exr(file, [&](Imf::InputFile& in) {
        ExrMetadata out;
        for (auto a = in.header().begin(); a != in.header().end(); ++a) {
            const std::string name = a.name();
            if (name.rfind(prefix, 0) != 0) continue;
            if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&a.attribute())) out.push_back({name, s->value()});
            else if (const auto* f = dynamic_cast<const Imf::FloatAttribute*>(&a.attribute())) out.push_back({name, f->value()});
            else if (const auto* i = dynamic_cast<const Imf::IntAttribute*>(&a.attribute())) out.push_back({name, i->value()});
        }
        return out;
    });
}

std::optional<ExrColour> read_exr_colour(const std::filesystem::path& file) {
    return with_exr(file, [&](Imf::InputFile& in) -> std::optional<ExrColour> {
        const Imf::Header& header = in.header();
        if (!Imf::hasChromaticities(header)) return std::nullopt;
        const Imf::Chromaticities& c = Imf::chromaticities(header);
        const auto* space = header.findTypedAttribute<Imf::StringAttribute>("colorSpace");
        return ExrColour{{{{c.red.x, c.red.y}}, {{c.green.x, c.green.y}}, {{c.blue.x, c.blue.y}}, {{c.white.x, c.white.y}}},
                         space ? space->value() : std::string()};
    });
}

}  // namespace metalfit::glpreview
