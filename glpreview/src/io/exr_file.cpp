#include "exr_file.hpp"

#include <Imath/half.h>
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

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <string>
#include <vector>

#include "glpreview/io/image_io.hpp"
#include "image_limits.hpp"
#include "libfit/base/errors.hpp"
#include "staged_write.hpp"

namespace metalfit::glpreview {
namespace {

// The EXR header walked before OpenEXR reads it (docs/scene.md, "Limits and checks"): OpenEXR allocates what an
// attribute's size, a preview's width x height or a data window declares before it finds the bytes missing (a
// 1 KB file cost 2 GB). Each attribute must fit in the file, previews and string vectors in their attribute, every
// part's data window within the limits and the pixel budget of the file's size, and tiles not so small that their
// offset table (8 bytes a tile, in the file) outgrows it. Empty when OpenEXR may read it; else the one-line reason.
std::string exr_header_problem(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    const std::uintmax_t size = file_bytes(file);
    auto read_u32 = [&](std::uint32_t& v) {
        unsigned char b[4];
        if (!in.read(reinterpret_cast<char*>(b), 4)) return false;
        v = b[0] | (b[1] << 8) | (b[2] << 16) | (static_cast<std::uint32_t>(b[3]) << 24);
        return true;
    };
    auto read_name = [&](std::string& name) {
        name.clear();
        for (char c; in.get(c);) {
            if (c == '\0') return true;
            if (name.size() == 255) return false;
            name.push_back(c);
        }
        return false;
    };
    const std::string truncated = "cannot read the image: the EXR header is truncated or malformed";
    std::uint32_t magic = 0, version = 0;
    if (!read_u32(magic) || !read_u32(version)) return truncated;
    if (version & 0x800) return "deep EXR images are not supported";
    const bool multipart = version & 0x1000;
    for (int part = 0;; ++part) {
        long long width = 0, height = 0, tile_w = 0, tile_h = 0;
        int channels = 0, attributes = 0;
        bool window = false;
        for (std::string name, type;;) {
            if (!read_name(name)) return truncated;
            if (name.empty()) break;  // the end of this header
            std::uint32_t bytes = 0;
            if (!read_name(type) || !read_u32(bytes)) return truncated;
            if (++attributes > 10000) return "more than 10000 attributes in an EXR header";
            const std::uintmax_t at = static_cast<std::uintmax_t>(in.tellg());
            if (bytes > 0x7fffffffu || bytes > size - at)
                return "the EXR attribute '" + name + "' declares " + std::to_string(bytes) + " bytes; the file has " +
                       std::to_string(size - at) + " left";
            std::vector<unsigned char> value;  // only the small ones the check reads
            if (type == "box2i" || type == "chlist" || type == "tiledesc" || type == "preview" ||
                type == "stringvector") {
                const std::uint32_t keep = type == "preview" ? std::min<std::uint32_t>(bytes, 8)
                                           : type == "chlist" || type == "stringvector"
                                               ? std::min<std::uint32_t>(bytes, 1u << 20)
                                               : bytes;
                value.resize(keep);
                if (!in.read(reinterpret_cast<char*>(value.data()), keep)) return truncated;
                in.seekg(bytes - keep, std::ios::cur);
            } else {
                in.seekg(bytes, std::ios::cur);
            }
            if (!in) return truncated;
            auto i32 = [&](std::size_t o) {
                return static_cast<std::int32_t>(value[o] | (value[o + 1] << 8) | (value[o + 2] << 16) |
                                                 (static_cast<std::uint32_t>(value[o + 3]) << 24));
            };
            if (type == "box2i" && name == "dataWindow" && bytes == 16) {
                width = static_cast<long long>(i32(8)) - i32(0) + 1;
                height = static_cast<long long>(i32(12)) - i32(4) + 1;
                window = true;
            } else if (type == "chlist") {
                for (std::size_t o = 0; o < value.size() && value[o] != 0; ++channels) {  // name\0, then 16 bytes
                    while (o < value.size() && value[o] != 0) ++o;
                    o += 17;
                }
            } else if (type == "tiledesc" && bytes >= 8) {
                tile_w = static_cast<std::uint32_t>(i32(0));
                tile_h = static_cast<std::uint32_t>(i32(4));
            } else if (type == "preview") {
                if (bytes < 8) return truncated;
                const std::uint64_t pixels =
                    std::uint64_t{static_cast<std::uint32_t>(i32(0))} * static_cast<std::uint32_t>(i32(4));
                if (8 + 4 * pixels != bytes)
                    return "the EXR preview '" + name + "' declares more pixels than its attribute holds";
            } else if (type == "stringvector") {
                for (std::size_t o = 0; o < value.size();) {
                    if (o + 4 > value.size()) return truncated;
                    const std::uint32_t length = static_cast<std::uint32_t>(i32(o));
                    if (length > value.size() - o - 4) return "a string of the EXR attribute '" + name + "' outruns it";
                    o += 4 + length;
                }
            }
        }
        if (!window) return "the EXR header has no dataWindow";
        if (std::string problem = dimensions_problem(width, height, channels); !problem.empty()) return problem;
        if (std::string problem = budget_problem(width, height, size); !problem.empty()) return problem;
        if (tile_w > 0 && tile_h > 0 &&
            8 * ((width + tile_w - 1) / tile_w) * ((height + tile_h - 1) / tile_h) > static_cast<long long>(size))
            return "the EXR's tiles (" + std::to_string(tile_w) + " x " + std::to_string(tile_h) +
                   ") need an offset table larger than the file";
        if (!multipart) return {};
        if (in.peek() == 0) return {};  // an empty header ends the list of parts
        if (part >= 1000) return "more than 1000 parts in an EXR";
    }
}

// Opens an EXR for reading; OpenEXR's exceptions become InputError naming the file.
template <class Read>
auto with_exr(const std::filesystem::path& file, Read read) {
    if (const std::string problem = not_a_file_problem(file); !problem.empty())
        throw InputError(InputLocation(file), problem);
    if (const std::string problem = exr_header_problem(file); !problem.empty())
        throw InputError(InputLocation(file), problem);
    // OpenEXR's own limits too (they are process-wide): a second line of defence if it reads a header differently.
    static const bool limited = [] {
        Imf::Header::setMaxImageSize(kMaxInputImageSide, kMaxInputImageSide);
        Imf::Header::setMaxTileSize(kMaxInputImageSide, kMaxInputImageSide);
        return true;
    }();
    (void)limited;
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

std::pair<int, int> read_exr_size(const std::filesystem::path& file) {
    return with_exr(file, [&](Imf::InputFile& in) {
        const Imath::Box2i window = in.header().dataWindow();
        return std::pair<int, int>(window.max.x - window.min.x + 1, window.max.y - window.min.y + 1);
    });
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
        if (channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B"))
            rgb = {"R", "G", "B"};
        else
            for (std::size_t c = 0; c < 3; ++c) rgb[c] = names[std::min(c, names.size() - 1)];
        Image image(static_cast<int>(width), static_cast<int>(height));
        // The slices address the image's own pixels, offset so that the data window's corner lands on index 0. A
        // frame buffer holds one slice per channel name: a file with fewer than three channels (delta-e.exr's one) is
        // read into the first slots its channels take, then copied into the others.
        char* base = reinterpret_cast<char*>(image.rgb.data()) -
                     (static_cast<std::ptrdiff_t>(window.min.y) * width + window.min.x) * 3 * sizeof(float);
        Imf::FrameBuffer frame;
        std::array<std::size_t, 3> source{0, 1, 2};
        for (std::size_t c = 0; c < 3; ++c) {
            source[c] = static_cast<std::size_t>(std::find(rgb.begin(), rgb.begin() + c, rgb[c]) - rgb.begin());
            if (source[c] == c)
                frame.insert(rgb[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), 3 * sizeof(float),
                                                static_cast<std::size_t>(width) * 3 * sizeof(float)));
        }
        in.setFrameBuffer(frame);
        in.readPixels(window.min.y, window.max.y);
        for (std::size_t p = 0; p < image.rgb.size(); p += 3)
            for (std::size_t c = 0; c < 3; ++c)
                if (source[c] != c) image.rgb[p + c] = image.rgb[p + source[c]];
        return image;
    });
}

namespace {

// The header every EXR of glpreview gets: the attributes OpenImageIO 2.4 wrote (the header's defaults, ZIP
// compression, the channels, capDate, chromaticities and colorSpace, then the metadata as string, float or int).
Imf::Header exr_header(int width, int height, const std::vector<std::pair<std::string, Imf::PixelType>>& channels,
                       const ExrColour* colour, const ExrMetadata& metadata) {
    Imf::Header header(width, height);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const auto& [name, type] : channels) header.channels().insert(name, Imf::Channel(type));
    add_capture_date(header);
    if (colour) {
        const Chromaticities& c = colour->chromaticities;
        auto xy = [](const auto& p) { return Imath::V2f(static_cast<float>(p[0]), static_cast<float>(p[1])); };
        Imf::addChromaticities(header, Imf::Chromaticities(xy(c.red), xy(c.green), xy(c.blue), xy(c.white)));
        header.insert("colorSpace", Imf::StringAttribute(colour->space));
    }
    for (const ExrAttribute& a : metadata) {
        if (const auto* text = std::get_if<std::string>(&a.value))
            header.insert(a.name, Imf::StringAttribute(*text));
        else if (const auto* f = std::get_if<float>(&a.value))
            header.insert(a.name, Imf::FloatAttribute(*f));
        else
            header.insert(a.name, Imf::IntAttribute(std::get<int>(a.value)));
    }
    return header;
}

}  // namespace

