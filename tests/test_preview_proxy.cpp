// An equirect image on a proxy (issue 17 item 6, docs/scene.md "Environments"): the image is painted on a box or a
// sphere around the capture point, captured into a cube map with the proxy's distances, and reflected with
// box-parallax, the distance impostor and the rough methods; the CPU ground truth traces the same proxy.
// Independent forms: a shipped room captured into an equirect (its own render is what a box proxy equal to its box
// must give), and the plain equirect at infinity (what a sphere proxy of a huge radius must approach).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "glpreview/gl/gl_context.hpp"
#include "glpreview/io/image_io.hpp"
#include "glpreview/render/environment.hpp"
#include "glpreview/render/features.hpp"
#include "glpreview/render/plan.hpp"
#include "glpreview/render/preview.hpp"
#include "glpreview/render/sphere_metrics.hpp"
#include "libfit/base/errors.hpp"
#include "test_support.hpp"

namespace metalfit::glpreview {
namespace test_preview_proxy {

using test::kData;
namespace fs = std::filesystem;

GlContext& gl() {
    static GlContext context = GlContext::create();
    return context;
}

std::string parse_error(const std::string& environment,
                        const std::string& spheres = R"([{"center": [0, 0, 0], "reflection": "classic"}])") {
    try {
        parse_scene(R"({"environment": )" + environment + R"(, "spheres": )" + spheres + "}", "s.json");
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(PreviewProxy, TheProxyIsParsedAndMalformedOnesNameTheirField) {
    const Scene box =
        parse_scene(R"({"environment": {"type": "equirect", "file": "sky.hdr", "reference_point": [0, 1, 0],
        "proxy": {"box": {"min": [-3, 0, -3], "max": [3, 3, 3]}}}, "spheres": [{"center": [0, 1, 0], "reflection": "box-parallax", "roughness": 0.3}]})",
                    "s.json");
    ASSERT_TRUE(box.environment.equirect.proxy);
    EXPECT_EQ(std::get<BoxProxy>(*box.environment.equirect.proxy).max.y, 3);
    EXPECT_TRUE(box.environment.captured());
    EXPECT_EQ(box.environment.parallax_box()->min.x, -3);
    const Scene sphere =
        parse_scene(R"({"environment": {"type": "equirect", "file": "sky.hdr", "proxy": {"sphere": 50}},
        "spheres": [{"center": [0, 1, 0], "roughness": 0.5, "glossy": "localized"}]})",
                    "s.json");
    EXPECT_EQ(std::get<SphereProxy>(*sphere.environment.equirect.proxy).radius, 50);
    EXPECT_FALSE(sphere.environment.parallax_box());
    // A camera outside the box proxy sees the painted box from behind: one warning (none inside, none for a sphere).
    EXPECT_TRUE(box.warnings.empty());
    const std::string outside =
        R"({"camera": {"position": [0, 1, 4]}, "environment": {"type": "equirect", "file": "sky.hdr", "reference_point": [0, 1, 0],
        "proxy": PROXY}, "spheres": [{"center": [0, 1, 0], "reflection": "box-parallax"}]})";
    auto with_proxy = [&](const std::string& proxy) {
        return std::string(outside).replace(outside.find("PROXY"), 5, proxy);
    };
    const Scene behind = parse_scene(with_proxy(R"({"box": {"min": [-3, 0, -3], "max": [3, 3, 3]}})"), "s.json");
    ASSERT_EQ(behind.warnings.size(), 1u);
    EXPECT_EQ(
        behind.warnings[0],
        "s.json: camera.position: outside the proxy box (environment.proxy.box: the view shows the painted box from behind)");
    EXPECT_TRUE(
        parse_scene(with_proxy(R"({"box": {"min": [-3, 0, -3], "max": [3, 3, 5]}})"), "s.json").warnings.empty());

    const std::string sky = R"({"type": "equirect", "file": "sky.hdr", )";
    EXPECT_TRUE(test::Contains(parse_error(sky + R"("proxy": 3})"), "environment.proxy: expected an object"));
    EXPECT_TRUE(test::Contains(parse_error(sky + R"("proxy": {}})"),
                               "environment.proxy: expected exactly one of 'box' or 'sphere'"));
    EXPECT_TRUE(test::Contains(parse_error(sky + R"("proxy": {"sphere": 2, "box": {}}})"),
                               "environment.proxy: expected exactly one"));
    EXPECT_TRUE(test::Contains(parse_error(sky + R"("proxy": {"cube": 2}})"), "environment.proxy.cube: unknown key"));
    EXPECT_TRUE(
        test::Contains(parse_error(sky + R"("proxy": {"sphere": -1}})"), "environment.proxy.sphere: must be in"));
    EXPECT_TRUE(test::Contains(parse_error(sky + R"("proxy": {"sphere": "big"}})"),
                               "environment.proxy.sphere: expected a number"));
    EXPECT_TRUE(test::Contains(parse_error(sky + R"("proxy": {"box": {"min": [-1, -1, -1]}}})"),
                               "environment.proxy.box.max: missing"));
    EXPECT_TRUE(test::Contains(parse_error(sky + R"("proxy": {"box": {"min": [-1, -1, -1], "max": [1, 1]}}})"),
                               "environment.proxy.box.max: expected an array of 3 numbers"));
    EXPECT_TRUE(test::Contains(parse_error(sky + R"("proxy": {"box": {"min": [-1, -1, -1], "max": [1, -1, 1]}}})"),
                               "environment.proxy.box.max: must exceed min"));
    EXPECT_TRUE(test::Contains(parse_error(sky + R"("proxy": {"box": {"min": [1, 1, 1], "max": [2, 2, 2]}}})"),
                               "environment.proxy.box: the capture point"));
    EXPECT_TRUE(test::Contains(
        parse_error(sky +
                    R"("reference_point": [5, 0, 0], "proxy": {"box": {"min": [-1, -1, -1], "max": [1, 1, 1]}}})"),
        "environment.reference_point: the capture point"));
    // What a proxy makes possible stays refused without one, and box-parallax needs a box.
    EXPECT_TRUE(test::Contains(
        parse_error(sky + "\"intensity\": 1}", R"([{"center": [0, 0, 0], "roughness": 0.2, "reflection": "classic"}])"),
        "spheres[0].roughness: rough spheres need a captured environment"));
    EXPECT_TRUE(test::Contains(parse_error(sky + "\"intensity\": 1}", R"([{"center": [0, 0, 0]}])"),
                               "spheres[0].reflection: an equirect environment is at infinity without a proxy"));
    EXPECT_TRUE(test::Contains(
        parse_error(sky + R"("proxy": {"sphere": 5}})", R"([{"center": [0, 0, 0], "reflection": "box-parallax"}])"),
        "spheres[0].reflection: box-parallax needs a room environment or an equirect with a box proxy"));
    // Capture settings without a proxy mean nothing: warnings.
    const Scene plain = parse_scene(R"({"environment": {"type": "equirect", "file": "sky.hdr", "cube_size": 64},
        "spheres": [{"center": [0, 1, 0], "reflection": "classic"}]})",
                                    "s.json");
    ASSERT_EQ(plain.warnings.size(), 1u);
    EXPECT_TRUE(test::Contains(plain.warnings[0], "environment.cube_size: ignored"));
}

