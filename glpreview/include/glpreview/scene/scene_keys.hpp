// The scene keys that are not the core's: each registered effect reads its own (its settings into Scene::effects or
// the sphere's fields), through this interface, which the effects implement (glpreview/effects/effect.hpp derives
// from it) and whose list the effects' registry provides. The scene stage names no effect.
#pragma once

#include <span>
#include <vector>

#include "glpreview/scene/scene.hpp"
#include "glpreview/scene/scene_reader.hpp"

namespace metalfit::glpreview {

class SceneKeys {
public:
    virtual ~SceneKeys() = default;
    // Top-level keys, read into the scene before its spheres; keys of each sphere, read after the sphere's centre
    // and radius (the sphere is not in scene.spheres yet); checks that need the whole scene, after every key.
    // Errors name the file and the field, as the scene's own.
    virtual std::vector<const char*> scene_keys() const { return {}; }
    virtual void read_scene(const SceneReader& /*top*/, Scene&) const {}
    virtual std::vector<const char*> sphere_keys() const { return {}; }
    virtual void read_sphere(const SceneReader& /*sphere*/, Sphere&, Scene&) const {}
    virtual void check_scene(const SceneReader& /*top*/, const Scene&) const {}
};

// Every registered effect's keys, in registry order (defined with the registry, src/effects/registry.cpp).
std::span<const SceneKeys* const> scene_key_readers();

}  // namespace metalfit::glpreview
