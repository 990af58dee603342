// Values a loader used to read a prefix of or skip without a word (issue 27's hostile runs):
// OBJ and MTL words that are not numbers, OBJ faces past Assimp's corner limit and indices past
// 2^31, glTF versions that are not 2.N, unusable normals, unknown cells file fields. Each is
// refused with one line naming the file and the cause, or warned about saying what is assumed;
// in zraster's OBJ reader and the Assimp path alike, in process and through the worker.
#include <zraster/load.hpp>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "io/io_test_util.hpp"
#include "io/load_with_warnings.hpp"
#include "support/test_support.hpp"

namespace zraster {
namespace {

constexpr LoadIsolation kIsolations[] = {LoadIsolation::InProcess, LoadIsolation::WorkerProcess};

LoadOptions isolated(LoadIsolation isolation) {
    LoadOptions o;
    o.isolation = isolation;
    return o;
}

// A line zraster's reader leaves to Assimp (a pentagon): put first, the file takes the Assimp
// path, whose pre-scan must refuse what the reader refuses.
const std::string kPentagon = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv -1 0 0\nf 1 2 3 4 5\n";

struct Refusal {
    std::string body;   // after the vertices
    std::string cause;  // "{N}" stands for the file's vertex count
    std::size_t line;   // counted from the body's first line as 1
};

// `body` after three vertices, read by the reader (the file as is) and by the Assimp path (the
// pentagon first): the same cause, at the line it is on.
void expect_obj_refused_both_ways(const std::string& test, const Refusal& r) {
    SCOPED_TRACE(r.body);
    const auto dir = test::temp_dir(test);
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    struct Variant {
        std::string name, text;
        std::size_t first_line;
        std::string vertices;
    };
    for (const Variant& v : {Variant{"reader.obj", tri + r.body, 4, "3"},
                             Variant{"assimp.obj", kPentagon + tri + r.body, 10, "8"}}) {
        SCOPED_TRACE(v.name);
        const auto path = dir / v.name;
        test::write_bytes(path, v.text);
        std::string cause = r.cause;
        if (const std::size_t at = cause.find("{N}"); at != std::string::npos)
            cause.replace(at, 3, v.vertices);
        for (const LoadIsolation isolation : kIsolations) {
            try {
                load_scene(path, isolated(isolation));
                ADD_FAILURE() << "loaded";
            } catch (const InputError& e) {
                EXPECT_EQ(e.file(), path.string());
                EXPECT_EQ(e.cause(),
                          "line " + std::to_string(v.first_line + r.line - 1) + ": " + cause);
            }
        }
    }
}

TEST(LoaderNonsense, ObjWordsThatAreNotNumbersAreRefusedByName) {
    const std::vector<Refusal> cases = {
        {"v 1e5x 0 0\nf 1 2 3\n", "'1e5x' is not a number", 1},
        {"v 0x10 0 0\nf 1 2 3\n", "'0x10' is not a number", 1},
        {"v 1,5 0 0\nf 1 2 3\n", "'1,5' is not a number", 1},
        {"v 1.#INF 0 0\nf 1 2 3\n", "'1.#INF' is not a number", 1},
        {"v 1 2 3#c\nf 1 2 3\n", "'3#c' is not a number", 1},
        {"vt 0.5x 0\nf 1/1 2/1 3/1\n", "'0.5x' is not a number", 1},
        {"vn 0 0 1e\nf 1//1 2//1 3//1\n", "'1e' is not a number", 1},
        {"f 1x 2 3\n", "'1x' is not a number", 1},
        {"f 1 2 0x3\n", "'0x3' is not a number", 1},
        {"vt 0 0\nf 1/1 2/1x 3/1\n", "'1x' is not a number", 2},
        {"f 1.5 2 3\n", "'1.5' is not a number", 1},
    };
    for (const Refusal& r : cases) expect_obj_refused_both_ways("nonsense-obj-numbers", r);
}

TEST(LoaderNonsense, ObjNumbersStillRead) {
    // Comments, signs, exponents, a trailing point, nan and inf (a non-finite position is an
    // error only when a face uses it).
    const auto path = test::write_fixture("nonsense-obj-good", "good.obj",
                                          "v +1 0 0 # a comment\nv 0 1.5E+0 0\nv 0 0 -2.\n"
                                          "v nan inf -INF\nvn 0 0 1\nf 1//1 2//1 3//1\n");
    for (const LoadIsolation isolation : kIsolations)
        EXPECT_EQ(load_scene(path, isolated(isolation)).meshes.at(0).indices.size(), 3u);
}

// A number starting with a point is a number (".5" is 0.5); Assimp's OBJ reader does not count it
// as one, so a file only Assimp reads (here: a pentagon) is refused saying so.
TEST(LoaderNonsense, ObjNumbersStartingWithAPoint) {
    const auto dir = test::temp_dir("nonsense-obj-point");
    test::write_bytes(dir / "t.obj", "v 0 0 0\nv .5 0 0\nv 0 -.5e1 0\nf 1 2 3\n");
    test::write_bytes(dir / "p.obj",
                      "v 0 0 0\nv .5 0 0\nv 0 1 0\nv -1 -1 0\nv 2 -1 0\nf 1 2 3 4 5\n");
    for (const LoadIsolation isolation : kIsolations) {
        const Scene scene = load_scene(dir / "t.obj", isolated(isolation));
        EXPECT_EQ(scene.meshes.at(0).positions.at(1).x, 0.5f);
        EXPECT_EQ(scene.meshes.at(0).positions.at(2).y, -5.0f);
        test::expect_input_error([&] { load_scene(dir / "p.obj", isolated(isolation)); },
                                 dir / "p.obj",
                                 "line 2: '.5' starts with a point, which the importer this file "
                                 "needs does not read as a number (write 0.5)");
    }
}

TEST(LoaderNonsense, ObjFacesPastAssimpsCornerLimitAreRefusedInOurTerms) {
    for (const std::size_t corners : {std::size_t{40'000}, std::size_t{100'000}}) {
        std::string face = "f";
        for (std::size_t k = 0; k < corners; ++k) face += " " + std::to_string(1 + k % 3);
        expect_obj_refused_both_ways(
            "nonsense-obj-corners",
            {face + "\n", "a face of " + std::to_string(corners) + " corners; at most 32767", 1});
    }
}

TEST(LoaderNonsense, ObjIndicesPast2To31NameTheIndex) {
    expect_obj_refused_both_ways(
        "nonsense-obj-2e31",
        {"f 1 2 2147483648\n", "vertex index out of range (2147483648; the file has {N} vertices)",
         1});
    expect_obj_refused_both_ways(
        "nonsense-obj-2e64",
        {"f 1 2 18446744073709551617\n",
         "vertex index out of range (18446744073709551617; the file has {N} vertices)", 1});
}

TEST(LoaderNonsense, MtlWordsThatAreNotNumbersAreRefusedNamingTheLibrary) {
    struct Case {
        std::string statement, cause;
    };
    for (const Case& c :
         {Case{"Kd 0.5abc 0 0", "'0.5abc' is not a number"},
          Case{"Ns 1e5x", "'1e5x' is not a number"}, Case{"d 0.5,", "'0.5,' is not a number"},
          Case{"Ka 0 0 0x1", "'0x1' is not a number"},
          Case{"Kd 0.5 0.5", "'Kd' of 2 numbers; a color is 1 or 3"},
          Case{"Ks", "'Ks' without a number; a color is 1 or 3"},
          Case{"illum 4294967296",
               "'illum 4294967296': the illumination model is one whole number from 0 to 10"},
          Case{"illum 11", "'illum 11': the illumination model is one whole number from 0 to 10"},
          Case{"illum 2 3",
               "'illum 2 ...': the illumination model is one whole number from 0 to 10"},
          Case{"illum 2.0",
               "'illum 2.0': the illumination model is one whole number from 0 to 10"}}) {
        SCOPED_TRACE(c.statement);
        const auto dir = test::temp_dir("nonsense-mtl");
        const auto mtl = dir / "m.mtl";
        test::write_bytes(mtl, "newmtl red\n" + c.statement + "\n");
        const std::string body = "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n";
        for (const std::string& text :
             {"mtllib m.mtl\n" + body, "mtllib m.mtl\n" + kPentagon + body}) {
            const auto obj = dir / "m.obj";
            test::write_bytes(obj, text);
            for (const LoadIsolation isolation : kIsolations)
                test::expect_input_error([&] { load_scene(obj, isolated(isolation)); }, obj,
                                         "material library m.mtl: line 2: " + c.cause);
        }
    }
    // Comments end a statement.
    const auto dir = test::temp_dir("nonsense-mtl-good");
    test::write_bytes(dir / "m.mtl", "newmtl red\nKd 1 0 0 # red\nd 0.5\nNs 10 #\nillum 010\n");
    test::write_bytes(dir / "m.obj",
                      "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
    EXPECT_EQ(load_scene(dir / "m.obj").materials.size(), 2u);
}

// ASCII PLY values are numbers: Assimp read the prefix of "0x" (0) and "1e5x" without a word.
TEST(LoaderNonsense, AsciiPlyWordsThatAreNotNumbersAreRefusedByName) {
    const std::string head =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\n";
    const std::string faces = "element face 1\nproperty list uchar int vertex_indices\n";
    struct Case {
        std::string text, cause;
    };
    for (const Case& c : {
             Case{head + faces + "end_header\n0 0 0x\n1 0 0\n0 1 0\n3 0 1 2\n",
                  "malformed PLY file: vertex 0's z: '0x' is not a number"},
             Case{head + "end_header\n0 0 0\n1e5x 0 0\n0 1 0\n",
                  "malformed PLY file: vertex 1's x: '1e5x' is not a number"},
             Case{head + "element face 1\nproperty list uchar float texcoord\nend_header\n"
                         "0 0 0\n1 0 0\n0 1 0\n2 0.5 0,5\n",
                  "malformed PLY file: face 0's texcoord: '0,5' is not a number"},
         }) {
        SCOPED_TRACE(c.cause);
        const auto path = test::write_fixture("nonsense-ply-numbers", "n.ply", c.text);
        for (const LoadIsolation isolation : kIsolations)
            test::expect_input_error([&] { load_scene(path, isolated(isolation)); }, path, c.cause);
    }
    const auto good = test::write_fixture(
        "nonsense-ply-good", "g.ply",
        head + faces + "end_header\n-0.5 +1 1e-3\n1.5E+1 0 0\n0 1. 0\n3 0 1 2\n");
    for (const LoadIsolation isolation : kIsolations)
        EXPECT_EQ(load_scene(good, isolated(isolation)).meshes.at(0).indices.size(), 3u);
}

TEST(LoaderNonsense, GltfVersionsThatAreNot2NAreRefused) {
    const auto dir = test::temp_dir("nonsense-gltf-version");
    for (const std::string version : {"2.0abc", "2", "02.0", "2.0.0", " 2.0", "2."}) {
        SCOPED_TRACE(version);
        const auto path = dir / "v.gltf";
        test::write_bytes(path, R"({"asset":{"version":")" + version + R"("}})");
        test::expect_input_error(
            [&] { load_scene(path); }, path,
            "glTF version '" + version + "' is not supported, only glTF 2.N (such as 2.0) is");
    }
}

// The specification: a loader refuses a file whose asset's minVersion it does not support.
TEST(LoaderNonsense, GltfMinVersionsAbove20AreRefused) {
    const auto dir = test::temp_dir("nonsense-gltf-min-version");
    const auto path = dir / "v.gltf";
    struct Case {
        std::string min_version, cause;
    };
    for (const Case& c :
         {Case{R"("3.0")",
               "its asset's \"minVersion\" is 3.0: it needs a glTF 3.0 reader, "
               "zraster reads glTF 2.0"},
          Case{R"("2.1")",
               "its asset's \"minVersion\" is 2.1: it needs a glTF 2.1 reader, "
               "zraster reads glTF 2.0"},
          Case{R"("2.0.1")", "its asset's \"minVersion\" is not a MAJOR.MINOR version string"},
          Case{"2", "its asset's \"minVersion\" is not a MAJOR.MINOR version string"}}) {
        SCOPED_TRACE(c.min_version);
        test::write_bytes(path,
                          R"({"asset":{"version":"2.1","minVersion":)" + c.min_version + "}}");
        for (const LoadIsolation isolation : kIsolations)
            test::expect_input_error([&] { load_scene(path, isolated(isolation)); }, path, c.cause);
    }
    // 2.0 is read (as far as this document goes).
    test::write_bytes(path, R"({"asset":{"version":"2.0","minVersion":"2.0"}})");
    test::expect_input_error([&] { load_scene(path); }, path, "no scene to draw");
}

// Node placements as glTF 2.0 defines them; the importer took any numbers (a projective matrix
// blanked the image, a quaternion of length 100 scaled the node by 10^4).
TEST(LoaderNonsense, GltfNodePlacementsAreChecked) {
    const auto dir = test::temp_dir("nonsense-gltf-nodes");
    const auto path = dir / "n.gltf";
    struct Case {
        std::string node, cause;
    };
    for (const Case& c : {
             Case{R"("matrix":[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],"translation":[1,0,0])",
                  "node 0: has a \"matrix\" and translation, rotation or scale: glTF 2.0 allows "
                  "one or the other"},
             Case{R"("matrix":[1,0,0,1,0,1,0,1,0,0,1,1,0,0,0,0])",
                  "node 0: \"matrix\" is not affine (its last row must be 0, 0, 0, 1)"},
             Case{R"("rotation":[0,0,0,0])",
                  "node 0: \"rotation\" is not a unit quaternion (length 0.000000)"},
             Case{R"("rotation":[0,0,10,0])",
                  "node 0: \"rotation\" is not a unit quaternion (length 10.000000)"},
             Case{R"("rotation":[0,0,"nan",1])",
                  "node 0: \"rotation\" must be 4 finite numbers, not [0,0,\"nan\",1]"},
             Case{R"("scale":[1,1])", "node 0: \"scale\" must be 3 finite numbers, not [1,1]"},
         }) {
        SCOPED_TRACE(c.node);
        test::write_bytes(path, R"({"asset":{"version":"2.0"},"nodes":[{)" + c.node + "}]}");
        test::expect_input_error([&] { load_scene(path); }, path, c.cause);
    }
    // An accessor of zeros (no bufferView, no sparse values), which the importer cannot read.
    test::write_bytes(
        path, R"({"asset":{"version":"2.0"},"accessors":[{"componentType":5126,"count":3,)"
              R"("type":"VEC3","min":[0,0,0],"max":[1,1,0]}],"meshes":[{"primitives":[)"
              R"({"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]})");
    test::expect_input_error([&] { load_scene(path); }, path,
                             "mesh 0, primitive 0: attribute POSITION reads accessor 0, which has "
                             "no bufferView (its values would all be zero): not supported");
}

// What Assimp's validation would refuse in its own terms ("aiCamera::mClipPlaneFar must be >=
// ...", "Member \"index\" was not of type \"uint\""), refused in the file's.
TEST(LoaderNonsense, GltfCamerasAndMaterialReferencesAreCheckedInTheFilesTerms) {
    const auto dir = test::temp_dir("nonsense-gltf-references");
    const std::string triangle =
        R"("asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
        R"("min":[0,0,0],"max":[1,1,0]}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
        R"("buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,)"
        R"(AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}])";
    const std::string primitive = R"("meshes":[{"primitives":[{"attributes":{"POSITION":0})";
    struct Case {
        std::string members, cause;
    };
    for (const Case& c : {
             Case{primitive + R"(}]}],"cameras":[{"type":"perspective","perspective":)"
                              R"({"yfov":0.5,"znear":-1,"zfar":-2}}])",
                  "glTF camera 0: znear -1 is not above 0"},
             Case{primitive + R"(}]}],"cameras":[{"type":"perspective","perspective":)"
                              R"({"yfov":0.5,"znear":2,"zfar":1}}])",
                  "glTF camera 0: zfar 1 is not beyond znear 2"},
             Case{primitive + R"(,"material":99}]}],"materials":[{}])",
                  "glTF mesh 0, primitive 0: material 99 is not one of the file's 1 materials"},
             Case{primitive + R"(,"material":0}]}],"materials":[null])",
                  "glTF material 0 is not a JSON object"},
             Case{primitive + R"(,"material":0}]}],"materials":[{"pbrMetallicRoughness":[]}])",
                  "glTF material 0: pbrMetallicRoughness is not a JSON object"},
             Case{primitive + R"(,"material":0}]}],"materials":[{"pbrMetallicRoughness":)"
                              R"({"baseColorTexture":{"index":-1}}}])",
                  "glTF material 0: baseColorTexture index -1 is not one of the file's 0 "
                  "textures"},
         }) {
        SCOPED_TRACE(c.cause);
        const auto path = dir / "r.gltf";
        test::write_bytes(path, "{" + triangle + "," + c.members + "}");
        for (const LoadIsolation isolation : kIsolations)
            test::expect_input_error([&] { load_scene(path, isolated(isolation)); }, path, c.cause);
    }
}

