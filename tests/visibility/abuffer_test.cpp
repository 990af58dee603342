// The A-buffer (Carpenter 1984, "The A-buffer, an antialiased hidden surface method") and
// supersampling of the z-buffer path: order-independent transparency against a sorted-by-depth
// reference blend, edge coverage against a 256-sample reference of the exact triangle, exact
// partition of the subsamples by adjacent polygons, fragment counts on cases with a known answer,
// and the fragment limit.
//
// Cost: a few 64 x 64 frames (one at 256 x 256 for 4x4 supersampling); well under a second.
#include <zraster/abuffer.hpp>
#include <zraster/error.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include <zraster/image_io.hpp>
#include <zraster/load.hpp>

#include "support/test_support.hpp"
#include "visibility/visibility_test_util.hpp"

namespace zraster::test {
namespace {

constexpr int kSize = 64;

// Orthographic camera on +z: world (x, y) lands on window (x + 32, 32 - y) exactly (the scale is
// 1/32 in clip space, a power of two), so the tests know each polygon's window position.
RenderOptions ortho_options() {
    RenderOptions o;
    o.width = kSize;
    o.height = kSize;
    o.threads = 1;
    Camera c;
    c.eye = {0.0, 0.0, 8.0};
    c.target = {0.0, 0.0, 0.0};
    c.projection = Camera::Projection::Orthographic;
    c.ortho_height = kSize;
    c.near = 1.0;
    c.far = 20.0;
    o.camera = c;
    return o;
}

// render()'s quantization of a color channel in [0, 1] (float, times 255, plus one half,
// truncated), which the A-buffer shares.
int unorm8(double v) {
    const float f = std::clamp(float(v), 0.0f, 1.0f);
    return int(f * 255.0f + 0.5f);
}

glm::dvec2 to_window(const glm::vec3& p) {
    return {double(p.x) + kSize / 2, kSize / 2 - double(p.y)};
}

// A convex polygon (counter-clockwise seen from +z) as a fan of triangles at depth z.
std::vector<glm::vec3> fan(const std::vector<glm::vec2>& ring, float z) {
    std::vector<glm::vec3> out;
    for (std::size_t k = 1; k + 1 < ring.size(); ++k)
        for (std::size_t c : {std::size_t{0}, k, k + 1}) out.emplace_back(ring[c], z);
    return out;
}

// Is the window point strictly inside the convex window polygon (either winding), by `margin`?
bool inside_convex(const std::vector<glm::dvec2>& poly, glm::dvec2 p, double margin) {
    int sign = 0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const glm::dvec2 a = poly[i], b = poly[(i + 1) % poly.size()];
        const glm::dvec2 d = b - a;
        const double cross = (d.x * (p.y - a.y) - d.y * (p.x - a.x)) / glm::length(d);
        if (std::abs(cross) <= margin) return false;
        const int s = cross > 0 ? 1 : -1;
        if (sign != 0 && s != sign) return false;
        sign = s;
    }
    return true;
}

bool pixel_inside(const std::vector<glm::dvec2>& poly, int px, int py) {
    for (int c = 0; c < 4; ++c)
        if (!inside_convex(poly, {px + (c & 1), py + (c >> 1)}, 1e-9)) return false;
    return true;
}

std::vector<glm::dvec2> window_ring(const std::vector<glm::vec2>& ring) {
    std::vector<glm::dvec2> out;
    for (const glm::vec2& p : ring) out.push_back(to_window(glm::vec3(p, 0.0f)));
    return out;
}

// ---------------------------------------------------------------------------------------------
// (a) Order-independent transparency.

struct Layer {
    std::vector<glm::vec2> ring;
    float z;
    glm::vec3 color;
    float opacity;
};

const std::array<Layer, 3> kLayers = {{
    // Far, opaque.
    {{{-20, -14}, {12, -14}, {12, 10}, {-20, 10}}, -1.0f, {0.9f, 0.2f, 0.1f}, 1.0f},
    // Middle, half transparent.
    {{{-12.3f, -6.6f}, {20.2f, -6.6f}, {20.2f, 18.4f}, {-12.3f, 18.4f}},
     0.0f,
     {0.1f, 0.8f, 0.3f},
     0.5f},
    // Near, a slanted parallelogram, mostly transparent.
    {{{-6, -20}, {10, -16}, {6, 6}, {-10, 2}}, 1.0f, {0.2f, 0.3f, 0.9f}, 0.35f},
}};

// The layers submitted in the given order (one mesh, material and instance each).
Scene layered_scene(const std::array<int, 3>& order) {
    std::vector<std::vector<glm::vec3>> meshes;
    for (int k : order)
        meshes.push_back(fan(kLayers[std::size_t(k)].ring, kLayers[std::size_t(k)].z));
    Scene scene = scene_from_triangles(meshes);
    scene.materials.resize(1);
    for (std::size_t i = 0; i < 3; ++i) {
        const Layer& layer = kLayers[std::size_t(order[i])];
        Material m;
        m.base_color = layer.color;
        m.opacity = layer.opacity;
        scene.materials.push_back(m);
        scene.meshes[i].material = std::uint32_t(scene.materials.size() - 1);
    }
    return scene;
}

// Materials' alpha modes, per polygon: Opaque ignores the opacity, Mask keeps or drops the
// whole polygon by its opacity against the cutoff, --alpha-mode opaque draws all opaque.
TEST(ABuffer, AlphaModesPerPolygon) {
    RenderOptions options = ortho_options();
    options.shading = ShadingMode::Unlit;
    const auto colors = [&](const Scene& scene, const RenderOptions& o) {
        return render_abuffer(scene, o, {}).targets.color;
    };
    Scene all_opaque = layered_scene({0, 1, 2});
    for (Material& m : all_opaque.materials) m.opacity = 1.0f;
    Scene scene = layered_scene({0, 1, 2});
    for (Material& m : scene.materials) m.alpha_mode = AlphaMode::Opaque;
    EXPECT_EQ(colors(scene, options), colors(all_opaque, options));
    RenderOptions opaque_mode = options;
    opaque_mode.alpha_mode = MaterialAlpha::Opaque;
    EXPECT_EQ(colors(layered_scene({0, 1, 2}), opaque_mode), colors(all_opaque, options));

    // The middle layer (opacity 0.5) as a cut-out: gone under a cutoff of 0.6, opaque at 0.4.
    scene = layered_scene({0, 1, 2});
    Scene without_middle = scene;
    without_middle.instances.erase(without_middle.instances.begin() + 1);
    scene.materials[2].alpha_mode = AlphaMode::Mask;
    scene.materials[2].alpha_cutoff = 0.6f;
    EXPECT_EQ(colors(scene, options), colors(without_middle, options));
    scene.materials[2].alpha_cutoff = 0.4f;
    Scene middle_opaque = layered_scene({0, 1, 2});
    middle_opaque.materials[2].opacity = 1.0f;
    EXPECT_EQ(colors(scene, options), colors(middle_opaque, options));
}

TEST(ABuffer, TransparencyIsIndependentOfSubmissionOrderAndMatchesSortedBlend) {
    RenderOptions options = ortho_options();
    options.shading = ShadingMode::Unlit;  // colors = base colors, for the reference blend
    options.background = {0.25f, 0.5f, 0.75f};
    std::array<int, 3> order = {0, 1, 2};
    std::vector<std::uint8_t> first;
    int orders = 0;
    do {
        ABufferStats stats;
        const RenderResult r = render_abuffer(layered_scene(order), options, {}, &stats);
        if (first.empty())
            first = r.targets.color;
        else
            EXPECT_EQ(r.targets.color, first) << "order " << order[0] << order[1] << order[2];
        EXPECT_GE(stats.max_list_length, 3u);
        ++orders;
    } while (std::next_permutation(order.begin(), order.end()));
    EXPECT_EQ(orders, 6);

    // Reference: pixels entirely inside all three layers; blend far to near with "over".
    std::array<std::vector<glm::dvec2>, 3> rings;
    for (std::size_t k = 0; k < 3; ++k) rings[k] = window_ring(kLayers[k].ring);
    glm::dvec3 expected(options.background);
    for (const Layer& layer : kLayers)  // listed far to near
        expected = double(layer.opacity) * glm::dvec3(layer.color) +
                   (1.0 - double(layer.opacity)) * expected;
    int checked = 0;
    for (int py = 0; py < kSize; ++py)
        for (int px = 0; px < kSize; ++px) {
            if (!pixel_inside(rings[0], px, py) || !pixel_inside(rings[1], px, py) ||
                !pixel_inside(rings[2], px, py))
                continue;
            ++checked;
            for (int c = 0; c < 3; ++c) {
                const double v = expected[c] * 255.0;
                const int got = first[(std::size_t(py) * kSize + std::size_t(px)) * 4 + c];
                // Exact unless the reference lies within rounding of a quantization boundary.
                const bool boundary = std::abs(v - std::floor(v) - 0.5) < 1e-4;
                if (boundary)
                    EXPECT_LE(std::abs(got - unorm8(expected[c])), 1);
                else
                    EXPECT_EQ(got, unorm8(expected[c])) << px << "," << py << " channel " << c;
            }
        }
    EXPECT_GT(checked, 100);

    // Only the opaque layer and the background: the opaque color, whatever lies behind.
    const int px = 14, py = 44;  // window (14.5, 44.5) = world (-17.5, -12.5): layer 0 only
    ASSERT_TRUE(pixel_inside(rings[0], px, py));
    ASSERT_FALSE(inside_convex(rings[1], {px + 0.5, py + 0.5}, 0.0));
    ASSERT_FALSE(inside_convex(rings[2], {px + 0.5, py + 0.5}, 0.0));
    for (int c = 0; c < 3; ++c)
        EXPECT_EQ(first[(std::size_t(py) * kSize + px) * 4 + std::size_t(c)],
                  unorm8(kLayers[0].color[c]));
}

TEST(ABuffer, CoplanarTransparentSurfacesDoNotDependOnOrder) {
    // Equal depths everywhere: the order falls to the fragments' content, not to submission.
    const std::vector<glm::vec3> a = fan({{-20, -10}, {10, -10}, {10, 15}, {-20, 15}}, 0.0f);
    const std::vector<glm::vec3> b = fan({{-5, -18}, {22, -18}, {22, 5}, {-5, 5}}, 0.0f);
    auto make = [&](bool swapped) {
        Scene scene = scene_from_triangles(swapped ? std::vector{b, a} : std::vector{a, b});
        Material red, green;
        red.base_color = {1.0f, 0.1f, 0.1f};
        red.opacity = 0.6f;
        green.base_color = {0.1f, 1.0f, 0.1f};
        green.opacity = 0.3f;
        scene.materials = {Material{}, swapped ? green : red, swapped ? red : green};
        scene.meshes[0].material = 1;
        scene.meshes[1].material = 2;
        return scene;
    };
    RenderOptions options = ortho_options();
    options.shading = ShadingMode::Unlit;
    const RenderResult first = render_abuffer(make(false), options);
    const RenderResult second = render_abuffer(make(true), options);
    EXPECT_EQ(first.targets.color, second.targets.color);
    // And the overlap is really a blend of both: neither color alone.
    const std::size_t p = (std::size_t(32 - 0) * kSize + std::size_t(32 + 2)) * 4;
    EXPECT_NE(first.targets.color[p], 255);
    EXPECT_NE(first.targets.color[p + 1], 255);
}

TEST(ABuffer, BitIdenticalForAnyThreadCount) {
    RenderOptions options = ortho_options();
    const Scene scene = layered_scene({2, 0, 1});
    const RenderResult one = render_abuffer(scene, options);
    options.threads = 2;
    const RenderResult two = render_abuffer(scene, options);
    EXPECT_EQ(one.targets.color, two.targets.color);
    EXPECT_EQ(one.targets.depth, two.targets.depth);
}

// ---------------------------------------------------------------------------------------------
// (b) Edge coverage against 256 point samples of the exact triangle.

const std::vector<glm::vec3> kSlanted = {
    {-23.3f, -17.1f, 0.0f}, {21.7f, -9.4f, 0.0f}, {-4.6f, 25.2f, 0.0f}};

// A black, unlit-looking (no specular) triangle over a white background.
Scene black_triangle_scene() {
    Scene scene = scene_from_triangles({kSlanted});
    Material m;
    m.base_color = glm::vec3(0.0f);
    m.specular = glm::vec3(0.0f);
    scene.materials.push_back(m);
    scene.meshes[0].material = 1;
    return scene;
}

struct CoverageError {
    double mean_edge = 0;  // mean |error| over pixels the reference covers partly
    double max = 0;        // max |error| over all pixels
    int edge_pixels = 0;
};

// Coverage measured from the resolved color (black over white: coverage = 1 - value / 255,
// within 0.5 / 255 of quantization) against 16 x 16 point samples of the exact window triangle.
CoverageError coverage_error(const RenderTargets& image) {
    std::vector<glm::dvec2> tri;
    for (const glm::vec3& p : kSlanted) tri.push_back(to_window(p));
    CoverageError e;
    double sum = 0;
    for (int py = 0; py < kSize; ++py)
        for (int px = 0; px < kSize; ++px) {
            int inside = 0;
            for (int j = 0; j < 16; ++j)
                for (int i = 0; i < 16; ++i)
                    inside += inside_convex(tri, {px + (i + 0.5) / 16, py + (j + 0.5) / 16}, 0.0);
            const double reference = inside / 256.0;
            const double value = image.color[(std::size_t(py) * kSize + std::size_t(px)) * 4];
            const double error = std::abs((1.0 - value / 255.0) - reference);
            e.max = std::max(e.max, error);
            if (inside > 0 && inside < 256) {
                sum += error;
                ++e.edge_pixels;
            }
        }
    e.mean_edge = e.edge_pixels ? sum / e.edge_pixels : 0.0;
    return e;
}

TEST(ABuffer, EdgeCoverageMatchesA256SampleReference) {
    RenderOptions options = ortho_options();
    options.shading = ShadingMode::Flat;
    options.background = glm::vec3(1.0f);
    const Scene scene = black_triangle_scene();

    const CoverageError abuf = coverage_error(render_abuffer(scene, options).targets);
    const CoverageError ssaa = coverage_error(render_supersampled(scene, options, 4).targets);
    const CoverageError aliased = coverage_error(render_supersampled(scene, options, 1).targets);
    const CoverageError msaa = coverage_error(render_multisampled(scene, options, 4).targets);
    EXPECT_LE(msaa.mean_edge, 1.0 / 16);
    EXPECT_LE(msaa.max, 1.0 / 8);
    std::printf("MSAA 4x4: %.4f / %.4f\n", msaa.mean_edge, msaa.max);
    std::printf(
        "edge pixels %d; |coverage error| mean / max: A-buffer 4x4 %.4f / %.4f, SSAA 4x4 "
        "%.4f / %.4f, no AA %.4f / %.4f\n",
        abuf.edge_pixels, abuf.mean_edge, abuf.max, ssaa.mean_edge, ssaa.max, aliased.mean_edge,
        aliased.max);
    ASSERT_GT(abuf.edge_pixels, 100);
    // 16 point samples per pixel: a straight edge misclassifies at most a fraction of a sample
    // row/column; measured 0.020 mean and 0.056 max here (SSAA 4x4: the same).
    EXPECT_LE(abuf.mean_edge, 1.0 / 16);
    EXPECT_LE(abuf.max, 1.0 / 8);
    EXPECT_LE(ssaa.mean_edge, 1.0 / 16);
    EXPECT_LE(ssaa.max, 1.0 / 8);
    // Without antialiasing edge pixels are all or nothing: measured 0.197 mean, 0.5 max.
    EXPECT_GT(aliased.mean_edge, 0.15);
    EXPECT_GT(aliased.max, 0.4);
}

// ---------------------------------------------------------------------------------------------
// (c) Adjacent polygons partition the samples.

TEST(ABuffer, AdjacentPolygonsPartitionTheSamples) {
    // A fan of 7 triangles around an off-center vertex: every interior edge is shared.
    std::vector<glm::vec2> ring;
    for (int k = 0; k < 7; ++k) {
        const double a = 0.3 + 2.0 * 3.14159265358979 * k / 7.0;
        ring.emplace_back(float(27.3 * std::cos(a)), float(21.9 * std::sin(a)));
    }
    const glm::vec2 center(1.37f, -2.11f);
    std::vector<glm::vec3> triangles;
    for (std::size_t k = 0; k < ring.size(); ++k)
        for (const glm::vec2& p : {center, ring[k], ring[(k + 1) % ring.size()]})
            triangles.emplace_back(p, 0.0f);
    const Scene scene = scene_from_triangles({triangles});
    RenderOptions options = ortho_options();
    const std::vector<ScreenPolygon> polygons = project_scene(scene, options);
    ASSERT_EQ(polygons.size(), 7u);
    const std::vector<glm::dvec2> hull = window_ring(ring);

    for (int n : {1, 2, 4, 8}) {
        const std::uint64_t full = n == 8 ? ~std::uint64_t{0} : (std::uint64_t{1} << (n * n)) - 1;
        std::vector<std::uint64_t> covered(std::size_t(kSize) * kSize, 0);
        std::size_t fragments = 0, double_covered = 0;
        for (const ScreenPolygon& p : polygons)
            for (const PixelCoverage& c : polygon_coverage(p, {kSize, kSize}, n)) {
                std::uint64_t& acc = covered[std::size_t(c.y) * kSize + std::size_t(c.x)];
                double_covered += (acc & c.mask) != 0;
                acc |= c.mask;
                ++fragments;
            }
        EXPECT_EQ(double_covered, 0u) << n;
        int interior = 0, missed = 0;
        for (int py = 0; py < kSize; ++py)
            for (int px = 0; px < kSize; ++px)
                if (pixel_inside(hull, px, py)) {
                    ++interior;
                    missed += covered[std::size_t(py) * kSize + std::size_t(px)] != full;
                }
        EXPECT_GT(interior, 1000);
        EXPECT_EQ(missed, 0) << n;
        if (n == 1) {
            // One sample at the pixel center: exactly the pixels render() fills, triangle by
            // triangle (its per-pixel fragment counts with the depth test off).
            RenderOptions counting = options;
            counting.depth_test = false;
            counting.coverage_counts = true;
            const RenderResult r = render(scene, counting);
            std::vector<std::uint32_t> hits(covered.size(), 0);
            for (const ScreenPolygon& p : polygons)
                for (const PixelCoverage& c : polygon_coverage(p, {kSize, kSize}, 1))
                    ++hits[std::size_t(c.y) * kSize + std::size_t(c.x)];
            EXPECT_EQ(hits, r.targets.front_hits);
            EXPECT_EQ(fragments, r.stats.fragments_passed);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// (d) Fragment counts on known cases; (e) the fragment limit.

// A quad (two triangles, diagonal from its bottom-left to its top-right corner) at window
// x in [8, 24] and y in [y0, y1].
Scene window_quad(double y0, double y1) {
    const float top = float(kSize / 2 - y0), bottom = float(kSize / 2 - y1);
    return scene_from_triangles({fan({{-24, bottom}, {-8, bottom}, {-8, top}, {-24, top}}, 0)});
}

ABufferStats count(const Scene& scene, int n) {
    ABufferOptions a;
    a.samples_per_side = n;
    ABufferStats stats;
    render_abuffer(scene, ortho_options(), a, &stats);
    return stats;
}

TEST(ABuffer, FragmentCountsOnKnownCases) {
    // Pixel-aligned 16 x 16 square: 256 pixels. Its diagonal x + y = 32 runs through pixel
    // corners across the 16 pixels with px + py = 31; there the samples with i + j = 3 (n = 4) or
    // i + j = 1 (n = 2) lie on the diagonal and samples on both sides remain, so both triangles
    // leave a fragment: 256 + 16. With one sample (the center, on the diagonal) exactly one does.
    const Scene square = window_quad(8, 24);
    for (int n : {2, 4, 8}) {
        const ABufferStats s = count(square, n);
        EXPECT_EQ(s.fragments, 272u) << n;
        EXPECT_EQ(s.pixels_with_fragments, 256u) << n;
        EXPECT_EQ(s.max_list_length, 2u) << n;
    }
    const ABufferStats one = count(square, 1);
    EXPECT_EQ(one.fragments, 256u);
    EXPECT_EQ(one.pixels_with_fragments, 256u);
    EXPECT_EQ(one.max_list_length, 1u);

    // Shifted down half a pixel (y in [8.5, 24.5]): rows 8..24 each hold covered samples, 17 x 16
    // = 272 pixels; the diagonal x + y = 32.5 crosses the pixels with px + py = 31 and 32 (16
    // each) with samples on both sides: 272 + 32 fragments. One sample per pixel: rows 8..23 (the
    // bottom edge through row 24's centers is not a top edge), 256.
    const Scene shifted = window_quad(8.5, 24.5);
    const ABufferStats s4 = count(shifted, 4);
    EXPECT_EQ(s4.fragments, 304u);
    EXPECT_EQ(s4.pixels_with_fragments, 272u);
    EXPECT_EQ(s4.max_list_length, 2u);
    EXPECT_EQ(count(shifted, 1).fragments, 256u);

    // Both quads at once (equal depth, so overlapping): fragments add up.
    Scene both = window_quad(8, 24);
    both.meshes.push_back(window_quad(8.5, 24.5).meshes[0]);
    both.instances.push_back(Instance{1, glm::mat4(1.0f), std::nullopt, ""});
    const ABufferStats sum = count(both, 4);
    EXPECT_EQ(sum.fragments, 272u + 304u);
    EXPECT_EQ(sum.pixels_with_fragments, 272u);
    EXPECT_EQ(sum.max_list_length, 4u);  // diagonal pixels of both
}

TEST(ABuffer, FragmentLimitIsAClearInputError) {
    const Scene square = window_quad(8, 24);
    ABufferOptions a;
    a.max_fragments = 272;
    EXPECT_NO_THROW(render_abuffer(square, ortho_options(), a));
    a.max_fragments = 271;
    try {
        render_abuffer(square, ortho_options(), a);
        FAIL() << "expected LimitExceeded";
    } catch (const LimitExceeded& e) {
        EXPECT_EQ(e.limit(), "max_abuffer_fragments");
        EXPECT_NE(std::string(e.what()).find("A-buffer: more than 271 fragments"),
                  std::string::npos)
            << e.what();
    }
    a.max_fragments = 1000;
    a.samples_per_side = 3;
    EXPECT_THROW(render_abuffer(square, ortho_options(), a), InputError);
    EXPECT_THROW(render_supersampled(square, ortho_options(), 0), InputError);
    EXPECT_THROW(render_supersampled(square, ortho_options(), 1000), InputError);
}

TEST(Supersample, BoxFilterIsTheExactRoundedMean) {
    // factor 1 is render(); factor 2 averages 2 x 2 blocks of the big frame.
    RenderOptions options = ortho_options();
    const Scene scene = black_triangle_scene();
    EXPECT_EQ(render_supersampled(scene, options, 1).targets.color,
              render(scene, options).targets.color);
    RenderOptions big = options;
    big.width = big.height = 2 * kSize;
    const RenderResult b = render(scene, big);
    const RenderResult s = render_supersampled(scene, options, 2);
    for (int py = 0; py < kSize; ++py)
        for (int px = 0; px < kSize; ++px)
            for (int c = 0; c < 4; ++c) {
                int sum = 0;
                for (int j = 0; j < 2; ++j)
                    for (int i = 0; i < 2; ++i)
                        sum += b.targets.color[(std::size_t(2 * py + j) * 2 * kSize +
                                                std::size_t(2 * px + i)) *
                                                   4 +
                                               std::size_t(c)];
                ASSERT_EQ(
                    s.targets
                        .color[(std::size_t(py) * kSize + std::size_t(px)) * 4 + std::size_t(c)],
                    (sum + 2) / 4);
            }
}

// ---------------------------------------------------------------------------------------------
// (f) Shading: the A-buffer and supersampling shade as the z-buffer does (modes, lighting,
// textures, perspective-correct attributes); on opaque scenes only edge pixels differ.

struct ShadingAgreement {
    std::size_t interior = 0;        // pixels whose 3x3 neighbourhood shows one triangle
    std::size_t interior_equal = 0;  // of which identical in all channels
    int interior_max = 0;            // largest channel difference there
    double interior_mean = 0;        // mean channel difference there
    std::size_t edge = 0;            // the other pixels
    double edge_mean = 0;            // mean channel difference there
};

// `reference` is render()'s frame with id targets.
ShadingAgreement compare_shading(const RenderTargets& reference, const RenderTargets& other) {
    ShadingAgreement a;
    const int w = reference.width, h = reference.height;
    auto id = [&](int x, int y) {
        const std::size_t p = std::size_t(y) * std::size_t(w) + std::size_t(x);
        return std::pair(reference.instance_id[p], reference.primitive_id[p]);
    };
    double interior_sum = 0, edge_sum = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            bool interior = id(x, y).first >= 0 && x > 0 && y > 0 && x + 1 < w && y + 1 < h;
            for (int dy = -1; dy <= 1 && interior; ++dy)
                for (int dx = -1; dx <= 1 && interior; ++dx)
                    interior = id(x + dx, y + dy) == id(x, y);
            int max = 0, sum = 0;
            for (std::size_t c = 0; c < 3; ++c) {
                const std::size_t i = (std::size_t(y) * std::size_t(w) + std::size_t(x)) * 4 + c;
                const int d = std::abs(int(reference.color[i]) - int(other.color[i]));
                max = std::max(max, d);
                sum += d;
            }
            if (interior) {
                ++a.interior;
                a.interior_equal += max == 0;
                a.interior_max = std::max(a.interior_max, max);
                interior_sum += sum / 3.0;
            } else {
                ++a.edge;
                edge_sum += sum / 3.0;
            }
        }
    a.interior_mean = a.interior ? interior_sum / double(a.interior) : 0.0;
    a.edge_mean = a.edge ? edge_sum / double(a.edge) : 0.0;
    return a;
}

void print(const char* label, const ShadingAgreement& a) {
    std::printf(
        "%s: interior %zu pixels, %zu identical (%.3f%%), max diff %d, mean %.4f; edge "
        "%zu pixels, mean diff %.3f\n",
        label, a.interior, a.interior_equal,
        100.0 * double(a.interior_equal) / double(std::max<std::size_t>(a.interior, 1)),
        a.interior_max, a.interior_mean, a.edge, a.edge_mean);
}

// The built-in default scene: a mipmapped, trilinear-filtered checkerboard ground under Phong
// lighting, and spheres with flat, Gouraud and Phong shading (instance overrides).
TEST(ABufferShading, OpaqueTexturedSceneMatchesTheZBufferInside) {
    const Scene scene = make_procedural_scene("builtin:default");
    RenderOptions options = id_options(240, 160);
    const RenderResult reference = render(scene, options);
    for (const Interpolation interpolation :
         {Interpolation::PerspectiveCorrect, Interpolation::ScreenLinear}) {
        RenderOptions o = options;
        o.interpolation = interpolation;
        const RenderResult z = render(scene, o);
        const RenderResult a = render_abuffer(scene, o);
        const ShadingAgreement agreement = compare_shading(z.targets, a.targets);
        const ShadingAgreement msaa =
            compare_shading(z.targets, render_multisampled(scene, o, 4).targets);
        print("MSAA 4x4 vs z-buffer", msaa);
        EXPECT_EQ(msaa.interior_equal, msaa.interior);
        EXPECT_LT(msaa.edge_mean, 12.0);
        print(interpolation == Interpolation::PerspectiveCorrect ? "A-buffer 4x4 vs z-buffer"
                                                                 : "A-buffer, screen-linear",
              agreement);
        ASSERT_GT(agreement.interior, 3000u);
        // A pixel covered whole by one opaque triangle is shaded at its center, as render()
        // shades it: bit for bit. (A nearer sliver that covers subsamples but no pixel center of
        // the 3x3 neighbourhood would be a legitimate difference; there is none here.)
        EXPECT_EQ(agreement.interior_equal, agreement.interior);
        // Edges: antialiased, so they differ, but they are the same surfaces.
        EXPECT_LT(agreement.edge_mean, 12.0);
        // Nearest-fragment ids inside surfaces are render()'s.
        std::size_t id_mismatch = 0;
        for (std::size_t p = 0; p < z.targets.primitive_id.size(); ++p)
            id_mismatch += z.targets.primitive_id[p] != a.targets.primitive_id[p];
        EXPECT_LT(double(id_mismatch), 0.01 * double(z.targets.primitive_id.size()));
    }
    // The shading really is not flat: the flat, untextured A-buffer of before differs inside.
    RenderOptions flat = options;
    flat.shading = ShadingMode::Flat;
    flat.textures = false;
    EXPECT_GT(compare_shading(reference.targets, render_abuffer(scene, flat).targets).interior_mean,
              1.0);
}

TEST(ABufferShading, NormalTargetIsTheShadingNormal) {
    const Scene scene = make_procedural_scene("builtin:default");
    RenderOptions options = id_options(240, 160);
    options.normal_target = true;
    const RenderResult z = render(scene, options);
    const RenderResult a = render_abuffer(scene, options);
    const ShadingAgreement agreement = compare_shading(z.targets, a.targets);
    std::size_t checked = 0, equal = 0;
    for (int y = 1; y + 1 < options.height; ++y)
        for (int x = 1; x + 1 < options.width; ++x) {
            const std::size_t p = std::size_t(y) * std::size_t(options.width) + std::size_t(x);
            if (z.targets.primitive_id[p] < 0 ||
                z.targets.primitive_id[p] != a.targets.primitive_id[p])
                continue;
            ++checked;
            equal += glm::length(z.targets.normal[p] - a.targets.normal[p]) < 1e-3f;
        }
    EXPECT_GT(checked, 4000u);
    EXPECT_GT(double(equal), 0.9 * double(checked));
    EXPECT_GT(agreement.interior, 3000u);
}

TEST(ABufferShading, TexturedSpotMatchesTheZBufferInside) {
    ZRASTER_REQUIRE_SHARED_DATA();
    Scene scene = load_scene(shared_data("meshes/obj/spot/spot_triangulated.obj"));
    // The OBJ has uvs but no MTL: bind its texture by hand.
    const ImageRGBA8 image = read_image_rgba8(shared_data("meshes/obj/spot/spot_texture.png"));
    for (Material& m : scene.materials)
        m.base_color_texture = std::make_shared<Texture>(image.width, image.height, image.rgba);
    ASSERT_FALSE(scene.meshes[0].uvs.empty());
    RenderOptions options = id_options(800, 600);  // large enough for pixels inside triangles
    for (const ShadingMode mode : {ShadingMode::Phong, ShadingMode::Gouraud, ShadingMode::Flat}) {
        options.shading = mode;
        const RenderResult z = render(scene, options);
        const ShadingAgreement agreement =
            compare_shading(z.targets, render_abuffer(scene, options).targets);
        print("spot, A-buffer vs z-buffer", agreement);
        ASSERT_GT(agreement.interior, 20000u);
        // Measured: all but 1 of 23776 identical in each mode (there a fold of the surface
        // covers subsamples of the pixel without covering a pixel center nearby).
        EXPECT_GE(double(agreement.interior_equal), 0.999 * double(agreement.interior))
            << int(mode);
    }
}

// Supersampling shades every subsample as render() does; inside a surface the box filter of 4
// samples of a smooth function is close to its value at the center. Texture detail (the checker
// edges, sampled from a finer mip level) makes the largest differences.
TEST(SupersampleShading, ShadesLikeTheZBuffer) {
    const Scene scene = make_procedural_scene("builtin:default");
    RenderOptions options = id_options(240, 160);
    const RenderResult z = render(scene, options);
    const ShadingAgreement agreement =
        compare_shading(z.targets, render_supersampled(scene, options, 2).targets);
    print("SSAA 2x2 vs z-buffer", agreement);
    RenderOptions untextured = options;
    untextured.textures = false;
    print("SSAA 2x2 vs z-buffer, untextured",
          compare_shading(render(scene, untextured).targets,
                          render_supersampled(scene, untextured, 2).targets));
    ASSERT_GT(agreement.interior, 3000u);
    // Measured 3.3: the checkerboard is sampled from one mip level finer at 2x (and averaged),
    // where render() filters it at its own level; untextured, the interiors are identical.
    EXPECT_LT(agreement.interior_mean, 4.0);
    EXPECT_LE(compare_shading(render(scene, untextured).targets,
                              render_supersampled(scene, untextured, 2).targets)
                  .interior_max,
              1);
    RenderOptions flat = options;
    flat.shading = ShadingMode::Flat;
    flat.textures = false;
    EXPECT_GT(compare_shading(z.targets, render_supersampled(scene, flat, 2).targets).interior_mean,
              2.0 * agreement.interior_mean);
}

TEST(ABufferShading, TransparentPhongLayersAreOrderIndependent) {
    RenderOptions options = ortho_options();
    options.shading = ShadingMode::Phong;
    std::array<int, 3> order = {0, 1, 2};
    std::vector<std::uint8_t> first;
    do {
        const RenderResult r = render_abuffer(layered_scene(order), options);
        if (first.empty())
            first = r.targets.color;
        else
            EXPECT_EQ(r.targets.color, first) << order[0] << order[1] << order[2];
    } while (std::next_permutation(order.begin(), order.end()));
}

// Two surfaces crossing inside a pixel: MSAA decides per sample (depth per sample), like 4x4
// supersampling; the A-buffer gives the whole pixel the order at its center.
TEST(Multisample, IntersectionLinesAreResolvedPerSample) {
    Scene scene = scene_from_triangles(interpenetrating_pair());
    Material red, blue;
    red.base_color = {1.0f, 0.0f, 0.0f};
    blue.base_color = {0.0f, 0.0f, 1.0f};
    scene.materials = {Material{}, red, blue};
    scene.meshes[0].material = 1;
    scene.meshes[1].material = 2;
    // An odd height: the intersection line (y = 0) runs through the centers of row 60, so each
    // of its pixels is split between the two surfaces.
    RenderOptions options = id_options(160, 121);
    options.camera = front_camera();
    options.cull = CullMode::None;
    options.shading = ShadingMode::Unlit;
    const RenderResult ssaa = render_supersampled(scene, options, 4);
    const RenderResult msaa = render_multisampled(scene, options, 4);
    const RenderResult abuf = render_abuffer(scene, options);
    // Pixels where both triangles show in the SSAA frame (red and blue both > 0): the
    // intersection line and the outlines where one lies over the other.
    std::size_t mixed = 0, msaa_close = 0, abuf_close = 0;
    for (std::size_t p = 0; p < ssaa.targets.color.size(); p += 4) {
        const auto* s = &ssaa.targets.color[p];
        if (s[0] < 20 || s[2] < 20 || s[0] + s[2] < 200) continue;
        ++mixed;
        auto close = [&](const std::vector<std::uint8_t>& image) {
            int d = 0;
            for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(image[p + c]) - int(s[c])));
            return d <= 17;  // one sample of 16 is 16 levels
        };
        msaa_close += close(msaa.targets.color);
        abuf_close += close(abuf.targets.color);
    }
    std::printf(
        "pixels with both surfaces: %zu; within one sample of 4x4 SSAA: MSAA %zu, "
        "A-buffer %zu\n",
        mixed, msaa_close, abuf_close);
    ASSERT_GT(mixed, 40u);
    EXPECT_GE(double(msaa_close), 0.95 * double(mixed));
    EXPECT_LT(abuf_close, msaa_close);
    // And the rest of the frame: same sample grid, same colors.
    std::size_t far = 0;
    for (std::size_t i = 0; i < ssaa.targets.color.size(); ++i)
        far += std::abs(int(ssaa.targets.color[i]) - int(msaa.targets.color[i])) > 17;
    EXPECT_LE(far, 8u);
}

TEST(Multisample, BitIdenticalForAnyThreadCountAndRejectsBadSampleCounts) {
    const Scene scene = make_procedural_scene("builtin:default");
    RenderOptions options = id_options(96, 64);
    const RenderResult one = render_multisampled(scene, options, 4);
    options.threads = 2;
    EXPECT_EQ(render_multisampled(scene, options, 4).targets.color, one.targets.color);
    EXPECT_THROW(render_multisampled(scene, options, 3), InputError);
    EXPECT_THROW(render_multisampled(scene, options, 16), InputError);
    RenderOptions limited = options;
    limited.limits.max_pixels = 96 * 64 * 4;  // 2 x 2 fits, 4 x 4 does not
    EXPECT_NO_THROW(render_multisampled(scene, limited, 2));
    EXPECT_THROW(render_multisampled(scene, limited, 4), InputError);
    // One sample per pixel at its center: render() exactly, shading included.
    EXPECT_EQ(render_multisampled(scene, options, 1).targets.color,
              render(scene, options).targets.color);
}

// ---------------------------------------------------------------------------------------------
// (g) Slivers between pixel centers: no pixel center, but subsamples.

TEST(ABuffer, SliverBetweenPixelCentersContributesCoverage) {
    // A black quad at window y in [10.6, 10.9], x in [6, 40]: between the centers of rows 10
    // (10.5) and 11 (11.5), over the samples at y = 10.625 and 10.875 (4 x 4 grid): half of
    // each pixel's samples in row 10.
    const float top = float(kSize / 2 - 10.6), bottom = float(kSize / 2 - 10.9);
    Scene scene =
        scene_from_triangles({fan({{-26, bottom}, {8, bottom}, {8, top}, {-26, top}}, 0)});
    Material black;
    black.base_color = glm::vec3(0.0f);
    black.specular = glm::vec3(0.0f);
    scene.materials.push_back(black);
    scene.meshes[0].material = 1;
    RenderOptions options = ortho_options();
    options.background = glm::vec3(1.0f);
    EXPECT_TRUE(project_scene(scene, options).empty());         // no pixel center covered
    EXPECT_EQ(project_scene(scene, options, true).size(), 2u);  // kept for subsamples
    const RenderResult z = render(scene, options);
    for (const std::uint8_t v : z.targets.color) ASSERT_EQ(v, 255);  // render() draws nothing
    ABufferStats stats;
    const RenderResult a = render_abuffer(scene, options, {}, &stats);
    EXPECT_GT(stats.fragments, 30u);
    const RenderResult s = render_supersampled(scene, options, 4);
    for (int px = 8; px < 38; ++px) {
        const std::size_t p = (std::size_t(10) * kSize + std::size_t(px)) * 4;
        EXPECT_NEAR(a.targets.color[p], 128, 1) << px;   // 8 of 16 samples black
        EXPECT_NEAR(s.targets.color[p], 128, 1) << px;   // the 4x4 supersampled frame agrees
        EXPECT_EQ(a.targets.color[p + 4 * kSize], 255);  // row 11 untouched
    }
}

}  // namespace
}  // namespace zraster::test
