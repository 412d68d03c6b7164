// The options of the error a fit minimises and reports (fit, report): metric, angular weight, quadrature nodes.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "libfit/reference/sampled_reference.hpp"

namespace metalfit::cli {

struct ErrorOptions {
    std::string metric = "rel";
    std::string weight = "uniform";
    int nodes = 128;

    ErrorSettings settings() const;
};

void add_error_options(CLI::App& app, ErrorOptions& options);

}  // namespace metalfit::cli
