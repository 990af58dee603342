// Inputs the fuzzers (fuzz/, RELIABILITY.md) found to crash, hang, exhaust memory or break a
// promise of the loader, each minimized and kept inline: they must now load or be refused with a
// one-line InputError, quickly.
#include <zraster/error.hpp>
#include <zraster/load.hpp>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

namespace zraster {
namespace {

// Loads `content` as `name`: it must be refused, with `cause` in the message, within a second.
void expect_refused(const std::string& test, const std::string& name, std::string_view content,
                    std::string_view cause) {
    const auto path = test::write_fixture("io-fuzz-" + std::string(test), name, content);
    const auto start = std::chrono::steady_clock::now();
    test::expect_input_error([&] { load_scene(path); }, path, cause);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
}

template <typename T>
void append(std::string& out, const T& value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

// fuzz_load_stl: a vertical tab (or form feed) between tokens of an ASCII STL was a blank the
// structure check's token loop stopped at but did not skip: it never moved on (a hang).
TEST(FuzzRegressions, StlVerticalTabBetweenTokens) {
    expect_refused("stl-vtab", "vtab.stl",
                   "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\v\n   vertex 1 0 "
                   "0\n  endloop\n endfacet\nendsolid x\n",
                   "has 2 vertices; STL facets have 3");
}

// fuzz_load_ply: Assimp takes a file for PLY by its first three bytes in any case ("plyply",
// "PLY"); the declared-count check wanted "ply" and white space, so the header of a 691-byte file
// of two headers run together reached Assimp unchecked, which asked for 4 GB (in process; the
// worker ran out of memory). Refused by its counts now, in process, in a second.
TEST(FuzzRegressions, PlyMagicAsAssimpReadsIt) {
    const std::string header =
        "\nformat ascii 1.0\nelement vertex 400000000\nproperty float x\n"
        "property float y\nproperty float z\nend_header\n0 0 0\n";
    for (const std::string magic : {"plyply", "PLY", "Ply"}) {
        SCOPED_TRACE(magic);
        expect_refused("ply-magic", "two.ply", magic + header,
                       "the PLY header declares 400000000 vertex records, more than its 6 bytes "
                       "of data can hold");
    }
}

// fuzz_load_off: "OFF4294967295" declares 4294967295 vertices to Assimp (no separator needed
// after the keyword); it allocated 48 GiB.
TEST(FuzzRegressions, OffCountGluedToTheKeyword) {
    expect_refused("off-glued", "glued.off", "OFF4294967295\n3 2 0\n0 0 0\n1 0 0\n",
                   "the OFF header declares 4294967295 vertex records");
}

// fuzz_load_off: Assimp reads the leading digits of "1099511627-776" (16 GiB of faces); the
// check used to give up on the token instead.
TEST(FuzzRegressions, OffCountWithTrailingGarbage) {
    expect_refused("off-garbage", "garbage.off", "OFF\n3 1099511627-776 0\n0 0 0\n1 0 0\n",
                   "the OFF header declares 1099511627 face records");
}

// fuzz_load_off: a face line of 0 indices makes Assimp 5.2.5 decrement its face count without
// advancing; a second one wrapped it to 2^32 - 1 and the importer crashed (SEGV) freeing faces.
TEST(FuzzRegressions, OffFaceWithoutIndices) {
    expect_refused("off-zero-face", "zero.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n0\nx",
                   "OFF face record 0 has 0 vertex indices (1 to 9 are supported)");
    expect_refused("off-zero-face-minimal", "minimal.off", "1 1 0 0 0 2\n0\nN",
                   "OFF face record 0 has 0 vertex indices");
    expect_refused("off-big-face", "big.off",
                   "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n12 0 1 2 0 1 2 0 1 2 0 1 2\n",
                   "OFF face record 0 has 12 vertex indices");
}

// fuzz_load_ply: Assimp 5.2.5 reads a PLY header without end_header forever (a hang, at any
// element count).
TEST(FuzzRegressions, PlyHeaderWithoutEnd) {
    const char* cause = "no end_header line in the PLY header";
    expect_refused("ply-no-end", "open.ply",
                   "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n", cause);
    expect_refused("ply-end-typo", "typo.ply",
                   "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_headerx\n0\n",
                   cause);
    // A count without digits used to end the check early, before the end_header test; it is
    // refused itself now.
    expect_refused("ply-count-letters", "letters.ply",
                   "ply\nformat binary_little_endian 1.0\nelement face t x\nproperty float z\n"
                   "element face 1\npr\n",
                   "element 'face' declares the count 't', not a number of 0 or more");
}

// fuzz_load_ply: Assimp resizes a list to its declared length before reading it: a binary
// length of 0x3ff00000 asked for 8 GiB (and RSS reached it) in a 400-byte file. A property line
// after a stray line belongs to no element in Assimp's reading, which the check now follows.
TEST(FuzzRegressions, PlyListLongerThanTheFile) {
    std::string binary =
        "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty double x\n"
        "999999property double y\nproperty double z\nelement face 1\n"
        "property list uint ushort vertex_indices\nend_header\n";
    binary += std::string(24, '\0');
    binary += std::string("\x3f\xf0\0\0", 4) + std::string(16, '\0');
    expect_refused("ply-binary-list", "list.ply", binary,
                   "a PLY face record holds a list of 1072693248 entries");
    expect_refused("ply-ascii-list", "ascii.ply",
                   "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                   "property float z\nelement face 1\nproperty list uint int vertex_indices\n"
                   "end_header\n0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n",
                   "a PLY face record holds a list of 4000000000 entries");
}

// fuzz_load_gltf: Assimp allocates a GLB chunk's declared length before reading it (a JSON
// chunk of 1,929,380,992 bytes in a 2.8 KB file).
TEST(FuzzRegressions, GlbChunkLongerThanTheFile) {
    std::string glb("glTF\x02\0\0\0\x40\0\0\0", 12);
    glb += std::string("\x80\x0b\x00\x73JSON", 8);
    glb += R"({"asset":{"version":"2.0"}})";
    expect_refused("glb-chunk", "chunk.glb", glb,
                   "GLB chunk 0 declares 1929382784 bytes, more than the 27 left in the file");
}

// A GLB whose header declares more bytes than the file holds (0xFFFFFFFF): Assimp said "No
// suitable reader found".
TEST(FuzzRegressions, GlbHeaderLongerThanTheFile) {
    const std::string json = R"({"asset":{"version":"2.0"}} )";  // 28 bytes, a multiple of 4
    std::string glb("glTF\x02\0\0\0\xff\xff\xff\xff", 12);
    glb += std::string("\x1c\0\0\0JSON", 8) + json;
    expect_refused("glb-length", "length.glb", glb,
                   "the GLB header declares 4294967295 bytes, the file holds 48 (truncated?)");
}

// fuzz_load_gltf: Assimp copied an accessor's bytes without checking them against its buffer
// view: 72 VEC3 floats from byte 1 of an 864-byte view read one byte past the buffer
// (heap-buffer-overflow in Assimp's memcpy).
TEST(FuzzRegressions, GltfAccessorPastItsBufferView) {
    const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};  // a triangle with an area
    const std::string buffer(reinterpret_cast<const char*>(xyz), sizeof xyz);
    const auto gltf = [&](const std::string& accessor_offset, const std::string& view_length) {
        return R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":)"
               R"("data:application/octet-stream;base64,)" +
               test::base64(buffer) + R"("}],"bufferViews":[{"buffer":0,"byteLength":)" +
               view_length + R"(}],"accessors":[{"bufferView":0,"byteOffset":)" + accessor_offset +
               R"(,"componentType":5126,"count":3,"type":"VEC3"}],"meshes":[{"primitives":)"
               R"([{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],)"
               R"("scene":0})";
    };
    expect_refused("gltf-accessor", "accessor.gltf", gltf("1", "36"),
                   "glTF accessor 0 reads 3 elements of 12 bytes from byte 1 of buffer view 0, "
                   "which holds 36");
    expect_refused("gltf-view", "view.gltf", gltf("0", "40"),
                   "glTF buffer view 0 spans bytes 0 + 40 of buffer 0, which holds 36");
    EXPECT_NO_THROW(
        load_scene(test::write_fixture("io-fuzz-gltf-fits", "fits.gltf", gltf("0", "36"))));
}

