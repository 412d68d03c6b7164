// Every catalog metal in the shape of Anton Palmqvist's Physically Based database (physicallybased.info, API v2,
// header.schemaVersion 2.1): per material F0 (`color`), the F82 tint and Gulbrandsen's edge tint (`specularColor`)
// and per-channel n, k (`complexIor`), each in srgb-linear (Linear Rec.709) and acescg (ACEScg) at once.
// `metalfit table --format physicallybased`; schemas/physicallybased.schema.json describes the document.
//
// F0 = R_c(1) and the F82 tint = R_c(1/7) / Schlick(F0, 1/7) exactly as `metalfit table` computes them. The
// Gulbrandsen edge tint g is solved per channel so that Gulbrandsen's curve with r = F0 passes through R_c(1/7)
// (bisection on g ∈ [0, 1]: both published angles hit exactly), and n, k are Gulbrandsen's mapping of that (r, g):
// their exact Fresnel at normal incidence ((n−1)² + k²)/((n+1)² + k²) is F0 itself. Gulbrandsen's r lies in
// [0, 0.99999]: an F0 outside it (gold's red in Rec.709 is above 1) stays in `color` as it is, and r is held at the
// bound for the edge tint and n, k of that channel.
#pragma once

#include <array>
#include <complex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "libfit/color/color.hpp"
#include "libfit/color/color_space.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/io/catalog.hpp"
#include "libfit/reference/reference_curve.hpp"

namespace metalfit {

// The config's colour space names of physicallybased.info's two spaces (names or aliases, as --space takes them).
inline constexpr const char* kPhysicallyBasedSrgbLinear = "lin_rec709";
inline constexpr const char* kPhysicallyBasedAcescg = "ACEScg";

// One material in one colour space.
struct PhysicallyBasedLook {
    RGB f0, f82_tint, edge_tint;                // edge_tint: Gulbrandsen's g
    std::array<std::complex<double>, 3> eta{};  // n + i k per channel
};

struct PhysicallyBasedRow {
    std::string id, name, reference, doi, licence, database_path;
    PhysicallyBasedLook srgb_linear, acescg;
};

struct PhysicallyBasedTable {
    std::string srgb_linear_space, acescg_space;  // the config's resolved names
    std::vector<PhysicallyBasedRow> rows;
};

struct PhysicallyBasedColour {
    const Colorimetry& colorimetry;
    const ColorSpaceConverter& srgb_linear;
    const ColorSpaceConverter& acescg;
    SpectralOptions spectral;
};

// Gulbrandsen's edge tint g ∈ [0, 1] with Gulbrandsen(r, g, µ = 1/7) = f82 (the nearer end of [0, 1] when no g
// reaches it); r ∈ [0, 0.99999].
double gulbrandsen_edge_tint_at_f82(double r, double f82);

// Every catalog material's primary source, in catalog order.
PhysicallyBasedTable physicallybased_table(const Catalog& catalog, const PhysicallyBasedColour& colour);

// The document {"header", "data"} (no "$schema" and no "images": see docs/export.md).
nlohmann::ordered_json physicallybased_json(const PhysicallyBasedTable& table);

}  // namespace metalfit
