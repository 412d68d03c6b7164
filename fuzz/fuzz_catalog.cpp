// libFuzzer target: the catalog (libfit/io/catalog), catalog.json of a data folder.
#include "fuzz_input.hpp"
#include "libfit/io/catalog.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto file = metalfit::fuzz::input_file(data, size, "catalog.json");
    metalfit::fuzz::expect_only_documented_errors([&] { metalfit::Catalog::load(file.parent_path()); });
    return 0;
}
