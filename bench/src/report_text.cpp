#include <algorithm>

#include "metalfit_bench/bench_report.hpp"
#include "report_tables.hpp"

namespace metalfit::bench {
namespace {

std::size_t width(const std::string& s) {
    std::size_t n = 0;
    for (unsigned char c : s) n += (c & 0xC0) != 0x80;  // code points, so that "±" and "μ" line up
    return n;
}

std::string pad(const std::string& s, std::size_t w, bool right) {
    const std::string fill(w > width(s) ? w - width(s) : 0, ' ');
    return right ? fill + s : s + fill;
}

}  // namespace

std::string to_text(const BenchReport& r) {
    std::string out = "metalfit bench on " + r.machine.one_line() + "\n" + detail::run_line(r) + "\n";
    for (const detail::Table& t : detail::report_tables(r)) {
        out += "\n" + t.title + "\n";
        std::vector<std::size_t> w(t.headers.size(), 0);
        for (std::size_t c = 0; c < t.headers.size(); ++c) w[c] = width(t.headers[c]);
        for (const auto& row : t.rows)
            for (std::size_t c = 0; c < row.size() && c < w.size(); ++c) w[c] = std::max(w[c], width(row[c]));
        const auto line = [&](const std::vector<std::string>& cells) {
            std::string l = " ";
            for (std::size_t c = 0; c < cells.size() && c < w.size(); ++c) l += " " + pad(cells[c], w[c], c > 0);
            while (!l.empty() && l.back() == ' ') l.pop_back();
            out += l + "\n";
        };
        line(t.headers);
        for (const auto& row : t.rows) line(row);
        for (const std::string& n : t.notes) out += "  " + n + "\n";
    }
    const std::vector<std::string> skipped = detail::skipped_lines(r);
    if (!skipped.empty()) out += "\n";
    for (const std::string& s : skipped) out += s + "\n";
    return out;
}

}  // namespace metalfit::bench
