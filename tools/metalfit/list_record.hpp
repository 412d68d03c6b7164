// The record of `metalfit list --json`: one object per catalog material (id, name, kind, source, alternates,
// wavelength coverage, reference, note). Shared by `metalfit list` and the Python module's catalog().
#pragma once

#include <nlohmann/json.hpp>

#include "libfit/io/catalog.hpp"

namespace metalfit::cli {

nlohmann::json list_record(const Catalog& catalog);

}  // namespace metalfit::cli
