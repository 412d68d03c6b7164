// The GL side of glpreview on whatever EGL gives (llvmpipe in CI), checked against independent forms: the CPU
// tracer of the same environment, box projection, the sphere-proxy closed form, the CPU reference image.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <numbers>
#include <random>
#include <variant>

#include "glpreview/effects/reflection_lookup.hpp"
#include "glpreview/gl/gl_context.hpp"
#include "glpreview/io/image_io.hpp"
#include "glpreview/render/cpu_reference.hpp"
#include "glpreview/render/environment.hpp"
#include "glpreview/render/gpu_bench.hpp"
#include "glpreview/render/gpu_renderer.hpp"
#include "glpreview/render/preview.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "glpreview/render/sphere_metrics.hpp"
#include "glpreview/scene/camera.hpp"
#include "libfit/base/version.hpp"
#include "libfit/color/color_space.hpp"
#include "libfit/models/model.hpp"
#include "test_support.hpp"

namespace metalfit::glpreview {
namespace test_preview_gpu {

using test::kData;
namespace fs = std::filesystem;

GlContext& gl() {
    static GlContext context = GlContext::create();
    return context;
}

PreviewOptions options() { return {kData, choose_ocio_config(std::nullopt, kData), {}, 0}; }

Scene room_scene(std::vector<RoomBox> boxes = {}) {
    Scene scene;
    scene.file = "test-scene.json";
    scene.environment.type = EnvironmentType::room;
    scene.environment.room.boxes = std::move(boxes);
    scene.environment.reference_point = Vec3{0, 1.2, 0};
    scene.environment.room.panels = {{-1, -1, 1, 1, {6, 6, 6}}};
    Sphere sphere;
    sphere.center = {0.3, 1.0, 0.2};
    scene.spheres = {sphere};
    return scene;
}

Scene difficult_scene() {
    return room_scene({{{-1.9, 0.0, -1.6}, {-1.1, 1.1, -0.8}, {0.85, 0.75, 0.2}},
                       {{0.9, 0.0, 0.9}, {1.5, 0.7, 1.5}, {0.2, 0.7, 0.8}},
                       {{1.35, 0.0, -1.65}, {1.85, 3.0, -1.15}, {0.8, 0.8, 0.85}}});
}

double angle_between(Vec3 a, Vec3 b) { return std::acos(std::clamp(dot(normalize(a), normalize(b)), -1.0, 1.0)); }

// Random shaded points x (relative to o) within `spread` of o, and random unit directions.
std::vector<std::array<Vec3, 2>> random_rays(int count, double spread, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::normal_distribution<double> n;
    std::vector<std::array<Vec3, 2>> rays;
    while (static_cast<int>(rays.size()) < count) {
        const Vec3 x{spread * u(random), spread * u(random), spread * u(random)};
        const Vec3 r{n(random), n(random), n(random)};
        if (length(r) < 1e-3) continue;
        rays.push_back({x, normalize(r)});
    }
    return rays;
}

// Box projection (Lagarde & Zanuttini 2012), written here independently of the shader.
Vec3 box_projection(const Room& room, Vec3 o, Vec3 x, Vec3 r) {
    double t = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
        if (r[i] == 0) continue;
        t = std::min(t, std::max((room.max[i] - o[i] - x[i]) / r[i], (room.min[i] - o[i] - x[i]) / r[i]));
    }
    return x + t * r;
}

Sphere impostor(Strategy strategy, int iterations) {
    Sphere s;
    s.reflection = ReflectionMode::distance_impostor;
    s.strategy = strategy;
    s.iterations = iterations;
    return s;
}

std::vector<const SphereFresnel*> no_fresnel(const Scene& scene) {
    static const SphereFresnel unit = [] {
        SphereFresnel f;
        f.lut.assign(2, RGB{1, 1, 1});
        return f;
    }();
    return std::vector<const SphereFresnel*>(scene.spheres.size(), &unit);
}

TEST(PreviewGpu, ContextIsOpenGl45Core) {
    const std::string version = gl().version();
    EXPECT_TRUE(version.rfind("4.", 0) == 0 && version[2] >= '5') << version;
    EXPECT_FALSE(gl().renderer().empty());
}

TEST(PreviewGpu, ShaderErrorsAreOneLineMessagesNamingTheShader) {
    gl();
    try {
        compile_compute_program("#version 450 core\nlayout(local_size_x = 1) in;\nvoid main() { undefined_call(); }\n",
                                "broken-probe");
        FAIL() << "no error";
    } catch (const GlError& e) {
        const std::string what = e.what();
        EXPECT_TRUE(test::Contains(what, "broken-probe"));
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
}

// The cube map GL captured holds, at each texel centre, what the CPU tracer sees from o in that direction.
TEST(PreviewGpu, CapturedCubeMatchesTheCpuTracerAtTexelCentres) {
    gl();
    Scene scene = difficult_scene();
    scene.environment.cube_size = 64;
    scene.spheres[0] = impostor(Strategy::false_position, 1);
    GpuRenderer gpu(scene, plan_features(scene), no_fresnel(scene), nullptr);
    gpu.capture_environment();
    const EnvironmentTracer tracer(scene.environment);
    const int n = scene.environment.cube_size;
    int mismatched = 0, total = 0;
    double worst_distance = 0;
    for (int face = 0; face < 6; ++face) {
        const std::vector<float> texels = gpu.read_cube_face(face);
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double s = 2.0 * (i + 0.5) / n - 1, t = 2.0 * (j + 0.5) / n - 1;
                // OpenGL's face table (spec 8.13), written out here independently of capture.frag.
                const Vec3 faces[6] = {{1, -t, -s}, {-1, -t, s}, {s, 1, t}, {s, -1, -t}, {s, -t, 1}, {-s, -t, -1}};
                const EnvironmentHit hit = tracer.trace(scene.environment.reference(), normalize(faces[face]));
                const float* v = &texels[4 * (static_cast<std::size_t>(j) * n + i)];
                ++total;
                worst_distance = std::max(worst_distance, std::abs(v[3] - hit.t) / hit.t);
                const double radiance_error =
                    std::max({std::abs(v[0] - hit.radiance.r), std::abs(v[1] - hit.radiance.g),
                              std::abs(v[2] - hit.radiance.b)});
                if (radiance_error > 1e-4) ++mismatched;  // a checker edge crossed in float
            }
    }
    EXPECT_LT(worst_distance, 1e-5);
    EXPECT_LT(mismatched, total / 500) << mismatched << " of " << total;
}

// Classic lookups read the texel of direction R: its distance is what the CPU tracer finds along R (this fixes the
// orientation of every face, independently of the capture's own face table).
TEST(PreviewGpu, ClassicLookupsReadTheDistanceAlongR) {
    gl();
    Scene scene = room_scene();
    scene.spheres[0] = impostor(Strategy::secant, 0);  // distance channel on
    GpuRenderer gpu(scene, plan_features(scene), no_fresnel(scene), nullptr);
    gpu.capture_environment();
    Sphere classic;
    classic.reflection = ReflectionMode::classic;
    const auto rays = random_rays(2000, 0.0, 7);
    const auto results = probe_reflection_lookups(gpu, classic, rays);
    const EnvironmentTracer tracer(scene.environment);
    double worst = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const double t = tracer.trace(scene.environment.reference(), rays[i][1]).t;
        worst = std::max(worst, std::abs(results[i].texel[3] - t) / t);
    }
    // Linear interpolation between texel centres bends distances where walls meet (up to ~2e-3 at corners); a face
    // in the wrong orientation would be off by tens of per cent.
    EXPECT_LT(worst, 1e-2);
}

