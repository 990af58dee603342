// The painter's algorithm, the BSP tree and Warnock's algorithm against the z-buffer, on opaque
// scenes: the primitive-id images must agree except on a small fraction of pixels.
//
// Why any pixels differ at all:
//  - Interpenetration lines. The z-buffer compares two float depths per pixel; the painter's
//    algorithm and the BSP tree split along the exact intersection line, whose new vertices are
//    rounded to float clip coordinates and snapped to 1/256 pixel; Warnock compares double plane
//    depths. A pixel center within that rounding of the line can go either way.
//  - Split vertices on outlines. A split adds vertices on a polygon's edges; snapped, they can
//    move the outline by up to half a subpixel, so a pixel center that close to an edge can
//    change hands (splitting never opens a crack: both pieces share the new vertices exactly).
//  - Depth ties (coincident surfaces) are broken by submission order in every algorithm, the
//    same way the z-buffer's LESS test breaks them, but near-ties along edges are decided on
//    differently rounded depths.
//  - Split lines. A fragment split again on one side of an earlier split line only (the other
//    side went to another subtree) gets a new vertex on that shared line, a T-junction: snapped,
//    it opens a sliver of at most 1/256 pixel along the split line where the surface behind
//    shows through. Split lines cross the interior of triangles, so the z-buffer image shows
//    nothing there: found at a pixel center 0.0005 pixel from a split line in the 2000-triangle
//    soup.
//  - Near-ties in depth, decided on differently rounded depths (Warnock's double planes from
//    window vertices, the z-buffer's float plane equations).
// All of these are bands narrower than a pixel along a line: they can put single differing
// pixels inside a surface, never a 2x2 block of them (IdAgreement::interior_blocks), which is
// what a surface drawn in the wrong order over any area would do.
#include <zraster/load.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "support/test_support.hpp"
#include "visibility/visibility_test_util.hpp"

namespace zraster::test {
namespace {

const char* name_of(VisibilityAlgorithm a) {
    switch (a) {
        case VisibilityAlgorithm::ZBuffer:
            return "zbuffer";
        case VisibilityAlgorithm::Painter:
            return "painter";
        case VisibilityAlgorithm::Bsp:
            return "bsp";
        case VisibilityAlgorithm::Warnock:
            return "warnock";
    }
    return "?";
}

// Renders with every algorithm and checks each against the z-buffer.
void expect_agreement(const Scene& scene, const RenderOptions& options, double max_fraction,
                      const std::string& label) {
    const RenderResult reference =
        render_with_visibility(scene, options, VisibilityAlgorithm::ZBuffer);
    std::size_t covered = 0;
    for (const std::int32_t id : reference.targets.primitive_id) covered += id >= 0;
    ASSERT_GT(covered, 1000u) << label << ": the scene should fill a good part of the image";
    for (const VisibilityAlgorithm a :
         {VisibilityAlgorithm::Painter, VisibilityAlgorithm::Bsp, VisibilityAlgorithm::Warnock}) {
        VisibilityStats stats;
        const auto start = std::chrono::steady_clock::now();
        const RenderResult r = render_with_visibility(scene, options, a, &stats);
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        const IdAgreement agreement = compare_ids(reference.targets, r.targets);
        std::printf(
            "[%s/%s] covered %zu differing %zu (%.4f%%) interior %zu (blocks %zu) | painter swaps "
            "%llu splits "
            "%llu | bsp nodes %zu depth %zu splits %zu | %.0f ms\n",
            label.c_str(), name_of(a), agreement.covered, agreement.differing,
            100.0 * agreement.fraction(), agreement.differing_interior, agreement.interior_blocks,
            static_cast<unsigned long long>(stats.painter.swaps),
            static_cast<unsigned long long>(stats.painter.splits), stats.bsp.nodes, stats.bsp.depth,
            stats.bsp.splits, ms);
        EXPECT_LE(agreement.fraction(), max_fraction) << label << " " << name_of(a);
        EXPECT_EQ(agreement.interior_blocks, 0u) << label << " " << name_of(a);

        // Same surface, same color: the shading is the z-buffer's, operation for operation. A
        // split piece's barycentrics come from its own fan (the split vertices' weights, rounded),
        // which may move a channel by one step; unsplit surfaces match bit for bit.
        const bool split = stats.painter.splits > 0 || stats.bsp.splits > 0;
        std::size_t color_mismatches = 0;
        int largest_step = 0;
        for (std::size_t p = 0; p < r.targets.primitive_id.size(); ++p)
            if (r.targets.primitive_id[p] == reference.targets.primitive_id[p] &&
                r.targets.instance_id[p] == reference.targets.instance_id[p])
                for (std::size_t c = 0; c < 4; ++c) {
                    const int step = std::abs(int(r.targets.color[4 * p + c]) -
                                              int(reference.targets.color[4 * p + c]));
                    color_mismatches += step != 0;
                    largest_step = std::max(largest_step, step);
                }
        if (!split) {
            EXPECT_EQ(color_mismatches, 0u) << label << " " << name_of(a);
        }
        EXPECT_LE(largest_step, 1) << label << " " << name_of(a);
    }
}

class SharedMesh : public ::testing::TestWithParam<const char*> {};

TEST_P(SharedMesh, AllAlgorithmsAgreeWithTheZBuffer) {
    ZRASTER_REQUIRE_SHARED_DATA();
    const Scene scene = load_scene(shared_data(GetParam()));
    // Back faces culled, as rendered normally: self-occlusion (ears, legs) is what is tested.
    expect_agreement(scene, id_options(320, 240), 0.005, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Shared, SharedMesh,
                         ::testing::Values("meshes/obj/bunny-small.obj",
                                           "meshes/obj/spot/spot_triangulated.obj"));

TEST(Agreement, InterpenetratingSoupBothSidesVisible) {
    // 2000 triangles ten times the benchmark soup's size: hundreds of intersecting pairs, and with
    // culling off every triangle is seen from one side or the other.
    const Scene scene = scene_from_meshes({make_interpenetrating_soup(2000, 0.2, 7)});
    RenderOptions options = id_options(320, 240);
    options.cull = CullMode::None;
    expect_agreement(scene, options, 0.005, "soup:2000");
}

TEST(Agreement, CameraInsideWithReversedZAndAUserClipPlane) {
    // The near plane, the guard band and a user plane cut triangles: clipped polygons (more than
    // three vertices, new vertices from clip_triangle) go through every algorithm.
    const Scene scene = scene_from_meshes({make_interpenetrating_soup(1000, 0.2, 9)});
    RenderOptions options = id_options(256, 192);
    options.cull = CullMode::None;
    Camera camera = orbit_camera({0.1, 0.0, 0.0}, 0.4, 30.0, 15.0, 80.0);
    camera.near = 0.05;
    camera.far = 5.0;
    camera.reversed_z = true;
    options.camera = camera;
    options.clip_planes = {glm::vec4(0.3f, 1.0f, 0.0f, 0.4f)};
    expect_agreement(scene, options, 0.005, "inside");
}

TEST(Agreement, CyclicOverlap) {
    const Scene scene = scene_from_triangles(cyclic_sticks());
    RenderOptions options = id_options(320, 240);
    options.camera = front_camera();
    expect_agreement(scene, options, 0.005, "cyclic");
}

TEST(Agreement, InterpenetratingPair) {
    const Scene scene = scene_from_triangles(interpenetrating_pair());
    RenderOptions options = id_options(320, 240);
    options.camera = front_camera();
    options.cull = CullMode::None;
    expect_agreement(scene, options, 0.005, "pair");
}

}  // namespace
}  // namespace zraster::test
