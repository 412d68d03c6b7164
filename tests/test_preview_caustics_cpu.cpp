// The rings and their caustics in the CPU references (issue 35 items 1, 4 and 8, the CPU side): the ring's
// intersection against the implicit equation (both sides, the arc), a ring seen as F(μ) × the room along the
// reflected ray, the rings' shadows, the photon tracer's energy, the caustic's focus against the closed forms, and
// bad input through the glpreview binary.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "effects/caustics/caustic_closed_form.hpp"
#include "effects/caustics/caustic_reference.hpp"
#include "effects/caustics/photon_tracer.hpp"
#include "effects/lights/cpu_lights.hpp"
#include "effects/rings/ring.hpp"
#include "effects/rings/rings_effect.hpp"
#include "glpreview/effects/caustics_bench.hpp"
#include "glpreview/effects/registry.hpp"
#include "glpreview/render/cpu_reference.hpp"
#include "glpreview/render/preview.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "libfit/base/errors.hpp"
#include "test_support.hpp"

namespace metalfit::glpreview {
namespace test_preview_caustics_cpu {

using test::kData;
namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;

FresnelLibrary& library() {
    static FresnelLibrary lib(kData, choose_ocio_config(std::nullopt, kData), "", "caustics.json");
    return lib;
}

// A 6 × 3 × 6 room (grey, no panels) with `rings`, `lights` and one small far sphere.
std::string ring_scene(const std::string& rings, const std::string& lights, const std::string& extra = "") {
    return R"({"image": {"width": 96, "height": 72},
      "camera": {"position": [0, 2.2, 2.6], "look_at": [0, 0.2, 0], "fov_y_deg": 55},
      "environment": {"type": "room", "panels": [], "floor_light": [0.5, 0.5, 0.5], "floor_dark": [0.5, 0.5, 0.5]},
      "rings": [)" +
           rings + R"(], "lights": [)" + lights + R"(],
      "spheres": [{"center": [2.4, 0.2, 2.4], "radius": 0.2}])" +
           extra + "}";
}

// The scene with its rings' Fresnel (and, with lights, their spectra) resolved, as a preview resolves them.
Scene resolved(const std::string& json, bool spectra = true) {
    Scene scene = parse_scene(json, "caustics.json");
    resolve_effect_materials(scene, library());
    if (spectra) resolve_caustic_spectra(scene, library(), true);
    return scene;
}

const Rings& rings_of(const Scene& scene) { return *scene.effects.find<Rings>(); }

// ---- The ring's intersection --------------------------------------------------------------------------------------

// The first wall the ray meets, independently: the implicit equation |p_xz − c|² = R² sampled along the ray, each
// sign change bisected, the height and the arc checked with the azimuth's own angle (atan2, not the cosine test).
std::optional<double> marched_hit(const Ring& ring, Vec3 o, Vec3 d, double t_max) {
    const auto f = [&](double t) {
        const Vec3 p = o + t * d;
        return (p.x - ring.base.x) * (p.x - ring.base.x) + (p.z - ring.base.z) * (p.z - ring.base.z) -
               ring.radius * ring.radius;
    };
    const double step = 1e-3;
    for (double t = 0; t < t_max; t += step) {
        double a = t, b = t + step;
        if ((f(a) < 0) == (f(b) < 0)) continue;
        for (int i = 0; i < 60; ++i) {
            const double m = 0.5 * (a + b);
            ((f(a) < 0) == (f(m) < 0) ? a : b) = m;
        }
        const Vec3 p = o + a * d;
        if (p.y < ring.base.y || p.y > ring.base.y + ring.height) continue;
        const double azimuth = std::atan2(p.z - ring.base.z, p.x - ring.base.x);
        const double off = std::remainder(azimuth - ring.facing_deg * kPi / 180, 2 * kPi);
        if (ring.arc_deg < 360 && std::abs(off) > 0.5 * ring.arc_deg * kPi / 180) continue;
        return a;
    }
    return std::nullopt;
}

TEST(RingIntersection, MatchesTheImplicitEquationOnBothSidesAndTheArc) {
    Ring ring;
    ring.base = {0.2, 0, -0.1};
    ring.radius = 0.8;
    ring.height = 0.5;
    ring.arc_deg = 200;
    ring.facing_deg = 30;
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    int hits = 0, inner = 0, outer = 0;
    for (int k = 0; k < 400; ++k) {
        const Vec3 o{u(random), 0.25 + 0.3 * u(random), u(random)};
        const Vec3 d = normalize(Vec3{u(random), 0.3 * u(random), u(random)});
        const std::optional<RingHit> hit = intersect_ring(ring, o, d, 0, 4);
        const std::optional<double> marched = marched_hit(ring, o, d, 4);
        ASSERT_EQ(hit.has_value(), marched.has_value()) << k;
        if (!hit) continue;
        ++hits;
        EXPECT_NEAR(hit->t, *marched, 1e-9) << k;
        EXPECT_LT(dot(hit->normal, d), 0) << "the normal faces the ray";
        EXPECT_NEAR(length(hit->normal), 1, 1e-12);
        // The inner side: the ray leaves the cylinder (its origin's side of the wall is inside).
        const Vec3 p = hit->point - ring.base;
        const bool leaving = dot(d, Vec3{p.x, 0, p.z}) > 0;
        EXPECT_EQ(hit->inner, leaving);
        (hit->inner ? inner : outer)++;
    }
    EXPECT_GT(hits, 40);
    EXPECT_GT(inner, 10);
    EXPECT_GT(outer, 10);
    // The arc: a ray through the middle meets it, one through the gap (opposite the middle) does not.
    const double f = ring.facing_deg * kPi / 180;
    const Vec3 middle{std::cos(f), 0, std::sin(f)};
    EXPECT_TRUE(intersect_ring(ring, ring.base + Vec3{0, 0.2, 0}, middle, 0, 9).has_value());
    EXPECT_FALSE(intersect_ring(ring, ring.base + Vec3{0, 0.2, 0}, -1.0 * middle, 0, 9).has_value());
    ring.arc_deg = 360;
    EXPECT_TRUE(intersect_ring(ring, ring.base + Vec3{0, 0.2, 0}, -1.0 * middle, 0, 9).has_value());
    // Above the wall, or beyond t_max: none.
    EXPECT_FALSE(intersect_ring(ring, ring.base + Vec3{0, 0.6, 0}, middle, 0, 9).has_value());
    EXPECT_FALSE(intersect_ring(ring, ring.base + Vec3{0, 0.2, 0}, middle, 0, 0.5).has_value());
}

// ---- The ring in the CPU references -------------------------------------------------------------------------------

const std::string kGoldRing =
    R"({"base": [0, 0, 0], "radius": 1.0, "height": 0.35, "arc_deg": 180, "facing_deg": -90, "material": "Au"})";

TEST(CpuRing, IsItsFresnelTimesTheRoomAlongTheReflectedRay) {
    const Scene scene = resolved(ring_scene(kGoldRing, ""), false);
    const Effect& rings = rings_effect();
    const EnvironmentTracer tracer(scene.environment, nullptr, {},
                                   [&](Vec3 o, Vec3 d, double t_max, const EnvironmentTracer& room) {
                                       return rings.cpu_environment_object(scene, o, d, t_max, room);
                                   });
    const SphereFresnel& gold = *rings_of(scene).fresnel[0];
    int seen = 0;
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int k = 0; k < 200; ++k) {
        const Vec3 o{0.3 * u(random), 0.2 + 0.1 * u(random), 0.5 + 0.3 * u(random)};
        const Vec3 d = normalize(Vec3{u(random), 0.2 * u(random), -1});
        const EnvironmentHit room = tracer.room_trace(o, d);
        const EnvironmentHit hit = tracer.trace(o, d);
        const std::optional<RingHit> ring = intersect_rings(rings_of(scene).rings, o, d, 0, room.t);
        if (!ring) {
            EXPECT_EQ(hit.radiance, room.radiance);
            continue;
        }
        ++seen;
        const double mu = std::clamp(-dot(d, ring->normal), 0.0, 1.0);
        const Vec3 reflected = d - 2 * dot(d, ring->normal) * ring->normal;
        const RGB expected = gold(mu) * tracer.room_trace(ring->point, reflected).radiance;
        EXPECT_EQ(hit.t, ring->t);
        for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(hit.radiance[c], expected[c]);
        // One reflection: a reflected ray that would meet the ring again reads the room alone.
    }
    EXPECT_GT(seen, 100);
}

