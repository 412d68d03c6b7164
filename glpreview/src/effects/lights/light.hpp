// The scene's lights (docs/scene.md, "Lights"), as the lights effect reads them: point and spot lights of a radiant
// intensity (W/sr), directional lights of an irradiance (W/m², normal to the light), sphere lights of a surface
// radiance (W/(m²·sr)); each a colour times its intensity, in the scene's colour space. Their shadow maps and the
// occluders that cast into them (every sphere and room box).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "glpreview/scene/scene.hpp"
#include "glpreview/scene/scene_reader.hpp"

namespace metalfit::glpreview {

enum class LightType { point, spot, directional, sphere };
inline constexpr EnumNames kLightTypeNames{"light type", KnownNamesWording::known,
                                           std::array{EnumName<LightType>{LightType::point, "point"},
                                                      EnumName<LightType>{LightType::spot, "spot"},
                                                      EnumName<LightType>{LightType::directional, "directional"},
                                                      EnumName<LightType>{LightType::sphere, "sphere"}}};

struct Light {
    LightType type = LightType::point;
    Vec3 position;             // point, spot, sphere
    Vec3 direction{0, -1, 0};  // unit: where a spot points, where directional light travels
    RGB colour{1, 1, 1};
    double intensity = 1;        // W/sr (point, spot), W/m² (directional), W/(m²·sr) (sphere)
    double radius = 0;           // sphere
    double cone_inner_deg = 30;  // spot: full intensity inside, none outside the outer angle
    double cone_outer_deg = 45;

    RGB power() const { return intensity * colour; }
    bool local() const { return type != LightType::directional; }  // at a position (a cube shadow map)
};

// The lights of a scene (Scene::effects); at most kMaxLights.
struct Lights {
    std::vector<Light> lights;
};
inline constexpr std::size_t kMaxLights = 8;
inline constexpr int kShadowMapSize = 256;

inline const char* to_string(LightType type) { return kLightTypeNames.name(type).data(); }
const char* intensity_unit(LightType type);  // "W/sr", "W/m2", "W/m2/sr"

// The "lights" key (an array), read strictly: errors name the file and the field.
Lights read_lights(const SceneReader& top);
// The checks that need the spheres: a room environment, every light inside the room and outside every sphere.
void check_lights(const SceneReader& top, const Scene& scene, const Lights& lights);

// Which shadow map each light draws into: its layer among the cube maps (point, spot, sphere) or the planes
// (directional), or none when nothing can cast a shadow from it (no sphere or box; for a spot, none in its cone).
struct ShadowLayout {
    std::vector<int> layer;        // per light; −1: none
    std::vector<std::string> why;  // per light: why it has a map or not (--explain)
    int cubes = 0, planes = 0;
};
ShadowLayout shadow_layout(const Scene& scene, const Lights& lights);

// A directional light's shadow plane: texel (u, v) ∈ [0, 1]² starts its ray at origin + u·axis_u + v·axis_v, along
// the light's direction; it covers the room.
struct ShadowPlane {
    Vec3 origin, axis_u, axis_v, direction;
};
ShadowPlane shadow_plane(const Room& room, const Light& light);

}  // namespace metalfit::glpreview
