// What a small file can expand into is bounded before it is expanded: a node graph whose shared
// children multiply the placed meshes is refused by its count, a cycle by name; the bytes a
// glTF's accessors decode to, and the triangulation's work on polygons of many corners, are
// refused before the importer reads the file.
#include <zraster/load.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <initializer_list>
#include <iterator>
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
    // 16 nodes, one triangle (180 bytes, and 1976 for the primitive itself), its buffer.
    test::write_bytes(model, empty_tree(3));
    LoadOptions o;
    o.max_geometry_bytes = 16 * 1152 + 180 + 1976 + 36;
    EXPECT_EQ(load_scene(model, o).instances.size(), 1u);
    --o.max_geometry_bytes;
    test::expect_limit_exceeded([&] { load_scene(model, o); }, model, "max_geometry_bytes",
                                "and the node graph's 16 nodes decode to about 20624 bytes");
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
// indices (36 bytes each) make 180 bytes a primitive, and the primitive itself 1976 more; the
// buffer of 36 bytes is read once.
TEST(LoadBudgets, DecodedGeometryIsCountedInBytesPerPrimitive) {
    const auto dir = test::temp_dir("budgets-geometry-bytes");
    const auto model = dir / "shared.gltf";
    test::write_bytes(model, shared_accessor_gltf(10));
    for (const LoadIsolation isolation : {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
        SCOPED_TRACE(isolation == LoadIsolation::InProcess ? "in process" : "worker");
        LoadOptions o;
        o.isolation = isolation;
        // 10 x (180 + 1976) bytes, the one node placing them (1152) and the buffer (36).
        o.max_geometry_bytes = 22748;
        EXPECT_EQ(load_scene(model, o).meshes.size(), 10u);
        o.max_geometry_bytes = 22747;
        test::expect_limit_exceeded(
            [&] { load_scene(model, o); }, model, "max_geometry_bytes",
            "the meshes' 10 primitives and the node graph's 1 node decode to about 22748 bytes of "
            "geometry, more than max_geometry_bytes (22747 bytes) (the importer copies an "
            "accessor into every primitive that reads it, and a node once per path to it)");
    }
    // A morph target's attributes are decoded too: 72 bytes more a primitive.
    const auto morphed = dir / "morphed.gltf";
    test::write_bytes(
        morphed, shared_accessor_gltf(10, "", R"("POSITION":0},"targets":[{"POSITION":0}],"x":{)"));
    LoadOptions o;
    o.max_geometry_bytes = 2520 + 19760 + 1152 + 36 - 1;
    test::expect_limit_exceeded([&] { load_scene(morphed, o); }, morphed, "max_geometry_bytes",
                                "decode to about 23468 bytes of geometry");
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

// --- What else a small glTF expands into (issue 27): each counted in max_geometry_bytes before
// the importer reads the file, the message naming what dominates. ---

// The little-endian bytes of `values` (floats, or 16-bit unsigned integers).
template <typename T>
std::string bytes_of(std::initializer_list<T> values) {
    std::string out(values.size() * sizeof(T), '\0');
    std::memcpy(out.data(), std::data(values), out.size());
    return out;
}

// Assimp's JSON parser recursed once per level: 200,000 nested arrays in "extras" (400 KB) were
// a SIGSEGV in process. glTF nests fewer than 20 levels: past 256 the file is refused first.
TEST(LoadBudgets, GltfJsonNestedPastAFixedDepthIsRefusedBeforeTheImporter) {
    const auto dir = test::temp_dir("budgets-json-depth");
    const auto nested = [](std::size_t levels) {  // the document's object is one level
        std::string json = shared_accessor_gltf(1);
        return "{\"extras\":" + std::string(levels - 1, '[') + std::string(levels - 1, ']') + "," +
               json.substr(1);
    };
    const auto deepest = dir / "deepest.gltf";
    test::write_bytes(deepest, nested(256));
    EXPECT_EQ(load_scene(deepest).meshes.size(), 1u);
    const auto deeper = dir / "deeper.gltf";
    test::write_bytes(deeper, nested(257));
    test::expect_input_error([&] { load_scene(deeper); }, deeper,
                             "malformed glTF file: its JSON nests arrays and objects more than "
                             "256 levels deep (at byte 265 of the JSON; glTF needs fewer than 20)");
    // 200,000 levels, as a .gltf and as a GLB's JSON chunk, in process and through the worker.
    const auto deep = dir / "deep.gltf";
    std::string json = nested(200000);
    test::write_bytes(deep, json);
    json.append((4 - json.size() % 4) % 4, ' ');
    const auto u32 = [](std::size_t v) {
        std::string out(4, '\0');
        for (int k = 0; k < 4; ++k) out[k] = char((v >> (8 * k)) & 0xff);
        return out;
    };
    const auto glb = dir / "deep.glb";
    test::write_bytes(
        glb, "glTF" + u32(2) + u32(12 + 8 + json.size()) + u32(json.size()) + "JSON" + json);
    for (const LoadIsolation isolation : {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
        SCOPED_TRACE(isolation == LoadIsolation::InProcess ? "in process" : "worker");
        LoadOptions o;
        o.isolation = isolation;
        for (const auto& file : {deep, glb})
            test::expect_input_error([&] { load_scene(file, o); }, file,
                                     "its JSON nests arrays and objects more than 256 levels "
                                     "deep");
    }
}

// A buffer is read whole, whatever its accessors use: a 392-byte file declaring 6 GiB of a sparse
// file reached 6.3 GB. Its byteLength counts, a byte a byte.
TEST(LoadBudgets, AGltfBufferCountsItsWholeByteLength) {
    const auto dir = test::temp_dir("budgets-buffer");
    const auto model = dir / "buffer.gltf";
    const auto with_buffer = [&](std::uint64_t length) {
        std::string json = shared_accessor_gltf(1);
        const std::size_t from = json.find(R"("buffers":)");
        return json.substr(0, from) + R"("buffers":[{"uri":"data.bin","byteLength":)" +
               std::to_string(length) + "}]}";
    };
    std::string data = bytes_of<float>({0, 0, 0, 1, 0, 0, 0, 1, 0});
    data.resize(4096);
    test::write_bytes(dir / "data.bin", data);
    test::write_bytes(model, with_buffer(4096));
    LoadOptions o;
    o.max_geometry_bytes = 180 + 1976 + 1152 + 4096;  // the triangle, its node, the buffer
    EXPECT_EQ(load_scene(model, o).meshes.size(), 1u);
    --o.max_geometry_bytes;
    test::expect_limit_exceeded([&] { load_scene(model, o); }, model, "max_geometry_bytes",
                                "the file decodes to about 7404 bytes in the importer, more than "
                                "max_geometry_bytes (7403 bytes), mostly buffer 0 (byteLength "
                                "4096 bytes, read whole by the importer): about 4096 bytes");
    // 6 GiB of a sparse file: refused with the defaults, before anything is read.
    std::filesystem::resize_file(dir / "data.bin", std::uint64_t{6} << 30);
    test::write_bytes(model, with_buffer(std::uint64_t{6} << 30));
    for (const LoadIsolation isolation : {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
        SCOPED_TRACE(isolation == LoadIsolation::InProcess ? "in process" : "worker");
        LoadOptions defaults;
        defaults.isolation = isolation;
        test::expect_limit_exceeded([&] { load_scene(model, defaults); }, model,
                                    "max_geometry_bytes",
                                    "more than max_geometry_bytes (1024 MiB), mostly buffer 0 "
                                    "(byteLength 6144 MiB, read whole by the importer)");
    }
}

// A triangle (data.bin: positions, then one sparse index and value) and an animation whose
// channels sample `keys` keys (sparse accessors: zeros and one value), `targets` translation
// targets (nodes 0..targets-1 each placing the triangle), `channels` channels per target.
std::string animated_gltf(std::uint64_t keys, int targets, int channels) {
    std::string nodes, roots, list;
    for (int t = 0; t < targets; ++t) {
        nodes += std::string(t ? "," : "") + R"({"mesh":0})";
        roots += std::string(t ? "," : "") + std::to_string(t);
        for (int c = 0; c < channels; ++c)
            list += std::string(list.empty() ? "" : ",") + R"({"sampler":0,"target":{"node":)" +
                    std::to_string(t) + R"(,"path":"translation"}})";
    }
    const std::string sparse =
        R"("sparse":{"count":1,"indices":{"bufferView":1,"componentType":5125},)"
        R"("values":{"bufferView":2}})";
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[)" + roots +
           R"(]}],"nodes":[)" + nodes +
           R"(],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"accessors":[)"
           R"({"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],)"
           R"("max":[1,1,0]},{"componentType":5126,"count":)" +
           std::to_string(keys) + R"(,"type":"SCALAR","min":[0],"max":[1],)" + sparse +
           R"(},{"componentType":5126,"count":)" + std::to_string(keys) + R"(,"type":"VEC3",)" +
           sparse +
           R"(}],"bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,)"
           R"("byteLength":4},{"buffer":0,"byteOffset":40,"byteLength":12}],)"
           R"("buffers":[{"uri":"data.bin","byteLength":52}],)"
           R"("animations":[{"samplers":[{"input":1,"output":2}],"channels":[)" +
           list + "]}]}";
}

// Accessors no primitive reads were outside the budget: a 998-byte file whose one channel samples
// a sparse accessor of 10^8 keys reached 7.5 GB. Each channel target's keys count (216 bytes a
// key), and a sparse accessor's dense copy once (4 bytes a time, 12 a translation).
TEST(LoadBudgets, AnimationKeysAreCountedPerChannelTarget) {
    const auto dir = test::temp_dir("budgets-animation");
    test::write_bytes(dir / "data.bin", bytes_of<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}) +
                                            std::string(4, '\0') + bytes_of<float>({1, 1, 1}));
    const auto model = dir / "animated.gltf";
    // 1,000 keys, one target named by 50 channels (the importer keeps one): 1000 x (216 + 16),
    // the triangle (180), its node (1152) and the buffer (52).
    test::write_bytes(model, animated_gltf(1000, 1, 50));
    LoadOptions o;
    o.max_geometry_bytes = 232000 + 180 + 1976 + 1152 + 52;
    EXPECT_EQ(load_scene(model, o).meshes.size(), 1u);
    --o.max_geometry_bytes;
    test::expect_limit_exceeded([&] { load_scene(model, o); }, model, "max_geometry_bytes",
                                "mostly the animations' 1000 keys (over 1 target of their "
                                "channels): about 232000 bytes");
    // Two targets of the same sampler: its keys twice, its dense copies once.
    const auto two = dir / "two.gltf";
    test::write_bytes(two, animated_gltf(1000, 2, 1));
    o.max_geometry_bytes = 448000 + 180 + 1976 + 2 * 1152 + 52;  // one primitive, two nodes
    EXPECT_EQ(load_scene(two, o).instances.size(), 2u);
    --o.max_geometry_bytes;
    test::expect_limit_exceeded([&] { load_scene(two, o); }, two, "max_geometry_bytes",
                                "mostly the animations' 2000 keys (over 2 targets");
    const auto huge = dir / "huge.gltf";
    test::write_bytes(huge, animated_gltf(100000000, 1, 1));
    for (const LoadIsolation isolation : {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
        SCOPED_TRACE(isolation == LoadIsolation::InProcess ? "in process" : "worker");
        LoadOptions defaults;
        defaults.isolation = isolation;
        test::expect_limit_exceeded([&] { load_scene(huge, defaults); }, huge, "max_geometry_bytes",
                                    "the file decodes to about 22125 MiB in the importer, more "
                                    "than max_geometry_bytes (1024 MiB), mostly the animations' "
                                    "100000000 keys");
    }
}

