// A kept Renderer makes no heap allocation once it has drawn a frame of the same size, options
// and scene shape (include/zraster/render.hpp): frame after frame, through the owning entry
// point and through views into caller targets, on every thread of its arena.
//
// This binary replaces the global operator new and delete (every form: sized, aligned,
// nothrow, array) with counting versions; they count only while a test says so, so gtest's own
// allocations do not matter. (oneTBB allocates its tasks with its own allocator, not operator
// new: they are not counted, and need not be.)
#include <zraster/mesh_view.hpp>
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "support/instance_grid.hpp"

namespace {

std::atomic<bool> counting{false};
std::atomic<std::size_t> allocations{0};

void* allocate(std::size_t size, std::size_t alignment, bool nothrow) {
    if (counting.load(std::memory_order_relaxed))
        allocations.fetch_add(1, std::memory_order_relaxed);
    if (size == 0) size = 1;
    void* p = nullptr;
    if (alignment <= alignof(std::max_align_t)) {
        p = std::malloc(size);
    } else if (posix_memalign(&p, alignment, size) != 0) {
        p = nullptr;
    }
    if (p == nullptr && !nothrow) throw std::bad_alloc();
    return p;
}

constexpr std::size_t kDefault = alignof(std::max_align_t);

}  // namespace

void* operator new(std::size_t size) {
    return allocate(size, kDefault, false);
}
void* operator new[](std::size_t size) {
    return allocate(size, kDefault, false);
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    return allocate(size, kDefault, true);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
    return allocate(size, kDefault, true);
}
void* operator new(std::size_t size, std::align_val_t alignment) {
    return allocate(size, static_cast<std::size_t>(alignment), false);
}
void* operator new[](std::size_t size, std::align_val_t alignment) {
    return allocate(size, static_cast<std::size_t>(alignment), false);
}
void* operator new(std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
    return allocate(size, static_cast<std::size_t>(alignment), true);
}
void* operator new[](std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
    return allocate(size, static_cast<std::size_t>(alignment), true);
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    std::free(p);
}

namespace zraster {
namespace {

// Allocations made by f.
template <class F>
std::size_t allocations_in(const F& f) {
    allocations = 0;
    counting = true;
    f();
    counting = false;
    return allocations.load();
}

TEST(NoAllocation, TheCounterCounts) {
    EXPECT_EQ(allocations_in([] { std::make_unique<int>(1).reset(); }), 1u);
    EXPECT_EQ(allocations_in([] {
                  std::vector<double>(100, 0.0).swap(*std::make_unique<std::vector<double>>());
              }),
              2u);
    EXPECT_EQ(allocations_in([] {
                  struct alignas(128) Wide {
                      char c;
                  };
                  std::make_unique<Wide>().reset();
              }),
              1u);
}

// An engine's vertex: position, normal, uv interleaved.
struct Vertex {
    glm::vec3 position, normal;
    glm::vec2 uv;
};

// A scene as engine buffers (interleaved, 16-bit indices where they fit) and views of them.
struct EngineScene {
    std::vector<std::vector<Vertex>> vertices;
    std::vector<std::vector<std::uint16_t>> indices;
    std::vector<MeshView> meshes;
    std::vector<InstanceView> instances;
    std::vector<Material> materials;