TEST(PreviewProxy, AProxyPlansTheCaptureOfTheImageAndThePlainEquirectDoesNot) {
    const std::string sky =
        R"({"image": {"width": 8, "height": 8}, "environment": {"type": "equirect", "file": "sky.hdr")";
    const std::string spheres = R"(, "spheres": [{"center": [0, 1, 0], "reflection": "classic"}]})";
    const Scene plain = parse_scene(sky + "}" + spheres, "s.json");
    const Scene proxied = parse_scene(sky + R"(, "proxy": {"sphere": 10}})" + spheres, "s.json");
    const Features a = plan_features(plain), b = plan_features(proxied);
    EXPECT_FALSE(a.environment_capture);
    EXPECT_TRUE(b.environment_capture);
    EXPECT_TRUE(a.equirect_image && b.equirect_image);
    EXPECT_EQ(*a.shader_variants.begin(), "ENV_EQUIRECT FRESNEL_REFERENCE REFLECTION_CLASSIC");
    EXPECT_TRUE(test::Contains(*b.shader_variants.begin(), "ENV_EQUIRECT_SPHERE"));
    const std::string text = explain(build_plan(proxied), proxied);
    EXPECT_TRUE(test::Contains(text, "equirect on its sphere proxy (radius 10.0): ray-cast by GL"));
    EXPECT_TRUE(test::Contains(text, "environment image on a proxy"));
    EXPECT_FALSE(test::Contains(explain(build_plan(plain), plain), "capture-environment ["));
}