// fuzz_load_gltf: file normals with tiny components were normalized in float, where their
// squares are denormal: (1e-22, 0, 1e-20) came out 6% too long. load.hpp promises unit normals.
TEST(FuzzRegressions, TinyFileNormalsComeOutUnitLength) {
    std::string buffer;
    for (float f : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) append(buffer, f);
    for (int v = 0; v < 3; ++v)
        for (float f : {1e-22f, 0.f, 1e-20f}) append(buffer, f);
    const std::string gltf =
        R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":72,"uri":)"
        R"("data:application/octet-stream;base64,)" +
        test::base64(buffer) +
        R"("}],"bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,)"
        R"("byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,)"
        R"("type":"VEC3","min":[0,0,0],"max":[1,1,0]},{"bufferView":1,"componentType":5126,)"
        R"("count":3,"type":"VEC3"}],"meshes":[{"primitives":[{"attributes":{"POSITION":0,)"
        R"("NORMAL":1}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0})";
    const Scene scene = load_scene(test::write_fixture("io-fuzz-tiny-normals", "tiny.gltf", gltf));
    ASSERT_EQ(scene.meshes.size(), 1u);
    ASSERT_EQ(scene.meshes[0].normals.size(), 3u);
    for (const glm::vec3& n : scene.meshes[0].normals) {
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
        EXPECT_NEAR(n.z, 1.0f, 1e-3f);
    }
}

