// compute_pvs against brute force: ids rendered from many viewpoints in each room, in six
// directions (a cube of 90-degree views), name the instances seen; every instance seen must have
// a cell in the room's PVS (so the PVS never makes portal culling miss anything), and the PVS is
// compared in size with the rooms seen that way.
#include <zraster/portals.hpp>
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <set>

namespace zraster {
namespace {

TEST(PvsSampling, HoldsEveryCellSeenFromSampledViewpoints) {
    const Scene scene = make_building(4, 4, 5);
    const CellGraph& graph = *scene.cells;
    const PotentiallyVisibleSets pvs = compute_pvs(graph);
    const std::uint32_t rooms = 16;
    SplitMix64 rng(21);
    Renderer renderer;
    RenderOptions options;
    options.width = options.height = 48;
    options.id_targets = true;
    options.color_target = false;
    const glm::dvec3 directions[6] = {{1, 0, 0},  {-1, 0, 0},    {0, 0, 1},
                                      {0, 0, -1}, {0, 1, 0.001}, {0, -1, 0.001}};
    double pvs_rooms = 0, seen_rooms = 0;
    for (std::uint32_t room = 0; room < rooms; ++room) {
        const CellVolume& v = graph.cells[room].volume;
        const std::vector<std::uint32_t>& set = pvs.visible[room];
        std::set<std::uint32_t> seen;  // rooms holding a one-cell instance seen
        for (int k = 0; k < 12; ++k) {
            Camera camera;
            camera.eye = {rng.uniform(v.lo.x, v.hi.x), rng.uniform(0.2, 2.8),
                          rng.uniform(v.lo.z, v.hi.z)};
            camera.fovy_degrees = 90.0;
            camera.near = 0.01;
            camera.far = 100.0;
            for (const glm::dvec3& d : directions) {
                camera.target = camera.eye + d;
                options.camera = camera;
                const RenderResult& r = renderer.render(scene, options);
                for (const std::int32_t id : r.targets.instance_id) {
                    if (id < 0) continue;
                    const std::vector<std::uint32_t>& cells = graph.instance_cells[id];
                    const bool listed = std::any_of(cells.begin(), cells.end(), [&](auto c) {
                        return std::binary_search(set.begin(), set.end(), c);
                    });
                    ASSERT_TRUE(listed) << "room " << room << " sees instance " << id << " '"
                                        << scene.instances[id].name << "' outside its PVS";
                    if (cells.size() == 1 && cells[0] < rooms) seen.insert(cells[0]);
                }
            }
        }
        EXPECT_TRUE(seen.contains(room));
        const auto pvs_room_count =
            std::count_if(set.begin(), set.end(), [&](std::uint32_t c) { return c < rooms; });
        pvs_rooms += double(pvs_room_count);
        seen_rooms += double(seen.size());
    }
    // How much larger the conservative sets are than what sampling saw (rooms only).
    std::printf("PVS: %.2f rooms per room, sampled %.2f: ratio %.2f\n", pvs_rooms / rooms,
                seen_rooms / rooms, pvs_rooms / seen_rooms);
    EXPECT_GE(pvs_rooms, seen_rooms);
    EXPECT_LT(pvs_rooms, double(rooms) * rooms);  // it does exclude rooms
}

}  // namespace
}  // namespace zraster
