// Painter's, BSP and Warnock shade their visible pixels as the z-buffer does (the same options and
// shading code): with default options (Phong, lights, textures) the color images equal the
// z-buffer's except where the visible surface differs (see agreement_test.cpp for why it can, on
// bands narrower than a pixel), at most 0.1% of the pixels.
#include <zraster/load.hpp>
#include <zraster/scenes.hpp>
#include <zraster/visibility.hpp>

#include <gtest/gtest.h>

#include <string>

#include "support/test_support.hpp"
#include "visibility/visibility_test_util.hpp"

namespace zraster::test {
namespace {

struct ColorAgreement {
    std::size_t pixels = 0;
    std::size_t differing = 0;               // any channel differs
    std::size_t differing_same_surface = 0;  // ... where both show the same triangle
    double fraction() const { return pixels ? double(differing) / double(pixels) : 0.0; }
};

ColorAgreement compare_colors(const RenderTargets& reference, const RenderTargets& other) {
    ColorAgreement a;
    a.pixels = reference.primitive_id.size();
    for (std::size_t p = 0; p < a.pixels; ++p) {
        bool differs = false;
        for (std::size_t c = 0; c < 4; ++c)
            differs |= reference.color[4 * p + c] != other.color[4 * p + c];
        a.differing += differs;
        a.differing_same_surface += differs && reference.primitive_id[p] == other.primitive_id[p] &&
                                    reference.instance_id[p] == other.instance_id[p];
    }
    return a;
}

void expect_zbuffer_colors(const Scene& scene, const RenderOptions& options,
                           const std::string& label, bool unsplit_surfaces_exact) {
    const RenderResult reference =
        render_with_visibility(scene, options, VisibilityAlgorithm::ZBuffer);
    std::size_t covered = 0;
    for (const std::int32_t id : reference.targets.primitive_id) covered += id >= 0;
    ASSERT_GT(covered, reference.targets.primitive_id.size() / 10) << label;
    for (const VisibilityAlgorithm a :
         {VisibilityAlgorithm::Painter, VisibilityAlgorithm::Bsp, VisibilityAlgorithm::Warnock}) {
        VisibilityStats stats;
        const RenderResult r = render_with_visibility(scene, options, a, &stats);
        const ColorAgreement agreement = compare_colors(reference.targets, r.targets);
        const std::string what = label + " algorithm " + std::to_string(int(a));
        EXPECT_LE(agreement.fraction(), 0.001)
            << what << ": " << agreement.differing << " of " << agreement.pixels
            << " pixels differ, " << agreement.differing_same_surface << " on the same surface";
        // Unsplit surfaces are shaded from the same barycentrics: bit for bit.
        const bool split = stats.painter.splits > 0 || stats.bsp.splits > 0;
        if (unsplit_surfaces_exact && !split) {
            EXPECT_EQ(agreement.differing_same_surface, 0u) << what;
        }
    }
}

RenderOptions shaded_options(int width, int height) {
    RenderOptions o = id_options(width, height);  // default shading: Phong, lights, textures
    EXPECT_EQ(o.shading, ShadingMode::Phong);
    return o;
}

TEST(ShadedAgreement, SphereGouraudAndPhong) {
    const Scene scene = make_procedural_scene("sphere:2000");
    for (const ShadingMode mode : {ShadingMode::Phong, ShadingMode::Gouraud, ShadingMode::Flat}) {
        RenderOptions o = shaded_options(240, 180);
        o.shading = mode;
        expect_zbuffer_colors(scene, o, "sphere mode " + std::to_string(int(mode)), true);
    }
}

TEST(ShadedAgreement, TexturedDefaultScene) {
    const Scene scene = make_procedural_scene("builtin:default");
    RenderOptions o = shaded_options(320, 180);
    o.camera = builtin_camera("builtin:default");
    expect_zbuffer_colors(scene, o, "builtin:default", false);
}

class ShadedSharedMesh : public ::testing::TestWithParam<const char*> {};

TEST_P(ShadedSharedMesh, ColorsAreTheZBuffers) {
    ZRASTER_REQUIRE_SHARED_DATA();
    const Scene scene = load_scene(shared_data(GetParam()));
    expect_zbuffer_colors(scene, shaded_options(320, 240), GetParam(), false);
}

INSTANTIATE_TEST_SUITE_P(Shared, ShadedSharedMesh,
                         ::testing::Values("meshes/obj/bunny-small.obj",
                                           "meshes/obj/spot/spot_triangulated.obj"));

}  // namespace
}  // namespace zraster::test
