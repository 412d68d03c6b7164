// Internal: rows of a tabulated file that no material has (negative n, k or ε₂, n or k above 1e6, |n + ik| near 0)
// lying outside the visible range. Such a row far from it (Lu and Garcia-Cortes's n < 0 in the infrared) does not stop
// the file from being used: the rows from it outward are dropped with a warning. One inside the range, or one that is
// the sample bracketing 360 or 830 nm (no valid sample between it and the range), is refused as before.
// Used by load_nk_csv (csv.cpp) and the refractiveindex.info reader (refractiveindex.cpp).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "libfit/base/errors.hpp"
#include "libfit/spectral/spectrum.hpp"

namespace metalfit::detail {

// A row refused by the checks of the import range: its wavelength, the error it is refused with, and the curves it
// gives values of (bit 0: n, bit 1: k).
struct UnphysicalRow {
    double nm = 0;
    InputError error;
    unsigned curves = 0;
};

// What was kept of each curve: the open interval (after_nm, before_nm) between its dropped rows (±inf when none).
struct KeptRange {
    double after_nm = -std::numeric_limits<double>::infinity(), before_nm = std::numeric_limits<double>::infinity();
    bool keeps(double nm) const { return nm > after_nm && nm < before_nm; }
};

struct UnphysicalTrim {
    KeptRange n, k;
    std::vector<std::string> warnings;  // one line per dropped side of a curve (the same row named once)
};

// `bad` in the file's order; `n` and `k` the valid samples read (either may be empty). Throws the first bad row that
// lies in kVisibleRange, then any that brackets an end of it; otherwise removes from `n` and `k` the samples at and
// beyond their bad rows on each side and says so. `unit_per_nm` and `unit` write wavelengths in the file's unit
// (1e-3 and "µm" for refractiveindex.info, 1 and "nm" for tables).
UnphysicalTrim drop_unphysical_ends(const std::vector<UnphysicalRow>& bad, std::vector<SpectrumSample>& n,
                                    std::vector<SpectrumSample>& k, double unit_per_nm, const char* unit);

}  // namespace metalfit::detail
