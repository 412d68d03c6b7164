// What the EXRs of a scene preview say about their spheres in their headers (docs/preview.md, "Outputs"), so that
// an image read on its own tells which material, model, parameters and roughness each sphere shows.
#pragma once

#include <string>
#include <vector>

#include "glpreview/io/image_io.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

// Per sphere i (scene order): metalfit/sphere<i>/material (as the scene names it), name, source, model ("reference"
// or the model id), params ("fit", "closed"; models only), parameters ("F0 = (r, g, b); tint = (r, g, b)", 9
// significant digits; models only), roughness (float) and reflection; and metalfit/spheres (int) and metalfit/scene.
ExrMetadata sphere_metadata(const Scene& scene, const std::vector<const SphereFresnel*>& fresnel);

// `metadata` with what every EXR metalfit writes carries: metalfit/version and metalfit/image (the file name).
ExrMetadata image_metadata(ExrMetadata metadata, const std::string& file);

}  // namespace metalfit::glpreview