TEST(CpuRing, CastsShadowsForTheLightsCpuShadowRays) {
    const Scene scene = resolved(
        ring_scene(kGoldRing, R"({"type": "directional", "direction": [0, -0.35, -1], "intensity": 3})"), false);
    const Lights& lights = *scene.effects.find<Lights>();
    const Vec3 to_light = -1.0 * lights.lights[0].direction;
    // Behind the wall (z < −1), low enough that the wall stands between the floor and the light.
    const Vec3 shadowed{0, 0, -1.3}, lit{0, 0, 1.5}, up{0, 1, 0};
    EXPECT_TRUE(occluded(scene, shadowed, to_light, std::numeric_limits<double>::infinity()));
    EXPECT_FALSE(occluded_by_spheres_and_boxes(scene, shadowed, to_light, std::numeric_limits<double>::infinity()));
    EXPECT_FALSE(occluded(scene, lit, to_light, std::numeric_limits<double>::infinity()));
    const RGB grey{0.5, 0.5, 0.5};
    EXPECT_EQ(light_on_surface(scene, lights, grey, shadowed, up), (RGB{0, 0, 0}));
    EXPECT_GT(light_on_surface(scene, lights, grey, lit, up).g, 0.1);
    // A point beyond the shadow's reach: the wall ends at 0.35 m, its shadow 1 m behind it.
    EXPECT_FALSE(occluded(scene, Vec3{0, 0, -2.2}, to_light, std::numeric_limits<double>::infinity()));
}