// In the empty box room the distance impostor converges to box projection (Lazányi 2008, ch. 4; Lagarde & Zanuttini 2012; docs/references.md). Secant converges
// superlinearly: every lookup direction is within 1e-3 rad of box projection's after 4 iterations. False position
// (and mixed, which continues with false-position steps) converges linearly, as regula falsi does when one end of
// the bracket sticks: after 4 iterations 90% of the rays are within 1e-3, after 16 iterations 99%; the worst ray
// improves with every iteration count. (docs/preview.md has the table; this test measures it.)
TEST(PreviewGpu, DistanceImpostorConvergesToBoxProjectionInTheEmptyRoom) {
    gl();
    Scene scene = room_scene();
    scene.environment.cube_size = 512;
    scene.spheres[0] = impostor(Strategy::false_position, 4);
    GpuRenderer gpu(scene, plan_features(scene), no_fresnel(scene), nullptr);
    gpu.capture_environment();
    const auto rays = random_rays(4000, 1.0, 11);
    const Vec3 o = scene.environment.reference();
    Sphere parallax;
    parallax.reflection = ReflectionMode::box_parallax;
    const auto box = probe_reflection_lookups(gpu, parallax, rays);
    for (std::size_t i = 0; i < rays.size(); ++i)
        ASSERT_LT(angle_between(box[i].lookup, box_projection(scene.environment.room, o, rays[i][0], rays[i][1])),
                  1e-5);
    for (Strategy strategy : {Strategy::secant, Strategy::false_position, Strategy::mixed}) {
        std::map<int, std::vector<double>> angles;  // sorted, per iteration count
        for (int iterations : {1, 4, 16}) {
            const auto results = probe_reflection_lookups(gpu, impostor(strategy, iterations), rays);
            for (std::size_t i = 0; i < rays.size(); ++i)
                angles[iterations].push_back(angle_between(results[i].lookup, box[i].lookup));
            std::sort(angles[iterations].begin(), angles[iterations].end());
        }
        auto quantile = [&](int iterations, double q) {
            return angles[iterations][static_cast<std::size_t>(q * (rays.size() - 1))];
        };
        SCOPED_TRACE(to_string(strategy));
        if (strategy == Strategy::secant) {
            EXPECT_LT(quantile(4, 1.0), 1e-3);
        }
        EXPECT_LT(quantile(4, 0.9), 1e-3);
        EXPECT_LT(quantile(16, 0.99), 1e-3);
        EXPECT_LT(quantile(4, 1.0), quantile(1, 1.0));
        EXPECT_LT(quantile(16, 1.0), quantile(4, 1.0));
    }
}

