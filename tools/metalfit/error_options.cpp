#include "error_options.hpp"

#include "commands.hpp"

namespace metalfit::cli {

ErrorSettings ErrorOptions::settings() const {
    return {nodes, parse_error_metric(metric), parse_angular_weight(weight)};
}

void add_error_options(CLI::App& app, ErrorOptions& o) {
    app.add_option("--metric", o.metric, "Error the fit minimises: rel or abs")
        ->check(CLI::IsMember(names_of(kErrorMetricNames)));
    app.add_option("--weight", o.weight, "Angular weight: uniform (in mu) or cosine (2 mu)")
        ->check(CLI::IsMember(names_of(kAngularWeightNames)));
    app.add_option("--nodes", o.nodes, "Gauss-Legendre nodes on [0, 1]")->check(CLI::Range(2, 4096));
}

}  // namespace metalfit::cli