// The share of the pixels that see no sphere (the room and the ring) where the GPU's beauty and the CPU reference
// agree within `tolerance` (relative, green), and their mean |difference|.
struct Agreement {
    double share = 0, mean_abs = 0;
};
Agreement agreement(const PreviewResult& r, double tolerance) {
    int agree = 0, total = 0;
    double sum = 0;
    for (int y = 0; y < r.beauty->height; ++y)
        for (int x = 0; x < r.beauty->width; ++x) {
            if (r.reference->sphere_id[static_cast<std::size_t>(y) * r.beauty->width + x] >= 0) continue;
            const double a = r.beauty->at(x, y).g, b = r.reference->image.at(x, y).g;
            ++total;
            sum += std::abs(a - b);
            agree += std::abs(a - b) <= tolerance * std::max(b, 1e-3) ? 1 : 0;
        }
    return {double(agree) / total, sum / total};
}

TEST(CpuRingGpu, TheReferenceAgreesWithTheBeautyWithoutLights) {
    // A room lit by its ceiling panel alone: no caustics; the gold ring seen, reflecting the room, on both sides.
    Scene scene = parse_scene(ring_scene(kGoldRing + R"(, {"base": [1.5, 0, -1.2], "radius": 0.5, "height": 0.6,
                                             "arc_deg": 300, "facing_deg": 135, "material": "Cu", "fresnel": "f82-tint"})",
                                         ""),
                              "caustics.json");
    scene.environment.room.panels.push_back({-0.5, -0.5, 0.5, 0.5, {4, 4, 4}});
    const PreviewResult r = run_preview(scene, {kData, choose_ocio_config(std::nullopt, kData), {}, 1});
    const Agreement a = agreement(r, 0.01);
    std::cout << "ring scene without lights: " << 100 * a.share << " % of the pixels within 1 %, mean |diff| "
              << a.mean_abs << "\n";
    EXPECT_GT(a.share, 0.999);
    EXPECT_LT(a.mean_abs, 1e-5);
}