// With a constant-distance environment (a sphere room of radius r around o) the hit has a closed form:
// d = −x·R + sqrt((x·R)² − |x|² + r²).
TEST(PreviewGpu, DistanceImpostorEqualsTheSphereProxyClosedForm) {
    gl();
    Scene scene = room_scene();
    scene.environment.type = EnvironmentType::sphere_room;
    scene.environment.sphere_room.radius = 4;
    scene.spheres[0] = impostor(Strategy::secant, 4);
    GpuRenderer gpu(scene, plan_features(scene), no_fresnel(scene), nullptr);
    gpu.capture_environment();
    const auto rays = random_rays(4000, 1.5, 13);
    for (Strategy strategy : {Strategy::secant, Strategy::false_position, Strategy::mixed}) {
        const auto results = probe_reflection_lookups(gpu, impostor(strategy, 4), rays);
        double worst = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const Vec3 x = rays[i][0], r = rays[i][1];
            const double xr = dot(x, r);
            const double d = -xr + std::sqrt(xr * xr - dot(x, x) + 16.0);
            worst = std::max(worst, angle_between(results[i].lookup, x + d * r));
        }
        EXPECT_LT(worst, 1e-3) << to_string(strategy);
    }
}

// An environment at infinity: classic reflections are exact, so the GPU image equals the CPU reference.
TEST(PreviewGpu, ClassicModeEqualsTheCpuReferenceForAnEnvironmentAtInfinity) {
    gl();
    test::TempDir dir;
    Image sky(64, 32);
    for (int y = 0; y < sky.height; ++y)
        for (int x = 0; x < sky.width; ++x)
            sky.set(x, y, {0.2 + 2.0 * x / sky.width, 0.1 + 1.5 * (y % 8) / 8.0, 1.0 + std::sin(0.3 * x + 0.2 * y)});
    write_exr(dir.path() / "sky.exr", sky);
    Scene scene;
    scene.file = dir.path() / "scene.json";
    scene.width = 96;
    scene.height = 64;
    scene.camera.position = {0, 0, 3};
    scene.camera.look_at = {0, 0, 0};
    scene.environment.type = EnvironmentType::equirect;
    scene.environment.equirect.file = dir.path() / "sky.exr";
    Sphere gold;
    gold.center = {-0.6, 0, 0};
    gold.reflection = ReflectionMode::classic;
    Sphere copper = gold;
    copper.center = {0.6, 0, 0};
    copper.material = "Cu";
    copper.fresnel = ModelFresnel{"f82-tint", ParameterSource::fit};
    scene.spheres = {gold, copper};
    scene.outputs.timing_frames = 5;
    const PreviewResult result = run_preview(scene, options(), &gl());
    ASSERT_TRUE(result.beauty && result.reference);
    for (const SphereError& e : sphere_errors(*result.beauty, *result.reference, 2)) {
        EXPECT_GT(e.pixels, 500u);
        EXPECT_LT(e.rmse, 2e-3);  // float camera rays and a half-float-free path: only rounding (LUT filtering)
    }
}