// The CPU ground truth of a proxy: the ray leaves the box (or sphere) and the image is read towards that point from
// the capture point. Written here independently: a proxy box around an image of six flat colours per face.
TEST(PreviewProxy, TheCpuTracerReadsTheImageWhereTheRayLeavesTheProxy) {
    Image sky(64, 32);
    for (int y = 0; y < sky.height; ++y)
        for (int x = 0; x < sky.width; ++x) sky.set(x, y, {double(x), double(y), 1});
    Environment env;
    env.type = EnvironmentType::equirect;
    env.reference_point = Vec3{0, 1, 0};
    env.equirect.proxy = BoxProxy{{-2, 0, -3}, {2, 3, 3}};
    const EnvironmentTracer tracer(env, &sky);
    const Vec3 origin{1, 0.5, 1}, dir = normalize(Vec3{0.2, 0.2, -1});
    const double t = (-3 - origin.z) / dir.z;  // leaves through z = −3 (x, y stay inside)
    const Vec3 hit = origin + t * dir;
    ASSERT_LT(std::abs(hit.x), 2);
    const EnvironmentHit h = tracer.trace(origin, dir);
    EXPECT_NEAR(h.t, t, 1e-12);
    const RGB expected = sample_equirect(sky, normalize(hit - Vec3{0, 1, 0}));
    EXPECT_EQ(h.radiance.r, expected.r);
    EXPECT_EQ(h.radiance.g, expected.g);
    env.equirect.proxy = SphereProxy{4};
    const EnvironmentHit s = EnvironmentTracer(env, &sky).trace(origin, dir);
    EXPECT_NEAR(length(origin + s.t * dir - Vec3{0, 1, 0}), 4, 1e-12);
    // Directions of texel centres invert the lookup.
    for (const auto& [x, y] : {std::pair{0, 0}, {17, 9}, {63, 31}}) {
        const RGB at = sample_equirect(sky, equirect_direction(x, y, 64, 32));
        EXPECT_NEAR(at.r, x, 1e-9);
        EXPECT_NEAR(at.g, y, 1e-9);
    }
}

// A shipped room captured into an equirect from its reference point, with a box proxy equal to the room's box: the
// room's own reflections are what the proxy must give.
struct RoomAsProbe {
    Scene room, probe;
};
RoomAsProbe capture_room(const fs::path& scene_file, const fs::path& dir, int width, int height) {
    RoomAsProbe r{load_scene(scene_file), {}};
    r.room.width = width;
    r.room.height = height;
    r.room.environment.cube_size = 128;
    const EnvironmentTracer tracer(r.room.environment);
    write_exr(dir / "probe.exr", capture_equirect(tracer, r.room.environment.reference(), 1024, 512));
    r.probe = r.room;
    r.probe.file = dir / "probe.json";
    r.probe.environment.type = EnvironmentType::equirect;
    r.probe.environment.equirect.file = dir / "probe.exr";
    r.probe.environment.equirect.proxy = BoxProxy{r.room.environment.room.min, r.room.environment.room.max};
    r.probe.environment.reference_point = r.room.environment.reference();
    return r;
}