    explicit EngineScene(const Scene& scene) : materials(scene.materials) {
        for (const Mesh& mesh : scene.meshes) {
            std::vector<Vertex>& v = vertices.emplace_back();
            for (std::size_t i = 0; i < mesh.positions.size(); ++i)
                v.push_back({mesh.positions[i],
                             mesh.normals.empty() ? glm::vec3(0, 1, 0) : mesh.normals[i],
                             mesh.uvs.empty() ? glm::vec2(0.0f) : mesh.uvs[i]});
            MeshView view;
            view.positions = {&v[0].position.x, v.size(), sizeof(Vertex)};
            if (!mesh.normals.empty()) view.normals = {&v[0].normal.x, v.size(), sizeof(Vertex)};
            if (!mesh.uvs.empty()) view.uvs = {&v[0].uv.x, v.size(), sizeof(Vertex)};
            std::vector<std::uint16_t>& i16 = indices.emplace_back();
            if (mesh.positions.size() <= 65536) {
                for (const std::uint32_t i : mesh.indices) i16.push_back(std::uint16_t(i));
                view.indices = {i16.data(), i16.size(), IndexType::UInt16};
            } else {
                view.indices = {mesh.indices.data(), mesh.indices.size(), IndexType::UInt32};
            }
            view.material = mesh.material < materials.size() ? mesh.material : 0;
            view.bounds = mesh.bounds;
            meshes.push_back(view);
        }
        for (const Instance& instance : scene.instances)
            instances.push_back({instance.mesh, instance.transform, instance.shading});
    }
    SceneView view() const { return {meshes, materials, instances}; }
};

struct Case {
    std::string what;
    Scene scene;
    RenderOptions options;
    bool fixed_camera = true;  // else fit_camera() over the scene every frame
};

std::vector<Case> cases() {
    RenderOptions base;
    base.width = 640;
    base.height = 360;
    base.threads = 2;
    std::vector<Case> out;
    out.push_back({"sphere, Phong", make_procedural_scene("sphere:20000"), base});
    RenderOptions depth = base;
    depth.color_target = false;
    out.push_back({"sphere, depth only", make_procedural_scene("sphere:20000"), depth});
    out.push_back({"many instances (instance BVH)", test::instance_grid(), base});
    RenderOptions occlusion = base;
    occlusion.occlusion_cull = true;
    occlusion.instance_order = InstanceOrder::FrontToBack;
    out.push_back(
        {"many instances, occlusion culling, front to back", test::instance_grid(), occlusion});
    RenderOptions everything = base;
    everything.normal_target = true;
    everything.id_targets = true;
    everything.shading = ShadingMode::Gouraud;
    everything.edges = RenderOptions::Edges::HiddenLine;
    out.push_back({"soup, normals, ids, Gouraud, hidden lines, no camera",
                   make_procedural_scene("soup:20000:3"), everything, false});
    RenderOptions clipped = base;
    clipped.clip_planes = {{1, 0, 0, 0.1f}};
    clipped.depth_format = DepthFormat::D24;
    clipped.strategy = ShadingStrategy::Forward;
    out.push_back(
        {"sphere, clip plane, D24, forward", make_procedural_scene("sphere:20000"), clipped});
    RenderOptions four = base;
    four.threads = 4;
    four.simd = false;
    out.push_back({"sphere, 4 threads, scalar", make_procedural_scene("sphere:20000"), four});
    return out;
}

// Frames after the first allocate nothing: the first sizes everything and builds the cluster
// bounds of the meshes it draws (render.hpp).
TEST(NoAllocation, KeptRendererFramesAllocateNothing) {
    constexpr int kWarmUp = 1, kFrames = 5;
    for (Case& c : cases()) {
        SCOPED_TRACE(c.what);
        const Scene& scene = c.scene;
        if (c.fixed_camera) c.options.camera = fit_camera(scene.world_positions());
        const EngineScene engine(scene);
        const SceneView view = engine.view();

        Renderer owning;
        for (int frame = 0; frame < kWarmUp; ++frame) owning.render(scene, c.options);
        for (int frame = 0; frame < kFrames; ++frame)
            EXPECT_EQ(allocations_in([&] { owning.render(scene, c.options); }), 0u)
                << "owning path, frame " << frame + kWarmUp;

        const std::size_t pixels = std::size_t(c.options.width) * std::size_t(c.options.height);
        std::vector<std::uint8_t> color(pixels * 4);
        std::vector<float> depth(pixels);
        std::vector<glm::vec3> normal(pixels);
        std::vector<std::int32_t> instance_id(pixels), primitive_id(pixels);
        TargetViews targets;
        targets.width = c.options.width;
        targets.height = c.options.height;
        if (c.options.color_target) targets.color = color.data();
        if (c.options.normal_target) targets.normal = normal.data();
        if (c.options.id_targets) {
            targets.instance_id = instance_id.data();
            targets.primitive_id = primitive_id.data();
        }
        Renderer viewing;
        for (int frame = 0; frame < kWarmUp; ++frame) viewing.render(view, c.options, targets);
        for (int frame = 0; frame < kFrames; ++frame) {
            // Depth wanted in some frames and not in others: still nothing new.
            targets.depth = frame % 2 == 0 ? depth.data() : nullptr;
            EXPECT_EQ(allocations_in([&] { viewing.render(view, c.options, targets); }), 0u)
                << "view path, frame " << frame + kWarmUp;
        }
        // One Renderer serving both entry points, alternately (after warming up for both).
        for (int frame = 0; frame < kWarmUp; ++frame) {
            owning.render(view, c.options, targets);
            owning.render(scene, c.options);
        }
        for (int frame = 0; frame < kFrames; ++frame) {
            EXPECT_EQ(allocations_in([&] {
                          owning.render(view, c.options, targets);
                          owning.render(scene, c.options);
                      }),
                      0u)
                << "both paths, frame " << frame;
        }
    }
}

// Without cluster culling (nothing of it built in the first frame) the same holds.
TEST(NoAllocation, FromTheSecondFrameWithoutClusterCulling) {
    const Scene scene = make_procedural_scene("sphere:20000");
    RenderOptions o;
    o.width = 320;
    o.height = 200;
    o.threads = 2;
    o.cluster_culling = false;
    const EngineScene engine(scene);
    std::vector<std::uint8_t> color(std::size_t(o.width) * std::size_t(o.height) * 4);
    TargetViews targets;
    targets.width = o.width;
    targets.height = o.height;
    targets.color = color.data();
    Renderer renderer;
    renderer.render(engine.view(), o, targets);
    renderer.render(scene, o);
    for (int frame = 1; frame < 4; ++frame) {
        EXPECT_EQ(allocations_in([&] { renderer.render(engine.view(), o, targets); }), 0u);
        EXPECT_EQ(allocations_in([&] { renderer.render(scene, o); }), 0u);
    }
}

// Cameras from matrices and from intrinsics are checked every frame as well, without allocating.
TEST(NoAllocation, CamerasFromMatricesAndIntrinsics) {
    const Scene scene = make_procedural_scene("sphere:2000");
    RenderOptions o;
    o.width = 320;
    o.height = 240;
    o.threads = 2;
    const Camera fitted = fit_camera(scene.world_positions());
    const Camera cameras[] = {
        Camera::from_matrices(fitted.view(), fitted.projection_matrix(320.0 / 240.0),
                              fitted.clip_depth_range()),
        Camera::from_intrinsics(fitted.intrinsics(320, 240), fitted.camera_to_world())};
    for (const Camera& camera : cameras) {
        o.camera = camera;
        Renderer renderer;
        for (int frame = 0; frame < 2; ++frame) renderer.render(scene, o);
        for (int frame = 2; frame < 5; ++frame)
            EXPECT_EQ(allocations_in([&] { renderer.render(scene, o); }), 0u) << "frame " << frame;
    }
}

}  // namespace
}  // namespace zraster
