// Cluster culling (src/render/cluster_cull.hpp, cluster_cache.hpp) must be invisible: every
// cluster it culls holds only triangles the exact path culls (after the vertex stage's float
// transform and the snap), the renderer draws the same images and counts with it on and off,
// and bounds kept from an earlier frame are never trusted once the mesh has changed.
#include <zraster/error.hpp>
#include <zraster/load.hpp>
#include <zraster/render.hpp>
#include <zraster/scene.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>
#include <hwy/targets.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "render/cluster_cull.hpp"
#include "render/frame.hpp"
#include "render/vertex_kernel.hpp"
#include "render/word_hash.hpp"
#include "support/simd_target_scope.hpp"
#include "support/test_support.hpp"

namespace zraster::test {
namespace {

using namespace detail;

TEST(WordHash, SimdMatchesScalarOnEveryTargetAndPiecesCombine) {
    SplitMix64 rng(41);
    std::vector<std::uint32_t> words(1000);
    for (auto& w : words) w = static_cast<std::uint32_t>(rng.next());
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        SimdTargetScope scope(target);
        SCOPED_TRACE(hwy::TargetName(target));
        for (int round = 0; round < 200; ++round) {
            const std::size_t first = rng.next() % 500, count = rng.next() % 500;
            const std::uint64_t index = round % 3 == 0 ? (1ull << 32) - 7 : rng.next() % 100000;
            const std::uint64_t whole = hash_words_scalar(&words[first], count, index);
            ASSERT_EQ(hash_words(&words[first], count, index), whole) << round;
            const std::size_t split = count == 0 ? 0 : rng.next() % count;
            ASSERT_EQ(combine_word_hashes(
                          hash_words(&words[first], split, index),
                          hash_words(&words[first + split], count - split, index + split)),
                      whole)
                << round;
        }
    }
}

TEST(WordHash, ChangesWithAnyWordItsPositionOrALengthChange) {
    SplitMix64 rng(43);
    std::vector<std::uint32_t> words(300);
    for (auto& w : words) w = static_cast<std::uint32_t>(rng.next());
    const std::uint64_t base = hash_words(words.data(), words.size(), 0);
    for (std::size_t i = 0; i < words.size(); ++i) {
        for (const std::uint32_t flip : {1u, 0x80000000u, 0x00010000u}) {
            words[i] ^= flip;
            ASSERT_NE(hash_words(words.data(), words.size(), 0), base) << i;
            words[i] ^= flip;
        }
        if (i + 1 < words.size() && words[i] != words[i + 1]) {  // two words swapped
            std::swap(words[i], words[i + 1]);
            ASSERT_NE(hash_words(words.data(), words.size(), 0), base) << i;
            std::swap(words[i], words[i + 1]);
        }
    }
    EXPECT_NE(hash_words(words.data(), words.size() - 1, 0), base);
    EXPECT_NE(hash_words(words.data(), words.size(), 3), base);
}

// --- The bound itself, against the exact path -------------------------------------------

// A mesh of clusters of kClusterTriangles triangles each: small patches of a jittered 8 x 4
// grid of quads, bent a little or not, one in eight with slivers, at random places and scales,
// from far below a pixel to large, so that some straddle the near and far planes and the guard
// band, some have true areas the snap rounds to zero, and some (placed close to `eye`) see it
// almost edge-on, bent. All of it shifted by `offset`: far from the origin, float coordinates
// are coarse and the transform's rounding is what matters.
Mesh random_patches(SplitMix64& rng, int clusters, const glm::dvec3& eye = glm::dvec3(0, 0, 10),
                    const glm::dvec3& offset = glm::dvec3(0.0)) {
    static_assert(kClusterTriangles == 64);
    Mesh mesh;
    for (int c = 0; c < clusters; ++c) {
        glm::dvec3 center(rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-6, 9));
        glm::dvec3 normal =
            glm::normalize(glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
        if (rng.next() % 6 == 0) {  // close to the eye, nearly edge-on
            const glm::dvec3 towards =
                glm::normalize(-eye + glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), 0.0));
            center = eye + rng.uniform(0.5, 4) * towards;
            normal = glm::normalize(glm::cross(towards, normal) + rng.uniform(-0.1, 0.1) * towards);
        }
        center += offset;
        const glm::dvec3 u =
            glm::normalize(glm::cross(normal, glm::dvec3(0.3, 0.5, 0.8)));  // in the plane
        const glm::dvec3 v = glm::cross(normal, u);
        const double size = std::pow(10.0, rng.uniform(-6.5, 0.3));
        const double bend = rng.uniform(-0.3, 0.3) * (rng.next() % 2);  // bowls and domes
        const bool slivers = rng.next() % 8 == 0;
        const auto corner = [&](int i, int j) {
            const double a = (i + rng.uniform(-0.2, 0.2)) / 4.0 - 1.0;
            const double b = (j + rng.uniform(-0.2, 0.2)) / 2.0 - 1.0;
            return center + size * (a * u + b * v + bend * (a * a + b * b) * normal);
        };
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 8; ++i) {
                const glm::dvec3 p00 = corner(i, j), p10 = corner(i + 1, j), p01 = corner(i, j + 1),
                                 p11 = corner(i + 1, j + 1);
                for (std::array<glm::dvec3, 3> p : {std::array{p00, p10, p11}, {p00, p11, p01}}) {
                    if (slivers && i % 3 == 0) p[2] = 0.5 * (p[0] + p[1]) + size * 1e-6 * normal;
                    // Wound so that the face normal points along `normal`.
                    if (glm::dot(glm::cross(p[1] - p[0], p[2] - p[0]), normal) < 0)
                        std::swap(p[1], p[2]);
                    for (const auto& q : p) {
                        mesh.indices.push_back(static_cast<std::uint32_t>(mesh.positions.size()));
                        mesh.positions.emplace_back(q);
                    }
                }
            }
    }
    update_bounds(mesh);
    return mesh;
}

