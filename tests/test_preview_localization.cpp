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
#include "glpreview/scene/scene.hpp"
#include "test_support.hpp"

namespace metalfit::glpreview {
namespace {

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
        double best = by_limit[0][s].rmse;
        for (std::size_t k = 1; k < limits.size(); ++k) {
            best = std::min(best, by_limit[k][s].rmse);
            if (GetParam().empty && limits[k] > 2) {
                EXPECT_TRUE(no_worse(by_limit[k][s].rmse, by_limit[k - 1][s].rmse))
                    << limits[k] << " steps: " << by_limit[k][s].rmse << " after " << by_limit[k - 1][s].rmse;
            }
        }
        if (GetParam().empty) {
            EXPECT_LT(at_default[s].rmse, 1.02 * best + 2e-4);
            EXPECT_LT(by_limit.back()[s].rmse, 1.02 * best + 2e-4);
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

}  // namespace
}  // namespace metalfit::glpreview