TEST(CpuRingGpu, WithALightTheyDifferInTheCausticAndAtShadowEdges) {
    // The GPU of this branch throws no caustic: the reference is brighter where the ring focuses the light, and
    // they differ where the shadow maps' texels blur the ring's shadow edge; elsewhere they agree.
    const Scene scene =
        parse_scene(ring_scene(kGoldRing, R"({"type": "directional", "direction": [0, -0.35, -1], "intensity": 3})",
                               R"(, "caustics": {"reference_photons": 100000})"),
                    "caustics.json");
    const PreviewResult r = run_preview(scene, {kData, choose_ocio_config(std::nullopt, kData), {}, 1});
    const Agreement a = agreement(r, 0.02);
    std::cout << "ring scene with a light: " << 100 * a.share << " % of the pixels within 2 %, mean |diff| "
              << a.mean_abs << "\n";
    EXPECT_GT(a.share, 0.85);
}

// ---- The photon tracer --------------------------------------------------------------------------------------------

CausticMap trace(const Scene& scene, int photons, double sigma, bool spectral = true) {
    PhotonFresnel fresnel;
    if (spectral) {
        const CausticSpectra& spectra = *scene.effects.find<CausticSpectra>();
        for (const auto& s : spectra.rings) fresnel.spectral.push_back(s.get());
        fresnel.uplift = spectra.uplift.get();
    } else {
        fresnel.rgb = rings_of(scene).fresnel;
    }
    PhotonOptions options;
    options.photons = photons;
    options.sigma = sigma;
    return trace_caustics(scene, rings_of(scene), *scene.effects.find<Lights>(), fresnel, options);
}

double max_fresnel(const SphereFresnel& f, int c) {
    double best = 0;
    for (int k = 0; k <= 1000; ++k) best = std::max(best, f(k / 1000.0)[c]);
    return best;
}

TEST(Photons, ConserveEnergy) {
    // A grazing directional light and a point light, a closed gold ring and a copper arc.
    const Scene scene = resolved(ring_scene(
        kGoldRing + R"(, {"base": [1.6, 0, -1.5], "radius": 0.6, "height": 0.4, "arc_deg": 360, "material": "Cu"})",
        R"({"type": "directional", "direction": [0.3, -0.35, -1], "intensity": 3},
           {"type": "point", "position": [-1, 1.5, 1], "intensity": 2})"));
    const CausticMap map = trace(scene, 100000, 0.03);
    const PhotonBudget& b = map.budget();
    ASSERT_GT(b.hits, 10000);
    EXPECT_GT(b.multiple, 0);
    // max over μ and channels of R_c(μ): above 1 for gold's red (a white-balanced channel of a saturated colour).
    double max_f = 0;
    for (int c = 0; c < 3; ++c)
        max_f =
            std::max({max_f, max_fresnel(*rings_of(scene).fresnel[0], c), max_fresnel(*rings_of(scene).fresnel[1], c)});
    RGB receivers{0, 0, 0};
    for (int r = 0; r < kReceivers; ++r) receivers = receivers + map.receiver(static_cast<Receiver>(r)).power;
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(receivers[c], b.deposited[c], 1e-9 * b.deposited[c]);
        EXPECT_GT(b.deposited[c], 0);
        // Deposited ≤ intercepted × max F (white light); what is reflected is deposited or absorbed.
        EXPECT_LE(b.deposited[c], b.intercepted[c] * max_f);
        EXPECT_LE(b.deposited[c] + b.absorbed[c], b.reflected[c] * (1 + 1e-12));
        EXPECT_LE(b.reflected[c], b.intercepted[c] * max_f);
        EXPECT_GT(b.deposited_multiple[c], 0);
        EXPECT_LT(b.deposited_multiple[c], b.deposited[c]);
    }
    // In luminance (a positive functional of the spectrum) no channel's white balance lifts it: Y out ≤ Y in.
    const RGB y{0.2126, 0.7152, 0.0722};
    const auto luminance = [&](const RGB& c) { return y.r * c.r + y.g * c.g + y.b * c.b; };
    EXPECT_LT(luminance(b.deposited), luminance(b.intercepted));
    // The grid keeps the power: Σ E × step² over a receiver is its photons' power.
    for (int r = 0; r < kReceivers; ++r) {
        const ReceiverMap& m = map.receiver(static_cast<Receiver>(r));
        if (m.photons.empty()) continue;
        const IrradiancePeak peak = measure_receiver(map, static_cast<Receiver>(r), {0.2126, 0.7152, 0.0722});
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(peak.power[c], m.power[c], 1e-4 * m.power[c] + 1e-12) << r;
    }
    // The grid's irradiance against the density estimate summed over every photon, near the floor's peak.
    const IrradiancePeak floor = measure_receiver(map, Receiver::floor, {0.2126, 0.7152, 0.0722});
    for (const double du : {0.0, 0.05, -0.07}) {
        const RGB grid = map.irradiance(Receiver::floor, floor.u + du, floor.v + 0.5 * du);
        const RGB exact = map.exact_irradiance(Receiver::floor, floor.u + du, floor.v + 0.5 * du);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(grid[c], exact[c], 0.01 * exact[c] + 1e-9) << du;
    }
}

