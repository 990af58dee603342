// Malformed files of every format Assimp reads: each is refused with one line naming the file
// and the cause in the user's terms (format_structure_check.cpp before Assimp, the translation
// of Assimp's messages in assimp_errors.cpp after it); Assimp's own text appears at most as a
// trailing "(Assimp: ...)" detail. In process and through the worker process alike.
#include <zraster/load.hpp>

#include "io/assimp_errors.hpp"
#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

#include <string>
#include <vector>

namespace zraster {
namespace {

struct Malformed {
    std::string name;   // the file name (its extension picks the format)
    std::string bytes;  // its contents
    std::string cause;  // the exact cause, up to any "(Assimp: ...)" detail
};

std::string binary_stl_header(std::uint32_t count) {
    std::string bytes(80, '\0');
    for (int b = 0; b < 4; ++b) bytes.push_back(static_cast<char>((count >> (8 * b)) & 0xff));
    return bytes;
}

std::string pseudo_random(std::size_t size, unsigned seed, char avoid) {
    std::string bytes;
    std::uint32_t x = seed;
    while (bytes.size() < size) {
        x = x * 1664525u + 1013904223u;
        const char c = static_cast<char>(x >> 24);
        if (c != avoid) bytes.push_back(c);
    }
    return bytes;
}

// A binary glTF 1.0 (KHR_binary_glTF) header and its JSON content.
std::string glb1_header(const std::string& json) {
    std::string bytes = "glTF";
    for (const std::uint32_t v : {1u, static_cast<std::uint32_t>(20 + json.size()),
                                  static_cast<std::uint32_t>(json.size()), 0u})
        for (int b = 0; b < 4; ++b) bytes.push_back(static_cast<char>((v >> (8 * b)) & 0xff));
    return bytes + json;
}

std::vector<Malformed> malformed_files() {
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    return {
        // STL
        {"random.stl", binary_stl_header(7) + std::string(16, 'x'),
         "neither an ASCII STL (starting with 'solid') nor a binary STL (84 + 50 x triangles "
         "bytes; its header declares 7 triangles, 434 bytes), this file has 100 bytes"},
        {"short.stl", "STL",
         "neither an ASCII STL (starting with 'solid') nor a binary STL (84 + "
         "50 x triangles bytes), this file has 3 bytes"},
        {"two.stl",
         "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\n"
         "endfacet\nendsolid x\n",
         "malformed ASCII STL: facet 1 (line 2) has 2 vertices; STL facets have 3"},
        {"cut.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 1 2 3\n",
         "truncated: the ASCII STL ends inside facet 1 (line 2) after 1 of its 3 vertices"},
        {"four.stl",
         "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
         "vertex 5 5 5\nendloop\nendfacet\nendsolid x\n",
         "malformed ASCII STL: facet 1 (line 2) has 4 vertices; STL facets have 3"},
        {"empty-solid.stl", "solid\n", "no triangles (an ASCII STL without a complete facet)"},
        {"zero.stl", binary_stl_header(0), "no triangles (a binary STL whose header declares 0)"},
        // glTF and GLB
        {"cut.gltf", R"({"asset":{"version":"2.0"},"nodes":[)",
         "not valid JSON: line 1, column 37: unexpected end of input; expected '[', '{', or a "
         "literal"},
        {"array.gltf", "[1, 2]", "not a glTF file: the JSON is not an object (a glTF file's is)"},
        {"short-header.glb",
         std::string("glTF\x02\0\0\0\x14\0\0\0\x1c\0\0\0JSON", 20) +
             R"({"asset":{"version":"2.0"}} )",
         "truncated or malformed GLB file: the GLB header declares 20 bytes, the file holds 48"},
        {"overflow.gltf", R"({"asset":{"version":"2.0"},"accessors":[{"count":1e400}]})",
         "not valid JSON: a number too large for a double ('1e400')"},
        // glTF rules Assimp does not check (gltf_schema_check.hpp).
        {"stride.gltf",
         R"({"asset":{"version":"2.0"},"bufferViews":[{"buffer":0,"byteLength":36,"byteStride":3}]})",
         "malformed glTF file: glTF buffer view 0: byteStride 3 is not a multiple of 4 in 4..252"},
        {"overlap.gltf",
         R"({"asset":{"version":"2.0"},"bufferViews":[{"buffer":0,"byteLength":36,"byteStride":8}],)"
         R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}]})",
         "malformed glTF file: glTF accessor 0: elements of 12 bytes, 8 bytes apart (byteStride of "
         "buffer view 0): they overlap"},
        {"color.gltf",
         R"({"asset":{"version":"2.0"},"accessors":[{"componentType":5126,"count":3,"type":"SCALAR"}],)"
         R"("meshes":[{"primitives":[{"attributes":{"COLOR_0":0}}]}]})",
         "malformed glTF file: glTF mesh 0, primitive 0: attribute COLOR_0 is a SCALAR accessor "
         "(VEC3 or VEC4 in glTF 2.0)"},
        {"draco.gltf",
         R"({"asset":{"version":"2.0"},"extensionsRequired":["KHR_draco_mesh_compression"]})",
         "the file requires the glTF extension KHR_draco_mesh_compression (extensionsRequired), "
         "which zraster does not read"},
        {"child.gltf", R"({"asset":{"version":"2.0"},"nodes":[{"children":[-1]}]})",
         "malformed glTF file: glTF node 0: child -1 is not a node of the file's 1"},
        {"absolute.gltf",
         R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":4,"uri":"/etc/passwd"}]})",
         "buffer 0's URI '/etc/passwd' is an absolute path: glTF buffers are read relative to "
         "the model's folder only (a relative URI such as 'data.bin')"},
        {"url.gltf",
         R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":4,"uri":"FILE:///dev/zero"}]})",
         "buffer 0's URI 'FILE:///dev/zero' is a file: URL: glTF buffers are read relative to "
         "the model's folder only (a relative URI such as 'data.bin')"},
        {"scene.gltf", R"({"asset":{"version":"2.0"},"scene":5,"scenes":[{"nodes":[]}]})",
         "malformed glTF file: glTF \"scene\" 5 is not one of the file's 1 scenes"},
        // JSON under another name: Assimp's glTF importers would read it.
        {"noasset.json", R"({"nodes": []})",
         "not a glTF file: the JSON has no \"asset\" object (every glTF file has one)"},
        {"noasset.gltf", R"({"nodes": []})",
         "not a glTF file: the JSON has no \"asset\" object (every glTF file has one)"},
        {"noversion.gltf", R"({"asset": {}})",
         "not a glTF file: its \"asset\" has no \"version\" string"},
        {"v3.gltf", R"({"asset": {"version": "3.0"}})",
         "glTF version '3.0' is not supported, only glTF 2.N (such as 2.0) is"},
        // glTF 1.0, which Assimp would read as far as its importer goes.
        {"v1.gltf", R"({"asset": {"version": "1.0"}, "meshes": {}})",
         "glTF 1.0 is not supported, only glTF 2.0 is (convert the file to 2.0)"},
        {"v1.glb", glb1_header(R"({"asset": {"version": "1.0"}})"),
         "GLB version 1 (binary glTF 1.0) is not supported, only GLB 2 (glTF 2.0) is (convert "
         "the file to 2.0)"},
        {"v1.json", R"({"asset": {"version": "1.0"}, "meshes": {}})",
         "glTF 1.0 is not supported, only glTF 2.0 is (convert the file to 2.0)"},
        {"v1-glb.bin", glb1_header(R"({"asset": {"version": "1.0"}})"),
         "GLB version 1 (binary glTF 1.0) is not supported, only GLB 2 (glTF 2.0) is (convert "
         "the file to 2.0)"},
        {"random.glb", pseudo_random(300, 1, 'g'),
         "not a binary glTF (GLB) file: it does not start with 'glTF'"},
        {"tiny.glb", std::string("glTF\x02\0\0", 7),
         "truncated: a binary glTF (GLB) file starts with a 12-byte header, this file has 7 bytes"},
        {"v9.glb", std::string("glTF\x09\0\0\0\x14\0\0\0", 12) + std::string(8, '\0'),
         "GLB version 9 is not supported (2 is)"},
        {"bin-first.glb",
         std::string("glTF\x02\0\0\0\x20\0\0\0\x0c\0\0\0BIN\0", 20) + std::string(12, '\0'),
         "malformed GLB file: its first chunk is not the JSON chunk"},
        {"bad-json.glb",
         std::string("glTF\x02\0\0\0\x1f\0\0\0\x0b\0\0\0JSON", 20) + "{\"asset\":[ ",
         "its JSON chunk is not valid JSON: line 1, column 12: unexpected end of input; expected "
         "'[', '{', or a literal"},
        // 3DS
        {"text.3ds", "this is text, not a 3DS file at all",
         "not a 3DS file: it does not start with the main chunk (0x4D4D), but with 0x6874"},
        {"past-end.3ds",
         std::string("MM\xe8\x03\0\0\x3d\x3d\x10\0\0\0", 12) + std::string(10, '\0'),
         "truncated: a 3DS chunk (0x4D4D at byte 0) declares 1000 bytes, 978 past the end of the "
         "file"},
        {"tiny-chunk.3ds",
         std::string("MM\x16\0\0\0\x3d\x3d\x02\0\0\0", 12) + std::string(10, '\0'),
         "malformed 3DS file: chunk 0x3D3D at byte 6 declares 2 bytes, less than its own 6-byte "
         "header"},
        {"short.3ds", std::string("MM\x10\0\0\0", 6),
         "truncated: 6 bytes are too few for a 3DS file (a main chunk of 16 or more)"},
        // Formats left to Assimp: its messages translated.
        {"random.ply", pseudo_random(300, 2, 'p'), "not a PLY file: it does not start with 'ply'"},
        {"random.off", "this is not an OFF file\n1 2 3\n",
         "not an OFF file: the header (OFF, then the vertex, face and edge counts) is invalid"},
        {"point.obj", tri + "f 1 2 3\nf 1\n",
         "line 5: a face of 1 corner; a face needs at least 3"},
        {"line.obj", tri + "f 1 2\nf 1 2 3\n",
         "line 4: a face of 2 corners; a face needs at least 3"},
        {"short-vertex.obj", "v 0 0\n" + tri + "f 2 3 4\n",
         "line 1: a vertex of 2 numbers; x y z are needed"},
        // The same in a file zraster's reader leaves to Assimp (a polygon of 5 corners first).
        {"point-assimp.obj", tri + "v 1 1 0\nv 2 0 0\nf 1 2 5 4 3\nf 1\n",
         "line 7: a face of 1 corner; a face needs at least 3"},
        {"short-vertex-assimp.obj", tri + "v 1 1 0\nv 2 0 0\nf 1 2 5 4 3\nv 0 0\n",
         "line 7: a vertex of 2 numbers; x y z are needed"},
        // Vertices of 5, 7 or more numbers: Assimp misreads them and blames a vertex index.
        {"five-numbers.obj", "v 0 0 0 1 1\n" + tri + "f 2 3 4\n",
         "line 1: a vertex of 5 numbers; a vertex is x y z, x y z w or x y z r g b"},
        {"eight-numbers.obj", "v 0 0 0 1 1 1 1 1\n" + tri + "f 2 3 4\n",
         "line 1: a vertex of 8 numbers; a vertex is x y z, x y z w or x y z r g b"},
        {"seven-numbers-assimp.obj", tri + "v 1 1 0\nv 2 0 0\nf 1 2 5 4 3\nv 0 0 0 1 0 0 0\n",
         "line 7: a vertex of 7 numbers; a vertex is x y z, x y z w or x y z r g b"},
        // OBJ texture and normal indices, which Assimp would clamp or drop without a word.
        {"uv.obj", tri + "vt 0 0\nf 1/99 2/1 3/1\n",
         "line 5: texture coordinate index out of range (99; the file has 1 texture coordinates)"},
        {"normal.obj", tri + "vn 0 0 1\nf 1//1 2//1 3//99\n",
         "line 5: normal index out of range (99; the file has 1 normals)"},
        {"normal-negative.obj", tri + "vt 0 0\nvn 0 0 1\nf 1/1/-2 2/1/1 3/1/1\n",
         "line 6: normal index out of range (a negative index before the first normal)"},
        {"no-uv.obj", tri + "f 1/1 2/1 3/1\n",
         "line 4: texture coordinate index out of range (1; the file has 0 texture coordinates)"},
        // OFF face indices, which Assimp would move to the last vertex (past the end) or read as
        // vertex 0 (missing, negative, not a number).
        {"index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
         "malformed OFF file: OFF face 0 (line 6) names vertex 7, but the file has 3 vertices (0 "
         "to 2)"},
        {"index-coff.off",
         "COFF\n3 2 0\n0 0 0 1 0 0 1\n1 0 0 1 0 0 1\n0 1 0 1 0 0 1\n3 0 1 2\n"
         "3 2 1 4294967296 255 0 0\n",
         "malformed OFF file: OFF face 1 (line 7) names vertex 4294967296, but the file has 3 "
         "vertices (0 to 2)"},
        {"index-noff.off",
         "NOFF\r\n3 1 0\r\n0 0 0 0 0 1\r\n1 0 0 0 0 1\r\n0 1 0 0 0 1\r\n3\t0\t3\t1\r\n",
         "malformed OFF file: OFF face 0 (line 6) names vertex 3, but the file has 3 vertices (0 "
         "to 2)"},
        {"negative.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n",
         "malformed OFF file: OFF face 0 (line 6): vertex index '-1' is not a number of 0 or more"},
        {"few.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n",
         "malformed OFF file: OFF face 0 (line 6) declares 3 vertices but lists 2 indices"},
        {"junk.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 junk\n",
         "malformed OFF file: OFF face 0 (line 6): 'junk' after its indices is not a color "
         "number"},
        // Random bytes that Assimp's ASE importer takes for a file of nodes without meshes (it
        // then draws a placeholder skeleton).
        {"random.ase", pseudo_random(4096, 5, '\0'),
         "no triangles in it (no mesh, only nodes: is it really a model in the ASE format?)"},
        {"short.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
         "a face without vertex indices (fewer face records than the header declares?)"},
        {"index.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
         "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
         "malformed PLY file: face 0 names vertex 7, but the file has 3 vertices (0 to 2)"},
        // Past a 32-bit index: Assimp wrapped it to vertex 0 without a word.
        {"wrap.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
         "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 4294967296\n",
         "malformed PLY file: face 0 names vertex 4294967296, but the file has 3 vertices (0 to "
         "2)"},
        // PLY 1.0's three formats only (Assimp read binary_middle_endian and version 2.0), and
        // vertex numbers that are integers (it truncated a float 2.5 to 2).
        {"middle-endian.ply",
         "ply\nformat binary_middle_endian 1.0\nelement vertex 3\nproperty float x\nend_header\n",
         "malformed PLY file: 'format binary_middle_endian 1.0': the format is ascii, "
         "binary_little_endian or binary_big_endian, version 1.0"},
        {"version-2.ply", "ply\nformat ascii 2.0\nelement vertex 3\nproperty float x\nend_header\n",
         "malformed PLY file: 'format ascii 2.0': the format is ascii, binary_little_endian or "
         "binary_big_endian, version 1.0"},
        {"float-index.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uchar float vertex_indices\n"
         "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2.5\n",
         "malformed PLY file: the list 'vertex_indices' holds vertex numbers as float: they are "
         "integers (char, uchar, short, ushort, int, uint)"},
        // ASCII STL numbers whole (Assimp read '1,5' as 1.5 and '0x10' as 0).
        {"comma.stl",
         "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1,5 0 0\nvertex 0 1 0\n"
         "endloop\nendfacet\nendsolid t\n",
         "malformed ASCII STL: line 5: '1,5' is not a number (vertices and normals are 3 decimal "
         "numbers)"},
        {"hex.stl",
         "solid t\nfacet normal 0 0 0x1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
         "endloop\nendfacet\nendsolid t\n",
         "malformed ASCII STL: line 2: '0x1' is not a number (vertices and normals are 3 decimal "
         "numbers)"},
        {"negative-count.ply",
         "ply\nformat ascii 1.0\nelement vertex -1\nproperty float x\nend_header\n",
         "malformed PLY file: element 'vertex' declares the count '-1', not a number of 0 or "
         "more"},
        {"letters-count.ply",
         "ply\nformat ascii 1.0\nelement vertex 3abc\nproperty float x\nend_header\n",
         "malformed PLY file: element 'vertex' declares the count '3abc', not a number of 0 or "
         "more"},
        {"binary-index.ply",
         std::string("ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                     "property float y\nproperty float z\nelement face 1\n"
                     "property list uchar int vertex_indices\nend_header\n") +
             std::string(36, '\0') + std::string("\x03\0\0\0\0\x01\0\0\0\x05\0\0\0", 13),
         "malformed PLY file: face 0 names vertex 5, but the file has 3 vertices (0 to 2)"},
        // Corner counts Assimp reads as a huge length (std::bad_alloc) or refuses in its
        // validation ("Face 0 has too many faces").
        {"negative-corners.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list int int vertex_indices\n"
         "end_header\n0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n",
         "malformed PLY file: face 0 has a negative corner count (-3)"},
        {"binary-negative-corners.ply",
         std::string("ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                     "property float y\nproperty float z\nelement face 1\n"
                     "property list int int vertex_indices\nend_header\n") +
             std::string(36, '\0') + std::string("\xfd\xff\xff\xff\0\0\0\0\x01\0\0\0", 12),
         "malformed PLY file: face 0 has a negative corner count (-3)"},
        {"many-corners.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uint uint vertex_indices\n"
         "end_header\n0 0 0\n1 0 0\n0 1 0\n40000" +
             [] {
                 std::string corners;
                 for (int k = 0; k < 40000; ++k) corners += k % 2 ? " 1" : " 0";
                 return corners;
             }() +
             "\n",
         "malformed PLY file: face 0 has 40000 corners; at most 32767"},
        {"letters-length.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
         "end_header\n0 0 0\n1 0 0\n0 1 0\n3x 0 1 2\n",
         "malformed PLY file: a face record's list length '3x' is not a whole number of 0 or "
         "more"},
        {"garbage.xyzzy", pseudo_random(4096, 4, '\0'),
         "no importer recognises its contents as a XYZZY file (a wrong extension, or not a 3D "
         "model)"},
        {"random.dae", pseudo_random(300, 3, '<'), "not well-formed XML, as a DAE file must be"},
    };
}