struct View {
    glm::dvec3 eye, offset;
    glm::mat4 mvp;
    ClipSettings clip;
    SetupSettings setup;
};

// A random camera and settings, made the way the renderer makes them (renderer.cpp).
View random_view(SplitMix64& rng) {
    View view;
    view.eye = {rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(6, 14)};
    view.offset = rng.next() % 4 == 0 ? glm::dvec3(std::pow(10.0, rng.uniform(2, 5)), -3e3, 0.0)
                                      : glm::dvec3(0.0);
    Camera camera;
    camera.eye = view.eye + view.offset;
    camera.target = glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), 0.0) + view.offset;
    camera.near = std::pow(10.0, rng.uniform(-3, 0.7));
    camera.far = camera.near + rng.uniform(2, 25);
    camera.fovy_degrees = rng.uniform(15, 120);
    camera.reversed_z = rng.next() % 2;
    camera.infinite_far = rng.next() % 4 == 0;
    if (rng.next() % 4 == 0) {
        camera.projection = Camera::Projection::Orthographic;
        camera.ortho_height = rng.uniform(1, 12);
    }
    const int width = 16 + int(rng.next() % 2500), height = 16 + int(rng.next() % 1500);
    // Sometimes scaled, sometimes mirrored (turns the winding), about the offset.
    glm::dmat4 shape(1.0);
    shape[0][0] = rng.uniform(0.5, 1.5) * (rng.next() % 3 == 0 ? -1.0 : 1.0);
    shape[1][0] = rng.uniform(-0.3, 0.3);
    glm::dmat4 to(1.0), from(1.0);
    to[3] = glm::dvec4(view.offset, 1.0);
    from[3] = glm::dvec4(-view.offset, 1.0);
    const glm::mat4 model(to * shape * from);
    view.mvp = camera.view_projection(double(width) / double(height)) * model;
    view.clip.depth_range = camera.clip_depth_range();
    view.clip.guard_x = static_cast<float>(kGuardBand / (0.5 * width));
    view.clip.guard_y = static_cast<float>(kGuardBand / (0.5 * height));
    view.setup.viewport = {width, height};
    view.setup.depth_range = camera.clip_depth_range();
    view.setup.cull = rng.next() % 2 ? CullMode::Back : CullMode::Front;
    view.setup.front_face = FrontFace(rng.next() % 2);
    return view;
}

// What the exact path makes of each cluster: whether it culls every triangle (all vertices
// inside, no clipping, each snapped area non-zero with the culled sign), and whether it does so
// with room to spare (areas of 2 pixels and more, depths away from the near and far planes).
struct ExactVerdict {
    bool all_culled = true, roomy = true;
};

std::vector<ExactVerdict> exact_verdicts(const Mesh& mesh, const View& view) {
    // The vertex stage's outputs (its SIMD kernel matches this bit for bit).
    std::vector<ScreenVertex> screen(mesh.positions.size());
    std::vector<std::uint32_t> outcode(mesh.positions.size());
    VertexJob job;
    job.positions = mesh.positions.data();
    job.count = mesh.positions.size();
    job.mvp = view.mvp;
    job.clip = view.clip;
    job.setup = view.setup;
    job.screen_out = screen.data();
    job.outcode_out = outcode.data();
    transform_vertices_scalar(job);
    std::vector<ExactVerdict> verdicts(cluster_count(mesh));
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        ExactVerdict& verdict = verdicts[t / kClusterTriangles];
        if (!verdict.all_culled) continue;
        const std::uint32_t* i = &mesh.indices[3 * t];
        TriangleBounds box;
        verdict.all_culled = (outcode[i[0]] | outcode[i[1]] | outcode[i[2]]) == 0 &&
                             classify_triangle(screen[i[0]], screen[i[1]], screen[i[2]], view.setup,
                                               box) == SetupResult::Culled;
        const ScreenVertex &a = screen[i[0]], &b = screen[i[1]], &d = screen[i[2]];
        const double area =
            (double(b.x) - a.x) * (double(d.y) - a.y) - (double(d.x) - a.x) * (double(b.y) - a.y);
        verdict.roomy &=
            verdict.all_culled && std::abs(area) >= 2.0 * kSubpixelScale * kSubpixelScale;
        for (const ScreenVertex* v : {&a, &b, &d}) verdict.roomy &= v->z > 0.02 && v->z < 0.98;
    }
    return verdicts;
}