TEST(Photons, InterceptTheLightTheRingPresents) {
    // A horizontal beam on a closed ring: its cross-section is the wall's 2R × h.
    const Scene scene =
        resolved(ring_scene(R"({"base": [0, 0, 0], "radius": 0.5, "height": 0.3, "arc_deg": 360, "material": "Ag"})",
                            R"({"type": "directional", "direction": [0, 0, -1], "intensity": 2})"));
    const CausticMap map = trace(scene, 200000, 0.03);
    const double expected = 2.0 * (2 * 0.5 * 0.3);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(map.budget().intercepted[c], expected, 0.01 * expected);
}

TEST(Photons, ASpotIsAPointLightInsideItsConeAndTheMapIsTheSameOnAnyThreads) {
    const std::string ring = R"({"base": [0, 0, 0], "radius": 0.5, "height": 0.3, "arc_deg": 360, "material": "Au"})";
    const Scene point = resolved(ring_scene(ring, R"({"type": "point", "position": [0, 2, 1.5], "intensity": 2})"));
    // Its axis on the ring, the cone wide enough for the whole bounding sphere: weight 1 on every photon.
    const Scene wide =
        resolved(ring_scene(ring, R"({"type": "spot", "position": [0, 2, 1.5], "direction": [0, -1.85, -1.5],
        "cone_inner_deg": 40, "cone_outer_deg": 50, "intensity": 2})"));
    const Scene narrow = resolved(ring_scene(ring, R"({"type": "spot", "position": [0, 2, 1.5], "direction": [0, 1, 0],
        "cone_inner_deg": 5, "cone_outer_deg": 10, "intensity": 2})"));
    const CausticMap p = trace(point, 50000, 0.03), w = trace(wide, 50000, 0.03), n = trace(narrow, 50000, 0.03);
    EXPECT_GT(p.budget().hits, 1000);
    for (int c = 0; c < 3; ++c) {
        EXPECT_DOUBLE_EQ(w.budget().intercepted[c], p.budget().intercepted[c]);
        EXPECT_DOUBLE_EQ(w.budget().deposited[c], p.budget().deposited[c]);
        EXPECT_EQ(n.budget().intercepted[c], 0);  // pointing away
    }
    // The same photons on 1 and 3 threads: the same map, bit for bit.
    PhotonFresnel fresnel;
    fresnel.rgb = rings_of(point).fresnel;
    PhotonOptions options;
    options.photons = 30000;
    options.threads = 1;
    const CausticMap one = trace_caustics(point, rings_of(point), *point.effects.find<Lights>(), fresnel, options);
    options.threads = 3;
    const CausticMap three = trace_caustics(point, rings_of(point), *point.effects.find<Lights>(), fresnel, options);
    EXPECT_EQ(one.receiver(Receiver::floor).grid, three.receiver(Receiver::floor).grid);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(one.budget().deposited[c], three.budget().deposited[c]);
}