// Every normal of a loaded scene is of unit length.
void expect_unit_normals(const Scene& scene) {
    for (const Mesh& mesh : scene.meshes)
        for (const glm::vec3& n : mesh.normals) {
            ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
            ASSERT_NEAR(glm::length(n), 1.0f, 1e-5f);
        }
}

TEST(LoaderNonsense, UnusableNormalsAreRecomputedWithOneWarningPerFile) {
    const auto dir = test::temp_dir("nonsense-normals");
    const std::string tris = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
    const std::string obj_body =
        "vn nan 0 0\nvn 0 0 0\nvn 0 0 1\nf 1//1 2//2 3//3\nf 1//3 2//3 4//1\n";
    std::vector<std::filesystem::path> files;
    files.push_back(dir / "reader.obj");
    test::write_bytes(files.back(), tris + obj_body);
    files.push_back(dir / "assimp.obj");
    test::write_bytes(files.back(), kPentagon + tris + obj_body);
    files.push_back(dir / "n.ply");
    test::write_bytes(files.back(),
                      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                      "property float y\nproperty float z\nproperty float nx\nproperty float ny\n"
                      "property float nz\nelement face 1\nproperty list uchar int vertex_indices\n"
                      "end_header\n0 0 0 nan 0 0\n1 0 0 0 0 1\n0 1 0 0 0 0\n3 0 1 2\n");
    // glTF: positions then NORMALs with a NaN and a zero one.
    const float data[18] = {0, 0, 0, 1, 0, 0, 0, 1, 0, std::nanf(""), 0, 0, 0, 0, 1, 0, 0, 0};
    files.push_back(dir / "n.gltf");
    test::write_bytes(
        files.back(),
        R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
        R"("meshes":[{"name":"tri","primitives":[{"attributes":{"POSITION":0,"NORMAL":1}}]}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
        R"("min":[0,0,0],"max":[1,1,0]},{"bufferView":0,"byteOffset":36,"componentType":5126,)"
        R"("count":3,"type":"VEC3"}],"bufferViews":[{"buffer":0,"byteLength":72}],)"
        R"("buffers":[{"byteLength":72,"uri":"data:application/octet-stream;base64,)" +
            test::base64(std::string(reinterpret_cast<const char*>(data), sizeof data)) +
            R"("}]})");
    for (const auto& path : files) {
        SCOPED_TRACE(path.string());
        for (const LoadIsolation isolation : kIsolations) {
            const io::LoadedScene loaded = test::load_with_warnings(path, isolated(isolation));
            expect_unit_normals(loaded.scene);
            std::size_t count = 0;
            for (const std::string& w : loaded.warnings) {
                if (w.find("normals that are missing, not finite or of zero length") ==
                    std::string::npos)
                    continue;
                ++count;
                EXPECT_EQ(w.rfind(path.string() + ": normals that are missing, not finite or of "
                                                  "zero length (first in mesh ",
                                  0),
                          0u)
                    << w;
                EXPECT_NE(w.find(") recomputed from the faces"), std::string::npos) << w;
            }
            EXPECT_EQ(count, 1u);
        }
    }
    // Usable normals: no warning.
    const auto good = dir / "good.obj";
    test::write_bytes(good, tris + "vn 0 0 2\nf 1//1 2//1 3//1\n");
    EXPECT_TRUE(test::load_with_warnings(good).warnings.empty());
}