// docs/scene.md, "Colour": an equirect image tagged `colorspace` is converted into the scene's space when it is read
// (checked against the published ACEScg → Rec.709 matrix, Bradford); naming the default space changes nothing.
TEST(PreviewGpu, AnEquirectImageIsConvertedFromItsColorspaceIntoTheScenesSpace) {
    test::TempDir dir;
    const RGB sky_acescg{0.5, 0.4, 0.3};
    Image sky(16, 8);
    for (int y = 0; y < sky.height; ++y)
        for (int x = 0; x < sky.width; ++x) sky.set(x, y, sky_acescg);
    write_exr(dir.path() / "sky.exr", sky);
    Scene scene;
    scene.file = dir.path() / "scene.json";
    scene.width = 32;
    scene.height = 24;
    scene.environment.type = EnvironmentType::equirect;
    scene.environment.equirect.file = dir.path() / "sky.exr";
    Sphere s;
    s.center = {0, 1, 0};
    s.radius = 0.2;
    s.reflection = ReflectionMode::classic;
    scene.spheres = {s};
    scene.outputs.beauty = scene.outputs.difference = scene.outputs.metrics = false;
    const PreviewResult untagged = run_preview(scene, options(), &gl());
    scene.environment.equirect.colorspace = "ACEScg";
    const PreviewResult tagged = run_preview(scene, options(), &gl());
    scene.space = "Linear Rec.709 (sRGB)";
    const PreviewResult named = run_preview(scene, options(), &gl());
    ASSERT_TRUE(untagged.reference && tagged.reference && named.reference);
    constexpr double M[3][3] = {
        {1.7048586, -0.6217160, -0.0832993}, {-0.1300768, 1.1407357, -0.0105598}, {-0.0239640, -0.1289755, 1.1530216}};
    const RGB corner_untagged = untagged.reference->image.at(0, 0), corner = tagged.reference->image.at(0, 0);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(corner_untagged[c], sky_acescg[c], 1e-3);  // half-float EXR: 3 decimal digits
        const double expected = M[c][0] * sky_acescg.r + M[c][1] * sky_acescg.g + M[c][2] * sky_acescg.b;
        EXPECT_NEAR(corner[c], expected, 2e-3) << c;
    }
    EXPECT_EQ(tagged.reference->image.rgb, named.reference->image.rgb);
}

// EXRs say which RGB they hold (issue 20 item 5): the `chromaticities` of the scene's space as OCIO maps it to CIE XYZ
// D65 (docs/preview.md, "Outputs"): Rec.709 / D65 (ITU-R BT.709) as published; ACEScg (AP1, ACES white, SMPTE ST
// 2065-1 / S-2014-004) Bradford-adapted to D65, computed here from the published primaries.
using Mat3 = std::array<std::array<double, 3>, 3>;
Mat3 mul(const Mat3& a, const Mat3& b) {
    Mat3 m{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) m[i][j] += a[i][k] * b[k][j];
    return m;
}
Mat3 inverse(const Mat3& a) {
    const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                       a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                       a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    Mat3 m;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
            m[i][j] = (a[r0][c0] * a[r1][c1] - a[r0][c1] * a[r1][c0]) / det;
        }
    return m;
}
std::array<double, 3> xyz_of(double x, double y) { return {x / y, 1.0, (1 - x - y) / y}; }
std::array<double, 3> times(const Mat3& m, const std::array<double, 3>& v) {
    return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
            m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}
