// The tables of a bench report as strings, rendered by report_text.cpp (aligned columns) and report_markdown.cpp
// (Markdown), so that the page and the terminal show the same figures.
#pragma once

#include <string>
#include <vector>

#include "metalfit_bench/bench_report.hpp"

namespace metalfit::bench::detail {

struct Table {
    std::string title;
    std::vector<std::string> headers;
    std::vector<std::vector<std::string>> rows;
    std::vector<std::string> notes;  // one line each, printed under the table
};

std::vector<Table> report_tables(const BenchReport& report);

// One line per skipped section ("GPU sections skipped: ..."), empty when nothing was skipped.
std::vector<std::string> skipped_lines(const BenchReport& report);

// The run in one line: material, rounds, catalog size, wall time.
std::string run_line(const BenchReport& report);

}  // namespace metalfit::bench::detail
