// Bad inputs: each is refused with one line naming the file and the cause, quickly, without a
// crash or a huge allocation.
#include <zraster/load.hpp>

#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

#include <chrono>

namespace zraster {
namespace {

const char* kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

std::filesystem::path errors_fixture(const std::string& test, const std::string& name,
                                     std::string_view content) {
    return test::write_fixture("io-errors-" + test, name, content);
}

void expect_load_error(const std::filesystem::path& path, std::string_view cause) {
    test::expect_input_error([&] { load_scene(path); }, path, cause);
}

TEST(LoadErrors, MissingFile) {
    const auto path = test::temp_dir("io-errors-missing") / "nothing.obj";
    expect_load_error(path, "file not found");
}

// A link loop or a dangling link is named as what it is, not "file not found".
TEST(LoadErrors, LinkLoopAndDanglingLink) {
    const auto dir = test::temp_dir("io-errors-links");
    std::filesystem::create_symlink("b.obj", dir / "a.obj");
    std::filesystem::create_symlink("a.obj", dir / "b.obj");
    std::filesystem::create_symlink("nothing.obj", dir / "dangling.obj");
    expect_load_error(dir / "a.obj", "is a loop of symbolic links");
    expect_load_error(dir / "dangling.obj", "is a symbolic link to a file that does not exist");
}

TEST(LoadErrors, Directory) {
    const auto dir = test::temp_dir("io-errors-dir") / "model.obj";
    std::filesystem::create_directory(dir);
    expect_load_error(dir, "not a regular file");
}

TEST(LoadErrors, EmptyFile) {
    expect_load_error(errors_fixture("empty", "empty.obj", ""), "empty file");
}

TEST(LoadErrors, TooLargeForTheLimit) {
    const auto path = errors_fixture("limit-bytes", "tri.obj", kTriangleObj);
    LoadOptions options;
    options.max_file_bytes = 10;
    test::expect_input_error([&] { load_scene(path, options); }, path, "file too large");
}

TEST(LoadErrors, UnknownExtensionWithGarbage) {
    std::string garbage;
    for (int i = 0; i < 4096; ++i) garbage.push_back(static_cast<char>((i * 7919) % 251));
    expect_load_error(errors_fixture("garbage", "model.xyzzy", garbage),
                      "no importer recognises its contents as a XYZZY file");
}

TEST(LoadErrors, TruncatedBinaryStl) {
    ZRASTER_REQUIRE_SHARED_DATA();
    const std::string stl = test::read_bytes(test::shared_data("meshes/stl/Spider_binary.stl"));
    expect_load_error(errors_fixture("stl", "half.stl", stl.substr(0, stl.size() / 2)),
                      "nor a binary STL (84 + 50 x triangles bytes; its header declares 1368 "
                      "triangles, 68484 bytes), this file has 34242 bytes");
}

TEST(LoadErrors, TruncatedGlb) {
    ZRASTER_REQUIRE_SHARED_DATA();
    const std::string glb = test::read_bytes(test::shared_data("meshes/gltf/Duck.glb"));
    const std::pair<std::size_t, const char*> cuts[] = {
        {glb.size() / 2, "truncated or malformed GLB file: GLB chunk 1 declares 118344 bytes"},
        {100, "truncated or malformed GLB file: GLB chunk 0 declares 2112 bytes"},
        {11, "truncated: a binary glTF (GLB) file starts with a 12-byte header, this file has 11"},
    };
    for (const auto& [keep, cause] : cuts) {
        SCOPED_TRACE(keep);
        expect_load_error(errors_fixture("glb", "cut.glb", glb.substr(0, keep)), cause);
    }
}

TEST(LoadErrors, ObjFaceIndexBeyondTheVertices) {
    expect_load_error(
        errors_fixture("obj-index", "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n"),
        "index out of range");
}

TEST(LoadErrors, PlyFaceIndexBeyondTheVertices) {
    expect_load_error(errors_fixture("ply-index", "bad.ply",
                                     "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                     "property float y\nproperty float z\nelement face 1\n"
                                     "property list uchar int vertex_indices\nend_header\n"
                                     "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"),
                      "face 0 names vertex 7, but the file has 3 vertices");
}

TEST(LoadErrors, ObjNaNAndInfinity) {
    expect_load_error(errors_fixture("nan", "nan.obj", "v 0 0 0\nv 1 0 0\nv nan 0 0\nf 1 2 3\n"),
                      "non-finite vertex coordinates (mesh defaultobject, vertex 2)");
    // 1e999 overflows to infinity when parsed.
    expect_load_error(errors_fixture("inf", "inf.obj", "v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n"),
                      "non-finite vertex coordinates (mesh defaultobject, vertex 1)");
}

TEST(LoadErrors, GltfWithInfinitePositions) {
    ZRASTER_REQUIRE_SHARED_DATA();
    const auto path = test::shared_data("meshes/gltf/BoxWithInfinites.glb");
    expect_load_error(path, "non-finite vertex coordinates (mesh Mesh, vertex 0)");
}

// A few bytes claiming 2^40 records: refused from the header, before Assimp reserves memory
// (it would try to allocate terabytes, or run for minutes on 3e8 records).
TEST(LoadErrors, PlyHeaderCountsBeyondTheFileSize) {
    const std::string header_start =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\n";
    const std::string face_list = "property list uchar int vertex_indices\nend_header\n";
    const std::string body = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    const auto start = std::chrono::steady_clock::now();
    expect_load_error(
        errors_fixture("ply-huge", "huge.ply",
                       header_start + "element face 1099511627776\n" + face_list + body),
        "truncated or malformed file: the PLY header declares 1099511627776 face records");
    expect_load_error(
        errors_fixture("ply-huge-vertices", "huge.ply",
                       "ply\nformat binary_little_endian 1.0\nelement vertex 300000000\n"
                       "property float x\nproperty float y\nproperty float z\n"
                       "element face 1\n" +
                           face_list + std::string(49, '\0')),
        "the PLY header declares 300000000 vertex records");
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
}

TEST(LoadErrors, OffHeaderCountsBeyondTheFileSize) {
    expect_load_error(errors_fixture("off-huge", "huge.off",
                                     "OFF\n3 300000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
                      "the OFF header declares 300000000 face records");
}

// Fewer faces than the header says: Debian's Assimp (assertions enabled) would abort in its
// triangulation; validating the structure first turns this into an error.
TEST(LoadErrors, OffBodyShorterThanItsHeader) {
    expect_load_error(
        errors_fixture("off-short", "short.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
        "a face without vertex indices (fewer face records than the header declares?)");
}

TEST(LoadErrors, OnlyPointsAndLines) {
    expect_load_error(
        errors_fixture("lines", "lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\np 1\n"),
        "no triangles");
    expect_load_error(
        errors_fixture("points-ply", "points.ply",
                       "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
                       "property float y\nproperty float z\nend_header\n0 0 0\n1 0 0\n"),
        "no triangles");
    expect_load_error(errors_fixture("vertices-only", "v.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"),
                      "no triangles");
}

TEST(LoadErrors, EveryTriangleWithoutArea) {
    const std::string cause = "every one of its 3 triangles has zero area";
    // Repeated corners, collinear corners, one point: in zraster's OBJ reader and through Assimp.
    const char* const objs[] = {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 1 1\nf 2 2 2\nf 3 3 3\n",
                                "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\nf 3 2 1\nf 1 3 2\n",
                                "v 5 5 5\nv 5 5 5\nv 5 5 5\nf 1 2 3\nf 2 3 1\nf 3 1 2\n"};
    for (const char* obj : objs)
        expect_load_error(errors_fixture("degenerate", "d.obj", obj), cause);
    const std::string ply =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 3\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 1 1\n2 2 2\n3 0 1 2\n3 2 1 0\n3 0 0 1\n";
    for (const LoadIsolation isolation : {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
        LoadOptions options;
        options.isolation = isolation;
        const auto path = errors_fixture("degenerate-ply", "d.ply", ply);
        test::expect_input_error([&] { load_scene(path, options); }, path, cause);
    }
    // Flattened by its placement: a glTF node scaled by 0.
    const std::string gltf =
        R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
        R"("nodes":[{"mesh":0,"scale":[0,0,0]}],"meshes":[{"primitives":[{"attributes":)"
        R"({"POSITION":0}}]}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,)"
        R"("type":"VEC3","min":[0,0,0],"max":[1,1,0]}],"bufferViews":[{"buffer":0,)"
        R"("byteLength":36}],"buffers":[{"byteLength":36,"uri":"data:application/)"
        R"(octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]})";
    expect_load_error(errors_fixture("degenerate-placed", "flat.gltf", gltf),
                      "every one of its 1 triangles has zero area as placed");
    // One triangle with an area among them is a scene (the rasterizer skips the others).
    EXPECT_EQ(load_scene(errors_fixture("degenerate-one", "d.obj",
                                        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 1 1\nf 1 2 3\n"))
                  .meshes.at(0)
                  .indices.size(),
              6u);
    // Corners a float apart near 1e-30 still make an area.
    EXPECT_NO_THROW(load_scene(errors_fixture("degenerate-tiny", "t.obj",
                                              "v 0 0 0\nv 1e-30 0 0\nv 0 1e-30 0\nf 1 2 3\n")));
}

TEST(LoadErrors, TooManyTriangles) {
    const auto path = errors_fixture("limit-triangles", "two.obj",
                                     "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n");
    LoadOptions options;
    options.max_triangles = 1;
    test::expect_input_error([&] { load_scene(path, options); }, path,
                             "too many triangles (2, limit 1)");
    options.max_triangles = 2;
    EXPECT_EQ(load_scene(path, options).triangle_count(), 2u);
}

}  // namespace
}  // namespace zraster
