// The zero-copy entry point, Renderer::render(const SceneView&, options, const TargetViews&):
// the caller's interleaved vertex buffers and 16-bit indices in, the caller's images out (at any
// row pitch, any subset of targets), bit for bit the owning path's images; and every view the
// renderer cannot read safely refused with an InputError naming the field.
#include <zraster/error.hpp>
#include <zraster/mesh_view.hpp>
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "support/instance_grid.hpp"

namespace zraster {
namespace {

// An engine's vertex: position, a float of something else, normal, uv (36 bytes).
struct Vertex {
    glm::vec3 position;
    float tag;
    glm::vec3 normal;
    glm::vec2 uv;
};
static_assert(sizeof(Vertex) == 36);

// A scene re-laid out as an engine holds it: one interleaved vertex buffer per mesh, 16-bit
// indices where the mesh has few enough vertices, and views of those.
struct EngineScene {
    std::vector<std::vector<Vertex>> vertices;
    std::vector<std::vector<std::uint16_t>> indices16;
    std::vector<std::vector<std::uint32_t>> indices32;
    std::vector<MeshView> meshes;
    std::vector<InstanceView> instances;
    std::vector<Material> materials;

    explicit EngineScene(const Scene& scene, bool keep_bounds = true) {
        const std::size_t n = scene.meshes.size();
        vertices.resize(n);
        indices16.resize(n);
        indices32.resize(n);
        meshes.resize(n);
        for (std::size_t m = 0; m < n; ++m) {
            const Mesh& mesh = scene.meshes[m];
            for (std::size_t i = 0; i < mesh.positions.size(); ++i)
                vertices[m].push_back({mesh.positions[i], -1.0f,
                                       mesh.normals.empty() ? glm::vec3(0.0f) : mesh.normals[i],
                                       mesh.uvs.empty() ? glm::vec2(0.0f) : mesh.uvs[i]});
            MeshView& view = meshes[m];
            const Vertex* first = vertices[m].data();
            const std::size_t count = vertices[m].size();
            view.positions = {&first->position.x, count, sizeof(Vertex)};
            if (!mesh.normals.empty()) view.normals = {&first->normal.x, count, sizeof(Vertex)};
            if (!mesh.uvs.empty()) view.uvs = {&first->uv.x, count, sizeof(Vertex)};
            if (mesh.positions.size() <= 65536) {
                for (const std::uint32_t i : mesh.indices)
                    indices16[m].push_back(static_cast<std::uint16_t>(i));
                view.indices = {indices16[m].data(), indices16[m].size(), IndexType::UInt16};
            } else {
                indices32[m] = mesh.indices;
                view.indices = {indices32[m].data(), indices32[m].size(), IndexType::UInt32};
            }
            view.material = mesh.material < scene.materials.size() ? mesh.material : 0;
            if (keep_bounds) view.bounds = mesh.bounds;
            view.name = mesh.name;
        }
        for (const Instance& instance : scene.instances)
            instances.push_back({instance.mesh, instance.transform, instance.shading});
        materials = scene.materials;
    }
    SceneView view() const { return {meshes, materials, instances}; }
};

// Caller-owned images with padded rows: `pad` bytes after each row hold a sentinel that must
// survive, and the rows start filled with garbage that must not.
struct CallerImages {
    static constexpr std::uint8_t kSentinel = 0xA5;
    int width, height;
    std::size_t pad;
    std::vector<std::byte> color, depth, normal, instance_id, primitive_id, front, back;

