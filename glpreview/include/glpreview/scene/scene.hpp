// The scene of a preview: plain structs parsed strictly from JSON (docs/scene.md); positions are Vec3, radiance
// and colours libfit RGB (linear, the scene_linear space). Unknown keys and wrong types are
// errors naming the field ("scene.json: spheres[1].iterations: expected an integer").
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <typeindex>
#include <variant>
#include <vector>

#include "glpreview/scene/vec3.hpp"
#include "libfit/base/enum_names.hpp"
#include "libfit/color/color.hpp"
#include "libfit/fit/parameter_source.hpp"

namespace metalfit::glpreview {

struct Camera {
    Vec3 position{0, 1.2, 3.5};
    Vec3 look_at{0, 1.0, 0};
    Vec3 up{0, 1, 0};
    double fov_y_deg = 45;
};

// An axis-aligned box inside a room (a column is a box from floor to ceiling).
struct RoomBox {
    Vec3 min, max;
    RGB color{0.6, 0.6, 0.6};  // radiance of its top face; sides are darker (docs/scene.md)
};

// A rectangular emissive panel on the ceiling, in x and z.
struct CeilingPanel {
    double min_x = 0, min_z = 0, max_x = 0, max_z = 0;
    RGB radiance{6, 6, 6};
};

// The procedural analytic room: an axis-aligned box with coloured walls, a checkerboard floor, emissive ceiling
// panels and optional boxes inside.
struct Room {
    Vec3 min{-3, 0, -3}, max{3, 3, 3};
    RGB wall_x_min{0.65, 0.20, 0.15}, wall_x_max{0.15, 0.25, 0.65};  // left, right
    RGB wall_z_min{0.60, 0.60, 0.55}, wall_z_max{0.20, 0.50, 0.25};  // back, front
    RGB floor_light{0.8, 0.8, 0.8}, floor_dark{0.08, 0.08, 0.08};
    RGB ceiling{0.35, 0.35, 0.35};
    double checker = 0.5;  // size of the floor and wall checks (m)
    std::vector<CeilingPanel> panels;
    std::vector<RoomBox> boxes;
};

// A spherical room of constant distance around the reference point (the sphere proxy's exact case).
struct SphereRoom {
    double radius = 4;
    double checker_deg = 15;  // latitude-longitude checks
    RGB light{0.9, 0.8, 0.6}, dark{0.1, 0.15, 0.3};
};

// The geometry an equirect image is projected onto (a reflection probe's proxy, docs/scene.md): the image seen from
// the reference point (the capture point) is painted on an axis-aligned box around it or on a sphere of `radius`
// centred on it, so that reflections of it can be localized (box-parallax, distance impostor) and rough spheres can
// be prefiltered from its captured cube.
struct BoxProxy {
    Vec3 min, max;  // world space; the reference point lies strictly inside
};
struct SphereProxy {
    double radius = 0;  // around the reference point
};
using EnvironmentProxy = std::variant<BoxProxy, SphereProxy>;

// An equirectangular (latitude-longitude) HDR image: at infinity (classic reflections only, mirrors only) or, with a
// proxy, on the proxy's surface (captured into a cube map with the proxy's distances, like a procedural room).
struct Equirect {
    std::filesystem::path file;  // resolved against the scene file's folder
    double intensity = 1;
    std::string colorspace;  // the OCIO colour space of the image's pixels; empty: the scene's space (untagged)
    std::optional<EnvironmentProxy> proxy;  // none: at infinity
};

enum class EnvironmentType { room, sphere_room, equirect };
// The scene's names of the enums' values (libfit's EnumNames: one table parses and prints), in the order the messages
// about an unknown value list them.
inline constexpr EnumNames kEnvironmentTypeNames{
    "environment type", KnownNamesWording::known,
    std::array{EnumName<EnvironmentType>{EnvironmentType::room, "room"},
               EnumName<EnvironmentType>{EnvironmentType::sphere_room, "sphere-room"},
               EnumName<EnvironmentType>{EnvironmentType::equirect, "equirect"}}};

struct Environment {
    EnvironmentType type = EnvironmentType::room;
    Room room;
    SphereRoom sphere_room;
    Equirect equirect;
    std::optional<Vec3> reference_point;  // cube map centre; default: the room's centre (else the origin)
    int cube_size = 256;                  // texels per cube face edge

