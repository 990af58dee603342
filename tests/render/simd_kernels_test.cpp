// Every SIMD kernel against its scalar reference, bit for bit: the visibility kernel on random
// triangles and blocks (with and without attribute interpolation), the Phong shading kernels on
// random inputs, and whole frames rendered with options.simd on and off.
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstring>
#include <memory>
#include <random>
#include <utility>
#include <vector>

#include "raster/visibility_kernel.hpp"
#include "render/every_simd_target.hpp"
#include "render/render_test_util.hpp"
#include "render/shade_kernel.hpp"

namespace zraster::detail {
namespace {

// (n may be 0 with null pointers: empty targets.)
template <class T>
bool same_bits(const T* a, const T* b, std::size_t n) {
    return n == 0 || std::memcmp(a, b, n * sizeof(T)) == 0;
}

std::unique_ptr<TileBuffers> cleared_tile() {
    auto t = std::make_unique<TileBuffers>();
    std::fill(std::begin(t->depth), std::end(t->depth), 1.0f);
    std::fill(std::begin(t->ref), std::end(t->ref), kNoTriangle);
    std::fill(std::begin(t->b1), std::end(t->b1), 0.0f);
    std::fill(std::begin(t->b2), std::end(t->b2), 0.0f);
    for (float* a : {t->nx, t->ny, t->nz, t->wx, t->wy, t->wz})
        std::fill_n(a, TileBuffers::kPixels, 0.0f);
    std::fill(std::begin(t->shade_tag), std::end(t->shade_tag), 0u);
    std::fill(std::begin(t->color), std::end(t->color), 0u);
    return t;
}

// Every buffer of the two tiles, bit for bit.
void expect_same_tiles(const TileBuffers& a, const TileBuffers& b) {
    EXPECT_TRUE(same_bits(a.depth, b.depth, TileBuffers::kPixels));
    EXPECT_TRUE(same_bits(a.ref, b.ref, TileBuffers::kPixels));
    EXPECT_TRUE(same_bits(a.b1, b.b1, TileBuffers::kPixels));
    EXPECT_TRUE(same_bits(a.b2, b.b2, TileBuffers::kPixels));
    EXPECT_TRUE(same_bits(a.shade_tag, b.shade_tag, TileBuffers::kPixels));
    for (const auto field : {&TileBuffers::nx, &TileBuffers::ny, &TileBuffers::nz, &TileBuffers::wx,
                             &TileBuffers::wy, &TileBuffers::wz})
        EXPECT_TRUE(same_bits(a.*field, b.*field, TileBuffers::kPixels));
    EXPECT_TRUE(same_bits(a.color, b.color, TileBuffers::kPixels));
}

// Forward shading's constants (two lights) for the kernel tests.
PhongConstants test_lighting() {
    LightingModel model;
    model.lights.push_back(Light{});
    model.lights.push_back(Light{});
    model.lights[1].direction = {0.3f, -0.8f, 0.5f};
    model.lights[1].color = {0.4f, 0.5f, 0.9f};
    Material material;
    material.base_color = {0.8f, 0.6f, 0.3f};
    material.shininess = 24.0f;
    EXPECT_TRUE(phong_kernel_applies(model, material));
    return make_phong_constants(model, material, {0.5f, 1.0f, 4.0f}, glm::vec3(0, 0, 1));
}

void VisibilityBlockMatchesScalarOnRandomTriangles() {
    std::mt19937 rng(99);
    std::uniform_real_distribution<double> coord(-20.0, 84.0);
    std::uniform_real_distribution<float> depth(0.0f, 1.0f), w(0.2f, 4.0f);
    auto simd_tile = cleared_tile();
    auto scalar_tile = cleared_tile();
    // Forward shading (lit in the kernel) for some of the interpolating triangles.
    const PhongConstants lighting = test_lighting();
    int lit = 0;
    // Corner attributes for a third of the triangles, a clipped piece's weights for some.
    std::uniform_real_distribution<float> attribute(-3.0f, 3.0f);
    const glm::vec3 piece[3] = {{0.7f, 0.2f, 0.1f}, {0.1f, 0.8f, 0.1f}, {0.3f, 0.3f, 0.4f}};
    int interpolated = 0;
    SetupSettings settings;
    settings.viewport = {64, 64};
    settings.cull = CullMode::None;
    // Each depth test the kernel is compiled for, and two of the shared (run-time) kernel's.
    const CompareFunc compares[] = {CompareFunc::Less,    CompareFunc::LessEqual,
                                    CompareFunc::Greater, CompareFunc::GreaterEqual,
                                    CompareFunc::Equal,   CompareFunc::Always};
    int blocks = 0, passed = 0, wide = 0;
    for (std::uint32_t tri = 0; tri < 3000; ++tri) {
        std::array<ScreenVertex, 3> v;
        for (auto& s : v) {
            s.window_x = static_cast<float>(coord(rng));
            s.window_y = static_cast<float>(coord(rng));
            s.x = static_cast<std::int32_t>(std::lrint(s.window_x * 256.0));
            s.y = static_cast<std::int32_t>(std::lrint(s.window_y * 256.0));
            s.z = depth(rng);
            s.inv_w = w(rng);
        }
        TriangleSetup setup;
        if (setup_triangle(v, settings, setup) != SetupResult::Visible) continue;
        BlockJob job;
        job.planes = {setup.depth, setup.q, setup.p1, setup.p2, setup.l1, setup.l2};
        job.compare = compares[(tri / 3) % 6];
        job.perspective = tri % 5 != 0;
        job.write_depth = tri % 7 != 0;
        job.attributes = tri % 8 != 5;  // depth only: the kernel's branch-free rows
        job.ref = tri;
        CornerAttributes corners;
        for (int k = 0; k < 3; ++k) {
            corners.world[k] = {attribute(rng), attribute(rng), attribute(rng)};
            corners.normal[k] = {attribute(rng), attribute(rng), attribute(rng)};
        }
        job.piece = tri % 2 ? piece : nullptr;
        corners.tag = (1 + tri % 4) | (tri % 5 == 0 ? kShadeFlip : 0u);
        job.corners = tri % 3 == 0 ? &corners : nullptr;
        job.shade_constants = tri % 6 == 0 ? &lighting : nullptr;
        // Jobs over the triangle's box on a grid of 8x8 blocks, or (as the tile rasterizer
        // gives small triangles) of strips 13 or 32 pixels wide and a whole tile tall; edges
        // straight from the setup.
        const int job_w = tri % 4 == 1 ? 32 : tri % 4 == 3 ? 13 : 8;
        const int job_h = job_w == 8 ? 8 : 64;
        for (int by = setup.min_y / job_h * job_h; by <= setup.max_y; by += job_h)
            for (int bx = setup.min_x / job_w * job_w; bx <= setup.max_x; bx += job_w) {
                const int x0 = std::max(bx, setup.min_x), y0 = std::max(by, setup.min_y);
                const int x1 = std::min(bx + job_w - 1, setup.max_x);
                const int y1 = std::min(by + job_h - 1, setup.max_y);
                for (std::size_t k = 0; k < 3; ++k) {
                    job.e[k] = static_cast<std::int32_t>(setup.edge_a[k] * x0 +
                                                         setup.edge_b[k] * y0 + setup.edge_c[k]);
                    job.step_x[k] = static_cast<std::int32_t>(setup.edge_a[k]);
                    job.step_y[k] = static_cast<std::int32_t>(setup.edge_b[k]);
                }
                job.full = (tri % 11 == 0);
                job.x0 = x0;
                job.y0 = y0;
                job.width = x1 - x0 + 1;
                job.height = y1 - y0 + 1;
                job.plane_dx = x0 - setup.min_x;
                job.plane_dy = y0 - setup.min_y;
                const int a = visibility_block(job, *simd_tile);
                const int b = visibility_block_scalar(job, *scalar_tile);
                ASSERT_EQ(a, b) << "triangle " << tri;
                passed += a;
                wide += a > 0 && job.width > 8 && job.height > 8;
                if (job.corners) (job.shade_constants ? lit : interpolated) += a;
                ++blocks;
            }
    }
    EXPECT_GT(blocks, 3000);
    EXPECT_GT(wide, 500);  // jobs wider than a block and taller than one, with pixels kept
    EXPECT_GT(passed, 10000);
    EXPECT_GT(interpolated, 1500);
    EXPECT_GT(lit, 3000);
    expect_same_tiles(*simd_tile, *scalar_tile);
    // The interpolating triangles kept pixels to the end (their tags are there).
    int tagged = 0;
    for (int at = 0; at < kTileStride * kTileStride; ++at)
        tagged += scalar_tile->shade_tag[at] != 0;
    EXPECT_GT(tagged, 100);
    ::testing::Test::RecordProperty("target", visibility_kernel_target());
}

void PhongShadingMatchesScalarOnRandomInputs() {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int round = 0; round < 200; ++round) {
        LightingModel model;
        model.reflection = round % 2 ? ReflectionModel::Phong : ReflectionModel::BlinnPhong;
        model.local_viewer = round % 3 != 0;
        model.lights.resize(std::size_t(1 + round % kMaxKernelLights));
        for (Light& l : model.lights) {
            l.direction = {u(rng), u(rng), u(rng)};
            l.color = glm::abs(glm::vec3(u(rng), u(rng), u(rng)));
        }
        Material material;
        material.base_color = glm::abs(glm::vec3(u(rng), u(rng), u(rng)));
        material.shininess = float(round % 97);  // 0 too: x^0 = 1
        ASSERT_TRUE(phong_kernel_applies(model, material));
        const PhongConstants k = make_phong_constants(model, material, {u(rng), u(rng), 3.0f},
                                                      glm::normalize(glm::vec3(u(rng), u(rng), 1)));
        auto simd = std::make_unique<PhongBatch>(), scalar = std::make_unique<PhongBatch>();
        simd->count = 1 + round % kShadeBatch;
        for (int i = 0; i < simd->count; ++i) {
            simd->nx[i] = u(rng);
            simd->ny[i] = u(rng);
            simd->nz[i] = i % 17 == 0 ? 0.0f : u(rng);
            if (i % 23 == 0) simd->nx[i] = simd->ny[i] = simd->nz[i] = 0.0f;  // zero normal
            simd->px[i] = u(rng);
            simd->py[i] = u(rng);
            simd->pz[i] = u(rng);
            simd->flip[i] = (i % 3 == 0) ? ~0u : 0u;
        }
        *scalar = *simd;
        shade_phong_batch(k, *simd);
        shade_phong_batch_scalar(k, *scalar);
        for (int i = 0; i < simd->count; ++i) {
            ASSERT_EQ(simd->r[i], scalar->r[i]) << "round " << round << " pixel " << i;
            ASSERT_EQ(simd->g[i], scalar->g[i]) << "round " << round << " pixel " << i;
            ASSERT_EQ(simd->b[i], scalar->b[i]) << "round " << round << " pixel " << i;
        }
    }
}

// The row shader: tagged pixels of up to 4 materials mixed in a row (with flips, zero normals
// and untagged pixels), against the scalar reference; untagged pixels keep what rgba held.
void TaggedRowShadingMatchesScalar() {
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    PhongConstants constants[4];
    for (int m = 0; m < 4; ++m) {
        LightingModel model;
        model.reflection = m % 2 ? ReflectionModel::Phong : ReflectionModel::BlinnPhong;
        model.local_viewer = m != 3;
        model.lights.resize(std::size_t(1 + m));
        for (Light& l : model.lights) {
            l.direction = {u(rng), u(rng), u(rng)};
            l.color = glm::abs(glm::vec3(u(rng), u(rng), u(rng)));
        }
        Material material;
        material.base_color = glm::abs(glm::vec3(u(rng), u(rng), u(rng)));
        material.shininess = float(1 + 13 * m);
        constants[m] = make_phong_constants(model, material, {u(rng), u(rng), 3.0f},
                                            glm::normalize(glm::vec3(u(rng), u(rng), 1)));
    }
    auto tile = std::make_unique<TileBuffers>();
    int shaded = 0;
    for (int round = 0; round < 100; ++round) {
        for (int i = 0; i < TileBuffers::kPixels; ++i) {
            tile->nx[i] = u(rng);
            tile->ny[i] = u(rng);
            tile->nz[i] = i % 29 == 0 ? 0.0f : u(rng);
            if (i % 31 == 0) tile->nx[i] = tile->ny[i] = tile->nz[i] = 0.0f;
            tile->wx[i] = u(rng);
            tile->wy[i] = u(rng);
            tile->wz[i] = u(rng);
            // Runs of one material, as triangles leave them, with gaps and other materials;
            // every third round runs longer than a vector (a row's usual material).
            const int run = (1 + round % 7) * (round % 3 == 0 ? 9 : 1);
            const std::uint32_t material = std::uint32_t(i / run) % 5;  // 0: untagged
            tile->shade_tag[i] = material | (i % 3 == 0 ? kShadeFlip : 0u);
        }
        const int row = round % 64, count = 1 + (round * 13) % 64;
        const std::size_t at = std::size_t(row * kTileStride);
        std::uint32_t simd[kTileStride], scalar[kTileStride];
        std::fill_n(simd, kTileStride, 0x12345678u);
        std::fill_n(scalar, kTileStride, 0x12345678u);
        const int a = shade_tagged_row(constants, *tile, at, count, simd);
        const int b = shade_tagged_row_scalar(constants, *tile, at, count, scalar);
        ASSERT_EQ(a, b) << "round " << round;
        shaded += a;
        for (int i = 0; i < count; ++i)
            ASSERT_EQ(simd[i], scalar[i]) << "round " << round << " " << i;
        for (int i = count; i < kTileStride; ++i)  // past the row: left alone
            ASSERT_EQ(simd[i], 0x12345678u) << "round " << round << " " << i;
    }
    EXPECT_GT(shaded, 1500);
}

// A camera whose near plane cuts through the scene's first mesh, a sphere: triangles crossing it
// are clipped into pieces, and the inside shows through the hole.
Camera near_plane_through(const Scene& sphere) {
    const Bounds3f box = sphere.meshes[0].bounds;
    const glm::dvec3 center = glm::dvec3(box.center());
    const double radius = 0.5 * double(box.hi.x - box.lo.x);
    Camera cut;
    cut.eye = center + glm::dvec3(0.3 * radius, 0.2 * radius, 1.6 * radius);
    cut.target = center;
    cut.near = 0.9 * radius;
    cut.far = 10.0 * radius;
    return cut;
}

// With a normal target too, and alone: the SIMD path writes it from the normals its kernel
// interpolated.
void expect_simd_equals_scalar(const Scene& scene, RenderOptions o) {
    o.id_targets = true;
    for (const int targets : {0, 1, 2}) {  // color, color and normals, normals
        const bool normals = targets > 0;
        o.normal_target = normals;
        o.color_target = targets < 2;
        o.simd = false;
        const RenderResult scalar = render(scene, o);
        o.simd = true;
        const RenderResult simd = render(scene, o);
        EXPECT_EQ(simd.targets.color, scalar.targets.color);
        EXPECT_TRUE(same_bits(simd.targets.depth.data(), scalar.targets.depth.data(),
                              simd.targets.depth.size()));
        EXPECT_EQ(simd.targets.primitive_id, scalar.targets.primitive_id);
        ASSERT_EQ(simd.targets.normal.size(), normals ? scalar.targets.depth.size() : 0u);
        ASSERT_EQ(scalar.targets.normal.size(), simd.targets.normal.size());
        EXPECT_TRUE(same_bits(simd.targets.normal.data(), scalar.targets.normal.data(),
                              simd.targets.normal.size()))
            << "normals";
    }
}

void WholeFramesMatchTheScalarPath() {
    RenderOptions o;
    o.width = 320;
    o.height = 200;
    expect_simd_equals_scalar(make_procedural_scene("sphere:50000"), o);
    expect_simd_equals_scalar(make_procedural_scene("city:300"), o);
    o.cull = CullMode::None;
    o.depth_compare = CompareFunc::LessEqual;
    expect_simd_equals_scalar(make_procedural_scene("soup:20000"), o);
    o.camera = builtin_camera("builtin:default");
    o.cull = CullMode::Back;
    o.depth_compare.reset();
    expect_simd_equals_scalar(make_procedural_scene("builtin:default"), o);
    // Instances with rotation, non-uniform scale and translation: the SIMD vertex stage computes
    // their world attributes and the kernel interpolates them: the same bits as the scalar path.
    Scene scene = make_procedural_scene("sphere:20000");
    scene.instances[0].transform =
        glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.3f, -0.2f, 0.1f)), 0.7f,
                               glm::vec3(0.3f, 1.0f, 0.2f)),
                   glm::vec3(1.0f, 0.4f, 2.5f));
    Instance second = scene.instances[0];
    second.transform = glm::translate(glm::mat4(1.0f), glm::vec3(-1.5f, 0.5f, -1.0f));
    scene.instances.push_back(second);
    o.camera.reset();
    expect_simd_equals_scalar(scene, o);
    // The near plane through a sphere: its clipped pieces interpolate with their corner weights
    // (the kernel gets them through the bin entry's ref), the inside seen through the hole.
    const Scene sphere = make_procedural_scene("sphere:5000");
    o.camera = near_plane_through(sphere);
    o.cull = CullMode::None;
    const RenderResult clipped = render(sphere, o);
    ASSERT_GT(clipped.stats.triangles_clipped, 50u);
    expect_simd_equals_scalar(sphere, o);
}