// A skinned triangle (JOINTS_0, WEIGHTS_0) whose skin lists `joints` distinct joint nodes and
// `matrices` inverse bind matrices (a sparse accessor; as many as joints by default), its node
// placed 2^levels times by nodes holding the one below twice.
std::string skinned_gltf(int joints, int levels, std::uint64_t matrices = 0) {
    std::string nodes, roots = "0", joint_list;
    for (int level = 0; level < levels; ++level)
        nodes += R"({"children":[)" + std::to_string(level + 1) + "," + std::to_string(level + 1) +
                 "]},";
    nodes += R"({"mesh":0,"skin":0})";
    for (int j = 0; j < joints; ++j) {
        const std::string index = std::to_string(levels + 1 + j);
        nodes += R"(,{"name":"j)" + std::to_string(j) + "\"}";
        roots += "," + index;
        joint_list += std::string(j ? "," : "") + index;
    }
    const std::string ibm = R"(,"inverseBindMatrices":3)";
    const std::string ibm_accessor =
        R"(,{"componentType":5126,"count":)" +
        std::to_string(matrices == 0 ? std::uint64_t(joints) : matrices) +
        R"(,"type":"MAT4","sparse":{"count":1,"indices":{"bufferView":3,)"
        R"("componentType":5125},"values":{"bufferView":4}}})";
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[)" + roots +
           R"(]}],"nodes":[)" + nodes +
           R"(],"meshes":[{"primitives":[{"attributes":{"POSITION":0,"JOINTS_0":1,)"
           R"("WEIGHTS_0":2}}]}],"skins":[{"joints":[)" +
           joint_list + "]" + ibm +
           R"(}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
           R"("min":[0,0,0],"max":[1,1,0]},{"bufferView":1,"componentType":5123,"count":3,)"
           R"("type":"VEC4"},{"bufferView":2,"componentType":5126,"count":3,"type":"VEC4"})" +
           ibm_accessor +
           R"(],"bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,)"
           R"("byteLength":24},{"buffer":0,"byteOffset":60,"byteLength":48},{"buffer":0,)"
           R"("byteOffset":108,"byteLength":4},{"buffer":0,"byteOffset":112,"byteLength":64}],)"
           R"("buffers":[{"uri":"data.bin","byteLength":176}]})";
}