TEST(ClusterCull, CulledClustersHoldOnlyTrianglesTheExactPathCulls) {
    SplitMix64 rng(20261124);
    std::size_t culled = 0, exactly_cullable = 0, clusters_seen = 0;
    std::size_t roomy_culled = 0, roomy_cullable = 0;
    for (int round = 0; round < 160; ++round) {
        SCOPED_TRACE("round " + std::to_string(round));
        const View view = random_view(rng);
        const Mesh mesh = random_patches(rng, 120, view.eye, view.offset);
        const std::vector<ClusterBounds> bounds = build_cluster_bounds(mesh);
        const ClusterView cluster_view = make_cluster_view(view.mvp, view.clip, view.setup);
        const std::vector<ExactVerdict> verdicts = exact_verdicts(mesh, view);
        for (std::size_t c = 0; c < bounds.size(); ++c) {
            const bool all_culled = verdicts[c].all_culled;
            // Far from the origin the float transform's rounding rules: no room to spare.
            const bool roomy = verdicts[c].roomy && view.offset == glm::dvec3(0.0);
            ++clusters_seen;
            exactly_cullable += all_culled;
            roomy_cullable += roomy;
            if (!cluster_is_culled(cluster_view, bounds[c])) continue;
            ++culled;
            roomy_culled += roomy;
            ASSERT_TRUE(all_culled) << "cluster " << c << " culled, but the exact path keeps, "
                                    << "clips or finds degenerate one of its triangles";
        }
    }
    // Not vacuous: clusters of all kinds are culled, and most of those the exact path culls
    // with room to spare (not those near the silhouette, whose bounds cannot tell).
    EXPECT_GT(exactly_cullable, clusters_seen / 10);
    EXPECT_GT(culled, exactly_cullable / 4) << culled << " of " << exactly_cullable;
    EXPECT_GT(roomy_culled, roomy_cullable * 65 / 100) << roomy_culled << " of " << roomy_cullable;
}

// The SIMD test gives every cluster the scalar verdict, on every instruction set, for clusters
// of all kinds (the random patches and views above) and any start and count.
TEST(ClusterCull, SimdVerdictsMatchTheScalarOnEveryTarget) {
    SplitMix64 rng(99);
    std::size_t culled = 0;
    for (int round = 0; round < 120; ++round) {
        const View view = random_view(rng);
        const ClusterArrays clusters(
            build_cluster_bounds(random_patches(rng, 100, view.eye, view.offset)));
        const ClusterView cluster_view = make_cluster_view(view.mvp, view.clip, view.setup);
        const std::size_t first = rng.next() % 10, count = 90 - rng.next() % 10;
        std::vector<std::uint8_t> expected(count), got(count);
        clusters_culled_scalar(cluster_view, clusters, first, count, expected.data());
        for (std::size_t i = 0; i < count; ++i)
            ASSERT_EQ(expected[i], cluster_is_culled(cluster_view, clusters[first + i]) ? 1 : 0);
        for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
            SimdTargetScope scope(target);
            std::fill(got.begin(), got.end(), 7);
            clusters_culled(cluster_view, clusters, first, count, got.data());
            ASSERT_EQ(got, expected) << hwy::TargetName(target) << " round " << round;
        }
        culled += std::size_t(std::count(expected.begin(), expected.end(), 1));
    }
    EXPECT_GT(culled, 200u);  // not vacuous
}

// A camera at `eye` looking at `target` (y up unless told), as the renderer would set it up at
// 400 x 300 with back faces culled.
View view_from(const glm::dvec3& eye, const glm::dvec3& target, double near,
               const glm::dvec3& up = glm::dvec3(0, 1, 0)) {
    Camera camera;
    camera.eye = eye;
    camera.target = target;
    camera.up = up;
    camera.near = near;
    camera.far = 10.0;
    View view;
    view.mvp = camera.view_projection(400.0 / 300.0);
    view.clip.guard_x = static_cast<float>(kGuardBand / 200.0);
    view.clip.guard_y = static_cast<float>(kGuardBand / 150.0);
    view.setup.viewport = {400, 300};
    return view;
}

bool culled_by_bounds(const Mesh& mesh, const View& view) {
    const std::vector<ClusterBounds> bounds = build_cluster_bounds(mesh);
    return bounds.size() == 1 &&
           cluster_is_culled(make_cluster_view(view.mvp, view.clip, view.setup), bounds[0]);
}

// Shingles: 64 small triangles around the plane z = 0, x in [-1, 1], facing down (-z) but each
// tilted by +-0.15 rad about y in turn. Seen from straight above, low, the outer ones tilted
// towards the eye show their fronts: a flat cluster whose normals spread, where the cone alone
// (its axis points at the eye) would call every triangle a back face.
TEST(ClusterCull, TiltedShinglesSeenFromCloseAreNotCulled) {
    Mesh mesh;
    for (std::size_t t = 0; t < kClusterTriangles; ++t) {
        const double x = -0.97 + 0.03 * double(t), tilt = t % 2 ? 0.15 : -0.15;
        const glm::dvec3 along(std::cos(tilt), 0.0, std::sin(tilt));  // tilted x axis
        // Clockwise seen from above: the face normal points down.
        for (const glm::dvec3& q :
             {glm::dvec3(x, -0.02, 0) - 0.02 * along, glm::dvec3(x, 0.02, 0) - 0.02 * along,
              glm::dvec3(x, -0.02, 0) + 0.02 * along}) {
            mesh.indices.push_back(static_cast<std::uint32_t>(mesh.positions.size()));
            mesh.positions.emplace_back(q);
        }
    }
    for (const double height : {3.0, 1.0, 0.3, 0.1, 0.05}) {
        const View view = view_from({0.0, 0.0, height}, {0.0, 0.0, -1.0}, 0.01);
        const bool exact = exact_verdicts(mesh, view)[0].all_culled;
        EXPECT_EQ(exact, height > 0.2) << height;  // the geometry does what this test is about
        EXPECT_TRUE(!culled_by_bounds(mesh, view) || exact) << height;
        if (height > 0.5) {
            EXPECT_TRUE(culled_by_bounds(mesh, view)) << height;
        }
    }
}