TEST(LoaderNonsense, CellsFileFieldsItDoesNotHaveAreRefusedByName) {
    const auto dir = test::temp_dir("nonsense-cells");
    test::write_bytes(dir / "t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    struct Case {
        std::string top, instance, cell, portal, cause;
    };
    const std::string box = R"("box":[[-5,-5,-5],[5,5,5]])";
    for (const Case& c : {
             Case{R"(,"portal":[])", "", "", "",
                  "(top level): \"portal\" is not a field of the file (zraster_cells, meshes, "
                  "instances, cells, portals: docs/portals.md)"},
             Case{"", R"(,"translation":[1,0,0])", "", "",
                  "instances[0]: \"translation\" is not a field of an instance (name, mesh, "
                  "matrix, translate, rotate_y_degrees, scale: docs/portals.md)"},
             Case{"", "", R"(,"bbox":1)", "",
                  "cells[0]: \"bbox\" is not a field of a cell (name, box, planes, instances: "
                  "docs/portals.md)"},
             Case{"", "", "", R"(,"name":"door")",
                  "portals[0]: \"name\" is not a field of a portal (cells, corners: "
                  "docs/portals.md)"},
         }) {
        SCOPED_TRACE(c.cause);
        const auto path = dir / "two.cells.json";
        test::write_bytes(
            path,
            R"({"zraster_cells":1,"meshes":{"t":"t.obj"},"instances":[{"name":"i","mesh":"t")" +
                c.instance + R"(}],"cells":[{"name":"a",)" + box + R"(,"instances":["i"])" +
                c.cell + R"(},{"name":"b","box":[[5,-5,-5],[6,5,5]],"instances":[]}],)" +
                R"("portals":[{"cells":["a","b"],"corners":[[5,0,0],[5,1,0],[5,1,1]])" + c.portal +
                "}]" + c.top + "}");
        test::expect_input_error([&] { load_scene(path); }, path, c.cause);
    }
}