// The floor's brightest point of a fine photon map against the closed form's focus. The focus is a cusp of the
// floor's irradiance: smoothed with a Gaussian of σ, its brightest point lies inside the cusp, towards the wall, at a
// distance that shrinks as σ^(2/3) (a cusp's scaling: across its axis as λ³, along it as λ²), not within σ. So the
// peak is found at σ and σ/2 and extrapolated to σ → 0 with that exponent: that lands on the closed form.
void expect_focus(const std::string& ring, const std::string& light) {
    const Scene scene = resolved(ring_scene(ring, light));
    const Ring& r = rings_of(scene).rings[0];
    std::string why;
    const std::optional<CausticFocus> focus = caustic_focus(r, scene.effects.find<Lights>()->lights[0], &why);
    ASSERT_TRUE(focus) << why;
    const CausticMap traced = trace(scene, 1000000, 0.02, false);
    const RGB y{0.2126, 0.7152, 0.0722};
    const IrradiancePeak coarse = measure_receiver(traced, Receiver::floor, y);
    const IrradiancePeak fine = measure_receiver(with_sigma(traced, 0.01), Receiver::floor, y);
    const double k = std::pow(2.0, 2.0 / 3.0);
    const double u0 = (k * fine.u - coarse.u) / (k - 1), v0 = (k * fine.v - coarse.v) / (k - 1);
    const double off_coarse = std::hypot(coarse.u - focus->point.x, coarse.v - focus->point.z);
    const double off_fine = std::hypot(fine.u - focus->point.x, fine.v - focus->point.z);
    const double off = std::hypot(u0 - focus->point.x, v0 - focus->point.z);
    std::cout << focus->form << ": focus (" << focus->point.x << ", " << focus->point.z << "); peak at sigma 0.02 off "
              << off_coarse << " m, at 0.01 off " << off_fine << " m; extrapolated (" << u0 << ", " << v0 << ") off "
              << off << " m\n";
    EXPECT_LT(off, 0.015);  // the peaks' noise (a few mm with 10⁶ photons), amplified by the extrapolation
    // The peak approaches the focus as σ shrinks, by about 2^(2/3) per halving, from the wall's side.
    EXPECT_LT(off_fine, off_coarse);
    EXPECT_GT(off_coarse / off_fine, 1.3);
    EXPECT_LT(off_coarse / off_fine, 2.0);
    const Vec3 towards_wall = r.base + r.radius * normalize(focus->point - r.base) - focus->point;
    EXPECT_GT(dot(Vec3{fine.u - focus->point.x, 0, fine.v - focus->point.z}, towards_wall), 0);
}

TEST(CausticFocus, DirectionalLightFocusesAtHalfTheRadius) {
    expect_focus(kGoldRing, R"({"type": "directional", "direction": [0, -0.35, -1], "intensity": 3})");
    // Another azimuth and elevation, a wider arc.
    expect_focus(
        R"({"base": [0.5, 0, 0.2], "radius": 0.8, "height": 0.5, "arc_deg": 240, "facing_deg": 0, "material": "Cu"})",
        R"({"type": "directional", "direction": [1, -0.6, 0.2], "intensity": 3})");
}

TEST(CausticFocus, PointLightOnTheCircleFocusesAtAThirdOfTheRadius) {
    expect_focus(kGoldRing, R"({"type": "point", "position": [0, 0.8, 1], "intensity": 3})");
}