// A cluster facing away just beyond a near plane of 0.001, where the guard band (2^20 pixels
// from the center) is 8 units to the side: inside it, culled; across it, clipped, not culled.
TEST(ClusterCull, ClustersAcrossTheGuardBandAreNotCulled) {
    for (const int axis : {0, 1}) {
        for (const double from : {5.0, 7.5}) {
            Mesh mesh;
            for (std::size_t t = 0; t < kClusterTriangles; ++t) {
                glm::dvec3 a(0.0, 0.0, -0.002);
                a[axis] = from + 0.02 * double(t);
                glm::dvec3 b = a, c = a;
                b[axis] += 0.05;
                c[1 - axis] += 0.05;
                // Counter-clockwise seen from the eye: front faces of a plane facing the eye,
                // so wound the other way.
                for (const glm::dvec3& q : axis == 0 ? std::array{a, c, b} : std::array{a, b, c}) {
                    mesh.indices.push_back(static_cast<std::uint32_t>(mesh.positions.size()));
                    mesh.positions.emplace_back(q);
                }
            }
            const View view = view_from({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, 0.001);
            const bool exact = exact_verdicts(mesh, view)[0].all_culled;
            EXPECT_EQ(exact, from < 6.0) << axis << " " << from;
            EXPECT_EQ(culled_by_bounds(mesh, view), exact) << axis << " " << from;
        }
    }
}

// One cluster in two parallel layers facing down (z = 0 and z = 0.2), seen from the side at
// heights between and above them: from between, the lower layer shows its back and the upper
// its front, though a test at the cluster's center alone would call both back faces.
TEST(ClusterCull, TwoLayersWithTheEyeBetweenThemAreNotCulled) {
    Mesh mesh;
    for (std::size_t t = 0; t < kClusterTriangles; ++t) {
        const float z = t % 2 ? 0.2f : 0.0f;
        const float x = 2.0f + 0.05f * float(t / 2 % 8), y = 0.1f * float(t / 16) - 0.2f;
        // Clockwise seen from above: the face normal points down (-z).
        for (const glm::vec3& p :
             {glm::vec3(x, y, z), glm::vec3(x, y + 0.08f, z), glm::vec3(x + 0.04f, y, z)}) {
            mesh.indices.push_back(static_cast<std::uint32_t>(mesh.positions.size()));
            mesh.positions.push_back(p);
        }
    }
    const std::vector<ClusterBounds> bounds = build_cluster_bounds(mesh);
    ASSERT_EQ(bounds.size(), 1u);
    ASSERT_TRUE(bounds[0].cullable());
    for (const double height : {0.3, 0.19, 0.15, 0.12, 0.1, 0.05, -0.1}) {
        Camera camera;
        camera.eye = {0.0, 0.0, height};
        camera.target = {2.2, 0.0, height};
        camera.up = {0.0, 0.0, 1.0};
        camera.near = 0.5;
        camera.far = 5.0;
        SetupSettings setup;
        setup.viewport = {400, 300};
        ClipSettings clip;
        clip.guard_x = static_cast<float>(kGuardBand / 200.0);
        clip.guard_y = static_cast<float>(kGuardBand / 150.0);
        const ClusterView view =
            make_cluster_view(camera.view_projection(400.0 / 300.0), clip, setup);
        // Above both layers, both show their backs; anywhere else, some triangle its front.
        EXPECT_EQ(cluster_is_culled(view, bounds[0]), height > 0.2) << height;
    }
}

// Meshes the bounds must refuse: a bad index, a non-finite vertex, a degenerate triangle, a
// cluster whose normals point every way.
TEST(ClusterCull, UnsafeClustersAreNeverCullable) {
    SplitMix64 rng(5);
    Mesh mesh = random_patches(rng, 6);
    mesh.indices[3 * kClusterTriangles * 1 + 4] = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions[mesh.indices[3 * kClusterTriangles * 2 + 7]].y = NAN;
    const std::uint32_t* degenerate = &mesh.indices[3 * kClusterTriangles * 3 + 9];
    mesh.positions[degenerate[2]] = mesh.positions[degenerate[0]];
    for (std::size_t t = 4 * kClusterTriangles; t < 5 * kClusterTriangles; t += 2)
        std::swap(mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]);  // half turned around
    const std::vector<ClusterBounds> bounds = build_cluster_bounds(mesh);
    ASSERT_EQ(bounds.size(), 6u);
    EXPECT_TRUE(bounds[0].cullable());
    for (std::size_t c = 1; c <= 4; ++c) EXPECT_FALSE(bounds[c].cullable()) << c;
    EXPECT_TRUE(bounds[5].cullable());
}

// --- The renderer ------------------------------------------------------------------------

