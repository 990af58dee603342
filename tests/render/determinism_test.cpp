// The same scene and options give bit-identical color, depth and ids for any thread count and
// across repeated runs.
#include <zraster/load.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include "render/render_test_util.hpp"
#include "support/test_support.hpp"

namespace zraster::test {
namespace {

void expect_identical_for_thread_counts(const Scene& scene, RenderOptions o) {
    o.id_targets = true;
    o.normal_target = true;
    o.threads = 1;
    const RenderResult reference = render(scene, o);
    for (int threads : {2, 3, 4, 1}) {
        o.threads = threads;
        const RenderResult r = render(scene, o);
        EXPECT_EQ(r.targets.color, reference.targets.color) << threads << " threads";
        EXPECT_EQ(r.targets.depth, reference.targets.depth) << threads << " threads";
        EXPECT_EQ(r.targets.primitive_id, reference.targets.primitive_id) << threads << " threads";
        EXPECT_EQ(r.targets.instance_id, reference.targets.instance_id) << threads << " threads";
        EXPECT_TRUE(r.targets.normal == reference.targets.normal) << threads << " threads";
    }
}

// One Renderer kept across frames whose thread count changes (it keeps its thread arena while the
// count stays and makes a new one when it changes): the same images as one-off renders.
TEST(Determinism, ReusedRendererAcrossThreadCounts) {
    const Scene scene = make_procedural_scene("soup:20000:7");
    RenderOptions o;
    o.width = 300;
    o.height = 200;
    o.cull = CullMode::None;
    o.id_targets = true;
    o.threads = 1;
    const RenderResult reference = render(scene, o);
    Renderer renderer;
    for (int threads : {2, 2, 1, 3, 2}) {
        o.threads = threads;
        const RenderResult& r = renderer.render(scene, o);
        EXPECT_EQ(r.targets.color, reference.targets.color) << threads << " threads";
        EXPECT_EQ(r.targets.depth, reference.targets.depth) << threads << " threads";
        EXPECT_EQ(r.targets.primitive_id, reference.targets.primitive_id) << threads << " threads";
        EXPECT_EQ(r.stats.fragments_passed, reference.stats.fragments_passed);
    }
}

TEST(Determinism, DefaultSceneAnyThreadCount) {
    RenderOptions o;
    o.width = 400;
    o.height = 300;
    o.camera = builtin_camera("builtin:default");
    expect_identical_for_thread_counts(make_procedural_scene("builtin:default"), o);
}

TEST(Determinism, RandomSoupWithInterpenetrationAnyThreadCount) {
    // Many overlapping triangles at similar depths: submission order decides ties, so any
    // reordering between threads would show.
    RenderOptions o;
    o.width = 300;
    o.height = 200;
    o.cull = CullMode::None;
    o.shading = ShadingMode::Flat;
    o.depth_compare = CompareFunc::LessEqual;
    expect_identical_for_thread_counts(make_procedural_scene("soup:20000:7"), o);
}

TEST(Determinism, SharedMeshesAnyThreadCount) {
    ZRASTER_REQUIRE_SHARED_DATA();
    for (const char* file :
         {"meshes/obj/bunny.obj", "meshes/gltf/Duck.glb", "meshes/obj/spider/spider.obj"}) {
        SCOPED_TRACE(file);
        RenderOptions o;
        o.width = 320;
        o.height = 240;
        expect_identical_for_thread_counts(load_scene(shared_data(file)), o);
    }
}

}  // namespace
}  // namespace zraster::test
