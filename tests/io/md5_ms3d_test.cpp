// MD5 meshes and MS3D files whose importers trusted their indices (issue 27, hostile run 6's
// M21): a triangle index of -1 (an assertion), a vertex naming weights past the mesh's (SIGSEGV),
// triangles over no vertices (SIGSEGV), refused by name before the import.
#include <zraster/load.hpp>

#include <string>
#include <utility>

#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

namespace zraster {
namespace {

std::string md5(const std::string& verts, const std::string& tri) {
    return "MD5Version 10\ncommandline \"\"\nnumJoints 1\nnumMeshes 1\njoints {\n\"root\" -1 ( 0 0 "
           "0 ) ( 0 0 0 )\n}\nmesh {\nshader \"x\"\nnumverts 3\n" +
           verts + "numtris 1\n" + tri +
           "numweights 3\nweight 0 0 1 ( 0 0 0 )\nweight 1 0 1 ( 1 0 0 )\nweight 2 0 1 ( 0 1 0 "
           ")\n}\n";
}

const std::string kVerts = "vert 0 ( 0 0 ) 0 1\nvert 1 ( 0 0 ) 1 1\nvert 2 ( 0 0 ) 2 1\n";

TEST(GameFormats, Md5IndicesAndWeightsAreCheckedBeforeTheImport) {
    const auto dir = test::temp_dir("md5");
    const std::pair<std::string, std::string> cases[] = {
        {md5(kVerts, "tri 0 0 1 -1\n"),
         "malformed MD5 file: line 15: triangle index '-1' is not one of the mesh's 3 vertices"},
        {md5(kVerts, "tri 0 0 1 3\n"),
         "malformed MD5 file: line 15: triangle index '3' is not one of the mesh's 3 vertices"},
        {md5("vert 0 ( 0 0 ) 0 1\nvert 1 ( 0 0 ) 1 1\nvert 2 ( 0 0 ) 2 60000\n", "tri 0 0 1 2\n"),
         "malformed MD5 file: line 13: a vertex's weights 2..60002 are past the mesh's 3 "
         "weights"},
    };
    int k = 0;
    for (const auto& [text, cause] : cases) {
        SCOPED_TRACE(cause);
        const auto path = dir / ("m" + std::to_string(k++) + ".md5mesh");
        test::write_bytes(path, text);
        test::expect_refused_both_ways(path, cause);
    }
}

// An MS3D file's start: the header, `vertices` vertices of 15 zero bytes, `triangles` declared,
// then `records` triangles of 70 bytes naming vertices 0, 1 and `last`.
std::string ms3d(int vertices, int triangles, int records, int last) {
    std::string s = "MS3D000000" + std::string("\x04\x00\x00\x00", 4);
    s += static_cast<char>(vertices);
    s += '\0';
    s += std::string(std::size_t(vertices) * 15, '\0');
    s += static_cast<char>(triangles);
    s += '\0';
    for (int t = 0; t < records; ++t) {
        std::string record(70, '\0');
        record[4] = 1;
        record[6] = static_cast<char>(last);
        s += record;
    }
    return s;
}

TEST(GameFormats, Ms3dTrianglesAreCheckedBeforeTheImport) {
    const auto dir = test::temp_dir("ms3d");
    const std::pair<std::string, std::string> cases[] = {
        {ms3d(0, 1, 1, 0),
         "malformed MS3D file: triangle 0 names vertex 0, the file has 0 vertices"},
        {ms3d(3, 1, 1, 9),
         "malformed MS3D file: triangle 0 names vertex 9, the file has 3 vertices"},
        {ms3d(3, 5, 1, 2),
         "truncated or malformed MS3D file: it declares 5 triangles of 70 bytes, more than the "
         "file holds"},
    };
    int k = 0;
    for (const auto& [bytes, cause] : cases) {
        SCOPED_TRACE(cause);
        const auto path = dir / ("m" + std::to_string(k++) + ".ms3d");
        test::write_bytes(path, bytes);
        test::expect_refused_both_ways(path, cause);
    }
}

}  // namespace
}  // namespace zraster
