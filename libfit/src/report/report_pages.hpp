// The HTML pages of the report (private to the report stage): skeletons that load the chart libraries, the page
// script and report-data.js; the script builds everything on them from report.json.
#pragma once

#include <string>

#include "libfit/fit/fit.hpp"

namespace metalfit::report_detail {

std::string catalog_page();
std::string material_page(const Material& material);
// The material page's path in the report folder: "materials/<id as a path component>.html" (libfit/base/names.hpp),
// also its link in report.json; an id like "../../x" stays inside the folder.
std::string material_page_file(const Material& material);
// A material's sphere renders in the report folder: "assets/renders/<id as a path component>.png" (its page's name).
std::string render_image_file(const std::string& material_id);

}  // namespace metalfit::report_detail