// RGB → XYZ of primaries r, g, b and white w (xy pairs), then Bradford from w to D65; the xy of each column and of white.
std::array<double, 8> adapted_chromaticities(const std::array<double, 8>& p) {
    Mat3 P;
    for (int c = 0; c < 3; ++c) {
        const auto v = xyz_of(p[2 * c], p[2 * c + 1]);
        for (int r = 0; r < 3; ++r) P[r][c] = v[r];
    }
    const auto W = xyz_of(p[6], p[7]), D65 = xyz_of(0.3127, 0.3290);
    const auto S = times(inverse(P), W);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) P[r][c] *= S[c];
    const Mat3 B{{{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}}};
    const auto from = times(B, W), to = times(B, D65);
    const Mat3 D{{{to[0] / from[0], 0, 0}, {0, to[1] / from[1], 0}, {0, 0, to[2] / from[2]}}};
    const Mat3 M = mul(mul(inverse(B), mul(D, B)), P);
    std::array<double, 8> out;
    for (int c = 0; c < 4; ++c) {
        const auto v = c < 3 ? std::array<double, 3>{M[0][c], M[1][c], M[2][c]} : times(M, {1, 1, 1});
        const double sum = v[0] + v[1] + v[2];
        out[2 * c] = v[0] / sum, out[2 * c + 1] = v[1] / sum;
    }
    return out;
}

TEST(PreviewGpu, ExrOutputsCarryTheChromaticitiesOfTheScenesSpace) {
    test::TempDir dir;
    Scene scene;
    scene.file = dir.path() / "scene.json";
    scene.width = 16;
    scene.height = 12;
    Sphere s;
    s.reflection = ReflectionMode::classic;
    scene.spheres = {s};
    scene.outputs.beauty = scene.outputs.difference = scene.outputs.metrics = scene.outputs.png = false;
    struct Case {
        std::string space, name;
        std::array<double, 8> xy;
    };
    const std::array<double, 8> rec709{0.64, 0.33, 0.30, 0.60, 0.15, 0.06, 0.3127, 0.3290};
    const std::array<double, 8> ap1{0.713, 0.293, 0.165, 0.830, 0.128, 0.044, 0.32168, 0.33767};
    EXPECT_NEAR(adapted_chromaticities(rec709)[0], 0.64, 1e-12);  // the adaptation of D65 to D65 changes nothing
    for (const Case& c :
         {Case{"", "Linear Rec.709 (sRGB)", rec709}, Case{"ACEScg", "ACEScg", adapted_chromaticities(ap1)}}) {
        scene.space = c.space;
        PreviewOptions o = options();
        o.output_dir = dir.path() / ("out-" + c.name.substr(0, 6));
        run_preview(scene, o, &gl());
        const auto colour = read_exr_colour(o.output_dir / "reference.exr");
        ASSERT_TRUE(colour) << c.name;
        EXPECT_EQ(colour->space, c.name);
        const auto& k = colour->chromaticities;
        const std::array<double, 8> got{k.red[0],  k.red[1],  k.green[0], k.green[1],
                                        k.blue[0], k.blue[1], k.white[0], k.white[1]};
        for (int i = 0; i < 8; ++i) EXPECT_NEAR(got[i], c.xy[i], 5e-4) << c.name << " " << i;
    }
    // An EXR written without them has none.
    write_exr(dir.path() / "plain.exr", Image(2, 2));
    EXPECT_FALSE(read_exr_colour(dir.path() / "plain.exr"));
}