// A transform is a matrix or its parts (docs/portals.md): with both, one was silently ignored.
TEST(LoaderNonsense, CellsInstancesWithAMatrixAndItsPartsAreRefused) {
    const auto dir = test::temp_dir("nonsense-cells-matrix");
    test::write_bytes(dir / "t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const auto path = dir / "m.cells.json";
    for (const std::string part : {"translate", "rotate_y_degrees", "scale"}) {
        SCOPED_TRACE(part);
        const std::string value = part == "translate" ? "[1,0,0]" : "2";
        test::write_bytes(
            path,
            R"({"zraster_cells":1,"meshes":{"t":"t.obj"},"instances":[{"name":"i","mesh":"t",)"
            R"("matrix":[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],")" +
                part + R"(":)" + value +
                R"(}],"cells":[{"name":"a","box":[[-5,-5,-5],[5,5,5]],"instances":["i"]}],)"
                R"("portals":[]})");
        test::expect_input_error(
            [&] { load_scene(path); }, path,
            "instances[0]: has both \"matrix\" and \"" + part +
                "\" (the transform is a matrix or translate, rotate_y_degrees and scale, not "
                "both: docs/portals.md)");
    }
}

// Two valid MTL statements Assimp's MTL reader misread: `decal` (taken for `d` and "ecal", which
// failed the load) and a color of one number (the MTL specification's gray, read as red). On
// both OBJ paths: zraster's reader, and Assimp's (a pentagon first).
TEST(LoaderNonsense, MtlDecalsAreIgnoredWithAWarningAndOneNumberColorsAreGray) {
    const auto dir = test::temp_dir("nonsense-mtl-decal");
    test::write_bytes(dir / "m.mtl", "newmtl gray\nKd 0.5\nKs 0.25 # spec\ndecal d.png\n");
    const std::string body = "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl gray\nf 1 2 3\n";
    for (const std::string& text : {"mtllib m.mtl\n" + body, "mtllib m.mtl\n" + kPentagon + body}) {
        const auto obj = dir / "m.obj";
        test::write_bytes(obj, text);
        for (const LoadIsolation isolation : kIsolations) {
            SCOPED_TRACE(text.size());
            const io::LoadedScene loaded = test::load_with_warnings(obj, isolated(isolation));
            ASSERT_EQ(loaded.scene.materials.size(), 2u);
            const Material& gray = loaded.scene.materials[1];
            EXPECT_EQ(gray.base_color, glm::vec3(0.5f));
            EXPECT_EQ(gray.specular, glm::vec3(0.25f));
            ASSERT_EQ(loaded.warnings.size(), 1u);
            EXPECT_NE(loaded.warnings[0].find(
                          "material library m.mtl: line 4: decal maps are not supported; ignored"),
                      std::string::npos)
                << loaded.warnings[0];
        }
    }
}

// A cause or warning quoting megabytes of the input (a field name, a material name) is cut: the
// one line stays a line.
TEST(LoaderNonsense, QuotesOfMegabytesAreCut) {
    const auto dir = test::temp_dir("nonsense-long-quotes");
    const std::string huge(10 << 20, 'x');
    test::write_bytes(dir / "t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const auto cells = dir / "long.cells.json";
    test::write_bytes(cells, R"({"zraster_cells":1,")" + huge + R"(":1})");
    try {
        load_scene(cells);
        ADD_FAILURE() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_LT(std::string(e.what()).size(), 4096 + cells.string().size() + 2);
        EXPECT_NE(e.cause().find("xxx... ("), std::string::npos);
        EXPECT_NE(e.cause().find(" bytes cut) ...xxx"), std::string::npos);
    }
    const auto obj = dir / "long-name.obj";
    test::write_bytes(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl " + huge + "\nf 1 2 3\n");
    std::vector<std::string> warnings;
    load_scene(obj, {}, &warnings);
    ASSERT_FALSE(warnings.empty());
    for (const std::string& w : warnings) EXPECT_LT(w.size(), 4096 + obj.string().size() + 2);
}

}  // namespace
}  // namespace zraster