// The importer makes a bone per joint (1,178 bytes) for each placement of a skinned primitive,
// and a weight (8 bytes) per joint influence of a vertex: 2,000 joints placed 4,096 times by a
// 61 KB file reached 7.8 GB.
TEST(LoadBudgets, SkinBonesAreCountedPerPlacement) {
    const auto dir = test::temp_dir("budgets-skin");
    std::string data =
        bytes_of<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}) +
        bytes_of<std::uint16_t>({0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3}) +
        bytes_of<float>({.25f, .25f, .25f, .25f, .25f, .25f, .25f, .25f, .25f, .25f, .25f, .25f}) +
        std::string(4, '\0') + bytes_of<float>({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
    test::write_bytes(dir / "data.bin", data);
    const auto model = dir / "skinned.gltf";
    // 4 joints placed 4 times: 4 x (4 x 1178 + 12 x 8) = 19232 bytes, and 4 inverse bind
    // matrices (a sparse accessor's dense copy and the importer's: 4 x 128); the primitive's 3
    // attributes and drawn indices (3 x 3 x 24 + 3 x 36 = 324) and itself (1976), 11 nodes copied
    // (the three above once, twice and four times, 4 joints: 12672) and the buffer (176).
    test::write_bytes(model, skinned_gltf(4, 2));
    LoadOptions o;
    o.max_geometry_bytes = 19232 + 512 + 324 + 1976 + 12672 + 176;
    EXPECT_EQ(load_scene(model, o).instances.size(), 4u);
    --o.max_geometry_bytes;
    test::expect_limit_exceeded([&] { load_scene(model, o); }, model, "max_geometry_bytes",
                                "mostly the skins' 16 bones (a bone per joint for each of 4 "
                                "placements of a skinned primitive: the importer makes them each "
                                "time) and 4 inverse bind matrices: about 19744 bytes");
    const auto many = dir / "many.gltf";
    test::write_bytes(many, skinned_gltf(2000, 12));
    const auto matrices = dir / "matrices.gltf";
    test::write_bytes(matrices, skinned_gltf(1, 0, 100000000));
    for (const LoadIsolation isolation : {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
        SCOPED_TRACE(isolation == LoadIsolation::InProcess ? "in process" : "worker");
        LoadOptions defaults;
        defaults.isolation = isolation;
        test::expect_limit_exceeded([&] { load_scene(many, defaults); }, many, "max_geometry_bytes",
                                    "mostly the skins' 8192000 bones (a bone per joint for each "
                                    "of 4096 placements");
        // Inverse bind matrices: read once (a sparse accessor made dense) and copied, 128 bytes a
        // matrix.
        test::expect_limit_exceeded([&] { load_scene(matrices, defaults); }, matrices,
                                    "max_geometry_bytes",
                                    "the file decodes to about 12207 MiB in the importer, more "
                                    "than max_geometry_bytes (1024 MiB), mostly the skins' 1 "
                                    "bones (a bone per joint for each of 1 placements of a "
                                    "skinned primitive: the importer makes them each time) and "
                                    "100000000 inverse bind matrices");
    }
}

// A material a primitive uses costs the import about 13 KB: 200,000 primitives of an 11 MB file,
// each with its own empty material, reached 3.09 GB. Counted once per material used.
TEST(LoadBudgets, MaterialsThePrimitivesUseAreCounted) {
    const auto dir = test::temp_dir("budgets-materials");
    std::string json = shared_accessor_gltf(10);
    for (int p = 0, at = 0; p < 10; ++p) {
        at = int(json.find(R"({"attributes")", std::size_t(at)));
        json.insert(std::size_t(at) + 1, R"("material":)" + std::to_string(p % 5) + ",");
        at += 2;
    }
    json.insert(1, R"("materials":[{},{},{},{},{}],)");
    const auto model = dir / "materials.gltf";
    test::write_bytes(model, json);
    LoadOptions o;
    o.max_geometry_bytes = 22748 + 5 * 13346;  // 5 materials used (twice each)
    EXPECT_EQ(load_scene(model, o).meshes.size(), 10u);
    --o.max_geometry_bytes;
    test::expect_limit_exceeded([&] { load_scene(model, o); }, model, "max_geometry_bytes",
                                "mostly the primitives' 5 materials: about 66730 bytes");
}

// A cells file's meshes: one file under many spellings is loaded once (1,000 spellings of a
// 100,000-triangle file were 1,000 loads, 3 GB), and the triangles the instances place are
// counted as the files load (refused before the rest are read).
TEST(LoadBudgets, CellsMeshFilesAreLoadedOnceAndCountedAsTheyLoad) {
    const auto dir = test::temp_dir("budgets-cells-spellings");
    std::filesystem::create_directories(dir / "d");
    test::write_bytes(dir / "t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n");
    const char* const spellings[] = {"t.obj", "./t.obj", "d/../t.obj", "././d/../t.obj"};
    const auto cells = [&] {
        std::string names, instances, listed;
        for (int k = 0; k < 4; ++k) {
            const std::string comma = k ? "," : "", n = std::to_string(k);
            names += comma + "\"m" + n + "\":\"" + spellings[k] + "\"";
            instances += comma + "{\"name\":\"i" + n + "\",\"mesh\":\"m" + n + "\"}";
            listed += comma + "\"i" + n + "\"";
        }
        return R"({"zraster_cells":1,"meshes":{)" + names + R"(},"instances":[)" + instances +
               R"(],"cells":[{"name":"a","box":[[-5,-5,-5],[5,5,5]],"instances":[)" + listed +
               "]}]}";
    };
    const auto path = dir / "s.cells.json";
    test::write_bytes(path, cells());
    const Scene scene = load_scene(path);
    EXPECT_EQ(scene.meshes.size(), 1u);  // one file, four spellings
    EXPECT_EQ(scene.instances.size(), 4u);
    EXPECT_EQ(scene.triangle_count(), 8u);
    LoadOptions few;
    few.max_triangles = 5;  // the third instance's mesh passes it
    test::expect_limit_exceeded([&] { load_scene(path, few); }, path, "max_triangles",
                                "meshes.m2: with the meshes before it, its 1 instances place "
                                "more than max_triangles (5) triangles");
}

}  // namespace
}  // namespace zraster