void expect_same_frame(const RenderResult& a, const RenderResult& b, const std::string& what) {
    EXPECT_TRUE(same_bits(a.targets.color, b.targets.color)) << what;
    EXPECT_TRUE(same_bits(a.targets.depth, b.targets.depth)) << what;
    EXPECT_TRUE(same_bits(a.targets.primitive_id, b.targets.primitive_id)) << what;
    const RenderStats &s = a.stats, &t = b.stats;
    EXPECT_EQ(s.triangles_in, t.triangles_in) << what;
    EXPECT_EQ(s.triangles_trivially_rejected, t.triangles_trivially_rejected) << what;
    EXPECT_EQ(s.triangles_clipped, t.triangles_clipped) << what;
    EXPECT_EQ(s.triangles_backface_culled, t.triangles_backface_culled) << what;
    EXPECT_EQ(s.triangles_degenerate, t.triangles_degenerate) << what;
    EXPECT_EQ(s.triangles_no_coverage, t.triangles_no_coverage) << what;
    EXPECT_EQ(s.triangles_rasterized, t.triangles_rasterized) << what;
    EXPECT_EQ(s.fragments_passed, t.fragments_passed) << what;
}

// Fine enough that a cluster (consecutive triangles of a ring) spans a narrow normal cone.
Scene sphere_scene() {
    Scene scene = scene_from_meshes({make_bench_sphere(200000)});
    scene.name = "sphere";
    return scene;
}

TEST(ClusterCulling, SameFramesAsWithoutItFrameAfterFrame) {
    SplitMix64 rng(77);
    std::vector<Scene> scenes;
    scenes.push_back(sphere_scene());
    scenes.push_back(scene_from_meshes({make_torus(1.0f, 0.35f, 160, 64)}));
    scenes.push_back(scene_from_meshes({random_patches(rng, 100)}));
    for (std::size_t s = 0; s < scenes.size(); ++s) {
        for (int variant = 0; variant < 6; ++variant) {
            const std::string what =
                "scene " + std::to_string(s) + " variant " + std::to_string(variant);
            RenderOptions o;
            o.width = 320;
            o.height = 200;
            o.id_targets = true;
            o.threads = 2;
            Camera camera = fit_camera(scenes[s].world_positions());
            camera.reversed_z = variant == 1;
            if (variant == 2) camera.projection = Camera::Projection::Orthographic;
            camera.ortho_height = 3.0;
            o.camera = camera;
            o.cull = variant == 3 ? CullMode::Front : CullMode::Back;
            o.front_face = variant == 4 ? FrontFace::Clockwise : FrontFace::CounterClockwise;
            o.simd = variant != 5;
            RenderOptions off = o;
            off.cluster_culling = false;
            Renderer with, without;
            for (int frame = 0; frame < 3; ++frame) {
                const RenderResult& a = with.render(scenes[s], o);
                const RenderResult& b = without.render(scenes[s], off);
                expect_same_frame(a, b, what + " frame " + std::to_string(frame));
                EXPECT_EQ(b.stats.clusters_culled, 0u);
                // Bounds are built in the first frame that draws a mesh, and used in it.
                if (s == 0) {
                    EXPECT_GT(a.stats.clusters_culled, 50u) << what;
                }
            }
        }
    }
}

// Real meshes (their triangle orders, shared vertices, slivers), from cameras all around: the
// same frames with and without cluster culling, frame after frame.
TEST(ClusterCulling, SharedMeshesFromEverySideSameAsWithout) {
    ZRASTER_REQUIRE_SHARED_DATA();
    int meshes = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(shared_data("meshes"))) {
        const std::string ext = entry.path().extension().string();
        if (ext != ".obj" && ext != ".ply" && ext != ".stl" && ext != ".glb") continue;
        Scene scene;
        try {
            scene = load_scene(entry.path());
        } catch (const InputError&) {
            continue;  // the deliberately broken ones
        }
        if (scene.triangle_count() < kMinClusteredTriangles) continue;
        ++meshes;
        SCOPED_TRACE(entry.path().string());
        const Camera fit = fit_camera(scene.world_positions());
        const double distance = glm::length(fit.eye - fit.target);
        RenderOptions o;
        o.width = 256;
        o.height = 192;
        o.id_targets = true;
        RenderOptions off = o;
        off.cluster_culling = false;
        Renderer with, without;
        for (int view = 0; view < 6; ++view) {
            Camera camera = orbit_camera(fit.target, distance * (view % 3 == 2 ? 0.6 : 1.0),
                                         60.0 * view, view % 2 ? 35.0 : -20.0);
            camera.near = distance * 0.05;
            camera.far = distance * 3.0;
            o.camera = off.camera = camera;
            const RenderResult& a = with.render(scene, o);
            expect_same_frame(a, without.render(scene, off), "view " + std::to_string(view));
        }
    }
    EXPECT_GT(meshes, 3);
}

TEST(ClusterCulling, OneShotRendersBuildNoBounds) {
    Scene scene = sphere_scene();
    Instance second = scene.instances[0];  // the same mesh twice: still its first frame
    second.transform[3] = glm::vec4(0.5f, 0.0f, 0.0f, 1.0f);
    scene.instances.push_back(second);
    RenderOptions o;
    o.width = 160;
    o.height = 100;
    EXPECT_EQ(render(scene, o).stats.clusters_culled, 0u);
    EXPECT_EQ(render(scene, o).stats.clusters_culled, 0u);
}

