// libFuzzer target: glpreview's scene parser (glpreview/scene, parse_scene), called as glpreview calls it.
#include <string>

#include "fuzz_input.hpp"
#include "glpreview/scene/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    metalfit::fuzz::expect_only_documented_errors([&] { metalfit::glpreview::parse_scene(text, "fuzz-scene.json"); });
    return 0;
}
