// RenderOptions::portal_cull: from hundreds of random cameras inside building: scenes (in rooms,
// standing in doorways, on the planes of portals seen edge on, down long chains of doorways),
// the image (color, depth, instance and primitive ids) is bit-identical with and without portal
// culling, in both variants and with a PVS, while the walk skips instances (so that the test
// can fail if culling does nothing). Cameras outside every cell, or too close to a wall, are
// drawn without culling and say so.
#include <zraster/portals.hpp>
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/test_support.hpp"

namespace zraster {
namespace {

struct Frame {
    RenderTargets targets;
    RenderStats stats;
};

Frame draw(Renderer& renderer, const Scene& scene, RenderOptions options, PortalCull mode) {
    options.portal_cull = mode;
    const RenderResult& r = renderer.render(scene, options);
    return {r.targets, r.stats};
}

bool same_image(const RenderTargets& a, const RenderTargets& b) {
    return test::same_bits(a.color, b.color) && test::same_bits(a.depth, b.depth) &&
           test::same_bits(a.instance_id, b.instance_id) &&
           test::same_bits(a.primitive_id, b.primitive_id);
}

// A random point of the cell's box, next to a face plane one time in five (portals seen edge on),
// and exactly on it one time in twenty (then not culled: walls in the eye's plane are degenerate).
glm::dvec3 point_in(const Cell& cell, SplitMix64& rng) {
    const glm::dvec3 lo = cell.volume.lo, hi = cell.volume.hi;
    glm::dvec3 p(rng.uniform(lo.x, hi.x), rng.uniform(0.3, std::min(hi.y, 2.0)),
                 rng.uniform(lo.z, hi.z));
    if (rng.unit() < 0.2) {
        const int axis = rng.unit() < 0.5 ? 0 : 2;
        const double inset = rng.unit() < 0.25 ? 0.0 : 1e-4;
        p[axis] = rng.unit() < 0.5 ? lo[axis] + inset : hi[axis] - inset;
    }
    return p;
}

RenderOptions camera_options(const glm::dvec3& eye, SplitMix64& rng) {
    RenderOptions options;
    options.width = 96;
    options.height = 64;
    options.id_targets = true;
    Camera camera;
    camera.eye = eye;
    const double yaw = rng.uniform(0.0, 6.283185307179586);
    const double pitch = rng.uniform(-0.5, 0.5);
    camera.target = eye + glm::dvec3(std::cos(yaw) * std::cos(pitch), std::sin(pitch),
                                     std::sin(yaw) * std::cos(pitch));
    camera.fovy_degrees = rng.uniform(40.0, 100.0);
    camera.near = rng.uniform(0.01, 0.1);
    camera.far = 200.0;
    options.camera = camera;
    return options;
}

struct Tally {
    int cameras = 0, culled_frames = 0, doorway_frames = 0;
    std::uint64_t portal_culled = 0;
};

// `count` random cameras in random cells of the scene: every variant the same image as none.
void check_cameras(const Scene& scene, int count, std::uint64_t seed, Tally& tally) {
    const CellGraph& graph = *scene.cells;
    SplitMix64 rng(seed);
    Renderer renderer;
    for (int k = 0; k < count; ++k) {
        const auto cell = std::uint32_t(rng.next() % graph.cells.size());
        const glm::dvec3 eye = point_in(graph.cells[cell], rng);
        const RenderOptions options = camera_options(eye, rng);
        const Frame off = draw(renderer, scene, options, PortalCull::Off);
        for (const PortalCull mode : {PortalCull::Rectangles, PortalCull::Frustum}) {
            const Frame on = draw(renderer, scene, options, mode);
            std::string lost;
            for (std::size_t px = 0; px < off.targets.instance_id.size(); ++px)
                if (off.targets.instance_id[px] != on.targets.instance_id[px])
                    lost += " " + std::to_string(off.targets.instance_id[px]) + "@" +
                            std::to_string(px % 96) + "," + std::to_string(px / 96);
            ASSERT_TRUE(same_image(off.targets, on.targets))
                << lost.substr(0, 300) << " outcome " << int(on.stats.portal_outcome) << " cell "
                << on.stats.portal_camera_cell << " target " << options.camera->target.x << ","
                << options.camera->target.y << "," << options.camera->target.z << " fovy "
                << options.camera->fovy_degrees << " near " << options.camera->near << " camera "
                << k << " eye (" << eye.x << ", " << eye.y << ", " << eye.z << ") in cell "
                << graph.cells[cell].name << ", mode " << int(mode);
            EXPECT_NE(on.stats.portal_outcome, PortalOutcome::OverBound);
            if (on.stats.portal_outcome == PortalOutcome::Culled) {
                ++tally.culled_frames;
                tally.portal_culled += on.stats.instances_portal_culled;
                if (graph.cells[cell].name.starts_with("door")) ++tally.doorway_frames;
            }
        }
        ++tally.cameras;
    }
}

TEST(PortalCull, SameImageFromRandomCamerasInBuildings) {
    Tally tally;
    check_cameras(make_building(4, 4, 1), 240, 11, tally);
    check_cameras(make_building(3, 5, 7), 160, 12, tally);
    EXPECT_EQ(tally.cameras, 400);
    // Cameras in rooms are mostly clear of the walls (in doorways mostly not: the near plane
    // reaches the jambs): the walk ran and skipped instances.
    std::printf("%d cameras, %d frames culled (%d in doorways), %llu instances portal-culled\n",
                tally.cameras, tally.culled_frames, tally.doorway_frames,
                static_cast<unsigned long long>(tally.portal_culled));
    EXPECT_GT(tally.culled_frames, 250);
    EXPECT_GT(tally.doorway_frames, 10);
    EXPECT_GT(tally.portal_culled, std::uint64_t(tally.culled_frames) * 5);
}

// One row of rooms: doorways along it make long chains of portals, seen from either end.
TEST(PortalCull, SameImageDownLongChainsOfDoorways) {
    const Scene scene = make_building(1, 14, 3);
    Tally tally;
    SplitMix64 rng(5);
    Renderer renderer;
    for (int k = 0; k < 40; ++k) {
        const double end = k % 2 == 0 ? 0.6 : 4.0 * 14 - 0.6;
        const glm::dvec3 eye(end, rng.uniform(0.5, 2.0), rng.uniform(0.5, 3.5));
        RenderOptions options = camera_options(eye, rng);
        options.camera->target = glm::dvec3(4.0 * 14 - end, 1.0, rng.uniform(1.0, 3.0));
        const Frame off = draw(renderer, scene, options, PortalCull::Off);
        const Frame on = draw(renderer, scene, options, PortalCull::Frustum);
        ASSERT_TRUE(same_image(off.targets, on.targets)) << "camera " << k;
        ASSERT_EQ(on.stats.portal_outcome, PortalOutcome::Culled);
        tally.portal_culled += on.stats.instances_portal_culled;
        if (on.stats.portal_cells_visited > 6) ++tally.culled_frames;
    }
    EXPECT_GT(tally.culled_frames, 0);  // some views reach far down the row
    EXPECT_GT(tally.portal_culled, 0u);
}

// In room (0, 0) looking at a closed wall: everything behind it is skipped.
TEST(PortalCull, ClosedWallsCullTheRoomsBehind) {
    const Scene scene = make_building(4, 4, 1);
    RenderOptions options;
    options.width = 160;
    options.height = 90;
    options.id_targets = true;
    options.camera = builtin_camera("building:4x4");
    Renderer renderer;
    const Frame off = draw(renderer, scene, options, PortalCull::Off);
    const Frame on = draw(renderer, scene, options, PortalCull::Frustum);
    EXPECT_TRUE(same_image(off.targets, on.targets));
    EXPECT_EQ(on.stats.portal_outcome, PortalOutcome::Culled);
    EXPECT_EQ(on.stats.portal_camera_cell, 0);
    EXPECT_GT(on.stats.instances_portal_culled, on.stats.instances / 2);
    EXPECT_LT(on.stats.portal_cells_visited, scene.cells->cells.size());
}

TEST(PortalCull, CameraOutsideEveryCellCullsNothing) {
    const Scene scene = make_building(2, 2, 1);
    RenderOptions options;
    options.width = 64;
    options.height = 48;
    Camera camera;
    camera.eye = {4.0, 20.0, -10.0};
    camera.target = {4.0, 0.0, 4.0};
    options.camera = camera;
    options.portal_cull = PortalCull::Frustum;
    const RenderResult r = render(scene, options);
    EXPECT_EQ(r.stats.portal_outcome, PortalOutcome::CameraOutside);
    EXPECT_EQ(r.stats.instances_portal_culled, 0u);
}

TEST(PortalCull, SettingsThatCouldChangeTheImageTurnItOff) {
    const Scene scene = make_building(2, 2, 1);
    RenderOptions options;
    options.width = 64;
    options.height = 48;
    options.portal_cull = PortalCull::Frustum;
    options.edges = RenderOptions::Edges::Wireframe;
    const RenderResult r = render(scene, options);
    EXPECT_EQ(r.stats.portal_outcome, PortalOutcome::NotExact);
    EXPECT_EQ(r.stats.instances_portal_culled, 0u);
}

// With a PVS alone (portal_cull Off) and with a PVS and the walk: the same image again.
TEST(PortalCull, PvsFiltersWithTheSameImage) {
    Scene scene = make_building(4, 4, 2);
    auto graph = std::make_shared<CellGraph>(*scene.cells);
    graph->pvs = compute_pvs(*graph).visible;
    const Scene plain = scene;
    scene.cells = graph;
    SplitMix64 rng(9);
    Renderer renderer;
    std::uint64_t culled = 0;
    for (int k = 0; k < 40; ++k) {
        const auto cell = std::uint32_t(rng.next() % 16);  // rooms
        const RenderOptions options = camera_options(point_in(graph->cells[cell], rng), rng);
        const Frame reference = draw(renderer, plain, options, PortalCull::Off);
        for (const PortalCull mode : {PortalCull::Off, PortalCull::Frustum}) {
            const Frame on = draw(renderer, scene, options, mode);
            ASSERT_TRUE(same_image(reference.targets, on.targets))
                << "camera " << k << " mode " << int(mode);
            culled += on.stats.instances_portal_culled;
        }
    }
    EXPECT_GT(culled, 0u);
}

}  // namespace
}  // namespace zraster