// The cache's bookkeeping on its own: bounds on the first sighting of a mesh, none for a mesh
// that changed until it is seen unchanged, and a soup (every cluster's normals point every way)
// is left alone after one look.
TEST(ClusterCache, BuildsOnTheFirstSightingAndGivesUpOnSoups) {
    const Mesh sphere_mesh = make_bench_sphere(20000);
    const Mesh soup_mesh = make_bench_soup(20000);
    const MeshView sphere_view = view_of(sphere_mesh), soup_view = view_of(soup_mesh);
    const FrameMesh sphere = frame_mesh(sphere_view), soup = frame_mesh(soup_view);
    RenderOptions options;
    Frame frame;
    frame.options = &options;
    const auto sighting = [&](const FrameMesh& mesh, std::uint64_t hash) {
        frame.instances.assign(1, FrameInstance{});
        frame.instances[0].mesh = &mesh;
        frame.instances[0].positions_hashed = frame.cluster_cache.wants_positions_hash(*mesh.view);
        frame.instances[0].positions_hash = hash;
        attach_clusters(frame);
        return frame.instances[0].clusters;
    };
    EXPECT_NE(sighting(sphere, 1), nullptr);
    EXPECT_NE(sighting(sphere, 1), nullptr);
    EXPECT_EQ(sighting(sphere, 2), nullptr);  // changed
    EXPECT_EQ(sighting(sphere, 3), nullptr);  // changed again (animated)
    EXPECT_NE(sighting(sphere, 3), nullptr);  // seen unchanged
    EXPECT_TRUE(frame.cluster_cache.wants_positions_hash(sphere_view));
    EXPECT_EQ(sighting(soup, 3), nullptr);  // built, and found not worth it
    EXPECT_FALSE(frame.cluster_cache.wants_positions_hash(soup_view));
    // The sphere is not drawn: kept for a while.
    EXPECT_EQ(frame.cluster_cache.entries.count(mesh_key(sphere_view)), 1u);
    EXPECT_EQ(sighting(soup, 3), nullptr);
    EXPECT_NE(sighting(sphere, 3), nullptr);  // still there, unchanged
    for (std::uint64_t k = 0; k < ClusterCache::kForgetAfterFrames; ++k) sighting(soup, 3);
    EXPECT_EQ(frame.cluster_cache.entries.count(mesh_key(sphere_view)), 0u);  // forgotten
    EXPECT_NE(sighting(sphere, 3), nullptr);  // first sighting again: built at once
}

// Instances of one mesh share its bounds (and its positions are hashed once a frame): both are
// culled from the first frame on, each from its own view of them.
TEST(ClusterCulling, InstancesOfOneMeshShareItsBounds) {
    Scene scene = sphere_scene();
    Instance second = scene.instances[0];
    second.transform = glm::rotate(glm::mat4(1.0f), 2.0f, glm::vec3(0, 1, 0));
    second.transform[3] = glm::vec4(2.5f, 0.0f, 0.0f, 1.0f);
    scene.instances.push_back(second);
    RenderOptions o;
    o.width = 320;
    o.height = 200;
    o.threads = 2;
    o.camera = fit_camera(scene.world_positions());
    RenderOptions off = o;
    off.cluster_culling = false;
    Renderer with, without;
    std::uint64_t culled = 0;
    for (int frame = 0; frame < 3; ++frame) {
        const RenderResult& a = with.render(scene, o);
        expect_same_frame(a, without.render(scene, off), "frame " + std::to_string(frame));
        culled = a.stats.clusters_culled;
    }
    Scene alone = sphere_scene();
    Renderer single;
    for (int frame = 0; frame < 2; ++frame) single.render(alone, o);
    // More than one instance's worth: the second instance's clusters are culled too.
    EXPECT_GT(culled, single.render(alone, o).stats.clusters_culled + 50);
}

// A grid of triangles facing away from the camera: nothing is drawn, and from the first frame
// on, whole clusters are culled. Then the mesh changes under the kept bounds.
Scene back_facing_grid() {
    Mesh mesh;
    const int n = 64;  // 2 * 64 * 64 = 8192 triangles
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x)
            mesh.positions.emplace_back(float(x) / n - 0.5f, float(y) / n - 0.5f, 0.0f);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const auto at = [&](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
            // Clockwise seen from +z, where the camera is: back faces.
            mesh.indices.insert(mesh.indices.end(), {at(x, y), at(x, y + 1), at(x + 1, y)});
            mesh.indices.insert(mesh.indices.end(), {at(x + 1, y), at(x, y + 1), at(x + 1, y + 1)});
        }
    update_bounds(mesh);
    return scene_from_meshes({std::move(mesh)});
}

RenderOptions grid_options() {
    RenderOptions o;
    o.width = 200;
    o.height = 200;
    o.threads = 2;
    Camera camera;
    camera.eye = {0.1, 0.2, 2.0};
    camera.target = {0.0, 0.0, 0.0};
    camera.near = 0.5;
    camera.far = 5.0;
    o.camera = camera;
    return o;
}

// Renders with the kept Renderer and checks it against a fresh one-shot render.
const RenderResult& render_and_check(Renderer& kept, const Scene& scene, const RenderOptions& o,
                                     const std::string& what) {
    const RenderResult& result = kept.render(scene, o);
    expect_same_frame(result, render(scene, o), what);
    return result;
}