// fuzz_load_gltf: stb_image quotes the bytes of an unknown PNG chunk type in its failure reason,
// so a chunk named "\n\nAB" made a warning of three lines.
TEST(FuzzRegressions, TextureDecodeWarningIsOneLine) {
    std::string png("\x89PNG\r\n\x1a\n", 8);
    const auto chunk = [&](std::string_view type, std::string_view data) {
        const std::uint32_t n = std::uint32_t(data.size());
        const char length[4] = {char(n >> 24), char(n >> 16), char(n >> 8), char(n)};
        png.append(length, 4);
        png.append(type);
        png.append(data);
        png.append(4, '\0');  // CRC: stb_image does not check it
    };
    chunk("IHDR", std::string("\0\0\0\x02\0\0\0\x02\x08\x06\0\0\0", 13));
    chunk("\n\nAB", "x");
    const std::string gltf =
        R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":42,"uri":)"
        R"("data:application/octet-stream;base64,)" +
        test::base64(std::string(
            "\0\0\0\0\0\0\0\0\0\0\0\0\0\0\x80\x3f\0\0\0\0\0\0\0\0\0\0\0\0\0\0\x80\x3f\0\0\0\0"
            "\0\0\x01\0\x02\0",
            42)) +
        R"("}],"bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,)"
        R"("byteLength":6}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,)"
        R"("type":"VEC3","min":[0,0,0],"max":[1,1,0]},{"bufferView":1,"componentType":5123,)"
        R"("count":3,"type":"SCALAR"}],"images":[{"uri":"data:image/png;base64,)" +
        test::base64(png) +
        R"("}],"textures":[{"source":0}],"materials":[{"pbrMetallicRoughness":)"
        R"({"baseColorTexture":{"index":0}}}],"meshes":[{"primitives":[{"attributes":)"
        R"({"POSITION":0},"indices":1,"material":0}]}],"nodes":[{"mesh":0}],)"
        R"("scenes":[{"nodes":[0]}],"scene":0})";
    std::vector<std::string> warnings;
    const Scene scene =
        load_scene(test::write_fixture("io-fuzz-png-chunk", "chunk.gltf", gltf), {}, &warnings);
    ASSERT_FALSE(warnings.empty());
    for (const std::string& w : warnings) {
        EXPECT_EQ(w.find('\n'), std::string::npos) << w;
        EXPECT_NE(w.find("cannot be decoded"), std::string::npos) << w;
    }
}

// An InputError is one line whatever its cause quotes (names and paths come from the file).
TEST(FuzzRegressions, InputErrorIsOneLine) {
    const InputError e("model.obj", "bad name 'a\nb\r\x01' here");
    EXPECT_EQ(std::string(e.what()), "model.obj: bad name 'a b ?' here");
    EXPECT_EQ(e.cause(), "bad name 'a b ?' here");
}

// fuzz_cells: cell b's first plane (x + 20 y >= 1) reaches into cell a, so the doorway at x = 1
// lies inside b instead of on its boundary; validation took corners inside both cells for a
// portal between them, and portal culling then skipped a crate seen through the doorway.
TEST(FuzzRegressions, CellsPortalInsideACell) {
    const auto dir = test::temp_dir("io-fuzz-cells-interior-portal");
    test::write_bytes(dir / "a.obj",
                      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                      "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 3 4 8 7\nf 2 3 7 6\nf 1 5 8 4\n");
    test::write_bytes(dir / "floor.obj", "v 0 0 0\nv 0 0 1\nv 1 0 1\nv 1 0 0\nf 1 2 3 4\n");
    test::write_bytes(dir / "x.cells.json", R"({"zraster_cells": 1,
 "meshes": {"floor": "floor.obj", "crate": "a.obj"},
 "instances": [{"name": "floor_a", "mesh": "floor"},
               {"name": "floor_b", "mesh": "floor", "translate": [1, 0, 0]},
               {"name": "crate_b", "mesh": "crate", "translate": [1.4, 0, 0.4], "scale": 0.2}],
 "cells": [{"name": "a", "box": [[0, 0, 0], [1, 1, 1]], "instances": ["floor_a", "floor_b"]},
           {"name": "b", "planes": [[1, 20, 0, -1], [-1, 0, 0, 2], [0, 1, 0, 0], [0, -1, 0, 1],
                                    [0, 0, 1, 0], [0, 0, -1, 1]],
            "instances": ["floor_a", "floor_b", "crate_b"]}],
 "portals": [{"cells": ["a", "b"], "corners": [[1, 0, 0.3], [1, 0, 0.7], [1, 0.8, 0.7],
                                               [1, 0.8, 0.3]]}]})");
    test::expect_input_error([&] { load_scene(dir / "x.cells.json"); }, dir / "x.cells.json",
                             "portals[0]: does not lie in a face of cells[1] 'b'");
}

}  // namespace
}  // namespace zraster
