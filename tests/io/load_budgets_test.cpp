// What a small file can expand into is bounded before it is expanded: a node graph whose shared
// children multiply the placed meshes is refused by its count, a cycle by name; the bytes a
// glTF's accessors decode to, and the triangulation's work on polygons of many corners, are
// refused before the importer reads the file.
#include <zraster/load.hpp>

#include <cmath>
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

// The importer copies a node once per path to it, meshes or not: 30 levels of empty nodes, each
// holding the one below twice, are 2^31 nodes from a 500-byte file (it ran out of memory at
// 7.8 GB). Counted in the geometry's bytes, exactly.
TEST(LoadBudgets, NodesSharingChildrenAreCountedInTheImportersBytes) {
    const auto dir = test::temp_dir("budgets-empty-nodes");
    // Node 0 places the triangle; node 1 holds node 2 twice, ..., node `levels` holds the empty
    // leaf node levels + 1 twice: 1 + (2^(levels + 1) - 1) nodes copied.
    const auto empty_tree = [](int levels) {
        std::string json = shared_children_gltf(0, 1);
        std::string nodes = R"({"mesh":0})";
        for (int level = 1; level <= levels; ++level)
            nodes += R"(,{"children":[)" + std::to_string(level + 1) + "," +
                     std::to_string(level + 1) + "]}";
        nodes += ",{}";
        json.replace(json.find(R"({"mesh":0})"), 10, nodes);
        json.replace(json.find(R"("nodes":[0])"), 11, R"("nodes":[0,1])");
        return json;
    };
    const auto model = dir / "tree.gltf";
    test::write_bytes(model, empty_tree(3));  // 16 nodes, one triangle (180 bytes)
    LoadOptions o;
    o.max_geometry_bytes = 16 * 1152 + 180;
    EXPECT_EQ(load_scene(model, o).instances.size(), 1u);
    --o.max_geometry_bytes;
    test::expect_limit_exceeded([&] { load_scene(model, o); }, model, "max_geometry_bytes",
                                "and the node graph's 16 nodes decode to about 18612 bytes");
    const auto huge = dir / "huge.gltf";
    test::write_bytes(huge, empty_tree(30));
    for (const LoadIsolation isolation : {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
        LoadOptions defaults;
        defaults.isolation = isolation;
        test::expect_limit_exceeded(
            [&] { load_scene(huge, defaults); }, huge, "max_geometry_bytes",
            "the meshes' 1 primitives and the node graph's 2147483648 nodes decode to about "
            "2359296 MiB of geometry, more than max_geometry_bytes (1024 MiB) (the importer "
            "copies an accessor into every primitive that reads it, and a node once per path to "
            "it)");
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

// The bytes decoded, per primitive: 3 vertices of one attribute (24 bytes each) and 3 drawn
// indices (36 bytes each) make 180 bytes a primitive.
TEST(LoadBudgets, DecodedGeometryIsCountedInBytesPerPrimitive) {
    const auto dir = test::temp_dir("budgets-geometry-bytes");
    const auto model = dir / "shared.gltf";
    test::write_bytes(model, shared_accessor_gltf(10));
    for (const LoadIsolation isolation : {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
        SCOPED_TRACE(isolation == LoadIsolation::InProcess ? "in process" : "worker");
        LoadOptions o;
        o.isolation = isolation;
        // 10 x 180 bytes, and the one node placing them: 1152.
        o.max_geometry_bytes = 2952;
        EXPECT_EQ(load_scene(model, o).meshes.size(), 10u);
        o.max_geometry_bytes = 2951;
        test::expect_limit_exceeded(
            [&] { load_scene(model, o); }, model, "max_geometry_bytes",
            "the meshes' 10 primitives and the node graph's 1 node decode to about 2952 bytes of "
            "geometry, more than max_geometry_bytes (2951 bytes) (the importer copies an "
            "accessor into every primitive that reads it, and a node once per path to it)");
    }
    // A morph target's attributes are decoded too: 72 bytes more a primitive.
    const auto morphed = dir / "morphed.gltf";
    test::write_bytes(
        morphed, shared_accessor_gltf(10, "", R"("POSITION":0},"targets":[{"POSITION":0}],"x":{)"));
    LoadOptions o;
    o.max_geometry_bytes = 2520 + 1152 - 1;
    test::expect_limit_exceeded([&] { load_scene(morphed, o); }, morphed, "max_geometry_bytes",
                                "decode to about 3672 bytes of geometry");
}

// A 578-byte glTF whose one sparse accessor declares 150 million vertices (one of them given):
// within the triangle budget's 3 x 50 million vertices, it reached 7.6 GB in the importer. The
// bytes are refused at once, with the defaults.
TEST(LoadBudgets, ASparseAccessorOfMillionsIsRefusedByItsBytes) {
    const auto dir = test::temp_dir("budgets-sparse");
    const auto model = dir / "sparse.gltf";
    test::write_bytes(
        model,
        R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":16,"uri":)"
        R"("data:application/octet-stream;base64,AAAAAAAAgD8AAIA/AACAPw=="}],)"
        R"("bufferViews":[{"buffer":0,"byteLength":4},{"buffer":0,"byteOffset":4,"byteLength":12}],)"
        R"("accessors":[{"componentType":5126,"count":150000000,"type":"VEC3","min":[0,0,0],)"
        R"("max":[1,1,1],"sparse":{"count":1,"indices":{"bufferView":0,"componentType":5125},)"
        R"("values":{"bufferView":1}}}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
        R"("nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0})");
    for (const LoadIsolation isolation : {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
        SCOPED_TRACE(isolation == LoadIsolation::InProcess ? "in process" : "worker");
        LoadOptions o;
        o.isolation = isolation;
        test::expect_limit_exceeded(
            [&] { load_scene(model, o); }, model, "max_geometry_bytes",
            "the meshes' 1 primitives and the node graph's 1 node decode to about 10871 MiB of "
            "geometry, more than "
            "max_geometry_bytes (1024 MiB)");
    }
}

// A polygon of n corners counts n^2 against max_triangulation_work (the importer's ear clipping
// is quadratic: one face of 32,767 corners took 12 s), in OBJ (whose polygons of more than 4
// corners go to the importer; a face continued over lines too) and PLY files.
TEST(LoadBudgets, PolygonsOfManyCornersAreCountedBeforeTriangulation) {
    const auto dir = test::temp_dir("budgets-triangulation");
    std::string obj = "", face = "f", ply_face = "200";
    for (int k = 0; k < 200; ++k) {
        obj += "v " + std::to_string(std::cos(k * 0.0314)) + " " +
               std::to_string(std::sin(k * 0.0314)) + " 0\n";
        face += " " + std::to_string(k + 1);
        ply_face += " " + std::to_string(k);
    }
    const auto one_line = dir / "polygon.obj";
    test::write_bytes(one_line, obj + face + "\n");
    const auto continued = dir / "continued.obj";
    const std::size_t cut = face.find(' ', 300);
    test::write_bytes(continued, obj + face.substr(0, cut) + " \\\n" + face.substr(cut + 1) + "\n");
    std::string ply =
        "ply\nformat ascii 1.0\nelement vertex 200\nproperty float x\n"
        "property float y\nproperty float z\nelement face 1\n"
        "property list ushort int vertex_indices\nend_header\n";
    for (int k = 0; k < 200; ++k)
        ply += std::to_string(std::cos(k * 0.0314)) + " " + std::to_string(std::sin(k * 0.0314)) +
               " 0\n";
    const auto polygon_ply = dir / "polygon.ply";
    test::write_bytes(polygon_ply, ply + ply_face + "\n");
    struct Case {
        std::filesystem::path file;
        std::string where;
    };
    for (const Case& c :
         {Case{one_line, "line 201"}, Case{continued, "line 201"}, Case{polygon_ply, "face 0"}}) {
        SCOPED_TRACE(c.file.string());
        for (const LoadIsolation isolation :
             {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
            LoadOptions o;
            o.isolation = isolation;
            o.max_triangulation_work = 40'000;
            EXPECT_EQ(load_scene(c.file, o).triangle_count(), 198u);
            o.max_triangulation_work = 39'999;
            test::expect_limit_exceeded(
                [&] { load_scene(c.file, o); }, c.file, "max_triangulation_work",
                c.where +
                    ": a polygon of 200 corners takes the triangulation's work (corners^2 summed "
                    "over the polygons of more than 4 corners) past max_triangulation_work "
                    "(39999)");
        }
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
