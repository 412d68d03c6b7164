#include "libfit/base/data_dir.hpp"

#include <cstdlib>

namespace metalfit {

std::filesystem::path default_data_dir() {
    if (const char* env = std::getenv("METALFIT_DATA"); env != nullptr && *env != '\0') return env;
    return METALFIT_DATA_DIR;
}

}  // namespace metalfit