    CallerImages(int w, int h, std::size_t padding) : width(w), height(h), pad(padding) {
        for (const auto& [image, element] : images())
            image->assign(pitch(element) * std::size_t(h), std::byte{kSentinel});
        scribble();
    }
    // Every image with its bytes per pixel.
    std::array<std::pair<std::vector<std::byte>*, std::size_t>, 7> images() {
        return {{{&color, 4},
                 {&depth, 4},
                 {&normal, 12},
                 {&instance_id, 4},
                 {&primitive_id, 4},
                 {&front, 4},
                 {&back, 4}}};
    }
    std::size_t pitch(std::size_t element) const { return std::size_t(width) * element + pad; }
    // Garbage in every row (padding untouched).
    void scribble() {
        for (const auto& [image, element] : images())
            for (int y = 0; y < height; ++y)
                std::memset(image->data() + pitch(element) * std::size_t(y), 0x3C,
                            std::size_t(width) * element);
    }
    template <class T>
    T* at(std::vector<std::byte>& image) {
        return reinterpret_cast<T*>(image.data());
    }
    TargetViews views(bool color_target = true, bool depth_target = true, bool normal_target = true,
                      bool ids = true, bool hits = false) {
        TargetViews t;
        t.width = width;
        t.height = height;
        if (color_target) {
            t.color = at<std::uint8_t>(color);
            t.color_pitch = pitch(4);
        }
        if (depth_target) {
            t.depth = at<float>(depth);
            t.depth_pitch = pitch(4);
        }
        if (normal_target) {
            t.normal = at<glm::vec3>(normal);
            t.normal_pitch = pitch(12);
        }
        if (ids) {
            t.instance_id = at<std::int32_t>(instance_id);
            t.instance_id_pitch = pitch(4);
            t.primitive_id = at<std::int32_t>(primitive_id);
            t.primitive_id_pitch = pitch(4);
        }
        if (hits) {
            t.front_hits = at<std::uint32_t>(front);
            t.front_hits_pitch = pitch(4);
            t.back_hits = at<std::uint32_t>(back);
            t.back_hits_pitch = pitch(4);
        }
        return t;
    }
};

// The rows of a caller image equal the owning target (bytes), and its padding is untouched.
template <class T>
void expect_rows(const CallerImages& images, const std::vector<std::byte>& image,
                 const std::vector<T>& want, std::size_t per_pixel, const char* what) {
    SCOPED_TRACE(what);
    ASSERT_EQ(want.size(), std::size_t(images.width) * std::size_t(images.height) * per_pixel);
    const std::size_t row = std::size_t(images.width) * per_pixel * sizeof(T);
    const std::size_t pitch = row + images.pad;
    for (int y = 0; y < images.height; ++y) {
        const std::byte* got = image.data() + pitch * std::size_t(y);
        ASSERT_EQ(
            std::memcmp(got, want.data() + std::size_t(y) * std::size_t(images.width) * per_pixel,
                        row),
            0)
            << "row " << y;
        for (std::size_t k = row; k < pitch; ++k)
            ASSERT_EQ(got[k], std::byte{CallerImages::kSentinel}) << "padding of row " << y;
    }
}

// Renders the scene through the owning path and through views of its engine layout into padded
// caller images, and compares every target both produce.
void expect_same_images(const Scene& scene, RenderOptions options, const std::string& what,
                        bool hits = false) {
    SCOPED_TRACE(what);
    options.normal_target = true;
    options.id_targets = true;
    options.coverage_counts = hits;
    const RenderResult want = render(scene, options);
    const EngineScene engine(scene);
    CallerImages images(options.width, options.height, 12);
    Renderer renderer;
    for (int frame = 0; frame < 2; ++frame) {  // the second frame with kept state and caches
        images.scribble();
        const RenderStats& stats = renderer.render(
            engine.view(), options, images.views(options.color_target, true, true, true, hits));
        EXPECT_EQ(stats.triangles_rasterized, want.stats.triangles_rasterized);
        EXPECT_EQ(stats.fragments_passed, want.stats.fragments_passed);
        if (options.color_target) expect_rows(images, images.color, want.targets.color, 4, "color");
        expect_rows(images, images.depth, want.targets.depth, 1, "depth");
        expect_rows(images, images.normal, want.targets.normal, 1, "normal");
        expect_rows(images, images.instance_id, want.targets.instance_id, 1, "instance ids");
        expect_rows(images, images.primitive_id, want.targets.primitive_id, 1, "primitive ids");
        if (hits) {
            expect_rows(images, images.front, want.targets.front_hits, 1, "front hits");
            expect_rows(images, images.back, want.targets.back_hits, 1, "back hits");
        }
        if (::testing::Test::HasFailure()) return;
    }
}

RenderOptions small_options() {
    RenderOptions o;
    o.width = 200;
    o.height = 130;  // not a multiple of the tile size
    o.threads = 2;
    return o;
}

Scene textured_sphere() {
    std::vector<Mesh> meshes;
    meshes.push_back(make_uv_sphere(1.0f, 24, 48));
    Scene scene = scene_from_meshes(std::move(meshes));
    scene.materials[0].base_color_texture = std::make_shared<const Texture>(
        make_checkerboard_texture(8, 4, {255, 40, 40, 255}, {40, 40, 255, 255}));
    Instance second = scene.instances[0];
    second.transform = glm::translate(glm::mat4(1.0f), glm::vec3(1.5f, 0.3f, -1.0f));
    second.shading = ShadingMode::Gouraud;
    scene.instances.push_back(second);
    return scene;
}

TEST(MeshView, InterleavedBuffersAnd16BitIndicesGiveTheOwningImages) {
    const Scene sphere = make_procedural_scene("sphere:20000");
    const Scene city = test::instance_grid(5);
    const Scene soup = make_procedural_scene("soup:3000:5");
    const Scene textured = textured_sphere();
    const RenderOptions o = small_options();
    expect_same_images(sphere, o, "sphere");
    expect_same_images(city, o, "city");
    expect_same_images(soup, o, "soup");
    expect_same_images(textured, o, "textured, Phong and Gouraud");
    RenderOptions scalar = o;
    scalar.simd = false;
    expect_same_images(textured, scalar, "scalar kernels");
    RenderOptions planes = o;
    planes.clip_planes = {{1, 0.2f, 0, 0.1f}};
    expect_same_images(sphere, planes, "user clip planes");
    RenderOptions d16 = o;
    d16.depth_format = DepthFormat::D16;
    expect_same_images(sphere, d16, "D16 depth");
    RenderOptions forward = o;
    forward.strategy = ShadingStrategy::Forward;
    expect_same_images(textured, forward, "forward shading");
    RenderOptions occlusion = o;
    occlusion.occlusion_cull = true;
    expect_same_images(city, occlusion, "occlusion culling");
    RenderOptions hidden_line = o;
    hidden_line.edges = RenderOptions::Edges::HiddenLine;
    expect_same_images(textured, hidden_line, "hidden-line edges");
    RenderOptions depth_only = o;
    depth_only.color_target = false;
    expect_same_images(sphere, depth_only, "depth only");
    RenderOptions front_to_back = o;
    front_to_back.instance_order = InstanceOrder::FrontToBack;
    expect_same_images(city, front_to_back, "front to back");
    RenderOptions counts = o;
    counts.depth_test = false;
    expect_same_images(sphere, counts, "coverage counts", true);
}

// Cluster culling keys its bounds by the views' addresses: a Renderer drawing the same caller
// buffers frame after frame culls clusters from the first frame on, with the same images.
TEST(MeshView, ClusterCullingWorksThroughViews) {
    const Scene sphere = make_procedural_scene("sphere:20000");
    const EngineScene engine(sphere);
    RenderOptions o = small_options();
    const RenderResult want = render(sphere, o);
    CallerImages images(o.width, o.height, 0);
    Renderer renderer;
    std::uint64_t culled = 0;
    for (int frame = 0; frame < 4; ++frame) {
        images.scribble();
        culled = renderer.render(engine.view(), o, images.views(true, true, false, false))
                     .clusters_culled;
        expect_rows(images, images.color, want.targets.color, 4, "color");
        expect_rows(images, images.depth, want.targets.depth, 1, "depth");
    }
    EXPECT_GT(culled, 0u);
}

// The caller's targets are written whole every frame, whatever is in them: unlike the
// Renderer's own targets, no tile is assumed to still hold last frame's cleared values. And a
// Renderer alternating between the two entry points keeps both right.
TEST(MeshView, EveryPixelIsWrittenEveryFrame) {
    const Scene sphere = make_procedural_scene("sphere:400");
    RenderOptions o = small_options();
    o.camera = fit_camera(sphere.world_positions());
    o.camera->eye *= 3.0;  // small in the middle: most tiles empty
    o.camera->far *= 4.0;
    const RenderResult want = render(sphere, o);
    std::vector<MeshView> meshes;
    std::vector<InstanceView> instances;
    const SceneView view = view_of(sphere, meshes, instances);
    CallerImages images(o.width, o.height, 4);
    Renderer renderer;
    for (int frame = 0; frame < 3; ++frame) {
        SCOPED_TRACE(frame);
        images.scribble();
        renderer.render(view, o, images.views(true, true, false, false));
        expect_rows(images, images.color, want.targets.color, 4, "color");
        expect_rows(images, images.depth, want.targets.depth, 1, "depth");
        const RenderResult& own = renderer.render(sphere, o);
        EXPECT_EQ(own.targets.color, want.targets.color);
        EXPECT_EQ(own.targets.depth, want.targets.depth);
    }
}

// TargetViews::unchanged_since_last_frame: with the camera moving (tiles going from drawn to
// empty and back) every frame is the one-shot render's; empty tiles are really left alone (a
// byte scribbled in one survives: the promise is taken, not checked); and frames that break the
// premise in ways the renderer can see (other arrays, a frame written without the promise in
// between) are written whole.
TEST(MeshView, TargetsUnchangedSinceTheLastFrame) {
    const Scene sphere = make_procedural_scene("sphere:400");
    RenderOptions o = small_options();
    Camera camera = fit_camera(sphere.world_positions());
    camera.eye *= 2.0;
    camera.far *= 3.0;
    std::vector<MeshView> meshes;
    std::vector<InstanceView> instances;
    const SceneView view = view_of(sphere, meshes, instances);
    CallerImages images(o.width, o.height, 4), other(o.width, o.height, 0);
    Renderer renderer;
    const auto frame = [&](int k, CallerImages& into, bool promise) {
        SCOPED_TRACE("frame " + std::to_string(k));
        // The sphere moves right and back: tiles it left are empty again.
        Camera c = camera;
        const double shift = 0.6 * std::sin(0.9 * k);
        c.eye.x += shift;
        c.target.x += shift;
        o.camera = c;
        TargetViews t = into.views(true, true, false, false);
        t.unchanged_since_last_frame = promise;
        renderer.render(view, o, t);
        const RenderResult want = render(sphere, o);
        expect_rows(into, into.color, want.targets.color, 4, "color");
        expect_rows(into, into.depth, want.targets.depth, 1, "depth");
    };
    frame(0, images, true);  // first frame: nothing kept to rely on
    for (int k = 1; k < 6; ++k) frame(k, images, true);
    // A scribble in the top-left tile (background in every frame here) stays.
    const std::byte background_red = images.color[0];
    images.color[0] = std::byte{0x11};
    Camera c = camera;
    o.camera = c;
    TargetViews t = images.views(true, true, false, false);
    t.unchanged_since_last_frame = true;
    renderer.render(view, o, t);
    EXPECT_EQ(images.color[0], std::byte{0x11}) << "an empty tile was rewritten";
    images.color[0] = background_red;
    // Other arrays with the promise: written whole.
    other.scribble();
    frame(6, other, true);
    // A frame without the promise into the same arrays, then with it: written whole again.
    frame(7, images, false);
    frame(8, images, true);
    images.scribble();
    frame(9, images, false);
    // Own targets in between: both kept right.
    for (int k = 10; k < 13; ++k) {
        frame(k, images, true);
        const RenderResult& own = renderer.render(sphere, o);
        EXPECT_EQ(own.targets.color, render(sphere, o).targets.color);
    }
}

// Any subset of targets: each one given is the owning path's, the others are not touched.
TEST(MeshView, SubsetsOfTargets) {
    const Scene scene = textured_sphere();
    RenderOptions o = small_options();
    o.normal_target = true;
    o.id_targets = true;
    const RenderResult all = render(scene, o);
    RenderOptions color_only = o;
    color_only.normal_target = color_only.id_targets = false;
    const RenderResult tagged = render(scene, color_only);  // (tagged shading: color alone)
    const EngineScene engine(scene);
    Renderer renderer;
    struct Subset {
        const char* what;
        bool color, depth, normal, ids;
    };
    for (const Subset& s :
         {Subset{"color", true, false, false, false}, Subset{"depth", false, true, false, false},
          Subset{"normal", false, false, true, false}, Subset{"ids", false, false, false, true},
          Subset{"color and ids", true, false, false, true},
          Subset{"none", false, false, false, false}}) {
        SCOPED_TRACE(s.what);
        CallerImages images(o.width, o.height, 8);
        const std::vector<std::byte> untouched = images.color;
        renderer.render(engine.view(), o, images.views(s.color, s.depth, s.normal, s.ids));
        const RenderResult& want = s.color && !s.normal && !s.ids ? tagged : all;
        if (s.color)
            expect_rows(images, images.color, want.targets.color, 4, "color");
        else
            EXPECT_EQ(images.color, untouched);
        if (s.depth) expect_rows(images, images.depth, want.targets.depth, 1, "depth");
        if (s.normal) expect_rows(images, images.normal, want.targets.normal, 1, "normal");
        if (s.ids) {
            expect_rows(images, images.instance_id, want.targets.instance_id, 1, "instances");
            expect_rows(images, images.primitive_id, want.targets.primitive_id, 1, "primitives");
        }
    }
    // Instance ids alone.
    CallerImages images(o.width, o.height, 0);
    TargetViews only_instances = images.views(false, false, false, true);
    only_instances.primitive_id = nullptr;
    const std::vector<std::byte> primitive_before = images.primitive_id;
    renderer.render(engine.view(), o, only_instances);
    expect_rows(images, images.instance_id, all.targets.instance_id, 1, "instances alone");
    EXPECT_EQ(images.primitive_id, primitive_before);
}

TEST(MeshView, SameImagesForAnyThreadCount) {
    const Scene city = test::instance_grid(5);
    const EngineScene engine(city);
    RenderOptions o = small_options();
    std::vector<std::byte> first_color, first_depth;
    for (const int threads : {1, 2, 3, 5}) {
        SCOPED_TRACE(threads);
        o.threads = threads;
        CallerImages images(o.width, o.height, 4);
        Renderer renderer;
        for (int frame = 0; frame < 2; ++frame)
            renderer.render(engine.view(), o, images.views(true, true, false, false));
        if (first_color.empty()) {
            first_color = images.color;
            first_depth = images.depth;
        }
        EXPECT_EQ(images.color, first_color);
        EXPECT_EQ(images.depth, first_depth);
        // One-shot too.
        CallerImages once(o.width, o.height, 4);
        render(engine.view(), o, once.views(true, true, false, false));
        EXPECT_EQ(once.color, first_color);
    }
}

// Meshes without bounds are bounded by the renderer: a view without them, and an owning mesh
// whose bounds were never computed, draw what the bounded mesh draws (not the background).
TEST(MeshView, MeshesWithoutBoundsAreBounded) {
    const Scene bounded = make_procedural_scene("sphere:20000");
    Scene unbounded = bounded;
    for (Mesh& mesh : unbounded.meshes) mesh.bounds = Bounds3f{};
    RenderOptions o = small_options();
    o.camera = fit_camera(bounded.world_positions());
    const RenderResult want = render(bounded, o);
    ASSERT_GT(want.stats.triangles_rasterized, 0u);
    const RenderResult got = render(unbounded, o);
    EXPECT_EQ(got.targets.color, want.targets.color);
    EXPECT_EQ(got.stats.instances_frustum_culled, 0u);
    Renderer renderer;
    for (int frame = 0; frame < 2; ++frame)
        EXPECT_EQ(renderer.render(unbounded, o).targets.color, want.targets.color);

    const EngineScene engine(bounded, false);  // MeshView::bounds unset
    ASSERT_FALSE(engine.meshes[0].bounds.has_value());
    CallerImages images(o.width, o.height, 0);
    renderer.render(engine.view(), o, images.views(true, false, false, false));
    expect_rows(images, images.color, want.targets.color, 4, "color");
    // Empty bounds in a view count as none.
    EngineScene empty_bounds(bounded);
    empty_bounds.meshes[0].bounds = Bounds3f{};
    images.scribble();
    renderer.render(empty_bounds.view(), o, images.views(true, false, false, false));
    expect_rows(images, images.color, want.targets.color, 4, "color, empty bounds");
}

// A scene with nothing in it: every pixel the background and the clear depth.
TEST(MeshView, EmptySceneClearsTheTargets) {
    const Material material;
    SceneView scene;
    scene.materials = std::span(&material, 1);
    RenderOptions o = small_options();
    CallerImages images(o.width, o.height, 4);
    Renderer renderer;
    renderer.render(scene, o, images.views(true, true, false, true));
    const RenderResult want = render(Scene{}, o);
    o.id_targets = true;
    const RenderResult want_ids = render(Scene{}, o);
    expect_rows(images, images.color, want.targets.color, 4, "color");
    expect_rows(images, images.depth, want.targets.depth, 1, "depth");
    expect_rows(images, images.instance_id, want_ids.targets.instance_id, 1, "ids");
}

// --- Bad input ---------------------------------------------------------------------------

struct BadInput : ::testing::Test {
    std::vector<glm::vec3> positions{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    std::vector<std::uint16_t> indices{0, 1, 2, 1, 3, 2};
    std::vector<Material> materials{Material{}};
    std::vector<MeshView> meshes;
    std::vector<InstanceView> instances{InstanceView{}};
    std::vector<std::uint8_t> color = std::vector<std::uint8_t>(16 * 16 * 4);
    std::vector<float> depth = std::vector<float>(16 * 16);
    RenderOptions options;
    TargetViews targets;

    void SetUp() override {
        positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
        indices = {0, 1, 2, 1, 3, 2};
        materials = {Material{}};
        instances = {InstanceView{}};
        options = RenderOptions{};
        targets = TargetViews{};
        MeshView mesh;
        mesh.positions = {&positions[0].x, positions.size(), 0};
        mesh.indices = {indices.data(), indices.size(), IndexType::UInt16};
        mesh.name = "wall";
        meshes.assign(3, mesh);  // mesh 2 is the one instanced
        instances[0].mesh = 2;
        options.width = options.height = 16;
        options.threads = 1;
        targets.width = targets.height = 16;
        targets.color = color.data();
        targets.depth = depth.data();
    }
    MeshView& mesh() { return meshes[2]; }
    SceneView scene() const { return {meshes, materials, instances}; }

    void expect_refused(const std::string& cause) {
        SCOPED_TRACE(cause);
        for (const bool kept : {false, true}) {
            try {
                if (kept) {
                    Renderer renderer;
                    renderer.render(scene(), options, targets);
                } else {
                    render(scene(), options, targets);
                }
                ADD_FAILURE() << "no InputError (expected '" << cause << "')";
            } catch (const InputError& e) {
                EXPECT_NE(std::string(e.what()).find(cause), std::string::npos) << e.what();
            }
        }
    }
};

TEST_F(BadInput, TheValidSceneRenders) {
    EXPECT_NO_THROW(render(scene(), options, targets));
    EXPECT_NE(color[(8 * 16 + 8) * 4], 51);  // the quad covers the middle (not background)
}

TEST_F(BadInput, NullDataWithElements) {
    mesh().positions.data = nullptr;
    expect_refused("mesh 2 'wall': positions.data is null with 4 elements");
    SetUp();
    mesh().indices.data = nullptr;
    expect_refused("mesh 2 'wall': indices.data is null with 6 indices");
    SetUp();
    mesh().normals = {nullptr, 4, 0};
    expect_refused("mesh 2 'wall': normals.data is null with 4 elements");
    SetUp();
    mesh().uvs = {nullptr, 4, 0};
    expect_refused("mesh 2 'wall': uvs.data is null with 4 elements");
}

TEST_F(BadInput, StridesShorterThanAnElement) {
    mesh().positions.stride = 8;
    expect_refused("mesh 2 'wall': positions.stride 8 is smaller than a position (12 bytes)");
    SetUp();
    mesh().normals = {&positions[0].x, 4, 11};
    expect_refused("mesh 2 'wall': normals.stride 11 is smaller than a normal (12 bytes)");
    SetUp();
    mesh().uvs = {&positions[0].x, 4, 4};
    expect_refused("mesh 2 'wall': uvs.stride 4 is smaller than a uv (8 bytes)");
    SetUp();
    mesh().positions.stride = std::numeric_limits<std::size_t>::max() / 2;
    expect_refused("mesh 2 'wall': positions.stride");
}

TEST_F(BadInput, AttributeCounts) {
    mesh().normals = {&positions[0].x, 3, 0};
    expect_refused("mesh 2 'wall': 3 normals for 4 positions (normals.count must be 0");
    SetUp();
    mesh().uvs = {&positions[0].x, 5, 0};
    expect_refused("mesh 2 'wall': 5 uvs for 4 positions (uvs.count must be 0");
}

TEST_F(BadInput, Indices) {
    indices[4] = 4;
    expect_refused("mesh 2 'wall': vertex index 4 out of range (4 positions)");
    SetUp();
    std::vector<std::uint32_t> wide{0, 1, 2, 1, 3, 70000};
    mesh().indices = {wide.data(), wide.size(), IndexType::UInt32};
    expect_refused("mesh 2 'wall': vertex index 70000 out of range (4 positions)");
    SetUp();
    mesh().indices.type = static_cast<IndexType>(7);
    expect_refused("mesh 2 'wall': indices.type 7 is neither UInt16 nor UInt32");
    SetUp();
    mesh().indices.data = reinterpret_cast<const std::byte*>(indices.data()) + 1;
    mesh().indices.count = 4;
    expect_refused("mesh 2 'wall': indices.data is not aligned to 2 bytes");
    // Seen or not: a culled instance's mesh is checked too.
    SetUp();
    indices[4] = 9;
    instances[0].transform = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 1000));
    options.camera = Camera{};
    expect_refused("mesh 2 'wall': vertex index 9 out of range (4 positions)");
}

TEST_F(BadInput, InstancesAndMaterials) {
    instances[0].mesh = 3;
    expect_refused("instance 0 refers to mesh 3 of 3");
    SetUp();
    mesh().material = 1;
    expect_refused("mesh 2 'wall': material 1 past the scene's 1 materials");
    SetUp();
    materials.clear();
    expect_refused("the scene has no materials");
    // Meshes no instance uses are not read, nor checked.
    SetUp();
    meshes[0].positions.data = nullptr;
    EXPECT_NO_THROW(render(scene(), options, targets));
}

TEST_F(BadInput, Targets) {
    targets.width = 15;
    expect_refused("targets: size 15x16 differs from the options' 16x16");
    SetUp();
    targets.depth_pitch = 60;
    expect_refused("targets: depth_pitch 60 is smaller than a row of 16 floats (64 bytes)");
    SetUp();
    targets.color_pitch = 63;
    expect_refused("targets: color_pitch 63 is smaller than a row of 16 RGBA8 pixels (64 bytes)");
    SetUp();
    std::vector<float> more(16 * 17 + 1);
    targets.depth = reinterpret_cast<float*>(reinterpret_cast<std::byte*>(more.data()) + 2);
    expect_refused("targets: depth is not aligned to 4 bytes");
    SetUp();
    targets.depth = more.data();
    targets.depth_pitch = 66;
    expect_refused("targets: depth_pitch 66 is not a multiple of 4");
    SetUp();
    std::vector<std::int32_t> ids(16 * 16);
    targets.instance_id = ids.data();
    targets.instance_id_pitch = 4;
    expect_refused("targets: instance_id_pitch 4 is smaller than a row of 16 int32 ids");
    SetUp();
    std::vector<glm::vec3> normals(16 * 16);
    targets.normal = normals.data();
    targets.normal_pitch = 100;
    expect_refused("targets: normal_pitch 100 is smaller than a row of 16 vec3 normals (192");
    SetUp();
    targets.color_pitch = std::numeric_limits<std::size_t>::max() / 4;
    expect_refused("targets: color_pitch");
}

// Nothing is written when the input is refused.
TEST_F(BadInput, RefusedFramesWriteNothing) {
    std::fill(color.begin(), color.end(), std::uint8_t{7});
    mesh().positions.stride = 4;
    EXPECT_THROW(render(scene(), options, targets), InputError);
    for (const std::uint8_t c : color) ASSERT_EQ(c, 7);
}

}  // namespace
}  // namespace zraster
