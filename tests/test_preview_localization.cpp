// The distance impostor's claims per sphere, in rooms of the tests' own (a long empty room, a sphere beside a
// column, an off-centre reference point, an occluder maze) and the shipped ones: for every sphere the default
// strategy's error against the CPU reference does not grow with the iteration limit (beyond the cube map's float
// noise), converges to box projection in empty rooms, and at its default limit is no worse than the better of
// classic and box-parallax. The thesis's secant stall is shown where it happens, and the safeguarded strategies
// are shown not to stall. Unit Fresnel (F = 1): the error is the localization's alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include "glpreview/effects/reflection_lookup.hpp"
#include "glpreview/gl/gl_context.hpp"
#include "glpreview/render/cpu_reference.hpp"
#include "glpreview/render/environment.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/sphere_metrics.hpp"
#include "glpreview/scene/camera.hpp"
#include "glpreview/scene/scene.hpp"
#include "test_support.hpp"

namespace metalfit::glpreview {
namespace test_preview_localization {

using test::kData;

GlContext& gl() {
    static GlContext context = GlContext::create();
    return context;
}

const SphereFresnel* unit_fresnel() {
    static const SphereFresnel unit = [] {
        SphereFresnel f;
        f.lut.assign(2, RGB{1, 1, 1});
        return f;
    }();
    return &unit;
}

// One reflection setting, applied to every sphere of a room at once (their masks do not overlap).
struct Setting {
    ReflectionMode mode = ReflectionMode::distance_impostor;
    Strategy strategy = kDefaultStrategy;
    int iterations = kDefaultIterations;
    double tolerance = kDefaultTolerance;
};
Setting classic() { return {ReflectionMode::classic}; }
Setting box_parallax() { return {ReflectionMode::box_parallax}; }
Setting impostor(Strategy strategy, int iterations, double tolerance = kDefaultTolerance) {
    return {ReflectionMode::distance_impostor, strategy, iterations, tolerance};
}

// A room rendered with many settings against one CPU reference; the cube map is captured once.
class Bench {
public:
    explicit Bench(Scene scene)
        : scene_(std::move(scene)),
          own_(scene_.spheres),
          reference_(render_reference(scene_, fresnel(), EnvironmentTracer(scene_.environment), 2)) {
        for (Sphere& s : scene_.spheres) {
            s.reflection = ReflectionMode::distance_impostor;  // the cube stores distances
            s.fresnel = ReferenceFresnel{};                    // the unit LUT
        }
        gpu_.emplace(scene_, plan_features(scene_), fresnel(), nullptr);
        gpu_->capture_environment();
    }
    std::size_t spheres() const { return scene_.spheres.size(); }
    const Scene& scene() const { return scene_; }

