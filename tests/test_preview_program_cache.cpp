// The GL programs of one context are linked once for every renderer made in it (glpreview --batch): a second scene
// with the same shaders links none, and draws its own room and materials (each renderer sets its own uniforms on a
// shared program), as it would in a context of its own.
#include <gtest/gtest.h>

#include <optional>

#include "glpreview/gl/gl_context.hpp"
#include "glpreview/gl/program_cache.hpp"
#include "glpreview/render/preview.hpp"
#include "libfit/color/color_space.hpp"
#include "test_support.hpp"

namespace metalfit::glpreview {
namespace test_preview_program_cache {

using test::kData;

Scene room_scene() {
    Scene scene;
    scene.width = 48;
    scene.height = 36;
    Sphere classic;
    classic.center = {-0.6, 1.2, 0};
    classic.radius = 0.4;
    classic.reflection = ReflectionMode::classic;
    Sphere parallax = classic;
    parallax.center = {0.6, 1.2, 0};
    parallax.material = "Cu";
    parallax.fresnel = ModelFresnel{"f82-tint", ParameterSource::fit};
    parallax.reflection = ReflectionMode::box_parallax;
    scene.spheres = {classic, parallax};
    scene.outputs.reference = scene.outputs.difference = scene.outputs.metrics = false;
    scene.outputs.timing_frames = 1;
    return scene;
}

PreviewOptions options() { return {kData, choose_ocio_config(std::nullopt, kData), {}, 0}; }

TEST(PreviewProgramCache, RenderersOfOneContextShareItsProgramsAndKeepTheirOwnUniforms) {
    const Scene first = room_scene();
    Scene second = room_scene();  // the same shaders; other materials, walls and camera: other uniforms
    second.spheres[0].material = "Ag";
    second.spheres[1].material = "Au";
    second.environment.room.wall_x_min = {0.1, 0.6, 0.2};
    second.environment.room.max = {3.5, 2.5, 3};
    second.camera.position = {0.3, 1.4, 3.2};
    Scene rough = room_scene();  // one shader more: a rough sphere
    rough.spheres[1].roughness = 0.3;

    std::optional<Image> shared_second, shared_first;
    {
        GlContext context = GlContext::create();
        const PreviewResult a = run_preview(first, options(), &context);
        const std::size_t linked = context.programs().size();
        EXPECT_GT(linked, 1u);
        const PreviewResult b = run_preview(second, options(), &context);
        EXPECT_EQ(context.programs().size(), linked) << "the second scene linked programs the first had linked";
        run_preview(rough, options(), &context);
        EXPECT_GT(context.programs().size(), linked);
        ASSERT_TRUE(a.beauty && b.beauty);
        shared_first = a.beauty;
        shared_second = b.beauty;
    }
    GlContext context = GlContext::create();
    const PreviewResult alone = run_preview(second, options(), &context);
    ASSERT_TRUE(alone.beauty);
    EXPECT_EQ(alone.beauty->rgb, shared_second->rgb) << "a shared program drew with the other scene's uniforms";
    EXPECT_NE(alone.beauty->rgb, shared_first->rgb);
}

}  // namespace test_preview_program_cache
}  // namespace metalfit::glpreview