TEST(CausticFocus, SaysWhyThereIsNone) {
    Ring ring;
    ring.height = 0.1;
    ring.arc_deg = 180;
    ring.facing_deg = -90;
    Light light;
    light.type = LightType::directional;
    light.direction = normalize(Vec3{0, -0.35, -1});
    std::string why;
    EXPECT_FALSE(caustic_focus(ring, light, &why));  // needs 0.175 m
    EXPECT_TRUE(test::Contains(why, "(R/2) tan e"));
    ring.height = 0.2;
    EXPECT_TRUE(caustic_focus(ring, light));
    light.direction = normalize(Vec3{0, -0.35, 1});  // towards the gap
    EXPECT_FALSE(caustic_focus(ring, light, &why));
    light.type = LightType::point;
    light.position = {0.5, 1, 0.5};
    EXPECT_FALSE(caustic_focus(ring, light, &why));
    EXPECT_TRUE(test::Contains(why, "circle"));
}

// ---- The per-model table -------------------------------------------------------------------------------------------

TEST(CausticsBench, EveryModelAgainstTheSpectralReference) {
    const nlohmann::ordered_json j =
        bench_caustics({kData, choose_ocio_config(std::nullopt, kData), {}, 0}, /*quick=*/true);
    ASSERT_EQ(j["metals"].size(), 3u);
    for (const auto& m : j["metals"]) {
        // Every model of the registry has a fitted row; the RGB reference curve is the spectral one's within 0.5 %.
        std::size_t fitted = 0;
        for (const auto& r : m["rows"]) fitted += r["params"] == "fit" ? 1 : 0;
        EXPECT_EQ(fitted, all_models().size());
        const auto& lut = m["rows"][0];
        EXPECT_EQ(lut["model"], "reference-lut");
        EXPECT_LT(std::abs(lut["power_rel"]["worst"].get<double>()), 0.005) << m["metal"];
        EXPECT_LT(std::abs(lut["peak_rel"]["worst"].get<double>()), 0.005) << m["metal"];
        EXPECT_LT(m["reference"]["focus_distance"].get<double>(), 0.1);  // σ = 0.03: the σ^(2/3) offset
        for (const auto& r : m["rows"]) EXPECT_EQ(r["peak_shift"].get<double>(), 0.0);
    }
}

// ---- Bad input ------------------------------------------------------------------------------------------------------

TEST(CausticsCli, BadRingsAndCausticsAreExit3NamingTheFileAndField) {
    test::TempDir dir;
    const auto run = [&](const std::string& ring, const std::string& extra) {
        const fs::path scene = dir.write("bad.json", ring_scene(ring, "", extra));
        return test::run_command(test::kGlpreviewExe, scene.string() + " -o " + (dir.path() / "out").string(),
                                 dir.path());
    };
    const test::CommandResult radius = run(R"({"base": [0, 0, 0], "radius": 0})", "");
    EXPECT_EQ(radius.exit_code, 3);
    EXPECT_TRUE(test::Contains(radius.err, "bad.json: rings[0].radius: must be > 0")) << radius.err;
    const test::CommandResult negative = run(R"({"base": [0, 0, 0], "radius": -1})", "");
    EXPECT_EQ(negative.exit_code, 3);
    EXPECT_TRUE(test::Contains(negative.err, "rings[0].radius: must be > 0")) << negative.err;
    for (const char* arc : {"0", "-10", "360.5", "720"}) {
        const test::CommandResult r = run(R"({"base": [0, 0, 0], "arc_deg": )" + std::string(arc) + "}", "");
        EXPECT_EQ(r.exit_code, 3) << arc;
        EXPECT_TRUE(test::Contains(r.err, "bad.json: rings[0].arc_deg: must be in (0, 360]")) << r.err;
    }
    const test::CommandResult map = run(kGoldRing, R"(, "caustics": {"map_size": 100000})");
    EXPECT_EQ(map.exit_code, 3);
    EXPECT_TRUE(test::Contains(map.err, "bad.json: caustics.map_size")) << map.err;
    EXPECT_EQ(std::count(map.err.begin(), map.err.end(), '\n'), 1) << map.err;
    EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

}  // namespace test_preview_caustics_cpu
}  // namespace metalfit::glpreview
