// Determinism beyond determinism_test.cpp: random scenes with random options (shading modes,
// strategies, depth formats and compare functions, cull modes, clip planes, interpolation,
// SIMD or scalar, every target), every shared mesh, and a Renderer reused across frames: color,
// depth, normals, ids and coverage counts are bit-identical for 1, 2, 3 and 5 threads and across
// repeated runs.
#include <zraster/error.hpp>
#include <zraster/load.hpp>
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "support/test_support.hpp"

namespace zraster::test {
namespace {

void expect_same(const RenderTargets& a, const RenderTargets& b, const std::string& what) {
    EXPECT_TRUE(same_bits(a.color, b.color)) << what;
    EXPECT_TRUE(same_bits(a.depth, b.depth)) << what;
    EXPECT_TRUE(same_bits(a.normal, b.normal)) << what;
    EXPECT_TRUE(same_bits(a.instance_id, b.instance_id)) << what;
    EXPECT_TRUE(same_bits(a.primitive_id, b.primitive_id)) << what;
    EXPECT_TRUE(same_bits(a.front_hits, b.front_hits)) << what;
    EXPECT_TRUE(same_bits(a.back_hits, b.back_hits)) << what;
}

// 1 thread is the reference; 2, 3 and 5 threads, a second 1-thread run and a Renderer that
// drew other frames before must all match it.
void expect_deterministic(const Scene& scene, RenderOptions o, Renderer& reused) {
    o.threads = 1;
    const RenderResult reference = render(scene, o);
    for (int threads : {2, 3, 5, 1}) {
        o.threads = threads;
        expect_same(render(scene, o).targets, reference.targets,
                    std::to_string(threads) + " threads");
    }
    o.threads = 2;
    expect_same(reused.render(scene, o).targets, reference.targets, "reused Renderer");
}

// A soup of triangles with shared and duplicate vertices, some crossing the near plane and the
// screen edges, in a few instances with different transforms.
Scene random_scene(SplitMix64& rng) {
    Scene scene;
    scene.name = "random";
    const int meshes = 1 + int(rng.next() % 3);
    for (int m = 0; m < meshes; ++m) {
        Mesh mesh;
        const int vertices = 3 + int(rng.next() % 300);
        for (int v = 0; v < vertices; ++v) {
            if (v > 3 && rng.next() % 8 == 0) {
                mesh.positions.push_back(mesh.positions[rng.next() % mesh.positions.size()]);
                continue;
            }
            mesh.positions.emplace_back(rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-6, 3));
        }
        const int triangles = 1 + int(rng.next() % 400);
        for (int t = 0; t < 3 * triangles; ++t)
            mesh.indices.push_back(std::uint32_t(rng.next() % mesh.positions.size()));
        if (rng.next() % 2) compute_angle_weighted_normals(mesh);
        if (rng.next() % 2)
            for (std::size_t v = 0; v < mesh.positions.size(); ++v)
                mesh.uvs.emplace_back(rng.uniform(-1, 2), rng.uniform(-1, 2));
        mesh.material = std::uint32_t(rng.next() % 3);
        update_bounds(mesh);
        scene.meshes.push_back(std::move(mesh));
    }
    Material textured;
    textured.base_color = {0.9f, 0.5f, 0.2f};
    textured.shininess = 7.5f;  // fractional: the pow() path
    textured.base_color_texture = std::make_shared<const Texture>(
        make_checkerboard_texture(4, 8, {255, 255, 255, 255}, {20, 40, 200, 255}));
    scene.materials.push_back(textured);
    Material shiny;
    shiny.shininess = 64.0f;
    scene.materials.push_back(shiny);
    const int instances = 1 + int(rng.next() % 4);
    for (int i = 0; i < instances; ++i) {
        Instance instance;
        instance.mesh = std::uint32_t(rng.next() % scene.meshes.size());
        instance.transform[3] =
            glm::vec4(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), 1);
        instance.transform[0][0] = float(rng.uniform(0.5, 1.5));
        if (rng.next() % 4 == 0) instance.shading = ShadingMode::Gouraud;
        scene.instances.push_back(instance);
    }
    return scene;
}

RenderOptions random_options(SplitMix64& rng) {
    RenderOptions o;
    o.width = 40 + int(rng.next() % 200);
    o.height = 30 + int(rng.next() % 150);
    Camera camera;
    camera.eye = {rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(4, 8)};
    camera.near = rng.uniform(0.05, 3.0);  // often inside the geometry: near-plane clipping
    camera.far = 40.0;
    camera.reversed_z = rng.next() % 2;
    camera.infinite_far = rng.next() % 4 == 0;
    if (rng.next() % 4 == 0) camera.projection = Camera::Projection::Orthographic;
    camera.ortho_height = 6.0;
    o.camera = camera;
    o.shading = ShadingMode(rng.next() % 4);
    o.strategy = ShadingStrategy(rng.next() % 3);
    o.simd = rng.next() % 2;
    o.cull = CullMode(rng.next() % 3);
    o.front_face = FrontFace(rng.next() % 2);
    o.depth_format = DepthFormat(rng.next() % 3);
    if (rng.next() % 2) o.depth_compare = CompareFunc(rng.next() % 8);
    o.depth_write = rng.next() % 4 != 0;
    o.interpolation = Interpolation(rng.next() % 2);
    o.texture_filter = TextureFilter(rng.next() % 3);
    o.lighting.reflection = ReflectionModel(rng.next() % 2);
    o.lighting.local_viewer = rng.next() % 2;
    if (rng.next() % 2) {
        Light point;
        point.type = Light::Type::Point;
        point.position = {1.0f, 3.0f, 2.0f};
        point.quadratic_attenuation = 0.05f;
        o.lighting.lights.push_back(point);
    }
    if (rng.next() % 3 == 0) o.clip_planes.emplace_back(0.3f, 1.0f, 0.1f, 0.5f);
    o.normal_target = true;
    o.id_targets = true;
    o.coverage_counts = rng.next() % 2;
    return o;
}

TEST(DeterminismRandom, RandomScenesAndOptions) {
    SplitMix64 rng(20261122);
    Renderer reused;
    for (int i = 0; i < 24; ++i) {
        SCOPED_TRACE("random scene " + std::to_string(i));
        const Scene scene = random_scene(rng);
        expect_deterministic(scene, random_options(rng), reused);
    }
}

TEST(DeterminismRandom, EverySharedMesh) {
    ZRASTER_REQUIRE_SHARED_DATA();
    Renderer reused;
    int meshes = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(shared_data("meshes"))) {
        const std::string ext = entry.path().extension().string();
        if (ext != ".obj" && ext != ".ply" && ext != ".stl" && ext != ".off" && ext != ".glb" &&
            ext != ".gltf" && ext != ".3ds")
            continue;
        Scene scene;
        try {
            scene = load_scene(entry.path());
        } catch (const InputError&) {
            continue;  // the deliberately broken ones
        }
        SCOPED_TRACE(entry.path().string());
        RenderOptions o;
        o.width = 96;
        o.height = 72;
        o.normal_target = true;
        o.id_targets = true;
        expect_deterministic(scene, o, reused);
        ++meshes;
    }
    EXPECT_GE(meshes, 20);
}

}  // namespace
}  // namespace zraster::test
