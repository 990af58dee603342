// Watertightness through the whole pipeline: rendering a closed mesh with culling and the depth
// test off, every pixel gets as many front-facing as back-facing fragments (every ray enters
// the surface as often as it leaves it); for a sphere, exactly one of each inside the
// silhouette and none outside.
#include <zraster/load.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include "render/render_test_util.hpp"
#include "support/test_support.hpp"

namespace zraster::test {
namespace {

RenderResult coverage_render(const Scene& scene, int w, int h, std::optional<Camera> camera = {}) {
    RenderOptions o;
    o.width = w;
    o.height = h;
    o.camera = camera;
    o.cull = CullMode::None;
    o.depth_test = false;
    o.coverage_counts = true;
    o.color_target = false;
    return render(scene, o);
}

struct Balance {
    std::size_t unbalanced = 0, covered = 0;
};

Balance front_back_balance(const RenderTargets& t) {
    Balance b;
    for (std::size_t i = 0; i < t.front_hits.size(); ++i) {
        b.unbalanced += t.front_hits[i] != t.back_hits[i];
        b.covered += t.front_hits[i] > 0;
    }
    return b;
}

TEST(WatertightMesh, SphereHasExactlyOneFrontAndOneBackHitInsideItsSilhouette) {
    const Mesh sphere = make_uv_sphere(1.0f, 40, 80);
    Scene scene = scene_from_meshes({sphere});
    const auto r = coverage_render(scene, 320, 240);
    const RenderTargets& t = r.targets;
    std::size_t inside = 0;
    for (std::size_t i = 0; i < t.front_hits.size(); ++i) {
        ASSERT_LE(t.front_hits[i], 1u) << "pixel " << i;
        ASSERT_EQ(t.front_hits[i], t.back_hits[i]) << "pixel " << i;
        inside += t.front_hits[i];
    }
    // The framed sphere fills the vertical field of view: a disc of diameter ~240 px.
    EXPECT_GT(inside, std::size_t(0.9 * 3.14159 * 120 * 120 * 0.95));
}

TEST(WatertightMesh, BenchSphereWithSubpixelTrianglesIsBalanced) {
    // The benchmark generator at about 200,000 triangles: many are smaller than a pixel here.
    Scene scene = scene_from_meshes({make_bench_sphere(200000)});
    const auto r = coverage_render(scene, 640, 360);
    const Balance b = front_back_balance(r.targets);
    EXPECT_EQ(b.unbalanced, 0u);
    EXPECT_GT(b.covered, 50000u);
}

class SharedClosedMesh : public ::testing::TestWithParam<const char*> {};

TEST_P(SharedClosedMesh, FrontAndBackHitsBalanceAtEveryPixel) {
    ZRASTER_REQUIRE_SHARED_DATA();
    const Scene scene = load_scene(shared_data(GetParam()));
    const auto r = coverage_render(scene, 480, 320);
    const Balance b = front_back_balance(r.targets);
    EXPECT_EQ(b.unbalanced, 0u) << GetParam();
    EXPECT_GT(b.covered, 1000u);
}

// The closed, manifold meshes of the MANIFEST.
INSTANTIATE_TEST_SUITE_P(Shared, SharedClosedMesh,
                         ::testing::Values("meshes/obj/bunny.obj", "meshes/obj/bunny-small.obj",
                                           "meshes/obj/nefertiti.obj",
                                           "meshes/obj/spot/spot_triangulated.obj",
                                           "meshes/ply/cube_binary.ply", "meshes/ply/fuze.ply"));

}  // namespace
}  // namespace zraster::test
