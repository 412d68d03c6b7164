// libFuzzer target: user n,k CSV tables (libfit/io/csv).
#include "fuzz_input.hpp"
#include "libfit/io/csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto file = metalfit::fuzz::input_file(data, size, "input.csv");
    metalfit::fuzz::expect_only_documented_errors([&] { metalfit::load_nk_csv(file); });
    return 0;
}
