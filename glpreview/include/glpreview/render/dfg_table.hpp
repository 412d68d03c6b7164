// The split-sum DFG term of one rough sphere's own Fresnel: a 2D table over (μ = n·v, roughness) of the
// GGX-weighted integral ∫ F(v·h) D(h) G2(v, l) / (4 n·v) dl of that sphere's F — the libfit model with its
// parameters, or the exact R_c table for `reference` — never Schlick's F0·A + B applied to another curve.
// Computed on the CPU by visible-normal sampling over a Hammersley set; uploaded as a 2D RGB texture the
// prefiltered method multiplies its prefiltered radiance by (docs/scene.md, "Rough spheres").
#pragma once

#include <map>
#include <vector>

#include "glpreview/render/sphere_fresnel.hpp"

namespace metalfit::glpreview {

struct DfgTable {
    static constexpr int kMuSize = 32;         // μ_i = i / (kMuSize − 1)
    static constexpr int kRoughnessSize = 17;  // roughness_j = j / (kRoughnessSize − 1)
    static constexpr int kSamples = 4096;      // Hammersley points per entry

    std::vector<RGB> values;  // [j * kMuSize + i]

    RGB at(int mu_index, int roughness_index) const {
        return values[static_cast<std::size_t>(roughness_index) * kMuSize + mu_index];
    }
    // Bilinear between the entries, clamped to the table (as the GPU's linear filter between texel centres).
    RGB operator()(double mu, double roughness) const;
};

// The tables of the rough spheres of one Fresnel model (one per distinct material and parameters), as one pass
// of the preview graph makes them.
struct DfgSet {
    std::map<const SphereFresnel*, DfgTable> tables;
};

// The table of `fresnel` (the values SphereFresnel::operator() gives, as on the GPU).
DfgTable make_dfg_table(const SphereFresnel& fresnel);

// The lobe integral of F at one (μ, roughness): the entry's definition (make_dfg_table evaluates it at the grid).
// μ is taken as at least 1e-4 (at μ = 0 the view direction lies in the tangent plane).
RGB dfg_integral(const SphereFresnel& fresnel, double mu, double roughness, int samples = DfgTable::kSamples);

}  // namespace metalfit::glpreview
