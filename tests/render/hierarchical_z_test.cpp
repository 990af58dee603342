// Hierarchical z (src/render/hierarchical_z.hpp) must be invisible in the image: its block test
// never hides a fragment the per-pixel test keeps, for every compare function it serves, and it
// does skip work on scenes with overdraw.
#include <zraster/mesh.hpp>
#include <zraster/render.hpp>
#include <zraster/scene.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "render/hierarchical_z.hpp"
#include "support/test_support.hpp"

namespace zraster::test {
namespace {

using detail::block_hidden;

// The kernel's depth at a pixel: the plane in float, in its order, clamped as it does.
float kernel_depth(const PlaneEquation& p, int dx, int dy) {
    return std::min(std::max(p.at(dx, dy), 0.0f), 1.0f) + 0.0f;
}

// For random planes and blocks, a stored bound just beyond the nearest fragment lets that
// fragment pass: the block test must not call the block hidden. And a bound at or before every
// fragment's depth must (mostly) be recognised as hidden, or the test would be useless.
TEST(HierarchicalZ, BlockTestIsConservativeAndUseful) {
    SplitMix64 rng(7);
    int recognised = 0, hideable = 0;
    for (int i = 0; i < 200000; ++i) {
        const float scale = float(std::pow(10.0, rng.uniform(-7, 0)));
        PlaneEquation p{float(rng.uniform(-1, 1) * scale), float(rng.uniform(-1, 1) * scale),
                        float(rng.uniform(-0.2, 1.2))};
        const int dx0 = int(rng.next() % 64), dy0 = int(rng.next() % 64);
        const int dx1 = dx0 + int(rng.next() % 8), dy1 = dy0 + int(rng.next() % 8);
        float nearest_lo = 2.0f, nearest_hi = -1.0f;
        for (int y = dy0; y <= dy1; ++y)
            for (int x = dx0; x <= dx1; ++x) {
                nearest_lo = std::min(nearest_lo, kernel_depth(p, x, y));
                nearest_hi = std::max(nearest_hi, kernel_depth(p, x, y));
            }
        // Stored depths lie in [0, 1]: bounds outside cannot occur.
        const float above = std::nextafter(nearest_lo, 2.0f);
        const float below = std::nextafter(nearest_hi, -1.0f);
        if (above <= 1.0f) {
            ASSERT_FALSE(block_hidden(p, dx0, dy0, dx1, dy1, above, CompareFunc::Less)) << i;
        }
        ASSERT_FALSE(block_hidden(p, dx0, dy0, dx1, dy1, nearest_lo, CompareFunc::LessEqual)) << i;
        if (below >= 0.0f) {
            ASSERT_FALSE(block_hidden(p, dx0, dy0, dx1, dy1, below, CompareFunc::Greater)) << i;
        }
        ASSERT_FALSE(block_hidden(p, dx0, dy0, dx1, dy1, nearest_hi, CompareFunc::GreaterEqual))
            << i;
        if (nearest_lo > 0.01f && nearest_lo < 0.99f) {
            ++hideable;
            recognised +=
                block_hidden(p, dx0, dy0, dx1, dy1, nearest_lo * 0.999f, CompareFunc::Less);
        }
    }
    EXPECT_GT(hideable, 50000);
    // Planes steep enough that the error margin exceeds 0.1% of the depth are the exceptions.
    EXPECT_GT(recognised, hideable * 95 / 100);
}

// Large random triangles in [-1, 1]^3, some long and thin: about 40 layers of overdraw in
// random depth order (at 640x480: most are larger than a single kernel job there, which is
// where hierarchical z is kept up to date).
Scene overdraw_scene() {
    SplitMix64 rng(11);
    Mesh mesh;
    for (int t = 0; t < 3000; ++t) {
        const glm::dvec3 c(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
        const double s = rng.uniform(0.05, 0.6);
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 o(rng.uniform(-s, s), rng.uniform(-s, s), rng.uniform(-s, s));
            mesh.positions.emplace_back(c + o);
            mesh.indices.push_back(std::uint32_t(mesh.positions.size() - 1));
        }
    }
    compute_angle_weighted_normals(mesh);
    update_bounds(mesh);
    std::vector<Mesh> meshes;
    meshes.push_back(std::move(mesh));
    return scene_from_meshes(std::move(meshes));
}

// Many overlapping triangles in random order (heavy overdraw), drawn with each compare function
// hierarchical z serves, also with equal depths (LessEqual/GreaterEqual keep the later one):
// every target is bit-identical with it off, and it skipped blocks.
TEST(HierarchicalZ, ImagesAreIdenticalWithItOff) {
    struct Case {
        CompareFunc compare;
        bool reversed_z;
    };
    for (const Case c : {Case{CompareFunc::Less, false}, Case{CompareFunc::LessEqual, false},
                         Case{CompareFunc::Greater, true}, Case{CompareFunc::GreaterEqual, true}}) {
        for (const bool simd : {true, false}) {
            SCOPED_TRACE(std::to_string(int(c.compare)) + (simd ? " simd" : " scalar"));
            Scene scene = overdraw_scene();
            // Duplicate the first triangles at the end: equal depths, drawn later.
            Mesh& mesh = scene.meshes[0];
            for (std::size_t i = 0; i < 3 * 500; ++i) mesh.indices.push_back(mesh.indices[i]);
            RenderOptions o;
            o.width = 640;
            o.height = 480;
            o.id_targets = true;
            o.simd = simd;
            o.cull = CullMode::None;
            o.depth_compare = c.compare;
            Camera camera = fit_camera(scene.world_positions());
            camera.reversed_z = c.reversed_z;
            o.camera = camera;
            const RenderResult on = render(scene, o);
            o.hierarchical_z = false;
            const RenderResult off = render(scene, o);
            EXPECT_TRUE(same_bits(on.targets.color, off.targets.color));
            EXPECT_TRUE(same_bits(on.targets.depth, off.targets.depth));
            EXPECT_TRUE(same_bits(on.targets.primitive_id, off.targets.primitive_id));
            EXPECT_EQ(on.stats.fragments_shaded, off.stats.fragments_shaded);
            EXPECT_GT(on.stats.blocks_hidden, 1000u);
            EXPECT_EQ(off.stats.blocks_hidden, 0u);
            // Hidden blocks had no passing fragment: the counts agree.
            EXPECT_EQ(on.stats.fragments_passed, off.stats.fragments_passed);
        }
    }
}

// A large wall drawn first, then many small triangles (one kernel job each) behind it, or in
// front of it: the hidden ones are skipped by their test (their own writes refresh no bound, so
// the wall's bounds must do), the visible ones are drawn, and the images are those without it.
TEST(HierarchicalZ, SmallTrianglesBehindALargeOccluder) {
    const auto scene_with = [](double small_z) {
        Mesh mesh;
        const auto add = [&](glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
            for (const glm::dvec3& p : {a, b, c}) {
                mesh.positions.emplace_back(p);
                mesh.indices.push_back(std::uint32_t(mesh.positions.size() - 1));
            }
        };
        add({-2, -2, 0}, {2, -2, 0}, {2, 2, 0});  // the wall, z = 0, facing the camera
        add({-2, -2, 0}, {2, 2, 0}, {-2, 2, 0});
        SplitMix64 rng(3);
        for (int t = 0; t < 4000; ++t) {
            const glm::dvec3 c(rng.uniform(-0.9, 0.9), rng.uniform(-0.9, 0.9), small_z);
            add(c, c + glm::dvec3(0.02, 0, 0), c + glm::dvec3(0, 0.02, 0));
        }
        update_bounds(mesh);
        std::vector<Mesh> meshes;
        meshes.push_back(std::move(mesh));
        return scene_from_meshes(std::move(meshes));
    };
    RenderOptions o;
    o.width = 256;
    o.height = 256;
    o.color_target = false;
    o.id_targets = true;
    Camera camera;
    camera.eye = {0, 0, 3};
    camera.target = {0, 0, 0};
    camera.near = 0.5;
    camera.far = 10;
    o.camera = camera;
    for (const double small_z : {-0.5, 0.5}) {  // behind the wall, then in front of it
        SCOPED_TRACE(small_z);
        const Scene scene = scene_with(small_z);
        const RenderResult on = render(scene, o);
        o.hierarchical_z = false;
        const RenderResult off = render(scene, o);
        o.hierarchical_z = true;
        EXPECT_TRUE(same_bits(on.targets.depth, off.targets.depth));
        EXPECT_TRUE(same_bits(on.targets.primitive_id, off.targets.primitive_id));
        EXPECT_EQ(on.stats.fragments_passed, off.stats.fragments_passed);
        // Every small triangle is one job of a few pixels, all inside the wall.
        if (small_z < 0)
            EXPECT_GE(on.stats.blocks_hidden, 3900u)
                << on.stats.blocks_hidden;  // all but a few at tile edges
        else
            EXPECT_EQ(on.stats.blocks_hidden, 0u);
    }
}

}  // namespace
}  // namespace zraster::test