TEST(ClusterCulling, ChangedIndicesAreNoticed) {
    Scene scene = back_facing_grid();
    const RenderOptions o = grid_options();
    Renderer kept;
    render_and_check(kept, scene, o, "first frame");
    const RenderResult& second = render_and_check(kept, scene, o, "second frame");
    ASSERT_EQ(second.stats.triangles_rasterized, 0u);
    ASSERT_EQ(second.stats.clusters_culled, 8192u / kClusterTriangles);
    // Turn a few triangles of one cluster to face the camera: same positions, same counts.
    std::vector<std::uint32_t>& indices = scene.meshes[0].indices;
    for (std::size_t t = 40 * kClusterTriangles; t < 40 * kClusterTriangles + 6; ++t)
        std::swap(indices[3 * t + 1], indices[3 * t + 2]);
    // Every vertex is used only by culled clusters, so the vertex stage would skip them all: it
    // checks every cluster's indices first, finds the change and culls no cluster this frame.
    const RenderResult& third = render_and_check(kept, scene, o, "indices changed");
    EXPECT_EQ(third.stats.triangles_rasterized, 6u);
    EXPECT_EQ(third.stats.clusters_culled, 0u);
    EXPECT_EQ(third.stats.vertices_skipped, 0u);
    // The bounds were dropped after that frame, and are rebuilt once the mesh is seen unchanged
    // again (the changed cluster now faces both ways: never culled).
    const RenderResult& fourth = render_and_check(kept, scene, o, "after the change");
    EXPECT_EQ(fourth.stats.triangles_rasterized, 6u);
    EXPECT_EQ(fourth.stats.clusters_culled, 0u);
    const RenderResult& fifth = render_and_check(kept, scene, o, "bounds rebuilt");
    EXPECT_EQ(fifth.stats.triangles_rasterized, 6u);
    EXPECT_EQ(fifth.stats.clusters_culled, 8192u / kClusterTriangles - 1);
    // From the next frame on, the vertices only the culled clusters use are not transformed.
    const RenderResult& sixth = render_and_check(kept, scene, o, "vertices skipped");
    EXPECT_EQ(sixth.stats.clusters_culled, 8192u / kClusterTriangles - 1);
    EXPECT_GT(sixth.stats.vertices_skipped, 3000u);
}

// Skipped vertices keep the screen positions of the last frame that transformed them: a frame
// that read one would draw it where an earlier camera saw it. With the camera moving every
// frame, every frame must still be the exact path's, when the mesh stays, when an index of a
// visible triangle is made to point at a skipped vertex, and when a skipped vertex moves.
// 320x240 on two threads: the frames the renderer tests below check against one-shot renders.
RenderOptions small_frame_options() {
    RenderOptions o;
    o.width = 320;
    o.height = 240;
    o.threads = 2;
    return o;
}

// The fitted camera with its eye turned about the vertical through the target, a little more
// each frame.
Camera circled(const Camera& fitted, int frame) {
    Camera camera = fitted;
    const double angle = 0.15 * frame;
    const glm::dvec3 eye = camera.eye - camera.target;
    camera.eye =
        camera.target + glm::dvec3(eye.x * std::cos(angle) - eye.z * std::sin(angle), eye.y,
                                   eye.x * std::sin(angle) + eye.z * std::cos(angle));
    return camera;
}

TEST(ClusterCulling, SkippedVerticesAreNeverRead) {
    Scene scene = sphere_scene();
    RenderOptions o = small_frame_options();
    const Camera fitted = fit_camera(scene.world_positions());
    Renderer kept;
    int frame = 0;
    const auto next_frame = [&](const std::string& what) -> const RenderResult& {
        o.camera = circled(fitted, frame++);
        return render_and_check(kept, scene, o, what);
    };
    next_frame("first");
    next_frame("second: bounds built");
    const RenderResult& third = next_frame("third: vertices skipped");
    ASSERT_GT(third.stats.vertices_skipped, 20000u);
    next_frame("fourth");
    // A vertex on the back, high up (so it projects far from the middle of the image), and two
    // triangles facing the eye: each gets it as a corner, one in each winding, so that one of
    // them faces the eye and is drawn.
    Mesh& mesh = scene.meshes[0];
    const glm::dvec3 toward_eye = glm::normalize(o.camera->eye - o.camera->target);
    const auto along = [&](std::size_t v, const glm::dvec3& d) {
        return glm::dot(glm::dvec3(mesh.positions[v]), d);
    };
    std::size_t back = 0, front = 0;
    float highest = -2.0f;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
        if (along(v, toward_eye) < -0.6 && mesh.positions[v].y > highest) {
            back = v;
            highest = mesh.positions[v].y;
        }
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
        if (along(mesh.indices[3 * t], toward_eye) > along(mesh.indices[3 * front], toward_eye))
            front = t;
    ASSERT_LT(along(back, toward_eye), -0.6);
    mesh.indices[3 * front + 1] = static_cast<std::uint32_t>(back);
    mesh.indices[3 * (front + 2) + 2] = static_cast<std::uint32_t>(back);
    const RenderResult& changed =
        next_frame("an index of a visible triangle points at a skipped vertex");
    EXPECT_EQ(changed.stats.vertices_skipped, 0u);
    next_frame("after the change");
    next_frame("bounds rebuilt");
    ASSERT_GT(next_frame("skipping again").stats.vertices_skipped, 20000u);
    mesh.positions[back].y = std::nextafter(mesh.positions[back].y, 2.0f);
    EXPECT_EQ(next_frame("a skipped vertex moved").stats.vertices_skipped, 0u);
    next_frame("after the move");
}

