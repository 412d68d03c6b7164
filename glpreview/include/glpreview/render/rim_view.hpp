// The grazing-rim view of a scene render (outputs.rim: rim.png; docs/preview.md, "Error views"): one row per sphere;
// on the left its rim unwrapped (render/rim_unwrap) and magnified, as strips: the model (the GPU beauty frame), the
// traced reference, the signed error view of the two (render/error_view, its own scale) and, where the frame with
// the exact curves was made, the fit error alone; on the right the sphere's Fresnel curves F(μ) per channel, the
// model's solid and the material's exact curve dotted, with the μ range of the rim's pixels shaded.
#pragma once

#include <string>
#include <vector>

#include "glpreview/io/image.hpp"
#include "glpreview/render/cpu_reference.hpp"
#include "glpreview/render/error_view.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

inline constexpr int kRimStripRows = 40;  // rows of a strip: the rim's 10 % of the radius, magnified
inline constexpr int kRimLabelRows = 14;  // the label band above each strip
inline constexpr int kRimPlotWidth = 300;
inline constexpr int kRimMinColumns = 240, kRimMaxColumns = 720;  // one column per pixel of the rim's length

struct RimInputs {
    const Scene& scene;
    const Image& beauty;
    const ReferenceRender& reference;
    const Image* fit_reference = nullptr;     // the frame with the exact curves (null: no fit-error strip)
    std::vector<const SphereFresnel*> shown;  // each sphere's Fresnel
    std::vector<const SphereFresnel*> exact;  // its material's exact curve
    LuminanceWeights luminance;               // the scene's space (the error views)
    double exposure = 1.0;                    // the strips of radiance, as the PNGs show them
    bool labels = true;                       // the text (needs the OpenImageIO module)
};

// The whole picture (linear RGB, already exposed: written with PngExposure::already_applied).
Image rim_view_image(const RimInputs& in);

}  // namespace metalfit::glpreview
