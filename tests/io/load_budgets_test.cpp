// What a small file can expand into is bounded before it is expanded: a node graph whose shared
// children multiply the placed meshes is refused by its count, a cycle by name.
#include <zraster/load.hpp>

#include <string>

#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

namespace zraster {
namespace {

// A triangle mesh (data URI), node 0 placing it, and `levels` nodes above, each holding the node
// below `fan_out` times: fan_out^levels placements from a 1-2 KB file.
std::string shared_children_gltf(int levels, int fan_out) {
    std::string nodes = R"({"mesh":0})";
    for (int level = 1; level <= levels; ++level) {
        std::string children;
        for (int i = 0; i < fan_out; ++i) children += (i ? "," : "") + std::to_string(level - 1);
        nodes += R"(,{"children":[)" + children + "]}";
    }
    // Three float3 positions: (0,0,0), (1,0,0), (0,1,0).
    const std::string data =
        "data:application/octet-stream;base64,"
        "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[)" + std::to_string(levels) +
           R"(]}],"nodes":[)" + nodes +
           R"(],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
           R"("min":[0,0,0],"max":[1,1,0]}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
           R"("buffers":[{"uri":")" +
           data + R"(","byteLength":36}]})";
}

TEST(LoadBudgets, SharedChildrenArePlacedEachTimeWithinTheBudget) {
    const auto dir = test::temp_dir("budgets-shared");
    const auto model = dir / "shared.gltf";
    test::write_bytes(model, shared_children_gltf(2, 3));
    const Scene scene = load_scene(model);
    EXPECT_EQ(scene.instances.size(), 9u);
    LoadOptions tight;
    tight.max_instances = 8;
    test::expect_limit_exceeded([&] { load_scene(model, tight); }, model, "max_instances",
                                "the node graph places more than 8 meshes");
}

TEST(LoadBudgets, AGraphOfBillionsIsRefusedBeforeItIsExpanded) {
    const auto dir = test::temp_dir("budgets-billions");
    const auto model = dir / "billions.gltf";
    test::write_bytes(model, shared_children_gltf(10, 10));  // 10^10 placements
    for (const LoadIsolation isolation : {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
        LoadOptions o;
        o.isolation = isolation;
        test::expect_limit_exceeded([&] { load_scene(model, o); }, model, "max_instances",
                                    "the node graph places more than 1000000 meshes "
                                    "(max_instances; nodes sharing children multiply)");
    }
    // Under another name Assimp reads it as glTF all the same (it asks every importer), and so do
    // the checks: before them it ran out of memory expanding it. (Through the worker only, whose
    // memory is bounded, so that a regression fails instead of exhausting the test's.)
    for (const char* name : {"billions.json", "billions"}) {
        const auto renamed = dir / name;
        std::filesystem::copy_file(model, renamed);
        LoadOptions o;
        o.isolation = LoadIsolation::WorkerProcess;
        test::expect_limit_exceeded([&] { load_scene(renamed, o); }, renamed, "max_instances",
                                    "the node graph places more than 1000000 meshes "
                                    "(max_instances; nodes sharing children multiply)");
    }
}

// The budgets of LoadOptions are LimitExceeded naming the field, in process and through the
// worker process (whose message carries the name): what lets the command name its flag.
TEST(LoadBudgets, BudgetRefusalsNameTheirLimitInProcessAndThroughTheWorker) {
    const auto dir = test::temp_dir("budgets-limits");
    const auto ply = dir / "two.ply";
    test::write_bytes(ply,
                      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
                      "property float y\nproperty float z\nelement face 2\n"
                      "property list uchar int vertex_indices\nend_header\n"
                      "0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 2\n");
    const auto obj = dir / "two.obj";
    test::write_bytes(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n");
    const auto stl = dir / "one.stl";
    test::write_bytes(stl,
                      "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                      "vertex 0 1 0\nendloop\nendfacet\nendsolid t\n");
    for (const LoadIsolation isolation : {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
        SCOPED_TRACE(isolation == LoadIsolation::InProcess ? "in process" : "worker");
        LoadOptions o;
        o.isolation = isolation;
        o.max_triangles = 1;
        // The PLY's triangles are counted by the importer: in the worker, in that case.
        test::expect_limit_exceeded([&] { load_scene(ply, o); }, ply, "max_triangles",
                                    "too many triangles (2, limit 1)");
        test::expect_limit_exceeded([&] { load_scene(obj, o); }, obj, "max_triangles",
                                    "too many triangles (2, limit 1)");
        LoadOptions small = o;
        small.max_triangles = 50;
        small.max_file_bytes = 40;
        test::expect_limit_exceeded([&] { load_scene(stl, small); }, stl, "max_file_bytes",
                                    "file too large (");
    }
}

// One accessor read by many primitives: Assimp copies it into each, so what it decodes is counted
// per primitive against the triangle budget (3 x max_triangles vertices, max_triangles faces)
// before it reads the file. A 1 KB document naming one million-vertex accessor 3000 times asked
// for tens of gigabytes and ended in std::bad_alloc inside Assimp.
std::string shared_accessor_gltf(int primitives, const std::string& extra_accessors = "",
                                 const std::string& attributes = R"("POSITION":0)") {
    std::string list;
    for (int p = 0; p < primitives; ++p)
        list += std::string(p ? "," : "") + R"({"attributes":{)" + attributes + "}}";
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
           R"("nodes":[{"mesh":0}],"meshes":[{"primitives":[)" +
           list +
           R"(]}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
           R"("min":[0,0,0],"max":[1,1,0]})" +
           extra_accessors +
           R"(],"bufferViews":[{"buffer":0,"byteLength":36}],)"
           R"("buffers":[{"uri":"data:application/octet-stream;base64,)"
           R"(AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA","byteLength":36}]})";
}

