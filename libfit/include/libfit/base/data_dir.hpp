// Where the built-in database lives.
#pragma once

#include <filesystem>

namespace metalfit {

// In this order: $METALFIT_DATA if set; else <directory of the running executable>/../share/metalfit if that
// directory exists (an installed, relocatable metalfit: <prefix>/bin and <prefix>/share/metalfit, found through
// /proc/self/exe); else the data/ folder of the source tree metalfit was built from (running from the build tree).
std::filesystem::path default_data_dir();

}  // namespace metalfit