PreviewOptions options() { return {kData, choose_ocio_config(std::nullopt, kData), {}, 0}; }

// Per sphere RMSE between two beauty images over the mask of `reference`.
std::vector<SphereError> beauty_difference(const Image& a, const Image& b, const ReferenceRender& mask,
                                           std::size_t spheres) {
    ReferenceRender as_reference = mask;
    as_reference.image = b;
    return sphere_errors(a, as_reference, spheres);
}

TEST(PreviewProxy, ABoxProxyEqualToTheRoomGivesTheRoomsOwnBoxParallaxReflections) {
    gl();
    test::TempDir dir;
    RoomAsProbe r = capture_room(kData / "scenes" / "difficult-room.json", dir.path(), 96, 72);
    for (Scene* s : {&r.room, &r.probe}) {
        for (Sphere& sphere : s->spheres) sphere.reflection = ReflectionMode::box_parallax;
        s->outputs.difference = s->outputs.metrics = false;
    }
    struct Case {
        const char* name;
        double roughness;
        GlossyMethod glossy;
    };
    std::optional<ReferenceRender> mask;  // the spheres' pixels, from the first (mirror) case's reference
    for (const Case c :
         {Case{"mirror", 0, GlossyMethod::prefiltered}, Case{"prefiltered 0.3", 0.3, GlossyMethod::prefiltered},
          Case{"localized 0.6", 0.6, GlossyMethod::localized}}) {
        for (Scene* s : {&r.room, &r.probe})
            for (Sphere& sphere : s->spheres) {
                sphere.roughness = c.roughness;
                sphere.glossy = c.glossy;
                sphere.localized_size = 8;
            }
        r.room.outputs.reference = c.roughness == 0;  // the mask (the analytic reference is cheap)
        r.probe.outputs.reference = false;
        const PreviewResult room = run_preview(r.room, options(), &gl());
        const PreviewResult probe = run_preview(r.probe, options(), &gl());
        ASSERT_TRUE(room.beauty && probe.beauty);
        if (room.reference) mask = room.reference;
        ASSERT_TRUE(mask);
        const auto errors = beauty_difference(probe.beauty.value(), room.beauty.value(), *mask, r.room.spheres.size());
        for (std::size_t i = 0; i < errors.size(); ++i) {
            std::printf(
                "room as a box-proxy probe, %s, sphere %zu: RMSE %.4f, mean |diff| %.4f against the room's own render\n",
                c.name, i, errors[i].rmse, errors[i].mean_abs);
            // The lookup's geometry is the room's; the image is the room resampled twice (half-float 1024 × 512
            // texels, then the 128² cube), which moves checker edges and the radiance-6 panels' borders by up to a
            // cube texel: on mirrors a few edge pixels carry the RMSE (measured 0.016–0.057, mean |diff|
            // 0.003–0.008), the lobes average them away (0.003–0.018). A proxy box 0.5 m too large (below) is
            // several times these bounds.
            if (c.roughness == 0) {
                EXPECT_LT(errors[i].mean_abs, 0.012) << c.name << " sphere " << i;
                EXPECT_LT(errors[i].rmse, 0.08) << c.name << " sphere " << i;
            } else {
                EXPECT_LT(errors[i].rmse, 0.03) << c.name << " sphere " << i;
            }
        }
        if (c.roughness == 0) {  // the control: the same image on a wrong box
            Scene wrong = r.probe;
            wrong.environment.equirect.proxy = BoxProxy{r.room.environment.room.min - Vec3{0.5, 0.5, 0.5},
                                                        r.room.environment.room.max + Vec3{0.5, 0.5, 0.5}};
            const PreviewResult off = run_preview(wrong, options(), &gl());
            const auto off_errors =
                beauty_difference(off.beauty.value(), room.beauty.value(), *mask, r.room.spheres.size());
            for (std::size_t i = 0; i < off_errors.size(); ++i) {
                std::printf("  the same on a box 0.5 m too large, sphere %zu: RMSE %.4f, mean |diff| %.4f\n", i,
                            off_errors[i].rmse, off_errors[i].mean_abs);
                EXPECT_GT(off_errors[i].mean_abs, 2 * 0.012) << i;
            }
        }
    }
}

