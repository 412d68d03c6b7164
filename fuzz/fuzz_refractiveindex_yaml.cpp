// libFuzzer target: refractiveindex.info YAML files (libfit/io/refractiveindex).
#include "fuzz_input.hpp"
#include "libfit/io/refractiveindex.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto file = metalfit::fuzz::input_file(data, size, "input.yml");
    metalfit::fuzz::expect_only_documented_errors([&] { metalfit::load_refractiveindex_yaml(file); });
    return 0;
}
