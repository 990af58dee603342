// validate_cell_graph: the exact messages for the mistakes it refuses, and a good graph passes.
#include <zraster/error.hpp>
#include <zraster/portals.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace zraster {
namespace {

// Two unit-box cells side by side along x, one instance in each, a square portal between them.
struct TwoRooms {
    CellGraph graph;
    std::vector<Bounds3f> boxes{Bounds3f{{0.2f, 0.2f, 0.2f}, {0.8f, 0.8f, 0.8f}},
                                Bounds3f{{1.2f, 0.2f, 0.2f}, {1.8f, 0.8f, 0.8f}}};
    std::vector<std::string> names{"chair", "table"};
    TwoRooms() {
        graph.cells.push_back({"a", box_volume({0, 0, 0}, {1, 1, 1}), {0}});
        graph.cells.push_back({"b", box_volume({1, 0, 0}, {2, 1, 1}), {1}});
        Portal door;
        door.cells = {0, 1};
        door.corners = {{1, 0.2, 0.2}, {1, 0.2, 0.8}, {1, 0.8, 0.8}, {1, 0.8, 0.2}};
        graph.portals.push_back(door);
    }
    std::string error() {
        try {
            validate_cell_graph(graph, boxes, names, "x.cells.json");
        } catch (const InputError& e) {
            return e.what();
        }
        return "";
    }
};

TEST(CellGraph, AGoodGraphPassesAndIsIndexed) {
    TwoRooms t;
    EXPECT_EQ(t.error(), "");
    EXPECT_EQ(t.graph.cell_portals[0], std::vector<std::uint32_t>{0});
    EXPECT_EQ(t.graph.instance_cells[1], std::vector<std::uint32_t>{1});
    EXPECT_EQ(find_cell(t.graph, {1.5, 0.5, 0.5}), 1);
    EXPECT_EQ(find_cell(t.graph, {3.0, 0.5, 0.5}), -1);
}

TEST(CellGraph, RefusesAPortalNamingAMissingCell) {
    TwoRooms t;
    t.graph.portals[0].cells[1] = 7;
    EXPECT_EQ(t.error(), "x.cells.json: portals[0]: names cell 7, which does not exist (2 cells)");
}

TEST(CellGraph, RefusesANonPlanarPortal) {
    TwoRooms t;
    t.graph.portals[0].corners[2].x = 1.01;
    EXPECT_EQ(t.error().substr(0, 64),
              "x.cells.json: portals[0]: is not planar (corner 0 is 0.002500 of");
}

TEST(CellGraph, RefusesANonConvexPortal) {
    TwoRooms t;
    t.graph.portals[0].corners = {
        {1, 0.2, 0.2}, {1, 0.2, 0.8}, {1, 0.3, 0.5}, {1, 0.8, 0.8}, {1, 0.8, 0.2}};
    EXPECT_EQ(t.error(), "x.cells.json: portals[0]: is not convex");
}

TEST(CellGraph, RefusesAPortalOffItsCells) {
    TwoRooms t;
    for (glm::dvec3& c : t.graph.portals[0].corners) c.x = 0.5;
    EXPECT_EQ(t.error(), "x.cells.json: portals[0]: corner 0 lies outside cells[1] 'b'");
}

// fuzz_cells: a portal whose corners lie inside cell b but on none of its faces (b reached past
// x = 1 into a) let a ray go from a into b without crossing it; the walk culled what it saw.
TEST(CellGraph, RefusesAPortalThroughACellsInterior) {
    TwoRooms t;
    t.graph.cells[1].volume = box_volume({0.9, 0, 0}, {2, 1, 1});
    EXPECT_EQ(t.error(),
              "x.cells.json: portals[0]: does not lie in a face of cells[1] 'b' (a portal is on "
              "the boundary of both its cells)");
}

TEST(CellGraph, RefusesAPortalWithBothCellsOnOneSide) {
    TwoRooms t;
    t.graph.cells[1].volume = box_volume({0.9, 0, 0}, {1, 1, 1});
    EXPECT_EQ(t.error(),
              "x.cells.json: portals[0]: has cells[0] 'a' and cells[1] 'b' on the same side (a "
              "portal joins cells on either side of it)");
}

TEST(CellGraph, RefusesAnInstanceInNoCell) {
    TwoRooms t;
    t.graph.cells[1].instances.clear();
    EXPECT_EQ(t.error(), "x.cells.json: instance 1 'table' is in no cell");
}

TEST(CellGraph, RefusesAnInstanceReachingAnUnlistedCell) {
    TwoRooms t;
    t.boxes[0].hi.x = 1.3f;
    EXPECT_EQ(t.error(),
              "x.cells.json: instance 0 'chair' reaches into cells[1] 'b', which does not list "
              "it (list an instance in every cell its bounds touch)");
}

TEST(CellGraph, ConvexVolumesFromPlanes) {
    const std::vector<glm::dvec4> tetrahedron{
        {1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {-1, -1, -1, 1}};
    const CellVolume v = convex_volume(tetrahedron);
    EXPECT_EQ(v.corners.size(), 4u);
    EXPECT_EQ(v.hi, glm::dvec3(1.0));
    const std::vector<glm::dvec4> open{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {1, 1, 1, 1}};
    EXPECT_THROW(convex_volume(open), InputError);
}

TEST(CellGraph, TheBuildingsGraphIsValid) {
    const Scene scene = make_building(3, 4, 2);
    ASSERT_TRUE(scene.cells);
    EXPECT_GE(scene.cells->cells.size(), 12u + 11u);  // rooms, and a doorway per tree edge
    EXPECT_EQ(scene.cells->portals.size(), 2 * (scene.cells->cells.size() - 12));
    EXPECT_EQ(find_cell(*scene.cells, {2.0, 1.6, 2.0}), 0);
}

}  // namespace
}  // namespace zraster