    Image render(const Setting& setting) {
        apply(setting);
        return gpu_->render();
    }
    std::vector<SphereError> errors(const Setting& setting) {
        return sphere_errors(render(setting), reference_, spheres());
    }
    // Per sphere: RMSE of the GPU image of `a` against that of `b` (not against the CPU reference).
    std::vector<SphereError> between(const Setting& a, const Setting& b) {
        const Image image_b = render(b);
        return sphere_errors(render(a), ReferenceRender{image_b, reference_.sphere_id}, spheres());
    }
    // The spheres' own settings from the scene file, with `tolerance` on the impostor spheres.
    Image render_own(double tolerance) {
        for (std::size_t i = 0; i < own_.size(); ++i) {
            scene_.spheres[i].reflection = own_[i].reflection;
            scene_.spheres[i].strategy = own_[i].strategy;
            scene_.spheres[i].iterations = own_[i].iterations;
            scene_.spheres[i].tolerance = tolerance;
        }
        return gpu_->render();
    }
    std::vector<SphereError> own_with_and_without_stop() {
        const Image fixed = render_own(0);
        return sphere_errors(render_own(kDefaultTolerance), ReferenceRender{fixed, reference_.sphere_id}, spheres());
    }
    std::vector<SphereLocalization> effort(const Setting& setting) {
        apply(setting);
        return sphere_localization(gpu_->render_localization(), reference_, spheres());
    }

private:
    std::vector<const SphereFresnel*> fresnel() const {
        return std::vector<const SphereFresnel*>(scene_.spheres.size(), unit_fresnel());
    }
    void apply(const Setting& s) {
        for (Sphere& sphere : scene_.spheres) {
            sphere.reflection = s.mode;
            sphere.strategy = s.strategy;
            sphere.iterations = s.iterations;
            sphere.tolerance = s.tolerance;
        }
    }
    Scene scene_;
    std::vector<Sphere> own_;
    ReferenceRender reference_;
    std::optional<GpuRenderer> gpu_;
};

Sphere sphere_at(Vec3 center, double radius) {
    Sphere s;
    s.center = center;
    s.radius = radius;
    return s;
}

Scene base_scene(int width, int height) {
    Scene scene;
    scene.file = "test-localization.json";
    scene.width = width;
    scene.height = height;
    scene.environment.cube_size = 256;
    return scene;
}

// A long empty room, 3 × 2.5 × 8 m, looked at along its length: far walls, grazing floors.
Scene long_empty_room() {
    Scene scene = base_scene(120, 90);
    Room& room = scene.environment.room;
    room.min = {-1.5, 0, -4};
    room.max = {1.5, 2.5, 4};
    room.panels = {{-0.6, -3, 0.6, -1, {6, 6, 6}}, {-0.6, 1, 0.6, 3, {5, 5, 5}}};
    scene.environment.reference_point = Vec3{0, 1.25, 0};
    scene.camera.position = {0, 1.3, 3.6};
    scene.camera.look_at = {0, 1.0, 0};
    scene.camera.fov_y_deg = 55;
    scene.spheres = {sphere_at({-0.8, 0.8, 1.0}, 0.35), sphere_at({0.0, 1.0, 0.3}, 0.35),
                     sphere_at({0.8, 0.6, 1.4}, 0.35), sphere_at({0.1, 0.35, 2.2}, 0.3)};
    return scene;
}

// A 4 × 3 × 4 m room with one column; a sphere 2 cm from the column, one 10 cm from it, one in the open.
Scene sphere_beside_a_column() {
    Scene scene = base_scene(120, 90);
    Room& room = scene.environment.room;
    room.min = {-2, 0, -2};
    room.max = {2, 3, 2};
    room.panels = {{-1, -1, 1, 1, {6, 6, 6}}};
    room.boxes = {{{0.3, 0, -0.5}, {0.8, 3, 0.0}, {0.8, 0.8, 0.85}}};  // a column 0.5 m wide
    scene.environment.reference_point = Vec3{-0.4, 1.3, 0.6};
    scene.camera.position = {-0.2, 1.3, 1.9};
    scene.camera.look_at = {0.1, 0.9, -0.1};
    scene.camera.fov_y_deg = 60;
    scene.spheres = {sphere_at({0.0, 0.9, -0.25}, 0.28), sphere_at({-0.6, 0.9, -0.4}, 0.28),
                     sphere_at({0.55, 0.35, 0.4}, 0.28)};
    return scene;
}

// An empty room whose reference point is near a corner (o is not the room's centre).
Scene off_centre_reference_point() {
    Scene scene = base_scene(120, 90);
    Room& room = scene.environment.room;
    room.min = {-2.5, 0, -2.5};
    room.max = {2.5, 2.8, 2.5};
    room.panels = {{-1.2, -1.2, 1.2, 1.2, {6, 6, 6}}};
    scene.environment.reference_point = Vec3{-1.9, 0.5, -1.8};
    scene.camera.position = {0.2, 1.4, 2.2};
    scene.camera.look_at = {-0.2, 0.9, -0.4};
    scene.camera.fov_y_deg = 60;
    scene.spheres = {sphere_at({-0.9, 0.9, -0.5}, 0.35), sphere_at({0.2, 0.9, -0.2}, 0.35),
                     sphere_at({0.9, 0.5, 0.6}, 0.3), sphere_at({-1.2, 1.5, -0.9}, 0.3)};
    return scene;
}

// Thin occluders beside the spheres: two 6 cm columns and a 5 cm bar across the room, so that many reflected rays
// cross ρ = 1 more than once (in front of a thin object, behind it, then the wall).
Scene thin_occluders() {
    Scene scene = base_scene(120, 90);
    Room& room = scene.environment.room;
    room.min = {-2, 0, -2};
    room.max = {2, 3, 2};
    room.panels = {{-1.2, -1.2, 0, 0, {6, 6, 6}}, {0.3, 0.2, 1.3, 1.2, {5, 5, 6}}};
    room.boxes = {{{-0.1, 0, -0.62}, {-0.04, 3, -0.56}, {0.9, 0.3, 0.2}},
                  {{0.95, 0, -0.2}, {1.01, 3, -0.14}, {0.2, 0.4, 0.9}},
                  {{-1.6, 1.5, -1.25}, {1.6, 1.55, -1.2}, {0.9, 0.9, 0.3}}};
    scene.environment.reference_point = Vec3{0.2, 1.4, 0.8};
    scene.camera.position = {0, 1.3, 2.2};
    scene.camera.look_at = {0, 0.9, -0.4};
    scene.camera.fov_y_deg = 60;
    scene.spheres = {sphere_at({-0.45, 0.9, -0.3}, 0.3), sphere_at({0.62, 0.8, -0.45}, 0.3),
                     sphere_at({0.1, 0.4, 0.3}, 0.25)};
    return scene;
}

// Boxes and columns around the spheres: parts of the room hidden from the reference point.
Scene occluder_maze() {
    Scene scene = base_scene(120, 90);
    Room& room = scene.environment.room;
    room.min = {-3, 0, -3};
    room.max = {3, 2.8, 3};
    room.panels = {{-1.5, -1.5, -0.3, -0.3, {6, 6, 6}}, {0.3, 0.3, 1.5, 1.5, {6, 5, 4}}};
    room.boxes = {{{-1.6, 0, -1.9}, {-1.2, 2.8, -1.5}, {0.8, 0.8, 0.85}},
                  {{0.9, 0, -1.4}, {1.3, 2.8, -1.0}, {0.7, 0.3, 0.6}},
                  {{-1.4, 0, 0.6}, {-0.6, 0.9, 1.2}, {0.85, 0.75, 0.2}},
                  {{0.5, 0, 0.9}, {1.1, 0.6, 1.5}, {0.2, 0.7, 0.8}},
                  {{-0.3, 0, -2.4}, {0.4, 1.6, -2.0}, {0.3, 0.8, 0.3}}};
    scene.environment.reference_point = Vec3{0, 1.2, -0.3};
    scene.camera.position = {0, 1.5, 2.6};
    scene.camera.look_at = {0, 0.8, -0.5};
    scene.camera.fov_y_deg = 60;
    scene.spheres = {sphere_at({-0.8, 0.6, -0.6}, 0.35), sphere_at({0.25, 0.9, -0.7}, 0.35),
                     sphere_at({1.0, 0.5, -0.2}, 0.3), sphere_at({-0.2, 0.35, 0.5}, 0.3)};
    return scene;
}

// A shipped scene at a small size, its spheres as they are (their settings are replaced per setting).
Scene shipped(const char* name) {
    Scene scene = load_scene(kData / "scenes" / name);
    scene.width = 128;
    scene.height = 96;
    return scene;
}

std::string describe(const std::vector<SphereError>& e) {
    std::string s;
    for (const SphereError& x : e) s += " " + std::to_string(x.rmse);
    return s;
}

// The float noise of the cube map's sampling allowed between two iteration limits.
bool no_worse(double a, double than) { return a <= than * 1.02 + 2e-4; }

struct RoomCase {
    const char* name;
    Scene (*make)();
    bool empty;
};
void PrintTo(const RoomCase& room, std::ostream* os) { *os << room.name; }
Scene difficult_room() { return shipped("difficult-room.json"); }
Scene shipped_empty_room() { return shipped("empty-room.json"); }
const std::vector<RoomCase>& rooms() {
    static const std::vector<RoomCase> r{{"long-empty", long_empty_room, true},
                                         {"beside-a-column", sphere_beside_a_column, false},
                                         {"off-centre-reference", off_centre_reference_point, true},
                                         {"occluder-maze", occluder_maze, false},
                                         {"shipped-difficult", difficult_room, false},
                                         {"shipped-empty", shipped_empty_room, true}};
    return r;
}

class PreviewLocalization : public ::testing::TestWithParam<RoomCase> {};

// Per sphere: in empty rooms (exact geometry) the error does not grow with the limit from two steps on and the
// default limit is within float noise of the best limit; in every room, at the default limit no sphere is worse
// than with the better of classic and box-parallax; in empty rooms the impostor converges to box projection's
// image. (In rooms with occluders an early limit can be luckier than convergence: docs/preview.md.)
TEST_P(PreviewLocalization, TheDefaultStrategyHoldsItsClaimsOnEverySphere) {
    gl();
    Bench bench(GetParam().make());
    const auto classic_error = bench.errors(classic());
    const auto parallax_error = bench.errors(box_parallax());
    std::vector<std::vector<SphereError>> by_limit;
    const std::vector<int> limits{0, 1, 2, 4, 8, 16, 32};
    for (int n : limits) by_limit.push_back(bench.errors(impostor(kDefaultStrategy, n)));
    const auto at_default = bench.errors(impostor(kDefaultStrategy, kDefaultIterations));
    std::printf("%s classic%s\n%s box-parallax%s\n", GetParam().name, describe(classic_error).c_str(), GetParam().name,
                describe(parallax_error).c_str());
    for (std::size_t k = 0; k < limits.size(); ++k)
        std::printf("%s %s %d%s\n", GetParam().name, to_string(kDefaultStrategy), limits[k],
                    describe(by_limit[k]).c_str());
    for (std::size_t s = 0; s < bench.spheres(); ++s) {
        SCOPED_TRACE("sphere " + std::to_string(s));
        ASSERT_GT(classic_error[s].pixels, 150u);
        for (std::size_t k = 1; k < limits.size(); ++k) {
            if (GetParam().empty && limits[k] > 2) {
                EXPECT_TRUE(no_worse(by_limit[k][s].rmse, by_limit[k - 1][s].rmse))
                    << limits[k] << " steps: " << by_limit[k][s].rmse << " after " << by_limit[k - 1][s].rmse;
            }
        }
        // In empty rooms the default limit and 32 steps are as good as the exact geometry's box projection, within
        // the cube map's noise. (Not "as good as the best limit": an early guess can be luckier than convergence, the
        // long room's sphere 2 at 0 and 1 steps 0.094 where box projection is 0.097.)
        if (GetParam().empty) {
            EXPECT_TRUE(no_worse(at_default[s].rmse, parallax_error[s].rmse));
            EXPECT_TRUE(no_worse(by_limit.back()[s].rmse, parallax_error[s].rmse));
        }
        const double better = std::min(classic_error[s].rmse, parallax_error[s].rmse);
        EXPECT_TRUE(no_worse(at_default[s].rmse, better)) << at_default[s].rmse << " vs " << better;
    }
    if (GetParam().empty) {
        // Exact geometry: once converged, the impostor's image is box projection's (the cube map's distance is
        // bilinear between texel centres, so "equal" is up to that filtering at panel and checker edges).
        const auto gap = bench.between(impostor(kDefaultStrategy, 32), box_parallax());
        const auto gap_default = bench.between(impostor(kDefaultStrategy, kDefaultIterations), box_parallax());
        std::printf("%s vs box-parallax: 32 steps%s, default%s\n", GetParam().name, describe(gap).c_str(),
                    describe(gap_default).c_str());
        for (std::size_t s = 0; s < bench.spheres(); ++s) {
            EXPECT_LT(gap[s].rmse, 0.01) << "sphere " << s;
            EXPECT_LT(gap_default[s].rmse, 0.02) << "sphere " << s;
        }
    }
}

// In empty rooms the safeguarded strategies reach box projection: every sphere within the cube map's filtering of
// it at 16 and at 32 steps.
TEST_P(PreviewLocalization, SafeguardedStrategiesConvergeToBoxProjectionInEmptyRooms) {
    gl();
    if (!GetParam().empty) GTEST_SKIP() << "box projection is exact only in empty rooms";
    Bench bench(GetParam().make());
    auto worst_gap = [&](const Setting& setting) {
        double w = 0;
        for (const SphereError& e : bench.between(setting, box_parallax())) w = std::max(w, e.rmse);
        return w;
    };
    for (Strategy strategy : {Strategy::illinois, Strategy::safe_secant}) {
        SCOPED_TRACE(to_string(strategy));
        const double at16 = worst_gap(impostor(strategy, 16, 0)), at32 = worst_gap(impostor(strategy, 32, 0));
        std::printf("%s %s worst gap to box-parallax: 16 steps %.5f, 32 steps %.5f\n", GetParam().name,
                    to_string(strategy), at16, at32);
        EXPECT_LT(at16, 0.01);
        EXPECT_LT(at32, 0.01);
    }
}

INSTANTIATE_TEST_SUITE_P(Rooms, PreviewLocalization, ::testing::ValuesIn(rooms()),
                         [](const ::testing::TestParamInfo<RoomCase>& info) {
                             std::string name = info.param.name;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

// Adaptive iterations: with a tolerance the pixels stop early (fewer mean steps than the limit) and the image stays
// within the cube map's noise of the image without early stopping; with tolerance 0 every pixel takes the limit.
TEST(PreviewLocalizationEffort, PixelsStopEarlyOnceRhoIsWithinTheTolerance) {
    gl();
    Bench bench(long_empty_room());
    const auto all = bench.effort(impostor(Strategy::illinois, 16, 0));
    const auto adaptive = bench.effort(impostor(Strategy::illinois, 16, 1e-3));
    const auto gap = bench.between(impostor(Strategy::illinois, 16, 1e-3), impostor(Strategy::illinois, 16, 0));
    for (std::size_t s = 0; s < bench.spheres(); ++s) {
        SCOPED_TRACE("sphere " + std::to_string(s));
        EXPECT_DOUBLE_EQ(all[s].mean_iterations, 16.0);
        EXPECT_LT(adaptive[s].mean_iterations, 8.0);
        EXPECT_GT(adaptive[s].mean_iterations, 1.0);
        EXPECT_LT(gap[s].rmse, 0.01);
        EXPECT_LT(all[s].mean_rho_error, 1e-3);
    }
}

// Probe rays through the long empty room (reflection_lookup on the GPU, against box projection written here): the
// safeguarded strategies converge on every ray, including rays that pass close by the reference point (where ρ
// is far from monotone along the ray); the thesis's strategies are measured on the same rays and printed, and its
// secant, kept as described, still stalls on some.
TEST(PreviewLocalizationProbe, SafeguardedStrategiesConvergeOnEveryRay) {
    gl();
    Scene scene = long_empty_room();
    scene.environment.cube_size = 512;
    GpuRenderer gpu(scene, plan_features(scene),
                    std::vector<const SphereFresnel*>(scene.spheres.size(), unit_fresnel()), nullptr);
    gpu.capture_environment();
    const Room& room = scene.environment.room;
    const Vec3 o = scene.environment.reference();
    std::mt19937 random(7);
    std::uniform_real_distribution<double> u(0, 1);
    std::normal_distribution<double> n;
    std::vector<std::array<Vec3, 2>> rays;
    while (rays.size() < 3000) {  // shaded points anywhere inside the room (10 cm from the walls), any direction
        Vec3 p;
        for (int i = 0; i < 3; ++i) p[i] = room.min[i] + 0.1 + u(random) * (room.max[i] - room.min[i] - 0.2);
        const Vec3 x = p - o;
        Vec3 r{n(random), n(random), n(random)};
        if (rays.size() % 3 == 0) r = -1.0 * x + 0.05 * r;  // passing within a few cm of o
        if (length(r) < 1e-6 || length(x) < 0.05) continue;
        rays.push_back({x, normalize(r)});
    }
    auto box_hit = [&](Vec3 x, Vec3 r) {
        double t = std::numeric_limits<double>::infinity();
        for (int i = 0; i < 3; ++i)
            if (r[i] != 0)
                t = std::min(t, std::max((room.max[i] - o[i] - x[i]) / r[i], (room.min[i] - o[i] - x[i]) / r[i]));
        return x + t * r;
    };
    auto angle = [](Vec3 a, Vec3 b) { return std::acos(std::clamp(dot(normalize(a), normalize(b)), -1.0, 1.0)); };
    for (Strategy strategy :
         {Strategy::secant, Strategy::false_position, Strategy::mixed, Strategy::illinois, Strategy::safe_secant}) {
        Sphere settings;
        settings.strategy = strategy;
        settings.iterations = 32;
        settings.tolerance = 0;
        const auto results = probe_reflection_lookups(gpu, settings, rays);
        double worst = 0;
        std::size_t off = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const double a = angle(results[i].lookup, box_hit(rays[i][0], rays[i][1]));
            worst = std::max(worst, a);
            if (a > 1e-2) ++off;
        }
        std::printf(
            "long room probes, %s, 32 steps: worst angle to box projection %.4f rad, %zu of %zu rays beyond 0.01 rad\n",
            to_string(strategy), worst, off, rays.size());
        if (strategy == Strategy::illinois || strategy == Strategy::safe_secant) {
            EXPECT_LT(worst, 5e-3) << to_string(strategy);
        }
        if (strategy == Strategy::secant) {
            EXPECT_GT(worst, 0.1);  // kept as the thesis describes it: some rays stall at d = 0
        }
    }
}

// The shipped scenes name the thesis's strategies and a fixed count; the default stop on |ρ − 1| changes their
// images by less than the cube map's filtering does (tolerance 0 reproduces the fixed count exactly).
TEST(PreviewLocalizationEffort, TheStopChangesTheShippedScenesImagesOnlyWithinNoise) {
    gl();
    for (const char* name : {"difficult-room.json", "empty-room.json", "sheet.json"}) {
        Bench bench(shipped(name));
        const auto gap = bench.own_with_and_without_stop();
        std::printf("%s: with and without the stop%s\n", name, describe(gap).c_str());
        for (std::size_t s = 0; s < bench.spheres(); ++s) EXPECT_LT(gap[s].rmse, 5e-4) << name << " sphere " << s;
    }
}

// The reflected rays of every pixel that shows a sphere (camera ray, exact sphere hit, mirror direction), as probe
// rays relative to the reference point.
std::vector<std::array<Vec3, 2>> sphere_pixel_rays(const Scene& scene) {
    const CameraBasis basis = camera_basis(scene.camera, scene.width, scene.height);
    const Vec3 o = scene.environment.reference();
    std::vector<std::array<Vec3, 2>> rays;
    for (int py = 0; py < scene.height; ++py)
        for (int px = 0; px < scene.width; ++px) {
            const Vec3 d = camera_ray(basis, px, py, scene.width, scene.height);
            double nearest = std::numeric_limits<double>::infinity();
            Vec3 hit, normal;
            for (const Sphere& s : scene.spheres) {
                const Vec3 oc = scene.camera.position - s.center;
                const double b = dot(oc, d), c = dot(oc, oc) - s.radius * s.radius, disc = b * b - c;
                if (disc < 0) continue;
                const double t = -b - std::sqrt(disc);
                if (t > 0 && t < nearest) {
                    nearest = t;
                    hit = scene.camera.position + t * d;
                    normal = normalize(hit - s.center);
                }
            }
            if (std::isfinite(nearest)) rays.push_back({hit - o, normalize(d - 2 * dot(d, normal) * normal)});
        }
    return rays;
}

// Where f(d) = ρ(x + R d) − 1 of the exact room (the CPU tracer's distance from o, not the cube map) changes from
// undershoot to overshoot along a ray, marched in 4000 steps even in the direction seen from o (the search's own
// parametrisation, d = |x| t / (1 − t)) up to t = 0.9995, each crossing refined by bisection.
std::vector<double> exact_crossings(const EnvironmentTracer& tracer, Vec3 o, Vec3 x, Vec3 r) {
    auto f = [&](double d) {
        const Vec3 p = x + d * r;
        return length(p) / tracer.trace(o, normalize(p)).t - 1;
    };
    std::vector<double> roots;
    const double scale = length(x);
    double d_prev = 0, f_prev = f(0);
    for (int k = 1; k <= 4000; ++k) {
        const double t = 0.9995 * k / 4000, d = scale * t / (1 - t), fd = f(d);
        if (f_prev < 0 && fd >= 0) {
            double lo = d_prev, hi = d;
            for (int i = 0; i < 50; ++i) (f(0.5 * (lo + hi)) < 0 ? lo : hi) = 0.5 * (lo + hi);
            roots.push_back(0.5 * (lo + hi));
        }
        d_prev = d;
        f_prev = fd;
    }
    return roots;
}

double angle_between(Vec3 a, Vec3 b) { return std::acos(std::clamp(dot(normalize(a), normalize(b)), -1.0, 1.0)); }

Scene thin_occluders_scene() { return thin_occluders(); }
Scene column_scene() { return sphere_beside_a_column(); }
Scene maze_scene() { return occluder_maze(); }

// The right root: in rooms with thin occluders many sphere pixels' reflected rays cross ρ = 1 more than once; the
// linear search brackets the first crossing, so the refinement ends there. Without it (search_steps 0, the
// refinement from the perpendicular guess) a share of those pixels converge to a later root. Measured per room: the
// share of multi-root pixels, how many of them end at the first root (within 0.02 rad, a few cube texels), and their
// share of the squared radiance error against the exact trace (F = 1), before and after.
TEST(PreviewLocalizationRoots, TheSearchBracketsTheFirstCrossing) {
    gl();
    struct Case {
        const char* name;
        Scene (*make)();
    };
    for (const Case& room : {Case{"thin-occluders", thin_occluders_scene}, Case{"beside-a-column", column_scene},
                             Case{"occluder-maze", maze_scene}, Case{"shipped-difficult", difficult_room}}) {
        SCOPED_TRACE(room.name);
        Scene scene = room.make();
        for (Sphere& s : scene.spheres) s.reflection = ReflectionMode::distance_impostor;
        GpuRenderer gpu(scene, plan_features(scene),
                        std::vector<const SphereFresnel*>(scene.spheres.size(), unit_fresnel()), nullptr);
        gpu.capture_environment();
        const EnvironmentTracer tracer(scene.environment);
        const Vec3 o = scene.environment.reference();
        const auto rays = sphere_pixel_rays(scene);
        std::vector<std::vector<double>> roots;
        for (const auto& [x, r] : rays) roots.push_back(exact_crossings(tracer, o, x, r));
        struct Result {
            std::size_t at_first = 0;
            double multi_error = 0, total_error = 0;
        };
        auto measure = [&](int search_steps) {
            Sphere settings;
            settings.search_steps = search_steps;
            const auto probes = probe_reflection_lookups(gpu, settings, rays);
            Result result;
            for (std::size_t i = 0; i < rays.size(); ++i) {
                const auto& [x, r] = rays[i];
                const RGB truth = tracer.trace(o + x, r).radiance;
                double e = 0;
                for (int c = 0; c < 3; ++c) e += std::pow(double(probes[i].texel[c]) - truth[c], 2);
                result.total_error += e;
                if (roots[i].size() < 2) continue;
                result.multi_error += e;
                if (angle_between(probes[i].lookup, x + roots[i].front() * r) < 0.02) ++result.at_first;
            }
            return result;
        };
        std::size_t multi = 0;
        for (const auto& r : roots) multi += r.size() >= 2;
        const Result before = measure(0), after = measure(kDefaultSearchSteps);
        for (int n : {4, 16, 32}) {  // the default's neighbours, for docs/preview.md's table
            const Result r = measure(n);
            std::printf(
                "  %s search_steps %d: at the first root %zu; squared error on multi-root pixels %.3f, total %.3f\n",
                room.name, n, r.at_first, r.multi_error, r.total_error);
        }
        std::printf("%s: %zu of %zu sphere pixels multi-root (%.1f %%); at the first root: %zu -> %zu; their share of "
                    "the squared error %.1f %% -> %.1f %% (total %.3f -> %.3f)\n",
                    room.name, multi, rays.size(), 100.0 * multi / rays.size(), before.at_first, after.at_first,
                    100 * before.multi_error / before.total_error, 100 * after.multi_error / after.total_error,
                    before.total_error, after.total_error);
        ASSERT_GT(multi, 20u);  // the rooms are made for it
        // Before, almost none end at the first root; after, most (a crossing narrower than a search step is missed).
        EXPECT_GE(double(after.at_first), double(before.at_first) + 0.3 * double(multi));
        EXPECT_GT(double(after.at_first), 0.4 * double(multi));
        EXPECT_LE(after.multi_error, before.multi_error);
        EXPECT_LE(after.total_error, before.total_error);
    }
}

// "iterations" is the same work for every strategy: D(R), the start's ρ and one ρ per step, 2 + iterations distance
// reads with tolerance 0 (the thesis's three and the safeguarded ones without a search); the search adds at most
// search_steps reads.
TEST(PreviewLocalizationProbe, IterationsAreTheSameWorkForEveryStrategy) {
    gl();
    Scene scene = sphere_beside_a_column();
    GpuRenderer gpu(scene, plan_features(scene),
                    std::vector<const SphereFresnel*>(scene.spheres.size(), unit_fresnel()), nullptr);
    gpu.capture_environment();
    const auto rays = sphere_pixel_rays(scene);
    for (Strategy strategy :
         {Strategy::secant, Strategy::false_position, Strategy::mixed, Strategy::illinois, Strategy::safe_secant})
        for (int n : {0, 1, 4, 8}) {
            SCOPED_TRACE(std::string(to_string(strategy)) + " " + std::to_string(n));
            Sphere settings;
            settings.strategy = strategy;
            settings.iterations = n;
            settings.tolerance = 0;
            settings.search_steps = 0;
            for (const ProbeResult& p : probe_reflection_lookups(gpu, settings, rays))
                ASSERT_EQ(p.distance_lookups, 2 + n);
            if (strategy != Strategy::illinois && strategy != Strategy::safe_secant) continue;
            settings.search_steps = kDefaultSearchSteps;
            int most = 0, least = 1 << 20;
            for (const ProbeResult& p : probe_reflection_lookups(gpu, settings, rays)) {
                most = std::max(most, p.distance_lookups);
                least = std::min(least, p.distance_lookups);
            }
            EXPECT_LE(most, 2 + n + kDefaultSearchSteps);
            EXPECT_GE(least, 2 + n + 1);  // the search reads at least once
        }
}

// The lookup is the best evaluated guess: |ρ − 1| at the lookup point never grows with the iteration limit, ray by
// ray, from 0 steps on (the first step cannot make the lookup worse in the quantity the finder sees).
TEST(PreviewLocalizationProbe, RhoAtTheLookupNeverGrowsWithTheLimit) {
    gl();
    for (Scene (*make)() : {thin_occluders_scene, long_empty_room}) {
        Scene scene = make();
        GpuRenderer gpu(scene, plan_features(scene),
                        std::vector<const SphereFresnel*>(scene.spheres.size(), unit_fresnel()), nullptr);
        gpu.capture_environment();
        const auto rays = sphere_pixel_rays(scene);
        for (Strategy strategy : {Strategy::illinois, Strategy::safe_secant})
            for (int search : {0, kDefaultSearchSteps}) {
                SCOPED_TRACE(std::string(to_string(strategy)) + " search " + std::to_string(search));
                std::vector<double> previous(rays.size(), std::numeric_limits<double>::infinity());
                std::size_t raised = 0;
                for (int n = 0; n <= 12; ++n) {
                    Sphere settings;
                    settings.strategy = strategy;
                    settings.iterations = n;
                    settings.tolerance = 0;
                    settings.search_steps = search;
                    const auto probes = probe_reflection_lookups(gpu, settings, rays);
                    for (std::size_t i = 0; i < rays.size(); ++i) {
                        const double rho_error = std::abs(length(probes[i].lookup) / probes[i].texel[3] - 1);
                        if (rho_error > previous[i] * (1 + 1e-5) + 1e-6) ++raised;
                        previous[i] = rho_error;
                    }
                }
                EXPECT_EQ(raised, 0u);
            }
    }
}

}  // namespace test_preview_localization
}  // namespace metalfit::glpreview