// Forward (SIMD Phong fragments lit in the visibility kernel as they pass) and deferred shading
// give the same image; Auto says which it used.
void expect_forward_equals_deferred(const Scene& scene, RenderOptions o, bool overdraw) {
    o.id_targets = true;
    o.strategy = ShadingStrategy::Deferred;
    const RenderResult deferred = render(scene, o);
    o.strategy = ShadingStrategy::Forward;
    const RenderResult forward = render(scene, o);
    o.strategy = ShadingStrategy::Auto;
    const RenderResult automatic = render(scene, o);
    EXPECT_TRUE(deferred.stats.deferred);
    EXPECT_TRUE(automatic.stats.deferred);
    EXPECT_FALSE(forward.stats.deferred);
    EXPECT_GT(deferred.stats.fragments_shaded, 1000u);
    // Forward lights every fragment that passes, deferred each visible pixel once.
    EXPECT_EQ(forward.stats.fragments_shaded, forward.stats.fragments_passed);
    if (overdraw) {
        EXPECT_LT(deferred.stats.fragments_shaded, forward.stats.fragments_shaded);
    } else {
        EXPECT_LE(deferred.stats.fragments_shaded, forward.stats.fragments_shaded);
    }
    EXPECT_EQ(forward.targets.color, deferred.targets.color);
    EXPECT_EQ(automatic.targets.color, deferred.targets.color);
    EXPECT_EQ(forward.targets.primitive_id, deferred.targets.primitive_id);
    EXPECT_TRUE(same_bits(forward.targets.depth.data(), deferred.targets.depth.data(),
                          deferred.targets.depth.size()));
}

