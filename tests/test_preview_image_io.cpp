// glpreview's image files (issue 19 item 4): EXRs through OpenEXR, read back here through OpenEXR's own API (the
// half pixels, the header's attributes and their types); OpenImageIO only in the module, loaded when a run needs it.
#include <gtest/gtest.h>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>

#include "glpreview/io/image_io.hpp"
#include "libfit/base/errors.hpp"
#include "test_support.hpp"

namespace metalfit::test {
namespace test_preview_image_io {

using glpreview::ExrColour;
using glpreview::Image;

TEST(PreviewImageIo, AnExrCarriesHalfPixelsChromaticitiesAndTypedAttributesAsOpenExrReadsThem) {
    TempDir dir;
    Image image(3, 2);
    for (std::size_t i = 0; i < image.rgb.size(); ++i)
        image.rgb[i] = 0.1f * static_cast<float>(i) + 1e-4f;  // not halves
    const ExrColour colour{{{{0.708, 0.292}}, {{0.170, 0.797}}, {{0.131, 0.046}}, {{0.3127, 0.3290}}},
                           "Linear Rec.2020"};
    const glpreview::ExrMetadata metadata{{"metalfit/sphere0/material", std::string("Au")},
                                          {"metalfit/sphere0/roughness", 0.25f},
                                          {"metalfit/spheres", 1}};
    ::setenv("SOURCE_DATE_EPOCH", "0", 1);
    glpreview::write_exr(dir.path() / "a.exr", image, &colour, metadata);
    ::unsetenv("SOURCE_DATE_EPOCH");

    Imf::InputFile in((dir.path() / "a.exr").c_str());
    const Imf::Header& header = in.header();
    EXPECT_EQ(header.compression(), Imf::ZIP_COMPRESSION);
    int channels = 0;
    for (auto c = header.channels().begin(); c != header.channels().end(); ++c, ++channels)
        EXPECT_EQ(c.channel().type, Imf::HALF) << c.name();
    EXPECT_EQ(channels, 3);
    ASSERT_TRUE(Imf::hasCapDate(header));
    EXPECT_EQ(Imf::capDate(header), "1970:01:01 00:00:00");
    ASSERT_TRUE(Imf::hasChromaticities(header));
    EXPECT_FLOAT_EQ(Imf::chromaticities(header).red.x, 0.708f);
    EXPECT_FLOAT_EQ(Imf::chromaticities(header).white.y, 0.3290f);
    ASSERT_TRUE(header.findTypedAttribute<Imf::StringAttribute>("colorSpace"));
    EXPECT_EQ(header.typedAttribute<Imf::StringAttribute>("colorSpace").value(), "Linear Rec.2020");
    ASSERT_TRUE(header.findTypedAttribute<Imf::StringAttribute>("metalfit/sphere0/material"));
    EXPECT_EQ(header.typedAttribute<Imf::StringAttribute>("metalfit/sphere0/material").value(), "Au");
    ASSERT_TRUE(header.findTypedAttribute<Imf::FloatAttribute>("metalfit/sphere0/roughness"));
    EXPECT_EQ(header.typedAttribute<Imf::FloatAttribute>("metalfit/sphere0/roughness").value(), 0.25f);
    ASSERT_TRUE(header.findTypedAttribute<Imf::IntAttribute>("metalfit/spheres"));
    EXPECT_EQ(header.typedAttribute<Imf::IntAttribute>("metalfit/spheres").value(), 1);

    // The pixels are each float rounded to the nearest half, in R, G, B order, top row first.
    std::vector<Imath::half> read(image.rgb.size());
    Imf::FrameBuffer frame;
    for (int c = 0; c < 3; ++c)
        frame.insert(std::string(1, "RGB"[c]),
                     Imf::Slice(Imf::HALF, reinterpret_cast<char*>(read.data() + c), 3 * sizeof(Imath::half),
                                3 * sizeof(Imath::half) * image.width));
    in.setFrameBuffer(frame);
    in.readPixels(0, image.height - 1);
    for (std::size_t i = 0; i < read.size(); ++i) EXPECT_EQ(read[i].bits(), Imath::half(image.rgb[i]).bits()) << i;

    // Without $SOURCE_DATE_EPOCH, the capture date is the time of writing.
    glpreview::write_exr(dir.path() / "now.exr", image);
    const Imf::InputFile now((dir.path() / "now.exr").c_str());
    ASSERT_TRUE(Imf::hasCapDate(now.header()));
    EXPECT_EQ(Imf::capDate(now.header()).size(), 19u) << Imf::capDate(now.header());
    EXPECT_FALSE(Imf::hasChromaticities(now.header()));

    // glpreview's own readers give the same back.
    const Image back = glpreview::read_image(dir.path() / "a.exr");
    for (std::size_t i = 0; i < read.size(); ++i) EXPECT_EQ(back.rgb[i], static_cast<float>(read[i])) << i;
    EXPECT_EQ(glpreview::read_image_metadata(dir.path() / "a.exr", "metalfit/").size(), 3u);
    EXPECT_EQ(glpreview::read_exr_colour(dir.path() / "a.exr")->space, "Linear Rec.2020");
}

TEST(PreviewImageIo, AnExrThatIsNotOneIsBadInputNamingTheFile) {
    TempDir dir;
    const fs::path bad = dir.write("cut.exr", std::string("\x76\x2f\x31\x01", 4) + "truncated");
    try {
        glpreview::read_image(bad);
        FAIL() << "read a truncated EXR";
    } catch (const InputError& e) {
        EXPECT_TRUE(std::string(e.what()).starts_with(bad.string() + ": cannot read the image: ")) << e.what();
    }
}

// The scene of the two runs below: EXR and PNG outputs, an environment from `environment`.
fs::path write_scene(const TempDir& dir, const std::string& environment) {
    return dir.write("scene.json",
                     R"({"image": {"width": 24, "height": 16}, )" + environment +
                         R"("spheres": [{"center": [0, 1, 0], "radius": 0.5, "reflection": "classic"}]})");
}

TEST(PreviewImageIo, OpenImageIoIsLoadedOnlyByARunThatNeedsIt) {
    TempDir dir;
    // The dynamic linker names every library it loads (LD_DEBUG=libs, on stderr).
    const fs::path plain = write_scene(dir, "");
    const CommandResult exr_png = run_command(kGlpreviewExe, plain.string() + " -o " + (dir.path() / "a").string(),
                                              dir.path(), "OCIO= LD_DEBUG=libs");
    ASSERT_EQ(exr_png.exit_code, 0) << exr_png.err;
    EXPECT_TRUE(fs::exists(dir.path() / "a" / "beauty.exr") && fs::exists(dir.path() / "a" / "beauty.png"));
    EXPECT_TRUE(Contains(exr_png.err, "libOpenEXR")) << "LD_DEBUG gave no library names";
    EXPECT_FALSE(Contains(exr_png.err, "libOpenImageIO"));
    const fs::path sky = write_scene(dir, R"("environment": {"type": "equirect", "file": ")" +
                                              (kData / "scenes" / "sky.hdr").string() + R"("}, )");
    const CommandResult hdr = run_command(kGlpreviewExe, sky.string() + " -o " + (dir.path() / "b").string(),
                                          dir.path(), "OCIO= LD_DEBUG=libs");
    ASSERT_EQ(hdr.exit_code, 0) << hdr.err;
    EXPECT_TRUE(Contains(hdr.err, "libmetalfit_glpreview_oiio.so"));
    EXPECT_TRUE(Contains(hdr.err, "libOpenImageIO"));
}

