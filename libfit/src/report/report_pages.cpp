#include "report/report_pages.hpp"

#include <vector>

#include "libfit/base/names.hpp"
#include "libfit/base/text.hpp"

namespace metalfit::report_detail {
namespace {

// `root`: the path from the page to the report folder ("." or "..").
// A material page also loads the viewer (viewer.js, then three.js, which hands it three.js's modules).
std::string page(const std::string& title, const std::string& body_attributes, const std::string& root, bool viewer) {
    std::vector<const char*> names{"vega.min.js", "vega-lite.min.js", "vega-embed.min.js", "report.js"};
    if (viewer) names.insert(names.end(), {"viewer.js", "three.js"});
    names.push_back("report-data.js");
    std::string scripts;
    for (const char* script : names) scripts += "<script src=\"" + root + "/assets/" + script + "\"></script>\n";
    return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + html_escaped(title) +
           "</title>\n<link rel=\"stylesheet\" href=\"" + root + "/assets/report.css\">\n</head>\n<body " +
           body_attributes + ">\n<main id=\"content\"></main>\n<noscript>This report is drawn by JavaScript from " +
           root + "/report.json (no network needed): enable scripts, or read report.json.</noscript>\n" + scripts +
           "</body>\n</html>\n";
}

}  // namespace

std::string catalog_page() { return page("metalfit report", "data-page=\"catalog\"", ".", false); }

std::string material_page(const Material& material) {
    return page("metalfit report: " + material.name + " (" + material.id + ")",
                "data-page=\"material\" data-material=\"" + html_escaped(material.id) + "\"", "..", true);
}

std::string material_page_file(const Material& material) {
    return "materials/" + path_component(material.id) + ".html";
}

std::string render_image_file(const std::string& material_id) {
    return "assets/renders/" + path_component(material_id) + ".png";
}

}  // namespace metalfit::report_detail