TEST(PreviewProxy, TheCpuReferenceOfTheProxyIsTheRoomsInAnEmptyRoom) {
    test::TempDir dir;
    RoomAsProbe r = capture_room(kData / "scenes" / "empty-room.json", dir.path(), 64, 48);
    for (Scene* s : {&r.room, &r.probe}) {
        s->outputs.beauty = s->outputs.difference = s->outputs.metrics = false;
        s->spheres[2].roughness = 0.4;
        s->outputs.reference_samples = 16;
    }
    const PreviewResult room = run_preview(r.room, options());
    const PreviewResult probe = run_preview(r.probe, options());
    ASSERT_TRUE(room.reference && probe.reference);
    const auto errors = sphere_errors(probe.reference->image, *room.reference, r.room.spheres.size());
    for (std::size_t i = 0; i < errors.size(); ++i) {
        std::printf("empty room as a box-proxy probe, CPU reference, sphere %zu: RMSE %.4f, mean |diff| %.4f\n", i,
                    errors[i].rmse, errors[i].mean_abs);
        EXPECT_LT(errors[i].mean_abs, 0.01) << i;  // the exact trace of the same walls through the image's texels
    }
}

TEST(PreviewProxy, ASphereProxyOfHugeRadiusApproachesThePlainEquirectAtInfinity) {
    gl();
    Scene plain = load_scene(kData / "scenes" / "sky.json");
    plain.width = 96;
    plain.height = 48;
    plain.outputs.difference = plain.outputs.metrics = false;
    const PreviewResult at_infinity = run_preview(plain, options(), &gl());
    ASSERT_TRUE(at_infinity.beauty && at_infinity.reference);
    double previous = 1e30;
    for (double radius : {4.0, 40.0, 1e4}) {
        Scene proxied = plain;
        proxied.environment.equirect.proxy = SphereProxy{radius};
        proxied.environment.cube_size = 128;
        for (Sphere& s : proxied.spheres) s.reflection = ReflectionMode::distance_impostor;
        const PreviewResult result = run_preview(proxied, options(), &gl());
        ASSERT_TRUE(result.beauty && result.reference);
        double worst_cpu = 0, worst_gpu = 0;
        const auto cpu = sphere_errors(result.reference->image, *at_infinity.reference, plain.spheres.size());
        const auto gpu =
            beauty_difference(*result.beauty, *at_infinity.beauty, *at_infinity.reference, plain.spheres.size());
        for (std::size_t i = 0; i < cpu.size(); ++i) {
            worst_cpu = std::max(worst_cpu, cpu[i].rmse);
            worst_gpu = std::max(worst_gpu, gpu[i].rmse);
        }
        std::printf(
            "sky on a sphere proxy of radius %g: worst sphere RMSE against the plain equirect: CPU reference %.5f, GPU %.5f\n",
            radius, worst_cpu, worst_gpu);
        EXPECT_LT(worst_cpu, previous);
        previous = worst_cpu;
        if (radius == 1e4) {
            EXPECT_LT(worst_cpu, 1e-3);  // parallax of |x| / radius ≈ 1e-4 rad
            EXPECT_LT(worst_gpu, 0.02);  // the image resampled into the 128² cube (measured, printed)
        }
    }
}

}  // namespace test_preview_proxy
}  // namespace metalfit::glpreview
