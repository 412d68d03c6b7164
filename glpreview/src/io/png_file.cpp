// 8-bit RGB PNG files through libpng (write_png and read_png8 of glpreview/io/image_io.hpp).
#include <png.h>
#include <stdio.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "glpreview/io/image_io.hpp"
#include "image_limits.hpp"
#include "libfit/base/errors.hpp"
#include "staged_write.hpp"

namespace metalfit::glpreview {
namespace {

struct FileCloser {
    void operator()(FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<FILE, FileCloser>;

// libpng reports errors through longjmp by default; these turn them into exceptions (libpng is built for C++ callers
// to throw from its error callback: the stack above is libpng's own, holding nothing to destroy).
[[noreturn]] void throw_png_error(png_structp, png_const_charp message) { throw std::runtime_error(message); }
void ignore_png_warning(png_structp, png_const_charp) {}

// The gamma of the gAMA chunk as OpenImageIO 2.4 computed it from the name "Gamma<g>" (g printed with 6 decimals,
// read back as a float, 1 outside 0.01 to 10), so that the chunk's value stays the same.
float gamma_written(double gamma) {
    const float g = std::stof(std::to_string(gamma));
    return g >= 0.01f && g <= 10.0f ? g : 1.0f;
}

}  // namespace

void write_png(const std::filesystem::path& file, const Image& image, const DisplayTransform& display) {
    const std::vector<unsigned char> pixels = display.apply(image.rgb, image.width, image.height);
    write_staged(file, [&](const std::filesystem::path& temporary) {
        const File out(std::fopen(temporary.c_str(), "wb"));
        if (!out) throw std::runtime_error("cannot create " + temporary.string());
        png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, throw_png_error, ignore_png_warning);
        if (png == nullptr) throw std::runtime_error("libpng: cannot create a writer");
        png_infop info = png_create_info_struct(png);
        struct Destroy {
            png_structp& png;
            png_infop& info;
            ~Destroy() { png_destroy_write_struct(&png, &info); }
        } destroy{png, info};
        if (info == nullptr) throw std::runtime_error("libpng: cannot create a writer");
        png_init_io(png, out.get());
        // The settings and chunks OpenImageIO 2.4's PNG writer used, so that the bytes stay the same: zlib level 6,
        // the default strategy, libpng's default filters; IHDR, oFFs 0 0, the colour chunks of the display and its name.
        png_set_compression_level(png, 6);
        png_set_compression_strategy(png, 0 /* Z_DEFAULT_STRATEGY */);
        png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
                     PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        png_set_oFFs(png, info, 0, 0, PNG_OFFSET_PIXEL);
        // sRGB: the sRGB chunk with gAMA 0.45455 and cHRM of Rec.709 / D65; a pure gamma g: gAMA 1/g. Another display
        // (other primaries, another curve) gets no colour chunk: none would be true.
        // OpenImageIO's readers learn the same from the tEXt chunk "oiio:ColorSpace" ("sRGB", "Gamma<g>").
        const DisplayEncoding& encoding = display.encoding();
        std::string space;
        if (encoding.kind == DisplayEncoding::Kind::srgb) {
            png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_ABSOLUTE);
            space = "sRGB";
        } else if (encoding.kind == DisplayEncoding::Kind::gamma) {
            png_set_gAMA(png, info, 1.0f / gamma_written(encoding.gamma));
            space = "Gamma" + std::to_string(encoding.gamma);
        }
        std::string key = "oiio:ColorSpace";
        png_text text{};
        text.compression = PNG_TEXT_COMPRESSION_NONE;
        text.key = key.data();
        text.text = space.data();
        if (!space.empty()) png_set_text(png, info, &text, 1);
        png_write_info(png, info);
        for (int y = 0; y < image.height; ++y)
            png_write_row(png, pixels.data() + static_cast<std::size_t>(y) * image.width * 3);
        png_write_end(png, info);
        if (std::fflush(out.get()) != 0 || std::ferror(out.get())) throw std::runtime_error("write error");
    });
}

Png8 read_png8(const std::filesystem::path& file) {
    if (const std::string problem = not_a_file_problem(file); !problem.empty())
        throw InputError(InputLocation(file), problem);
    const File in(std::fopen(file.c_str(), "rb"));
    if (!in) throw InputError(InputLocation(file), "cannot read the image: cannot open it");
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, throw_png_error, ignore_png_warning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    struct Destroy {
        png_structp& png;
        png_infop& info;
        ~Destroy() { png_destroy_read_struct(&png, &info, nullptr); }
    } destroy{png, info};
    if (info == nullptr) throw InputError(InputLocation(file), "cannot read the image: libpng cannot create a reader");
    try {
        png_init_io(png, in.get());
        png_read_info(png, info);
        const png_uint_32 width = png_get_image_width(png, info), height = png_get_image_height(png, info);
        const int type = png_get_color_type(png, info);
        const std::string problem = dimensions_problem(width, height, png_get_channels(png, info));
        if (!problem.empty()) throw InputError(InputLocation(file), problem);
        if (type != PNG_COLOR_TYPE_RGB || png_get_bit_depth(png, info) != 8)
            throw InputError(InputLocation(file), "expected an RGB image");
        Png8 out{static_cast<int>(width), static_cast<int>(height),
                 std::vector<unsigned char>(static_cast<std::size_t>(width) * height * 3)};
        for (png_uint_32 y = 0; y < height; ++y)
            png_read_row(png, out.rgb.data() + static_cast<std::size_t>(y) * width * 3, nullptr);
        png_read_end(png, nullptr);
        return out;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError(InputLocation(file), std::string("cannot read the image: ") + e.what());
    }
}

}  // namespace metalfit::glpreview