void write_exr(const std::filesystem::path& file, const Image& image, const ExrColour* colour,
               const ExrMetadata& metadata) {
    const Imf::Header header =
        exr_header(image.width, image.height, {{"R", Imf::HALF}, {"G", Imf::HALF}, {"B", Imf::HALF}}, colour, metadata);
    write_staged(file, [&](const std::filesystem::path& temporary) {
        Imf::OutputFile out(temporary.c_str(), header);
        // Each float rounded to the nearest half (Imath's conversion, as OpenImageIO's): OpenEXR writes what it is given.
        std::vector<Imath::half> halves(image.rgb.begin(), image.rgb.end());
        char* base = reinterpret_cast<char*>(halves.data());
        Imf::FrameBuffer frame;
        for (std::size_t c = 0; c < 3; ++c)
            frame.insert(std::string(1, "RGB"[c]),
                         Imf::Slice(Imf::HALF, base + c * sizeof(Imath::half), 3 * sizeof(Imath::half),
                                    static_cast<std::size_t>(image.width) * 3 * sizeof(Imath::half)));
        out.setFrameBuffer(frame);
        out.writePixels(image.height);
    });
}

void write_exr_channel(const std::filesystem::path& file, int width, int height, const std::vector<float>& values,
                       const std::string& channel, const ExrMetadata& metadata) {
    const Imf::Header header = exr_header(width, height, {{channel, Imf::FLOAT}}, nullptr, metadata);
    write_staged(file, [&](const std::filesystem::path& temporary) {
        Imf::OutputFile out(temporary.c_str(), header);
        Imf::FrameBuffer frame;
        frame.insert(channel, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(values.data())),
                                         sizeof(float), static_cast<std::size_t>(width) * sizeof(float)));
        out.setFrameBuffer(frame);
        out.writePixels(height);
    });
}

ExrMetadata read_image_metadata(const std::filesystem::path& file, const std::string& prefix) {
    return with_exr(file, [&](Imf::InputFile& in) {
        ExrMetadata out;
        for (auto a = in.header().begin(); a != in.header().end(); ++a) {
            const std::string name = a.name();
            if (name.rfind(prefix, 0) != 0) continue;
            if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&a.attribute()))
                out.push_back({name, s->value()});
            else if (const auto* f = dynamic_cast<const Imf::FloatAttribute*>(&a.attribute()))
                out.push_back({name, f->value()});
            else if (const auto* i = dynamic_cast<const Imf::IntAttribute*>(&a.attribute()))
                out.push_back({name, i->value()});
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
        return ExrColour{
            {{{c.red.x, c.red.y}}, {{c.green.x, c.green.y}}, {{c.blue.x, c.blue.y}}, {{c.white.x, c.white.y}}},
            space ? space->value() : std::string()};
    });
}

}  // namespace metalfit::glpreview