TEST(PreviewImageIo, AMissingOpenImageIoModuleIsOneLineNamingIt) {
    TempDir dir;
    // A glpreview without the module beside it (and none installed): EXR and PNG still work, a .hdr does not.
    const fs::path lone = dir.path() / "glpreview";
    fs::copy_file(kGlpreviewExe, lone);
    const CommandResult exr_png =
        run_command(lone, write_scene(dir, "").string() + " -o " + (dir.path() / "a").string(), dir.path());
    ASSERT_EQ(exr_png.exit_code, 0) << exr_png.err;
    const fs::path sky = write_scene(dir, R"("environment": {"type": "equirect", "file": ")" +
                                              (kData / "scenes" / "sky.hdr").string() + R"("}, )");
    const CommandResult hdr = run_command(lone, sky.string() + " -o " + (dir.path() / "b").string(), dir.path());
    EXPECT_EQ(hdr.exit_code, 1);
    EXPECT_TRUE(Contains(hdr.err, "the OpenImageIO module (libmetalfit_glpreview_oiio.so")) << hdr.err;
    EXPECT_TRUE(Contains(hdr.err, (dir.path() / "libmetalfit_glpreview_oiio.so").string())) << hdr.err;
    EXPECT_EQ(std::count(hdr.err.begin(), hdr.err.end(), '\n'), 1) << hdr.err;
}

}  // namespace test_preview_image_io
}  // namespace metalfit::test