// The chunks of a PNG file: type → data (read here from the file's bytes, not through the writer's library).
std::map<std::string, std::string> png_chunks(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::map<std::string, std::string> chunks;
    EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    for (std::size_t at = 8; at + 12 <= bytes.size();) {
        const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(bytes[i]); };
        const std::size_t length =
            (std::size_t(byte(at)) << 24) | (byte(at + 1) << 16) | (byte(at + 2) << 8) | byte(at + 3);
        chunks[bytes.substr(at + 4, 4)] += bytes.substr(at + 8, length);
        at += 12 + length;
    }
    return chunks;
}
std::vector<unsigned> big_endian_words(const std::string& data) {
    std::vector<unsigned> words;
    for (std::size_t i = 0; i + 4 <= data.size(); i += 4)
        words.push_back((unsigned(static_cast<unsigned char>(data[i])) << 24) |
                        (unsigned(static_cast<unsigned char>(data[i + 1])) << 16) |
                        (unsigned(static_cast<unsigned char>(data[i + 2])) << 8) |
                        unsigned(static_cast<unsigned char>(data[i + 3])));
    return words;
}

// Issue 20 item 5: each EXR names its spheres (material, model, parameters, roughness) and every image; each PNG of
// metalfit's sRGB display says so with sRGB, gAMA and cHRM chunks (PNG 1.2 §4.2: gAMA 45455, cHRM of Rec.709 / D65
// in units of 1e-5).
TEST(PreviewGpu, ExrHeadersNameEverySphereAndPngsCarryTheirSrgbChunks) {
    test::TempDir dir;
    Scene scene;
    scene.file = dir.path() / "scene.json";
    scene.width = 16;
    scene.height = 12;
    Sphere gold;
    gold.reflection = ReflectionMode::classic;
    Sphere copper;
    copper.center = {1.1, 0.9, 0};
    copper.material = "Cu";
    copper.fresnel = ModelFresnel{"f82-tint", ParameterSource::fit};
    copper.reflection = ReflectionMode::box_parallax;
    copper.roughness = 0.25;
    copper.glossy = GlossyMethod::prefiltered;
    scene.spheres = {gold, copper};
    scene.outputs.reference_samples = 4;
    PreviewOptions o = options();
    o.output_dir = dir.path() / "out";
    run_preview(scene, o, &gl());

    FresnelLibrary library(kData, o.ocio, "", scene.file);
    const SphereFresnel& fitted = library.get(copper, "copper");
    std::string parameters;
    char text[64];
    for (std::size_t i = 0; i < 2; ++i) {
        const RGB v = fitted.parameters.parameter(i);
        std::snprintf(text, sizeof text, "%s = (%.9g, %.9g, %.9g)", i ? "; tint" : "F0", v.r, v.g, v.b);
        parameters += text;
    }
    for (const std::string image : {"beauty.exr", "reference.exr", "difference.exr"}) {
        std::map<std::string, std::variant<std::string, float, int>> got;
        for (const ExrAttribute& a : read_image_metadata(o.output_dir / image, "metalfit/")) got[a.name] = a.value;
        using V = std::variant<std::string, float, int>;
        const std::map<std::string, V> expected{{"metalfit/version", V(std::string(METALFIT_VERSION))},
                                                {"metalfit/image", V(image)},
                                                {"metalfit/scene", V(std::string("scene.json"))},
                                                {"metalfit/spheres", V(2)},
                                                {"metalfit/sphere0/material", V(std::string("Au"))},
                                                {"metalfit/sphere0/name", V(std::string("gold"))},
                                                {"metalfit/sphere0/source", V(std::string("Johnson"))},
                                                {"metalfit/sphere0/model", V(std::string("reference"))},
                                                {"metalfit/sphere0/roughness", V(0.0f)},
                                                {"metalfit/sphere0/reflection", V(std::string("classic"))},
                                                {"metalfit/sphere1/material", V(std::string("Cu"))},
                                                {"metalfit/sphere1/name", V(std::string("copper"))},
                                                {"metalfit/sphere1/source", V(std::string("Johnson"))},
                                                {"metalfit/sphere1/model", V(std::string("f82-tint"))},
                                                {"metalfit/sphere1/params", V(std::string("fit"))},
                                                {"metalfit/sphere1/parameters", V(parameters)},
                                                {"metalfit/sphere1/roughness", V(0.25f)},
                                                {"metalfit/sphere1/reflection", V(std::string("box-parallax"))}};
        EXPECT_EQ(got, expected) << image;
    }
    for (const std::string image : {"beauty.png", "reference.png", "difference.png"}) {
        const auto chunks = png_chunks(o.output_dir / image);
        ASSERT_TRUE(chunks.count("sRGB")) << image;
        EXPECT_EQ(chunks.at("sRGB").size(), 1u);
        ASSERT_TRUE(chunks.count("gAMA")) << image;
        EXPECT_EQ(big_endian_words(chunks.at("gAMA")), std::vector<unsigned>{45455});
        ASSERT_TRUE(chunks.count("cHRM")) << image;
        EXPECT_EQ(big_endian_words(chunks.at("cHRM")),
                  (std::vector<unsigned>{31270, 32900, 64000, 33000, 30000, 60000, 15000, 6000}));  // white, R, G, B
    }
}