// The cause without a trailing "(Assimp: ...)", which must be Assimp's only place.
std::string without_detail(const std::string& cause) {
    const std::optional<std::string> detail = io::assimp_detail(cause);
    if (!detail) return cause;
    return cause.substr(0, cause.size() - detail->size() - std::string(" (Assimp: )").size());
}

TEST(MalformedFormats, EachIsRefusedInTheUsersTerms) {
    const auto dir = test::temp_dir("io-malformed-formats");
    for (const Malformed& m : malformed_files()) {
        SCOPED_TRACE(m.name);
        const auto path = dir / m.name;
        test::write_bytes(path, m.bytes);
        for (const LoadIsolation isolation :
             {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
            LoadOptions options;
            options.isolation = isolation;
            try {
                load_scene(path, options);
                ADD_FAILURE() << "loaded";
            } catch (const InputError& e) {
                EXPECT_EQ(e.file(), path.string());
                EXPECT_EQ(without_detail(e.cause()), m.cause) << e.what();
                EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
                for (const char* internal : {"aiMesh", "No suitable reader", "Failed to determine",
                                             "Chunk is too large", "File is too small"})
                    EXPECT_EQ(without_detail(e.cause()).find(internal), std::string::npos)
                        << e.what();
            }
        }
    }
}

// Assimp's messages that reach the table: ours first, Assimp's text only as the detail.
TEST(MalformedFormats, AssimpMessagesAreTranslated) {
    EXPECT_EQ(io::assimp_error_cause("m.3ds", "Chunk is too large"),
              "truncated: a 3DS chunk declares more bytes than the file holds (Assimp: Chunk is "
              "too large)");
    EXPECT_EQ(io::assimp_error_cause("m.fbx", "FBX-Tokenize (line 1 << col 49) unexpected"),
              "malformed FBX file (its text cannot be split into tokens) (Assimp: FBX-Tokenize "
              "(line 1 << col 49) unexpected)");
    EXPECT_EQ(io::assimp_error_cause("m.gltf", "GLTF: could not open referenced file \"a.bin\""),
              "the file it refers to, 'a.bin', is missing or cannot be read (Assimp: GLTF: could "
              "not open referenced file \"a.bin\")");
    EXPECT_EQ(io::assimp_error_cause("m.xyz", "something new"),
              "malformed or unsupported XYZ file (Assimp: something new)");
    EXPECT_EQ(io::assimp_error_cause("m", "something new"),
              "malformed or unsupported 3D model file (Assimp: something new)");
    EXPECT_EQ(io::assimp_error_cause("m.md2", "Invalid MD2 magic word: expected IDP2"),
              "not a MD2 file: it does not start with the format's signature (Assimp: Invalid MD2 "
              "magic word: expected IDP2)");
    EXPECT_EQ(io::assimp_error_cause("m.3mf", "Failed to open file m.3mf."),
              "not a valid 3MF file: the importer could not open its contents (Assimp: Failed to "
              "open file m.3mf.)");
    // An allocation that failed inside the importer: no C++ name, no Assimp detail.
    EXPECT_EQ(io::assimp_error_cause("m.dae", "std::bad_alloc"),
              "the importer ran out of memory reading it: it expands past the memory this "
              "process may use, in a part of the DAE format zraster does not count before "
              "reading");
    // Its validation's texts name its data structures: ours alone.
    EXPECT_EQ(io::assimp_error_cause(
                  "m.gltf",
                  "Validation failed: aiNode::mMeshes[1] is already referenced by this "
                  "node n (value: 0)"),
              "malformed GLTF file: a node places the same mesh twice");
    EXPECT_EQ(io::assimp_error_cause("m.gltf",
                                     "Validation failed: aiLight::mAngleInnerCone is "
                                     "larger than aiLight::mAngleOuterCone"),
              "malformed GLTF file: a spot light's inner cone angle is larger than its outer one");
    EXPECT_EQ(io::assimp_error_cause("m.smd", "Validation failed: Empty node animation channel"),
              "malformed SMD file: an animation channel without keys (its bones or skeleton are "
              "inconsistent: a bone its own parent, or no skeleton frame?)");
    // Its source file and line cut; a number it cannot parse quoted alone, not the rest of the
    // file.
    EXPECT_EQ(io::assimp_error_cause("m.mdl", "MDL: bad header (File: MDLLoader.cpp Line: 424)"),
              "malformed or unsupported MDL file (Assimp: MDL: bad header)");
    EXPECT_EQ(io::assimp_error_cause("m.off",
                                     "Cannot parse string \"x1p3 0 0?1 0 0?\" as a real "
                                     "number: does not start with digit"),
              "malformed or unsupported OFF file (Assimp: Cannot parse string \"x1p3\" as a real "
              "number: does not start with digit)");
    EXPECT_EQ(io::assimp_detail("x (Assimp: y (z))"), "y (z)");
    EXPECT_EQ(io::assimp_detail("no detail"), std::nullopt);
}

}  // namespace
}  // namespace zraster
