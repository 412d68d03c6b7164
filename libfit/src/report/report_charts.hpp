// The Vega-Lite specs of the report's charts (private to the report stage). Each spec names its data
// ("datasets" filled by the page script from report.json's numbers), never holds numbers itself.
#pragma once

#include <nlohmann/json.hpp>

namespace metalfit::report_detail {

// {"catalog": {chart id: spec}, "material": {chart id: spec}}: the charts of the catalog page and of every material
// page; the page script embeds each into the element of the same id.
nlohmann::ordered_json chart_specs(bool with_costs);

}  // namespace metalfit::report_detail
