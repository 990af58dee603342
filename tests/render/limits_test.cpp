// RenderOptions::limits and the scene checks of render(): requests past a limit and scenes whose
// arrays disagree are refused with one-line InputErrors before anything is allocated.
#include <zraster/error.hpp>
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <string>

namespace zraster {
namespace {

Scene triangle_scene() {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.indices = {0, 1, 2};
    update_bounds(mesh);
    std::vector<Mesh> meshes;
    meshes.push_back(mesh);
    Scene scene = scene_from_meshes(std::move(meshes));
    scene.name = "triangle";
    return scene;
}

void expect_refused(const Scene& scene, const RenderOptions& options, const std::string& cause) {
    const auto start = std::chrono::steady_clock::now();
    try {
        render(scene, options);
        ADD_FAILURE() << "no InputError (expected '" << cause << "')";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(cause), std::string::npos) << e.what();
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    }
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
}

TEST(Limits, DefaultsAreSensible) {
    const RenderLimits limits;
    EXPECT_EQ(limits.max_pixels, 64u << 20);       // 8192 x 8192
    EXPECT_GE(limits.max_triangles, 20'000'000u);  // the largest benchmark scene
    EXPECT_LE(limits.max_vertices, (1u << 31) - 1);
}

// A thread count oneTBB cannot make an arena of (2^31 - 1 crashed inside it) is capped at
// kMaxThreadsPerHardwareThread per hardware thread; the image is the one-thread image.
TEST(Limits, HugeThreadCountsAreCapped) {
    const int hardware = render_thread_count(0);
    EXPECT_GE(hardware, 1);
    EXPECT_EQ(render_thread_count(1), 1);
    EXPECT_EQ(render_thread_count(hardware), hardware);
    EXPECT_EQ(render_thread_count(2147483647), kMaxThreadsPerHardwareThread * hardware);
    const Scene scene = make_procedural_scene("sphere:2000");
    RenderOptions o;
    o.width = 96;
    o.height = 64;
    o.threads = 1;
    const RenderResult one = render(scene, o);
    o.threads = 2147483647;
    Renderer renderer;
    EXPECT_EQ(renderer.render(scene, o).targets.color, one.targets.color);
}

TEST(Limits, ImageSize) {
    RenderOptions o;
    o.width = 1'000'000;
    o.height = 1'000'000;
    expect_refused(triangle_scene(), o, "image size 1000000x1000000 out of range (1..16384");
    o.width = 16384;
    o.height = 16384;  // within the per-side range, over 64 Mpx
    expect_refused(triangle_scene(), o,
                   "image size 16384x16384 is 268435456 pixels, more than the limit of 67108864");
    o.width = 64;
    o.height = 64;
    o.limits.max_pixels = 4095;
    expect_refused(triangle_scene(), o, "is 4096 pixels, more than the limit of 4095");
    o.limits.max_pixels = 4096;
    EXPECT_EQ(render(triangle_scene(), o).targets.depth.size(), 4096u);
}

TEST(Limits, TrianglesAndVerticesOverInstances) {
    Scene scene = triangle_scene();
    for (int i = 0; i < 9; ++i) scene.instances.push_back(scene.instances[0]);  // 10 instances
    RenderOptions o;
    o.width = 16;
    o.height = 16;
    o.limits.max_triangles = 9;
    expect_refused(scene, o, "triangle: 10 triangles over all instances, more than the limit of 9");
    o.limits.max_triangles = 10;
    o.limits.max_vertices = 29;
    expect_refused(scene, o, "30 vertices over all instances, more than the limit of 29");
    o.limits.max_vertices = 30;
    EXPECT_NO_THROW(render(scene, o));
}

// A screen-sized triangle drawn over itself many times: binning's records (one per triangle and
// tile) are counted before they are allocated; exactly what the frame needs passes.
TEST(Limits, BinRecordsOfLargeTrianglesDrawnOverEachOther) {
    Scene scene = triangle_scene();
    scene.instances[0].transform = glm::scale(glm::mat4(1.0f), glm::vec3(50.0f, 50.0f, 1.0f));
    for (int i = 0; i < 999; ++i) scene.instances.push_back(scene.instances[0]);
    Camera camera;
    camera.eye = {0.5, 0.5, 3};
    camera.target = {0.5, 0.5, 0};
    RenderOptions o;
    o.width = 512;
    o.height = 512;
    o.camera = camera;
    o.limits.max_bin_bytes = 1 << 20;
    std::uint64_t needed = 0;
    try {
        render(scene, o);
        ADD_FAILURE() << "no LimitExceeded";
    } catch (const LimitExceeded& e) {
        EXPECT_EQ(e.limit(), "max_bin_bytes");
        EXPECT_EQ(e.file(), "");  // (the caller names the scene: the command does)
        const std::string cause = e.cause();
        ASSERT_EQ(cause.rfind("binning needs ", 0), 0u) << cause;
        needed = std::stoull(cause.substr(14));
        EXPECT_NE(cause.find("more than the limit of 1048576 (RenderLimits::max_bin_bytes)"),
                  std::string::npos)
            << cause;
    }
    // 1000 triangles over every tile of the frame: tens of MB, not a small multiple of 1000.
    EXPECT_GT(needed, std::uint64_t{1000} * 64 * 48);
    o.limits.max_bin_bytes = needed - 1;
    EXPECT_THROW(render(scene, o), LimitExceeded);
    o.limits.max_bin_bytes = needed;
    EXPECT_NO_THROW(render(scene, o));
}

// The frame's memory, estimated from the counts over all instances before anything is
// allocated: exactly at the estimate it renders, a byte less is refused (in well under a second,
// before the vertex stage); the caller's targets are the caller's memory and not counted.
TEST(Limits, FrameMemoryIsEstimatedBeforeAnythingIsAllocated) {
    EXPECT_EQ(RenderLimits{}.max_frame_bytes, std::uint64_t{4} << 30);
    Scene scene = make_procedural_scene("sphere:2000");
    const Instance one = scene.instances[0];
    scene.instances.assign(50, one);
    const std::uint64_t vertices = scene.vertex_count(), triangles = scene.triangle_count();
    RenderOptions o;
    o.width = 64;
    o.height = 48;
    const std::uint64_t with_targets = estimated_frame_bytes(vertices, triangles, 64 * 48);
    EXPECT_EQ(with_targets, vertices * 100 + triangles * 50 + 64 * 48 * 36);
    o.limits.max_frame_bytes = with_targets;
    EXPECT_NO_THROW(render(scene, o));
    --o.limits.max_frame_bytes;
    try {
        render(scene, o);
        ADD_FAILURE() << "no LimitExceeded";
    } catch (const LimitExceeded& e) {
        EXPECT_EQ(e.limit(), "max_frame_bytes");
        EXPECT_EQ(e.file(), scene.name);
        EXPECT_EQ(e.cause(), "the frame needs about " +
                                 std::to_string((with_targets + (1 << 20) - 1) >> 20) + " MiB (" +
                                 std::to_string(vertices) + " vertices and " +
                                 std::to_string(triangles) +
                                 " triangles over all instances, 3072 target samples), more than "
                                 "max_frame_bytes (" +
                                 std::to_string((with_targets + (1 << 20) - 2) >> 20) + " MiB)");
    }
    // Into the caller's targets: the vertices and triangles alone.
    RenderTargets targets;
    targets.color.resize(64 * 48 * 4);
    targets.depth.resize(64 * 48);
    TargetViews views = view_of(targets);
    views.width = 64;
    views.height = 48;
    std::vector<MeshView> meshes;
    std::vector<InstanceView> instances;
    const SceneView view = view_of(scene, meshes, instances);
    o.limits.max_frame_bytes = estimated_frame_bytes(vertices, triangles, 0);
    EXPECT_NO_THROW(render(view, o, views));
    --o.limits.max_frame_bytes;
    EXPECT_THROW(render(view, o, views), LimitExceeded);
    // A mesh placed a million times is refused at once with the defaults, long before the
    // vertex and triangle budgets (100 million each) that it stays within.
    std::vector<Mesh> small;
    small.push_back(make_uv_sphere(1.0f, 4, 8));  // 45 vertices, 64 triangles
    scene = scene_from_meshes(std::move(small));
    scene.instances.assign(1'000'000, scene.instances[0]);
    RenderOptions defaults;
    defaults.width = 64;
    defaults.height = 48;
    ASSERT_LT(scene.triangle_count(), defaults.limits.max_triangles);
    expect_refused(scene, defaults, "more than max_frame_bytes (4096 MiB)");
    // Saturated, not wrapped.
    EXPECT_EQ(estimated_frame_bytes(UINT64_MAX / 50, 1, 1), UINT64_MAX);
}

// Millions of instances of one mesh: counted before the vertex stage sizes its arrays (whose
// 32-bit vertex count would otherwise wrap).
TEST(Limits, InstanceCountCannotWrapTheVertexCount) {
    Scene scene = make_procedural_scene("sphere:20000");
    const Instance one = scene.instances[0];
    scene.instances.assign(300'000, one);  // 300k x ~10k vertices: 3e9, past 2^31
    RenderOptions o;
    o.width = 16;
    o.height = 16;
    o.limits.max_triangles = ~std::uint64_t{0};
    o.limits.max_vertices = ~std::uint64_t{0};
    expect_refused(scene, o, "more than the limit of 2147483647");
}

TEST(Limits, InconsistentScenes) {
    RenderOptions o;
    o.width = 16;
    o.height = 16;
    {
        Scene scene = triangle_scene();
        scene.instances[0].mesh = 3;
        expect_refused(scene, o, "triangle: instance 0 refers to mesh 3 of 1");
    }
    {
        Scene scene = triangle_scene();
        scene.meshes[0].indices = {0, 1, 3};
        expect_refused(scene, o, "mesh 0 '': vertex index 3 out of range (3 positions)");
    }
    {
        Scene scene = triangle_scene();
        scene.meshes[0].normals.resize(2);
        expect_refused(scene, o, "2 normals for 3 positions");
    }
    {
        Scene scene = triangle_scene();
        scene.meshes[0].uvs.resize(4);
        expect_refused(scene, o, "4 uvs for 3 positions");
    }
    {
        Scene scene = triangle_scene();
        scene.materials.clear();
        expect_refused(scene, o, "the scene has no materials");
    }
    {
        // A trailing partial triple is ignored (triangle_count() drops it), whatever it holds.
        Scene scene = triangle_scene();
        scene.meshes[0].indices.push_back(99);
        EXPECT_NO_THROW(render(scene, o));
    }
}

// The front end checks the indices of the triangles it assembles, and the renderer scans the
// meshes it did not draw: a bad index is refused, naming the first bad mesh, whatever the camera
// sees and whichever path (SIMD batches, scalar, per-triangle with user planes) assembles it.
TEST(Limits, BadIndicesAreRefusedWhateverTheCameraSees) {
    // Two spheres of ~2000 triangles (several classifier batches), side by side at x = -2, 2.
    const auto sphere_scene = [] {
        std::vector<Mesh> meshes;
        meshes.push_back(make_uv_sphere(1.0f, 24, 48));
        meshes.push_back(make_uv_sphere(1.0f, 24, 48));
        Scene scene = scene_from_meshes(std::move(meshes));
        scene.name = "spheres";
        scene.instances[0].transform = glm::translate(glm::mat4(1.0f), glm::vec3(-2, 0, 0));
        scene.instances[1].transform = glm::translate(glm::mat4(1.0f), glm::vec3(2, 0, 0));
        return scene;
    };
    const auto options_looking_at = [](float x) {
        RenderOptions o;
        o.width = 64;
        o.height = 64;
        Camera camera;
        camera.eye = {x, 0, 4};
        camera.target = {x, 0, 0};
        o.camera = camera;
        return o;
    };
    const auto break_index = [](Mesh& mesh, std::size_t triangle) {
        mesh.indices[3 * triangle + 1] = static_cast<std::uint32_t>(mesh.positions.size()) + 5;
        return "vertex index " + std::to_string(mesh.positions.size() + 5) + " out of range";
    };
    ASSERT_GT(sphere_scene().meshes[0].triangle_count(), 1500u);
    for (const bool simd : {true, false})
        for (const bool user_planes : {false, true})
            for (const float look_x : {-2.0f, 2.0f}) {
                SCOPED_TRACE(::testing::Message() << "simd " << simd << ", user planes "
                                                  << user_planes << ", looking at x " << look_x);
                RenderOptions o = options_looking_at(look_x);
                o.simd = simd;
                if (user_planes) o.clip_planes = {{0, 0, 1, 10}};
                Scene scene = sphere_scene();
                EXPECT_NO_THROW(render(scene, o));
                // Mesh 0, seen or not (looking at x = 2 frustum-culls its instance).
                const std::string cause = break_index(scene.meshes[0], 1234);
                expect_refused(scene, o, "mesh 0 'uv_sphere': " + cause);
                // Both bad: mesh 0 is named, even when only mesh 1 is in view.
                break_index(scene.meshes[1], 7);
                expect_refused(scene, o, "mesh 0 'uv_sphere': " + cause);
            }
}

}  // namespace
}  // namespace zraster