    Vec3 reference() const;
    // Captured into a cube map around the reference point (rooms, and an equirect with a proxy): reflections can be
    // localized and rough spheres rendered; false only for an equirect at infinity.
    bool captured() const { return type != EnvironmentType::equirect || equirect.proxy.has_value(); }
    // The box a box-parallax lookup intersects: the room's, or an equirect's box proxy; none otherwise.
    std::optional<BoxProxy> parallax_box() const;
};

enum class ReflectionMode { classic, distance_impostor, box_parallax };
inline constexpr EnumNames kReflectionModeNames{
    "reflection", KnownNamesWording::known,
    std::array{EnumName<ReflectionMode>{ReflectionMode::classic, "classic"},
               EnumName<ReflectionMode>{ReflectionMode::distance_impostor, "distance-impostor"},
               EnumName<ReflectionMode>{ReflectionMode::box_parallax, "box-parallax"}}};
// The impostor's root finder: the thesis's three as described (secant, false position, mixed), and two that keep a
// bracket and cannot stall or run away (illinois: false position with the Illinois modification; safe-secant:
// secant falling back to the bracket).
enum class Strategy { secant, false_position, mixed, illinois, safe_secant };
inline constexpr EnumNames kStrategyNames{"strategy", KnownNamesWording::known,
                                          std::array{EnumName<Strategy>{Strategy::secant, "secant"},
                                                     EnumName<Strategy>{Strategy::false_position, "false-position"},
                                                     EnumName<Strategy>{Strategy::mixed, "mixed"},
                                                     EnumName<Strategy>{Strategy::illinois, "illinois"},
                                                     EnumName<Strategy>{Strategy::safe_secant, "safe-secant"}}};

// What a sphere's Fresnel is: the exact reference curve, or a libfit model (named by its id, resolved against the
// model registry when the sphere's Fresnel data is made, where an unknown id is reported) with its parameters
// fitted or in closed form (libfit's ParameterSource).
struct ReferenceFresnel {};
struct ModelFresnel {
    std::string model;  // a libfit model id, "f82-tint"
    ParameterSource parameters = ParameterSource::fit;
};
using FresnelChoice = std::variant<ReferenceFresnel, ModelFresnel>;

// How a rough sphere (roughness > 0) reflects on the GPU (docs/scene.md): a GGX-prefiltered cube mip chain times the
// sphere's own DFG table (split sum), or the thesis's ch. 5 sum over the downsampled cube's texels as area lights.
enum class GlossyMethod { prefiltered, localized };
inline constexpr EnumNames kGlossyMethodNames{
    "glossy method", KnownNamesWording::known,
    std::array{EnumName<GlossyMethod>{GlossyMethod::prefiltered, "prefiltered"},
               EnumName<GlossyMethod>{GlossyMethod::localized, "localized"}}};
// What the scene asks for (`"glossy"`): `auto` (the default) lets the planner choose from the roughness and the measured
// table (glossy_choice.hpp); `localized` falls back to prefiltered where it fails.
enum class GlossyRequest { automatic, prefiltered, localized };
inline constexpr EnumNames kGlossyRequestNames{
    "glossy", KnownNamesWording::known,
    std::array{EnumName<GlossyRequest>{GlossyRequest::automatic, "auto"},
               EnumName<GlossyRequest>{GlossyRequest::prefiltered, "prefiltered"},
               EnumName<GlossyRequest>{GlossyRequest::localized, "localized"}}};

inline constexpr Strategy kDefaultStrategy = Strategy::illinois;
inline constexpr int kDefaultIterations = 8;
inline constexpr double kDefaultTolerance = 1e-4;
inline constexpr int kDefaultSearchSteps = 8;

// Limits on what a scene may ask for (docs/scene.md): bounded cost for any scene file.
inline constexpr int kMaxImageEdge = 8192;
inline constexpr long long kMaxImagePixels = 16777216;  // 4096²
inline constexpr std::size_t kMaxSpheres = 256;
inline constexpr std::size_t kMaxRoomBoxes = 32;  // boxes + columns (the shader's MAX_BOXES)
inline constexpr std::size_t kMaxPanels = 16;     // the shader's MAX_PANELS

struct Sphere {
    Vec3 center;
    double radius = 0.5;
    std::string material = "Au";  // catalog name or a file (resolved against the scene file's folder)
    std::string source;           // catalog source ("" = primary)
    std::string film;  // a thin film over the metal, as `metalfit --film` ("TiO2:80nm", "2.2:120nm"); "" = none
    std::string coat;  // a clear coat over it (and the film), as `metalfit --coat` ("1.5", "PMMA"); "" = none
    FresnelChoice fresnel =
        ReferenceFresnel{};  // JSON: "fresnel": "reference" or a model id, "params": "fit" | "closed"
    ReflectionMode reflection = ReflectionMode::distance_impostor;
    Strategy strategy = kDefaultStrategy;
    int iterations = kDefaultIterations;     // the most refinement steps a pixel takes
    double tolerance = kDefaultTolerance;    // a pixel stops once |ρ − 1| < tolerance (0: always `iterations` steps)
    int search_steps = kDefaultSearchSteps;  // illinois / safe-secant: linear-search reads before the refinement
    double roughness = 0;                    // GGX, α = roughness²; 0: the perfect mirror
    GlossyMethod glossy = GlossyMethod::prefiltered;  // the GPU method when roughness > 0 (as chosen from the request)
    GlossyRequest glossy_request = GlossyRequest::automatic;  // what the scene asked for
    int localized_size = 8;  // `localized`: M, the downsampled cube's texels per face edge (2–16), each an area light

