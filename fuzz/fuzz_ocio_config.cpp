// libFuzzer target: OCIO configs, read as metalfit reads them (libfit/color ColorSpaceConverter::create).
#include "fuzz_input.hpp"
#include "libfit/base/library_logging.hpp"
#include "libfit/color/color_space.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const bool quiet = [] {
        metalfit::route_library_logging("fuzz");
        return true;
    }();
    (void)quiet;
    const auto file = metalfit::fuzz::input_file(data, size, "config.ocio");
    metalfit::fuzz::expect_only_documented_errors([&] {
        metalfit::ColorSpaceConverter::create(metalfit::OcioConfigChoice{file, "fuzz"});
    });
    return 0;
}
