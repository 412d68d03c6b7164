// libFuzzer target: the headers of HDR and EXR environment images (glpreview/io read_image_size: the checks read_image
// makes before any pixel, then the header as OpenEXR, for a file with EXR's magic number, or the OpenImageIO module
// reads it; no pixels, so that a run does thousands of inputs a second). The first byte picks the extension.
#include "fuzz_input.hpp"
#include "glpreview/io/image_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const auto file = metalfit::fuzz::input_file(data + 1, size - 1, data[0] & 1 ? "input.exr" : "input.hdr");
    metalfit::fuzz::expect_only_documented_errors([&] { metalfit::glpreview::read_image_size(file); });
    return 0;
}
