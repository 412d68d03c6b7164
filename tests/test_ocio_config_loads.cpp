// The OCIO config is made once per process and file (libfit/color/ocio_config_loads.hpp), and metalfit's own config,
// built through OCIO's API instead of parsed, is the Config OCIO reads from data/ocio/config.ocio.
#include <gtest/gtest.h>

#include "test_support.hpp"

#include <OpenColorIO/OpenColorIO.h>

#include <fstream>
#include <sstream>
#include <string>

#include "libfit/color/color_space.hpp"
#include "libfit/color/ocio_config_loads.hpp"
#include "libfit/color/rgb_conversion.hpp"

namespace metalfit {
namespace test_ocio_config_loads {

namespace OCIO = OCIO_NAMESPACE;
using namespace metalfit::test;

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

std::string serialize(const OCIO::ConstConfigRcPtr& config) {
    std::ostringstream out;
    config->serialize(out);
    return out.str();
}

const OcioConfigChoice kShipped{kData / "ocio" / "config.ocio", "metalfit default"};

// The built config against OCIO's own reading of the file (Config::CreateFromFile, outside metalfit): the same
// serialisation (every key, space, alias, role, display, view and transform, in order), and the same processors.
TEST(OcioConfigLoads, ShippedConfigBuiltEqualsParsed) {
    const OcioConfigLoads before = ocio_config_loads();
    const std::string built = serialized_ocio_config(kShipped);
    const OcioConfigLoads after = ocio_config_loads();
    EXPECT_EQ(after.parsed, before.parsed);  // the shipped bytes are never handed to OCIO's YAML reader
    EXPECT_EQ(after.shipped_built + after.reused, before.shipped_built + before.reused + 1);
    const auto parsed = OCIO::Config::CreateFromFile(kShipped.path.c_str());
    EXPECT_EQ(built, serialize(parsed));

    // A copy with one comment more holds other bytes: metalfit parses it (with all its checks), and gets the same.
    const TempDir dir;
    const fs::path copy = dir.path() / "config.ocio";
    std::ofstream(copy, std::ios::binary) << read_text(kShipped.path) << "# a copy\n";
    EXPECT_EQ(serialized_ocio_config({copy, "test"}), built);
    EXPECT_EQ(ocio_config_loads().parsed, after.parsed + 1);

    // Every conversion from CIE XYZ gives the same numbers through either config.
    for (int i = 0; i < parsed->getNumColorSpaces(); ++i) {
        const char* space = parsed->getColorSpaceNameByIndex(i);
        if (parsed->getColorSpace(space)->isData()) continue;
        float expected[3] = {0.3f, 0.5f, 0.7f}, got[3] = {0.3f, 0.5f, 0.7f};
        parsed->getProcessor("CIE-XYZ-D65", space)->getDefaultCPUProcessor()->applyRGB(expected);
        RgbConversion::create(kShipped, "CIE-XYZ-D65", space).apply(got);
        for (int c = 0; c < 3; ++c) EXPECT_EQ(got[c], expected[c]) << space;
    }
}

// Converters and conversions made from one config file in one process share one Config: OCIO reads the file once,
// whatever asks for it next (another converter, another target, an RGB conversion) reuses it; a changed file is read
// again.
TEST(OcioConfigLoads, OneParsePerProcessAndFile) {
    const TempDir dir;
    const fs::path path = dir.path() / "mine.ocio";
    const std::string text = read_text(kShipped.path) + "# mine\n";
    std::ofstream(path, std::ios::binary) << text;
    const OcioConfigChoice mine{path, "test"};
    const OcioConfigLoads before = ocio_config_loads();
    const ColorSpaceConverter a = ColorSpaceConverter::create(mine);
    const ColorSpaceConverter b = ColorSpaceConverter::create(mine, "ACEScg");
    const RgbConversion c = RgbConversion::create(mine, "lin_rec709", "ACEScg");
    const ColorSpaceConverter d = ColorSpaceConverter::create(mine);
    OcioConfigLoads after = ocio_config_loads();
    EXPECT_EQ(after.parsed, before.parsed + 1);
    EXPECT_GE(after.reused, before.reused + 3);
    EXPECT_EQ(a({0.2, 0.3, 0.4}).r, d({0.2, 0.3, 0.4}).r);

    std::ofstream(path, std::ios::binary) << text << "# changed\n";
    const ColorSpaceConverter e = ColorSpaceConverter::create(mine);
    EXPECT_EQ(ocio_config_loads().parsed, after.parsed + 1);
    EXPECT_EQ(a({0.2, 0.3, 0.4}).g, e({0.2, 0.3, 0.4}).g);
}

}  // namespace test_ocio_config_loads
}  // namespace metalfit
