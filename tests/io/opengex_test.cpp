// OpenGEX meshes the importer trusted (issue 27, hostile run 6's M18 and M19): indices past the
// vertices (an assertion; one equal to their count was read from past the array and drawn),
// vertex arrays of other lengths, faces of other than 3 indices, empty or 2-wide positions,
// references to no structure and structures nested past 1,000 levels are refused by name.
#include <zraster/load.hpp>

#include <string>
#include <utility>

#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

namespace zraster {
namespace {

// One mesh: `arrays` inside its Mesh structure; the node refers to `reference`.
std::string opengex(const std::string& arrays, const std::string& reference = "$g") {
    return "GeometryNode { ObjectRef {ref {" + reference + "}} }\nGeometryObject $g { Mesh {\n" +
           arrays + "\n} }\n";
}

const std::string kPositions =
    R"(VertexArray (attrib = "position") { float[3] { {0, 0, 0}, {1, 0, 0}, {0, 1, 0} } })";

std::string indices(const std::string& data) {
    return "IndexArray { " + data + " }";
}

// `levels` Metric structures, each inside the one before.
std::string nested(int levels) {
    std::string s;
    for (int k = 0; k < levels; ++k) s += "Metric { ";
    for (int k = 0; k < levels; ++k) s += "} ";
    return s;
}

TEST(OpenGex, MeshesAreCheckedBeforeTheImport) {
    const auto dir = test::temp_dir("opengex");
    const std::pair<std::string, std::string> cases[] = {
        {opengex(kPositions + indices("unsigned_int32[3] { {0, 1, 2} }")), ""},
        {opengex(kPositions + indices("unsigned_int32[3] { {0, 1, 3} }")),
         "line 3: index '3' is not one of the mesh's 3 vertices"},
        {opengex(kPositions + indices("unsigned_int32[3] { {0, 1, 4000000000} }")),
         "line 3: index '4000000000' is not one of the mesh's 3 vertices"},
        {opengex(kPositions + indices("unsigned_int32[2] { {0, 1}, {2, 0} }")),
         "line 3: an index array of 2 (faces are triangles: [3])"},
        {opengex(R"(VertexArray (attrib = "position") { float[3] { } })" +
                 indices("unsigned_int32[3] { {0, 1, 2} }")),
         "line 3: vertex array 'position' is empty"},
        {opengex(R"(VertexArray (attrib = "position") { float[2] { {0, 0}, {1, 0}, {0, 1} } })" +
                 indices("unsigned_int32[3] { {0, 1, 2} }")),
         "line 3: the position array's elements are 2 numbers; x y z are needed ([3])"},
        {opengex(kPositions + R"(VertexArray (attrib = "normal") { float[3] { {0, 0, 1} } })" +
                 indices("unsigned_int32[3] { {0, 1, 2} }")),
         "line 3: vertex array 'normal' has 1 elements, the positions 3"},
        {opengex(kPositions + indices("unsigned_int32[3] { {0, 1, 2} }"), "$nosuch"),
         "line 1: a reference to $nosuch, which no structure is named"},
        {nested(1001), "line 1: structures nest more than 1000 levels deep"},
        // Types the importer does not read: its parser asserted, or read zeros.
        {opengex(kPositions + indices("unsigned_int16[3] { {0, 1, 2} }")),
         "line 3: an index array of unsigned_int16: the importer reads unsigned_int32 indices "
         "only"},
        {opengex(
             R"(VertexArray (attrib = "position") { double[3] { {0, 0, 0}, {1, 0, 0}, {0, 1, 0} } })" +
             indices("unsigned_int32[3] { {0, 1, 2} }")),
         "line 3: a vertex array of double: the importer reads float arrays only"},
    };
    int k = 0;
    for (const auto& [text, cause] : cases) {
        SCOPED_TRACE(cause);
        const auto path = dir / ("m" + std::to_string(k++) + ".ogex");
        test::write_bytes(path, text);
        if (!cause.empty()) {
            test::expect_refused_both_ways(path, "malformed OpenGEX file: " + cause);
            continue;
        }
        for (const LoadIsolation isolation : test::kBothIsolations) {
            LoadOptions o;
            o.isolation = isolation;
            EXPECT_EQ(load_scene(path, o).triangle_count(), 1u);
        }
    }
}

}  // namespace
}  // namespace zraster
