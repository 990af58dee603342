// Materials' sides (Material::double_sided, glTF doubleSided; RenderOptions::material_sides): a
// single-sided quad seen from behind is culled, a double-sided one is drawn and lit with the
// flipped normal (its colors are the front view's under mirrored lighting); the per-instance
// culling leaves the SIMD kernels, cluster culling and threads without effect on a bit; every
// visibility path culls as the z-buffer does.
#include <zraster/abuffer.hpp>
#include <zraster/render.hpp>
#include <zraster/scene.hpp>
#include <zraster/scenes.hpp>
#include <zraster/visibility.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include <glm/gtc/matrix_transform.hpp>

#include "render/render_test_util.hpp"
#include "support/test_support.hpp"

namespace zraster::test {
namespace {

constexpr int kSidesImage = 64;

// An orthographic camera on +z (or -z: from behind) looking at the origin, lit by one point
// light at `light`.
RenderOptions sides_options(double eye_z, const glm::vec3& light) {
    RenderOptions o;
    o.width = kSidesImage;
    o.height = kSidesImage;
    o.threads = 2;
    o.shading = ShadingMode::Phong;
    o.id_targets = true;
    o.normal_target = true;
    Camera c;
    c.eye = {0.0, 0.0, eye_z};
    c.target = {0.0, 0.0, 0.0};
    c.projection = Camera::Projection::Orthographic;
    c.ortho_height = kSidesImage;
    c.near = 1.0;
    c.far = 20.0;
    o.camera = c;
    Light point;
    point.type = Light::Type::Point;
    point.position = light;
    o.lighting.lights = {point};
    return o;
}

// A square in the plane z = 0, counter-clockwise and with normals +z as seen from +z.
Scene sides_quad(bool double_sided) {
    Mesh m;
    const float h = 20.0f;
    m.positions = {{-h, -h, 0}, {h, -h, 0}, {h, h, 0}, {-h, h, 0}};
    m.normals.assign(4, glm::vec3(0, 0, 1));
    m.indices = {0, 1, 2, 0, 2, 3};
    update_bounds(m);
    Scene scene;
    Material material;
    material.base_color = {0.8f, 0.6f, 0.3f};
    material.double_sided = double_sided;
    scene.materials = {material};
    scene.meshes = {m};
    scene.instances.resize(1);
    return scene;
}

int covered_pixels(const RenderResult& r) {
    int n = 0;
    for (const std::int32_t id : r.targets.instance_id) n += id >= 0;
    return n;
}

TEST(MaterialSides, SingleSidedBackFacesAreCulledDoubleSidedOnesDrawn) {
    const glm::vec3 light(3, 5, -6);
    const RenderOptions behind = sides_options(-8.0, light);
    const RenderResult single = render(sides_quad(false), behind);
    EXPECT_EQ(covered_pixels(single), 0);
    EXPECT_EQ(single.stats.triangles_backface_culled, 2u);
    const RenderResult both = render(sides_quad(true), behind);
    EXPECT_EQ(covered_pixels(both), 40 * 40);
    EXPECT_EQ(both.stats.triangles_backface_culled, 0u);
    // material_sides off: the cull mode applies to every triangle, as before materials had sides.
    RenderOptions all = behind;
    all.material_sides = false;
    EXPECT_EQ(covered_pixels(render(sides_quad(true), all)), 0);
    // Culling off draws the single-sided one too (today's behaviour for OBJ, PLY, STL).
    all.cull = CullMode::None;
    EXPECT_EQ(covered_pixels(render(sides_quad(false), all)), 40 * 40);
}

// Seen from behind, lit by the light mirrored through the quad's plane: every pixel is the front
// view's pixel mirrored left to right (the camera's x axis turns around), lit the same.
TEST(MaterialSides, ABackFaceIsLitAsTheFrontUnderMirroredLighting) {
    const RenderResult front = render(sides_quad(true), sides_options(8.0, {3, 5, 6}));
    const RenderResult back = render(sides_quad(true), sides_options(-8.0, {3, 5, -6}));
    int compared = 0;
    for (int py = 13; py < 51; ++py)
        for (int px = 13; px < 51; ++px) {
            const std::size_t b = (std::size_t(py) * kSidesImage + std::size_t(px)) * 4;
            const std::size_t f =
                (std::size_t(py) * kSidesImage + std::size_t(kSidesImage - 1 - px)) * 4;
            for (int c = 0; c < 3; ++c)
                EXPECT_LE(std::abs(int(back.targets.color[b + std::size_t(c)]) -
                                   int(front.targets.color[f + std::size_t(c)])),
                          1)
                    << px << "," << py;
            // The shading normal faces the viewer: -z.
            EXPECT_LT(back.targets.normal[b / 4].z, -0.999f);
            ++compared;
        }
    EXPECT_EQ(compared, 38 * 38);
    // Lit with the unflipped normal instead (culling off, one-sided lighting): dark, so the
    // comparison above is not vacuous.
    RenderOptions unflipped = sides_options(-8.0, {3, 5, -6});
    unflipped.cull = CullMode::None;
    unflipped.two_sided_lighting = false;
    const RenderResult dark = render(sides_quad(false), unflipped);
    const std::size_t center = (std::size_t(32) * kSidesImage + 32) * 4;
    EXPECT_LT(int(dark.targets.color[center]) + 20, int(back.targets.color[center]));
}

// A single-sided sphere (20000 triangles in coherent clusters, so that cluster culling runs) beside
// a double-sided triangle soup (half its triangles face away): the soup is drawn as a frame with
// culling off draws it, the sphere culled as before; SIMD, cluster culling, the thread count and
// the shading strategy change no bit.
TEST(MaterialSides, PerInstanceCullingIsExactWithEveryOptimization) {
    Scene scene;
    Material single, both;
    single.base_color = {0.9f, 0.4f, 0.2f};
    both.base_color = {0.2f, 0.5f, 0.9f};
    both.double_sided = true;
    scene.materials = {single, both};
    scene.meshes = {make_bench_sphere(20000), make_bench_soup(6000, 7)};
    scene.meshes[1].material = 1;
    scene.instances.resize(2);
    scene.instances[0].transform = glm::translate(glm::mat4(1.0f), glm::vec3(-1.2f, 0, 0));
    scene.instances[1].mesh = 1;
    scene.instances[1].transform = glm::translate(glm::mat4(1.0f), glm::vec3(1.2f, 0, 0));
    RenderOptions options;
    options.width = 160;
    options.height = 96;
    options.id_targets = true;
    options.normal_target = true;
    Camera camera;
    camera.eye = {0.0, 0.5, 6.0};
    camera.target = {0.0, 0.0, 0.0};
    options.camera = camera;
    // (Cluster bounds are kept by a Renderer: a one-shot render() builds none.)
    Renderer kept;
    const RenderResult reference = kept.render(scene, options);
    EXPECT_GT(reference.stats.clusters_culled, 0u);  // the single-sided sphere's
    const auto expect_same = [&](const RenderOptions& o, const char* what) {
        Renderer renderer;
        const RenderResult r = renderer.render(scene, o);
        EXPECT_EQ(r.targets.color, reference.targets.color) << what;
        EXPECT_TRUE(same_bits(r.targets.depth, reference.targets.depth)) << what;
        EXPECT_EQ(r.targets.primitive_id, reference.targets.primitive_id) << what;
        EXPECT_TRUE(same_bits(r.targets.normal, reference.targets.normal)) << what;
    };
    RenderOptions o = options;
    o.simd = false;
    expect_same(o, "scalar");
    o = options;
    o.cluster_culling = false;
    expect_same(o, "without cluster culling");
    o = options;
    o.threads = 1;
    expect_same(o, "one thread");
    o.strategy = ShadingStrategy::Forward;
    expect_same(o, "forward shading");

    // The double-sided soup alone: as a frame with culling off draws it (every triangle, lit
    // two-sided).
    const auto only = [&](std::size_t instance) {
        Scene s = scene;
        s.instances = {scene.instances[instance]};
        return s;
    };
    RenderOptions none = options;
    none.cull = CullMode::None;
    const RenderResult double_alone = render(only(1), options);
    const RenderResult culling_off = render(only(1), none);
    EXPECT_EQ(double_alone.targets.color, culling_off.targets.color);
    EXPECT_EQ(double_alone.targets.primitive_id, culling_off.targets.primitive_id);
    EXPECT_EQ(double_alone.stats.triangles_backface_culled, 0u);
    // And the single-sided sphere alone is culled as before.
    RenderOptions before = options;
    before.material_sides = false;
    EXPECT_EQ(render(only(0), options).targets.color, render(only(0), before).targets.color);
    EXPECT_GT(render(only(0), options).stats.triangles_backface_culled, 1000u);
}

// Every visibility path culls the single-sided quad from behind and draws the double-sided one
// with the z-buffer's colors where it covers whole pixels.
TEST(MaterialSides, EveryPathCullsPerMaterial) {
    const RenderOptions behind = sides_options(-8.0, {3, 5, -6});
    const RenderResult reference = render(sides_quad(true), behind);
    for (const VisibilityAlgorithm algorithm :
         {VisibilityAlgorithm::Painter, VisibilityAlgorithm::Bsp, VisibilityAlgorithm::Warnock}) {
        SCOPED_TRACE(int(algorithm));
        EXPECT_EQ(covered_pixels(render_with_visibility(sides_quad(false), behind, algorithm)), 0);
        const RenderResult r = render_with_visibility(sides_quad(true), behind, algorithm);
        EXPECT_EQ(r.targets.color, reference.targets.color);
        EXPECT_EQ(r.targets.instance_id, reference.targets.instance_id);
    }
    EXPECT_EQ(covered_pixels(render_abuffer(sides_quad(false), behind)), 0);
    EXPECT_EQ(covered_pixels(render_multisampled(sides_quad(false), behind, 2)), 0);
    // (A pixel off the quad's diagonal, which runs from corner to corner of the image's center.)
    const std::size_t center = (std::size_t(26) * kSidesImage + 40) * 4;
    for (const RenderResult& r : {render_abuffer(sides_quad(true), behind),
                                  render_multisampled(sides_quad(true), behind, 2)})
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(r.targets.color[center + std::size_t(c)],
                      reference.targets.color[center + std::size_t(c)]);
}

}  // namespace
}  // namespace zraster::test