// The same with two instances of the mesh: the second is skipped from the positions' hash the
// first computed, so a change must be seen before it skips anything.
TEST(ClusterCulling, SkippedVerticesOfASecondInstanceAreNeverRead) {
    Scene scene = sphere_scene();
    Instance second = scene.instances[0];
    second.transform = glm::translate(glm::mat4(1.0f), glm::vec3(2.5f, 0.0f, 0.0f));
    scene.instances.push_back(second);
    RenderOptions o = small_frame_options();
    Camera camera = fit_camera(scene.world_positions());
    Renderer kept;
    for (int frame = 0; frame < 5; ++frame) {
        camera.eye.y += 0.2;  // a new view every frame: skipped vertices hold stale positions
        o.camera = camera;
        if (frame == 4)  // mirrored: every triangle turns to face the other way
            for (glm::vec3& p : scene.meshes[0].positions) p.x = -p.x;
        const RenderResult& r = render_and_check(kept, scene, o, "frame " + std::to_string(frame));
        if (frame == 3) {
            EXPECT_GT(r.stats.vertices_skipped, 40000u);
        } else if (frame == 4) {
            EXPECT_EQ(r.stats.vertices_skipped, 0u);
        }
    }
}

TEST(ClusterCulling, ChangedPositionsAreNoticed) {
    Scene scene = back_facing_grid();
    const RenderOptions o = grid_options();
    Renderer kept;
    render_and_check(kept, scene, o, "first frame");
    ASSERT_GT(render_and_check(kept, scene, o, "second frame").stats.clusters_culled, 100u);
    // Mirror the grid in x: every triangle now faces the camera.
    for (glm::vec3& p : scene.meshes[0].positions) p.x = -p.x;
    const RenderResult& mirrored = render_and_check(kept, scene, o, "positions changed");
    EXPECT_EQ(mirrored.stats.clusters_culled, 0u);
    EXPECT_GT(mirrored.stats.triangles_rasterized, 8000u);
    // One vertex moved by the smallest step, in a mesh seen twice since: noticed too.
    render_and_check(kept, scene, o, "mirrored, again");
    for (glm::vec3& p : scene.meshes[0].positions) p.x = -p.x;  // back to facing away
    render_and_check(kept, scene, o, "facing away again");
    render_and_check(kept, scene, o, "facing away, bounds rebuilt");
    glm::vec3& moved = scene.meshes[0].positions[(64 + 1) * 20 + 20];
    moved.z = std::nextafter(moved.z, 1.0f);
    const RenderResult& nudged = render_and_check(kept, scene, o, "one vertex nudged");
    EXPECT_EQ(nudged.stats.clusters_culled, 0u);
}

// RenderOptions::static_meshes: the same frames while the promise holds, no hashing (a moved
// vertex goes unnoticed: that is the promise's price), and a change of size still noticed.
TEST(ClusterCulling, StaticMeshesAreCheckedBySizeOnly) {
    Scene scene = sphere_scene();
    RenderOptions o = small_frame_options();
    o.static_meshes = true;
    const Camera fitted = fit_camera(scene.world_positions());
    Renderer kept;
    int frame = 0;
    // A new view every frame: skipped vertices hold stale positions.
    const auto next_view = [&] { o.camera = circled(fitted, frame++); };
    const auto next_frame = [&](const std::string& what) -> const RenderResult& {
        next_view();
        return render_and_check(kept, scene, o, what);
    };
    EXPECT_GT(next_frame("first: bounds built").stats.clusters_culled, 100u);
    EXPECT_GT(next_frame("second: vertices skipped").stats.vertices_skipped, 20000u);
    // One more triangle (a copy of the first): the sizes changed, so it is a new mesh to the
    // cache: bounds built for it at once, no vertex skipped on the old ones.
    Mesh& mesh = scene.meshes[0];
    for (std::size_t k = 0; k < 3; ++k) mesh.indices.push_back(mesh.indices[k]);
    const RenderResult& grown = next_frame("a triangle added");
    EXPECT_GT(grown.stats.clusters_culled, 100u);
    EXPECT_EQ(grown.stats.vertices_skipped, 0u);
    EXPECT_GT(next_frame("seen again").stats.vertices_skipped, 20000u);
    // A promise broken: every vertex moved, same sizes. Not hashed, so not noticed: the
    // renderer still skips the vertices its old bounds cull (the frame is not checked).
    for (glm::vec3& p : mesh.positions) p *= 0.9f;
    next_view();
    EXPECT_GT(kept.render(scene, o).stats.vertices_skipped, 20000u);
    // Checked again from the next frame on: the moved mesh is taken as new.
    o.static_meshes = false;
    const RenderResult& checked = next_frame("checked again");
    EXPECT_EQ(checked.stats.clusters_culled, 0u);
    EXPECT_EQ(checked.stats.vertices_skipped, 0u);
    next_frame("checked, seen again");
    EXPECT_GT(next_frame("checked, bounds rebuilt").stats.vertices_skipped, 20000u);
}

}  // namespace
}  // namespace zraster::test
