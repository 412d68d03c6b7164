// Where the Python module finds the built-in database.
#pragma once

#include <filesystem>

namespace metalfit::python {

// In this order: $METALFIT_DATA if set and not empty; else the database installed with the module (the module in
// <prefix>/<python dir>, the database in <prefix>/share/metalfit: METALFIT_PYTHON_TO_DATA, the path between them); else
// default_data_dir() (the source tree's data/ when the module runs from the build tree).
std::filesystem::path module_data_dir();

}  // namespace metalfit::python