void ForwardEqualsDeferred() {
    RenderOptions o;
    o.width = 320;
    o.height = 200;
    expect_forward_equals_deferred(make_procedural_scene("sphere:300"), o, false);
    expect_forward_equals_deferred(make_procedural_scene("city:300"), o, true);
    o.cull = CullMode::None;  // back faces lit two-sided (flipped normals)
    o.two_sided_lighting = true;
    expect_forward_equals_deferred(make_procedural_scene("soup:20000"), o, true);
    // The near plane through the sphere: clipped triangles (pieces' weights), and the inside
    // seen through the hole (back faces, two-sided).
    const Scene sphere = make_procedural_scene("sphere:5000");
    o.camera = near_plane_through(sphere);
    expect_forward_equals_deferred(sphere, o, true);
    // A Gouraud instance among Phong ones: Forward takes the scalar path for the whole frame.
    Scene mixed = make_procedural_scene("sphere:5000");
    Instance second = mixed.instances[0];
    second.transform = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0.0f, -0.5f));
    second.shading = ShadingMode::Gouraud;
    mixed.instances.push_back(second);
    o.camera.reset();
    o.cull = CullMode::Back;
    expect_forward_equals_deferred(mixed, o, true);
}

// Each check on every instruction set this machine runs (AVX-512, AVX2, SSE4, ...), not only the
// best one: another machine may lack AVX-512.
// Triangles set up in lanes with a tile's window, their single jobs run by visibility_lanes
// (SIMD and scalar twin), against each job built from its TriangleSetup as the tile rasterizer
// builds a small triangle's one job and run by the scalar block kernel.
void VisibilityLanesRunTheSingleJobs() {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> center(-10.0, 74.0), offset(-6.0, 6.0);
    std::uniform_real_distribution<float> depth(0.0f, 1.0f), w(0.2f, 4.0f), attribute(-3.0f, 3.0f);
    SetupSettings settings;
    settings.viewport = {256, 256};
    settings.cull = CullMode::None;
    const JobWindow window{64, 128, 128, 192, 32};
    const PhongConstants lighting = test_lighting();
    const glm::vec3 piece[3] = {{0.7f, 0.2f, 0.1f}, {0.1f, 0.8f, 0.1f}, {0.3f, 0.3f, 0.4f}};
    auto simd_tile = cleared_tile(), scalar_tile = cleared_tile(), block_tile = cleared_tile();
    std::vector<CornerAttributes> corners(kSetupLanes);
    int singles = 0, others = 0;
    std::uint64_t passed = 0;
    for (int batch = 0; batch < 400; ++batch) {
        // Mostly small triangles around the window; some 20 times larger (not single jobs).
        VertexLanes in{};
        const int count = 1 + int(rng() % kSetupLanes);
        for (int lane = 0; lane < count; ++lane) {
            const double cx = window.x0 + center(rng), cy = window.y0 + center(rng);
            const double scale = rng() % 8 == 0 ? 20.0 : 1.0;
            for (int k = 0; k < 3; ++k) {
                ScreenVertex v;
                v.window_x = float(cx + scale * offset(rng));
                v.window_y = float(cy + scale * offset(rng));
                const auto snapped = snap_to_grid({v.window_x, v.window_y});
                v.x = std::int32_t(snapped[0]);
                v.y = std::int32_t(snapped[1]);
                v.z = depth(rng);
                v.inv_w = w(rng);
                in.set_vertex(k, lane, v);
            }
        }
        BlockJob shared;
        shared.compare = batch % 3 ? CompareFunc::Less : CompareFunc::GreaterEqual;
        shared.perspective = batch % 5 != 0;
        shared.write_depth = batch % 7 != 0;
        shared.attributes = shared.barycentrics = batch % 9 != 0;
        LaneJobs simd_jobs, scalar_jobs;
        SetupLanes simd_lanes, scalar_lanes;
        setup_lanes(in, count, settings, simd_lanes, &window);
        setup_lanes_scalar(in, count, settings, scalar_lanes, &window);
        simd_jobs.lanes = &simd_lanes;
        scalar_jobs.lanes = &scalar_lanes;
        for (int lane = 0; lane < count; ++lane) {
            CornerAttributes& a = corners[std::size_t(lane)];
            for (int k = 0; k < 3; ++k) {
                a.world[k] = {attribute(rng), attribute(rng), attribute(rng)};
                a.normal[k] = {attribute(rng), attribute(rng), attribute(rng)};
            }
            a.tag = (1 + std::uint32_t(rng() % 4)) | (rng() % 3 == 0 ? kShadeFlip : 0u);
            const int kind = int(rng() % 4);  // barycentrics, interpolated, piece, lit
            for (LaneJobs* jobs : {&simd_jobs, &scalar_jobs}) {
                jobs->ref[lane] = std::uint32_t(batch * kSetupLanes + lane);
                jobs->corners[lane] = kind == 0 ? nullptr : &a;
                jobs->piece[lane] = kind == 2 ? piece : nullptr;
                jobs->shade_constants[lane] = kind == 3 ? &lighting : nullptr;
            }
        }
        // Both twins, in runs of single jobs; the lanes that stop a run are left out.
        const auto run = [&](const auto& function, const LaneJobs& jobs, TileBuffers& tile) {
            std::vector<int> ran;
            std::uint64_t total = 0;
            for (int lane = 0; lane < count; ++lane) {
                const LaneJobsDone done = function(jobs, lane, count, shared, tile);
                for (int l = lane; l < done.next; ++l) ran.push_back(l);
                total += done.passed;
                lane = done.next;
            }
            return std::pair{ran, total};
        };
        const auto [simd_ran, simd_passed] = run(visibility_lanes, simd_jobs, *simd_tile);
        const auto [scalar_ran, scalar_passed] =
            run(visibility_lanes_scalar, scalar_jobs, *scalar_tile);
        ASSERT_EQ(simd_ran, scalar_ran) << batch;
        ASSERT_EQ(simd_passed, scalar_passed) << batch;
        // The same jobs from the setups.
        std::uint64_t block_passed = 0;
        for (const int lane : simd_ran) {
            TriangleSetup t;
            ASSERT_EQ(setup_triangle({in.vertex(0, lane), in.vertex(1, lane), in.vertex(2, lane)},
                                     settings, t),
                      SetupResult::Visible);
            BlockJob job = shared;
            const int x0 = std::max(t.min_x, window.x0), y0 = std::max(t.min_y, window.y0);
            const int x1 = std::min(t.max_x, window.x1 - 1), y1 = std::min(t.max_y, window.y1 - 1);
            for (std::size_t k = 0; k < 3; ++k) {
                job.e[k] = std::int32_t(t.edge_a[k] * x0 + t.edge_b[k] * y0 + t.edge_c[k]);
                job.step_x[k] = std::int32_t(t.edge_a[k]);
                job.step_y[k] = std::int32_t(t.edge_b[k]);
            }
            job.x0 = x0 - window.x0;
            job.y0 = y0 - window.y0;
            job.width = x1 - x0 + 1;
            job.height = y1 - y0 + 1;
            job.plane_dx = x0 - t.min_x;
            job.plane_dy = y0 - t.min_y;
            job.planes = {t.depth, t.q, t.p1, t.p2, t.l1, t.l2};
            job.ref = simd_jobs.ref[lane];
            job.corners = simd_jobs.corners[lane];
            job.piece = simd_jobs.piece[lane];
            job.shade_constants = simd_jobs.shade_constants[lane];
            block_passed += std::uint64_t(visibility_block_scalar(job, *block_tile));
        }
        ASSERT_EQ(simd_passed, block_passed) << batch;
        singles += int(simd_ran.size());
        others += count - int(simd_ran.size());
        passed += simd_passed;
    }
    EXPECT_GT(singles, 400);
    EXPECT_GT(others, 100);
    EXPECT_GT(passed, 5000u);
    expect_same_tiles(*simd_tile, *scalar_tile);
    expect_same_tiles(*simd_tile, *block_tile);
}