    bool rough() const { return roughness > 0; }
};

struct Outputs {
    bool beauty = true;           // GPU image
    bool reference = true;        // CPU ray-traced image
    bool difference = true;       // |beauty − reference|
    bool metrics = true;          // metrics.json (needs the reference)
    bool exr = true;              // linear images
    bool png = true;              // through the OCIO display transform
    bool localization = false;    // localization.exr: per pixel the refinement steps taken and the final |ρ − 1|
    bool labels = false;          // the PNGs say what they show, the display transform and the exposure (top band)
    bool rim = false;             // rim.png: each sphere's grazing rim unwrapped beside its Fresnel curves
    int timing_frames = 5;        // frames for ms_per_frame (median)
    int reference_samples = 256;  // Monte-Carlo samples per pixel of the reference on rough spheres
};

// Where a scene may read files from: its own folder and the database, unless paths outside are allowed.
struct PathPolicy {
    std::filesystem::path data_dir;  // empty: the scene's folder only
    bool allow_outside = false;
};

// What effects read from a scene beyond the core's keys (Effect::read_scene), by type: immutable once parsed, shared
// by copies of the scene.
class EffectSettings {
public:
    template <class T>
    void set(T value) {
        values_[std::type_index(typeid(T))] = std::make_shared<const T>(std::move(value));
    }
    template <class T>
    const T* find() const {
        const auto it = values_.find(std::type_index(typeid(T)));
        return it == values_.end() ? nullptr : static_cast<const T*>(it->second.get());
    }

private:
    std::map<std::type_index, std::shared_ptr<const void>> values_;
};

struct Scene {
    std::filesystem::path file;  // where it was read from (for messages and relative paths)
    int width = 512, height = 512;
    // The colour space the scene renders in (docs/scene.md): a colour space or role of the OCIO config in use;
    // empty: the role scene_linear. Colours of the scene, the Fresnel curves and the EXR are in it; the PNG is the
    // config's display transform from it.
    std::string space;
    Camera camera;
    Environment environment;
    std::vector<Sphere> spheres;
    Outputs outputs;
    bool camera_position_given = false;  // the default camera (z = 3.5) stands outside the default room: no warning
    std::vector<std::string> warnings;   // settings that are accepted but mean nothing or look wrong, one line each
    // Set by the CLI after confine_scene_paths: every file the scene names is then opened once and the policy checked
    // again on the open descriptor (ConfinedFile), so a link swapped in after the first check leads nowhere outside.
    // Unset (library use): no confinement.
    std::optional<PathPolicy> paths;
    EffectSettings effects;  // the effects' own keys (lights, ...)
};

// Every file the scene names (material files, the equirect image), resolved with links followed, must lie in the
// scene's folder or the database unless policy.allow_outside; throws InputError naming the field.
void confine_scene_paths(const Scene& scene, const PathPolicy& policy);
// Whether `resolved` (an absolute path, links resolved) lies in the folder of `scene_file` or the database, or the
// policy allows paths outside: the one test of confine_scene_paths and ConfinedFile.
bool policy_allows(const PathPolicy& policy, const std::filesystem::path& scene_file,
                   const std::filesystem::path& resolved);
// Checks the image size against the limits (kMaxImageEdge, kMaxImagePixels); throws InputError naming `what`.
void check_image_size(const std::filesystem::path& file, const std::string& what, int width, int height);

// Throws metalfit::InputError naming the file and the field.
Scene parse_scene(const std::string& json_text, const std::filesystem::path& file);
Scene load_scene(const std::filesystem::path& file);
// The sphere-visibility and placement warnings that need the whole scene (camera outside the room, a sphere through
// a wall); parse_scene adds them to Scene::warnings.
std::vector<std::string> placement_warnings(const Scene& scene);

// The names of the tables above.
inline const char* to_string(ReflectionMode mode) { return kReflectionModeNames.name(mode).data(); }
inline const char* to_string(Strategy strategy) { return kStrategyNames.name(strategy).data(); }
inline const char* to_string(EnvironmentType type) { return kEnvironmentTypeNames.name(type).data(); }
inline const char* to_string(GlossyMethod method) { return kGlossyMethodNames.name(method).data(); }
inline const char* to_string(GlossyRequest request) { return kGlossyRequestNames.name(request).data(); }
std::string fresnel_name(const FresnelChoice& fresnel);  // "reference" or the model id, as in the scene JSON
inline bool shows_reference(const Sphere& sphere) { return std::holds_alternative<ReferenceFresnel>(sphere.fresnel); }

}  // namespace metalfit::glpreview
