// Depth: interpenetrating triangles resolve per pixel as a ray cast says; a 16-bit buffer at a
// far/near ratio of 10^4 shows z-fighting that D32F and reversed-Z do not.
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include "render/render_test_util.hpp"

namespace zraster::test {
namespace {

Camera camera_at_origin(double near, double far) {
    Camera c;
    c.eye = {0, 0, 0};
    c.target = {0, 0, -1};
    c.near = near;
    c.far = far;
    c.fovy_degrees = 50;
    return c;
}

TEST(Depth, InterpenetratingTrianglesResolvePerPixelLikeARayCast) {
    // Two large triangles crossing each other along a slanted line, plus a third piercing both.
    const std::vector<std::vector<glm::vec3>> tris{
        {{-3, -2, -6}, {3, -2, -4}, {0, 3, -5}},
        {{-3, -2, -4}, {3, -2, -6}, {0, 3, -5.5f}},
        {{-2, 0.5f, -3}, {2, 0.5f, -3}, {0, -0.5f, -8}},
    };
    const Camera camera = camera_at_origin(0.5, 20);
    constexpr int W = 200, H = 150;
    RenderOptions o;
    o.width = W;
    o.height = H;
    o.camera = camera;
    o.cull = CullMode::None;
    o.id_targets = true;
    o.color_target = false;
    const auto r = render(scene_from_triangles(tris), o);
    RayCaster caster(camera, W, H);
    int wrong = 0, compared = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const PixelRay ray = caster.ray(x, y);
            int nearest = -1;
            double best = 1e300, second = 1e300;
            bool ambiguous = false;
            for (int i = 0; i < 3; ++i) {
                const auto& t = tris[std::size_t(i)];
                const auto hit = caster.intersect(ray, t[0], t[1], t[2]);
                if (!hit) continue;
                const double lo = std::min({hit->bary.x, hit->bary.y, hit->bary.z});
                if (std::abs(lo) < 1e-4) ambiguous = true;
                if (lo < 0) continue;
                if (hit->t < best) {
                    second = best;
                    best = hit->t;
                    nearest = i;
                } else {
                    second = std::min(second, hit->t);
                }
            }
            // Where two surfaces are within 1e-4 units, float depth cannot decide: skip.
            if (ambiguous || second - best < 1e-4) continue;
            ++compared;
            wrong += r.targets.instance_id[std::size_t(y * W + x)] != nearest;
        }
    EXPECT_GT(compared, 15000);
    EXPECT_EQ(wrong, 0);
}

// Two parallel quads 1 unit apart at distance ~500 with near = 0.1, far = 1000 (ratio 10^4);
// the nearer one is drawn second... and first: count pixels where the farther one wins.
int wrongly_ordered_pixels(DepthFormat format, bool reversed_z) {
    auto quad = [](float z) {
        return std::vector<glm::vec3>{{-400, -300, z}, {400, -300, z}, {400, 300, z},
                                      {-400, -300, z}, {400, 300, z},  {-400, 300, z}};
    };
    Camera camera = camera_at_origin(0.1, 1000);
    camera.reversed_z = reversed_z;
    RenderOptions o;
    o.width = 160;
    o.height = 120;
    o.camera = camera;
    o.depth_format = format;
    o.id_targets = true;
    o.color_target = false;
    int wrong = 0;
    // Submission order both ways: z-fighting shows up whichever comes first.
    for (int order = 0; order < 2; ++order) {
        const auto near_quad = quad(-500.0f), far_quad = quad(-501.0f);
        Scene scene = order == 0 ? scene_from_triangles({far_quad, near_quad})
                                 : scene_from_triangles({near_quad, far_quad});
        const auto r = render(scene, o);
        const int near_instance = order == 0 ? 1 : 0;
        for (const std::int32_t id : r.targets.instance_id) wrong += id != near_instance;
    }
    return wrong;
}

TEST(Depth, D16ZFightsAtRatio1e4WhereD32FAndReversedZDoNot) {
    const int d16 = wrongly_ordered_pixels(DepthFormat::D16, false);
    const int d24 = wrongly_ordered_pixels(DepthFormat::D24, false);
    const int d32 = wrongly_ordered_pixels(DepthFormat::D32F, false);
    const int reversed = wrongly_ordered_pixels(DepthFormat::D32F, true);
    EXPECT_GT(d16, 160 * 120 / 2) << "16 bits cannot separate 500 from 501 at near 0.1";
    EXPECT_LT(d16, 2 * 160 * 120) << "16 bits draws the quads (in submission order)";
    EXPECT_EQ(d24, 0) << "24 bits separate them (about 7 steps apart)";
    EXPECT_EQ(d32, 0);
    EXPECT_EQ(reversed, 0);
    RecordProperty("wrong_d16", d16);
    RecordProperty("wrong_d24", d24);
}

// Every depth format draws the same surfaces where depths are far apart: a sphere (no surface
// behind another after back-face culling) gives D32F's ids, and depths within a step of its.
TEST(Depth, UnormFormatsDrawWhatD32FDraws) {
    const Scene sphere = make_procedural_scene("sphere:20000");
    RenderOptions o;
    o.width = 200;
    o.height = 150;
    o.threads = 2;
    o.id_targets = true;
    const RenderResult d32 = render(sphere, o);
    ASSERT_GT(d32.stats.fragments_passed, 5000u);
    for (const DepthFormat format : {DepthFormat::D24, DepthFormat::D16}) {
        for (const bool simd : {true, false}) {
            SCOPED_TRACE(std::string(format == DepthFormat::D24 ? "D24" : "D16") +
                         (simd ? " SIMD" : " scalar"));
            o.depth_format = format;
            o.simd = simd;
            const RenderResult r = render(sphere, o);
            EXPECT_EQ(r.stats.fragments_passed, d32.stats.fragments_passed);
            EXPECT_EQ(r.targets.instance_id, d32.targets.instance_id);
            EXPECT_EQ(r.targets.primitive_id, d32.targets.primitive_id);
            const double step = format == DepthFormat::D24 ? 1.0 / 16777215 : 1.0 / 65535;
            for (std::size_t i = 0; i < r.targets.depth.size(); ++i)
                ASSERT_NEAR(r.targets.depth[i], d32.targets.depth[i], step) << "pixel " << i;
        }
    }
}

TEST(Depth, CompareFunctionsAndWriteMask) {
    // Two coincident-depth quads: LESS keeps the first, LEQUAL the second; with depth writes off
    // the second always wins with LESS against the cleared buffer.
    const std::vector<glm::vec3> q{{-1, -1, -3}, {1, -1, -3}, {0, 1, -3}};
    Scene scene = scene_from_triangles({q, q});
    RenderOptions o;
    o.width = 32;
    o.height = 32;
    o.camera = camera_at_origin(0.5, 10);
    o.id_targets = true;
    o.color_target = false;
    auto center_id = [&](const RenderOptions& opt) {
        return render(scene, opt).targets.instance_id[16 * 32 + 16];
    };
    o.depth_compare = CompareFunc::Less;
    EXPECT_EQ(center_id(o), 0);
    o.depth_compare = CompareFunc::LessEqual;
    EXPECT_EQ(center_id(o), 1);
    o.depth_compare = CompareFunc::Never;
    EXPECT_EQ(center_id(o), -1);
    o.depth_compare = CompareFunc::Less;
    o.depth_write = false;
    EXPECT_EQ(center_id(o), 1);
    o.depth_write = true;
    o.depth_test = false;
    EXPECT_EQ(center_id(o), 1);
}

TEST(Depth, DepthOutputIsWindowDepthOfTheOpenGLProjection) {
    // A quad facing the camera at z_eye = -d has window depth 0.5 * ndc_z + 0.5 with
    // ndc_z = (f + n)/(f - n) - 2fn / ((f - n) d).
    const double n = 1, f = 100, d = 10;
    const std::vector<glm::vec3> q{{-50, -50, float(-d)}, {50, -50, float(-d)}, {0, 50, float(-d)}};
    RenderOptions o;
    o.width = 16;
    o.height = 16;
    o.camera = camera_at_origin(n, f);
    const auto r = render(scene_from_triangles({q}), o);
    const double ndc = (f + n) / (f - n) - 2 * f * n / ((f - n) * d);
    EXPECT_NEAR(r.targets.depth[8 * 16 + 8], 0.5 * ndc + 0.5, 1e-6);
    // Reversed-Z: window depth = n (f - d) / ((f - n) d): near -> 1, far -> 0; cleared to 0.
    o.camera->reversed_z = true;
    const auto rr = render(scene_from_triangles({q}), o);
    EXPECT_NEAR(rr.targets.depth[8 * 16 + 8], n * (f - d) / ((f - n) * d), 1e-6);
}

}  // namespace
}  // namespace zraster::test