// The seed's claim: in a room with occluders, the distance impostor beats classic environment mapping, and more
// iterations help.
TEST(PreviewGpu, ErrorFallsFromClassicToOneToFourIterationsInTheDifficultRoom) {
    gl();
    Scene scene = difficult_scene();
    scene.width = 160;
    scene.height = 120;
    scene.camera.position = {0, 1.4, 2.4};
    scene.camera.look_at = {0, 0.9, 0};
    Sphere classic;
    classic.center = {0.2, 0.8, -0.2};
    classic.radius = 0.6;
    classic.reflection = ReflectionMode::classic;
    std::vector<double> rmse;
    for (int iterations : {-1, 1, 4}) {
        Sphere s = classic;
        if (iterations >= 0)
            s = impostor(Strategy::false_position, iterations), s.center = classic.center, s.radius = classic.radius;
        scene.spheres = {s};
        const PreviewResult result = run_preview(scene, options(), &gl());
        rmse.push_back(result.metrics["spheres"][0]["rmse"].get<double>());
    }
    EXPECT_GT(rmse[0], rmse[1]);
    EXPECT_GT(rmse[1], rmse[2]);
}

// One small picture as a regression guard over the whole path (room, Fresnel, lookups, OCIO display transform):
// at most 0.1 % of the pixels may differ by more than 5/255 in some channel (tests/fixtures/golden/README.md).
TEST(PreviewGpu, GoldenImage) {
    gl();
    test::TempDir dir;
    const fs::path golden = test::kFixtures / "golden";
    const Scene scene = load_scene(golden / "preview-small.json");
    PreviewOptions o = options();
    o.output_dir = dir.path();
    run_preview(scene, o, &gl());
    const Png8 expected = read_png8(golden / "preview-small.png");
    const Png8 actual = read_png8(dir.path() / "beauty.png");
    ASSERT_EQ(actual.width, expected.width);
    ASSERT_EQ(actual.height, expected.height);
    std::size_t failing = 0;
    for (std::size_t p = 0; p < expected.rgb.size() / 3; ++p) {
        int worst = 0;
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::abs(int(actual.rgb[3 * p + c]) - int(expected.rgb[3 * p + c])));
        if (worst > 5) ++failing;
    }
    EXPECT_LE(failing, expected.rgb.size() / 3 / 1000) << failing << " pixels differ by more than 5/255";
}

// The shader benchmark through its pass graph: one row per libfit model and the reference LUT, each timed, and the
// exact pass's paired ratio to itself is 1.
TEST(PreviewGpu, ShaderBenchmarkTimesEveryModelAndTheReferenceLut) {
    const nlohmann::ordered_json j = bench_shaders(gl(), options(), true);
    ASSERT_EQ(j["models"].size(), all_models().size() + 1);
    EXPECT_EQ(j["models"].back()["model"], "reference-lut");
    EXPECT_EQ(j["evaluations_per_pixel"], kShaderBenchEvaluationsPerPixel);
    for (const auto& m : j["models"]) {
        EXPECT_GT(m["ms_per_frame"].get<double>(), 0) << m["model"];
        if (m["model"] == "conductor-rgb") {
            EXPECT_EQ(m["ratio_to_conductor_rgb"].get<double>(), 1.0);
        }
    }
}

}  // namespace test_preview_gpu
}  // namespace metalfit::glpreview