TEST(SimdKernels, VisibilityBlockMatchesScalarOnRandomTriangles) {
    test::on_every_simd_target(VisibilityBlockMatchesScalarOnRandomTriangles);
}

TEST(SimdKernels, VisibilityLanesRunTheSingleJobs) {
    test::on_every_simd_target(VisibilityLanesRunTheSingleJobs);
}

TEST(SimdKernels, PhongShadingMatchesScalarOnRandomInputs) {
    test::on_every_simd_target(PhongShadingMatchesScalarOnRandomInputs);
}

TEST(SimdKernels, TaggedRowShadingMatchesScalar) {
    test::on_every_simd_target(TaggedRowShadingMatchesScalar);
}

TEST(SimdKernels, WholeFramesMatchTheScalarPath) {
    test::on_every_simd_target(WholeFramesMatchTheScalarPath);
}

TEST(SimdKernels, ForwardShadingGivesTheDeferredImage) {
    test::on_every_simd_target(ForwardEqualsDeferred);
}

TEST(SimdKernels, BlockFarthestDepthMatchesScalar) {
    test::on_every_simd_target([] {
        std::mt19937 rng(3);
        std::uniform_real_distribution<float> depth(0.0f, 1.0f);
        auto tile = std::make_unique<TileBuffers>();
        for (int round = 0; round < 50; ++round) {
            for (float& d : tile->depth) d = depth(rng);
            for (int b = 0; b < 64; ++b)
                for (const bool largest : {true, false})
                    ASSERT_EQ(block_farthest_depth(*tile, b % 8, b / 8, largest),
                              block_farthest_depth_scalar(*tile, b % 8, b / 8, largest));
        }
    });
}

}  // namespace
}  // namespace zraster::detail