TEST(LoadBudgets, AnAccessorReadByManyPrimitivesIsCountedForEach) {
    const auto dir = test::temp_dir("budgets-shared-accessor");
    const auto model = dir / "shared.gltf";
    test::write_bytes(model, shared_accessor_gltf(10));  // 30 vertices, 10 triangles decoded
    EXPECT_EQ(load_scene(model).meshes.size(), 10u);
    for (const LoadIsolation isolation : {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
        SCOPED_TRACE(isolation == LoadIsolation::InProcess ? "in process" : "worker");
        LoadOptions o;
        o.isolation = isolation;
        o.max_triangles = 9;
        test::expect_limit_exceeded(
            [&] { load_scene(model, o); }, model, "max_triangles",
            "the meshes' 10 primitives decode to more than 27 vertices, 3 x max_triangles (the "
            "importer copies an accessor into every primitive that reads it)");
        // Faces: an index accessor of 3 indices read by 10 primitives of points (a face each).
        o.max_triangles = 20;
        const auto points = dir / "points.gltf";
        test::write_bytes(points, shared_accessor_gltf(10, "", R"("POSITION":0},"mode":0,"x":{)"));
        test::expect_limit_exceeded(
            [&] { load_scene(points, o); }, points, "max_triangles",
            "the meshes' 10 primitives decode to more than 20 faces, max_triangles");
    }
}

TEST(LoadBudgets, ACycleOfNodesIsRefusedByName) {
    const auto dir = test::temp_dir("budgets-cycle");
    const auto model = dir / "cycle.gltf";
    std::string text = shared_children_gltf(2, 1);
    // Node 0 (the mesh) becomes a child of node 2, its own grandparent.
    const std::string mesh_node = R"({"mesh":0})";
    text.replace(text.find(mesh_node), mesh_node.size(), R"({"mesh":0,"children":[2]})");
    test::write_bytes(model, text);
    test::expect_input_error([&] { load_scene(model); }, model, "is its own ancestor");
}

}  // namespace
}  // namespace zraster
