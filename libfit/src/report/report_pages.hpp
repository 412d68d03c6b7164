// The HTML pages of the report (private to the report stage): skeletons that load the chart libraries, the page
// script and report-data.js; the script builds everything on them from report.json.
#pragma once

#include <string>

#include "libfit/fit/fit.hpp"

namespace metalfit::report_detail {

std::string catalog_page();
std::string material_page(const Material& material);

}  // namespace metalfit::report_detail
