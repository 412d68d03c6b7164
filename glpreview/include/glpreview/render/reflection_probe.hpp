// A scene's environment captured as a reflection probe (docs/preview.md, "Reflection probes"), as an engine bakes
// one: the equirect image seen from the capture point (each texel centre's ray traced exactly by the CPU tracer), and
// the scene that renders the same spheres with that image on the proxy matching the environment — the room's box, the
// sphere room's sphere, or an equirect's own proxy. An equirect at infinity has no proxy to give and is refused.
#pragma once

#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "glpreview/io/image.hpp"
#include "glpreview/io/image_io.hpp"
#include "glpreview/scene/scene.hpp"
#include "libfit/color/color_space.hpp"

namespace metalfit::glpreview {

struct ReflectionProbe {
    Image image;                   // width × height equirect, linear, in the scene's space
    ExrColour colour;              // that space: its primaries and white, its name (the probe's `colorspace`)
    nlohmann::ordered_json scene;  // the scene file's JSON with `environment` replaced by the probe on its proxy
};

// The probe of `scene` (read from scene.file) at `width` × `height`. Throws UsageError for an equirect at infinity,
// InputError for what the scene's files or colour space get wrong.
ReflectionProbe capture_probe(const Scene& scene, const OcioConfigChoice& ocio, int width, int height);

// OUTPUT/probe.exr (with its chromaticities and colour space) and OUTPUT/probe.json, the two as one unit; returns
// their paths.
std::vector<std::filesystem::path> write_probe(const ReflectionProbe& probe, const std::filesystem::path& output_dir);

}  // namespace metalfit::glpreview
