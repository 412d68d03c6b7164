// Where the built-in database lives.
#pragma once

#include <filesystem>

namespace metalfit {

// $METALFIT_DATA if set, else the data/ folder of the source tree metalfit was built from.
std::filesystem::path default_data_dir();

}  // namespace metalfit
