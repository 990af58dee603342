// The fast OBJ reader against load_scene's Assimp path: the same scene for the shared meshes and
// for small files exercising each statement, the cases it leaves to Assimp, and its errors.
#include <zraster/image_io.hpp>
#include <zraster/load.hpp>

#include "io/io_test_util.hpp"
#include "io/load_with_warnings.hpp"
#include "io/obj_parser.hpp"
#include "support/test_support.hpp"

#include <cmath>
#include <variant>

namespace zraster {
namespace {

using io::ObjFallback;

// Coordinates may differ in the last place: the fast reader rounds correctly, Assimp's
// fast_atof does not always.
bool near_ulps(float a, float b, int ulps) {
    for (int i = 0; i < ulps && a != b; ++i) a = std::nextafter(a, b);
    return a == b;
}

void expect_same_vec3(const std::vector<glm::vec3>& fast, const std::vector<glm::vec3>& assimp,
                      float tolerance, const char* what) {
    ASSERT_EQ(fast.size(), assimp.size()) << what;
    int reported = 0;
    for (std::size_t i = 0; i < fast.size() && reported < 5; ++i) {
        for (int k = 0; k < 3; ++k) {
            const bool same = tolerance == 0.0f ? near_ulps(fast[i][k], assimp[i][k], 2)
                                                : std::abs(fast[i][k] - assimp[i][k]) <= tolerance;
            if (!same) {
                ADD_FAILURE() << what << " " << i << "." << k << ": " << fast[i][k] << " vs "
                              << assimp[i][k];
                ++reported;
            }
        }
    }
}

// The whole scene: structure and indices exactly, coordinates to a couple of ulps, normals
// (normalised or computed from those coordinates) to 1e-4: on the shared meshes, where up to 7%
// of the coordinates differ by one ulp, computed normals differ by up to 1.7e-5 (teapot.obj).
// (With Assimp's own number parser in place of std::from_chars, every float is identical.)
void expect_same_scene(const io::LoadedScene& fast_loaded, const io::LoadedScene& assimp_loaded) {
    const Scene& fast = fast_loaded.scene;
    const Scene& assimp = assimp_loaded.scene;
    EXPECT_EQ(fast.name, assimp.name);
    EXPECT_EQ(fast_loaded.warnings, assimp_loaded.warnings);
    ASSERT_EQ(fast.meshes.size(), assimp.meshes.size());
    for (std::size_t m = 0; m < fast.meshes.size(); ++m) {
        const Mesh& a = fast.meshes[m];
        const Mesh& b = assimp.meshes[m];
        SCOPED_TRACE("mesh " + std::to_string(m) + " '" + b.name + "'");
        EXPECT_EQ(a.name, b.name);
        EXPECT_EQ(a.material, b.material);
        EXPECT_EQ(a.vertex_count(), b.vertex_count());
        EXPECT_EQ(a.triangle_count(), b.triangle_count());
        EXPECT_TRUE(a.indices == b.indices) << "indices differ";
        expect_same_vec3(a.positions, b.positions, 0.0f, "position");
        expect_same_vec3(a.normals, b.normals, 1e-4f, "normal");
        ASSERT_EQ(a.uvs.size(), b.uvs.size());
        for (std::size_t i = 0; i < a.uvs.size(); ++i) {
            ASSERT_TRUE(near_ulps(a.uvs[i].x, b.uvs[i].x, 2) &&
                        near_ulps(a.uvs[i].y, b.uvs[i].y, 2))
                << "uv " << i << ": (" << a.uvs[i].x << ", " << a.uvs[i].y << ") vs (" << b.uvs[i].x
                << ", " << b.uvs[i].y << ")";
        }
        for (int k = 0; k < 3; ++k) {
            EXPECT_TRUE(near_ulps(a.bounds.lo[k], b.bounds.lo[k], 2));
            EXPECT_TRUE(near_ulps(a.bounds.hi[k], b.bounds.hi[k], 2));
        }
    }
    ASSERT_EQ(fast.instances.size(), assimp.instances.size());
    for (std::size_t i = 0; i < fast.instances.size(); ++i) {
        EXPECT_EQ(fast.instances[i].mesh, assimp.instances[i].mesh);
        EXPECT_EQ(fast.instances[i].name, assimp.instances[i].name);
        EXPECT_EQ(fast.instances[i].transform, assimp.instances[i].transform);
    }
    ASSERT_EQ(fast.materials.size(), assimp.materials.size());
    for (std::size_t i = 0; i < fast.materials.size(); ++i) {
        const Material& a = fast.materials[i];
        const Material& b = assimp.materials[i];
        SCOPED_TRACE("material " + b.name);
        EXPECT_EQ(a.name, b.name);
        for (int k = 0; k < 3; ++k) {
            EXPECT_TRUE(near_ulps(a.base_color[k], b.base_color[k], 2));
            EXPECT_TRUE(near_ulps(a.specular[k], b.specular[k], 2));
        }
        EXPECT_TRUE(near_ulps(a.shininess, b.shininess, 2));
        EXPECT_TRUE(near_ulps(a.opacity, b.opacity, 2));
        EXPECT_EQ(a.alpha_mode, b.alpha_mode);
        EXPECT_EQ(a.alpha_cutoff, b.alpha_cutoff);
        ASSERT_EQ(a.base_color_texture != nullptr, b.base_color_texture != nullptr);
        if (a.base_color_texture) {
            EXPECT_EQ(a.base_color_texture->width(), b.base_color_texture->width());
            EXPECT_EQ(a.base_color_texture->height(), b.base_color_texture->height());
        }
        // Opacity textures are small in the tests: every texel.
        ASSERT_EQ(a.opacity_texture != nullptr, b.opacity_texture != nullptr);
        if (a.opacity_texture) {
            const auto x = a.opacity_texture->level_rgba(0), y = b.opacity_texture->level_rgba(0);
            EXPECT_TRUE(std::equal(x.begin(), x.end(), y.begin(), y.end()));
        }
    }
}

// The fast reader must read the file itself (no fallback) and agree with the Assimp path.
io::LoadedScene expect_parity(const std::filesystem::path& path) {
    SCOPED_TRACE(path.string());
    std::variant<io::LoadedScene, ObjFallback> fast = io::read_obj(path, {});
    if (const auto* fallback = std::get_if<ObjFallback>(&fast)) {
        ADD_FAILURE() << "left to Assimp: line " << fallback->line << ": " << fallback->reason;
        return {};
    }
    expect_same_scene(std::get<io::LoadedScene>(fast), io::load_scene_with_assimp(path, {}));
    // load_scene takes the fast path and gives the same.
    expect_same_scene(test::load_with_warnings(path), std::get<io::LoadedScene>(fast));
    return std::get<io::LoadedScene>(std::move(fast));
}

// The fast reader leaves the file to Assimp, and load_scene then gives Assimp's scene.
void expect_fallback(const std::filesystem::path& path, std::size_t line) {
    SCOPED_TRACE(path.string());
    std::variant<io::LoadedScene, ObjFallback> fast = io::read_obj(path, {});
    ASSERT_TRUE(std::holds_alternative<ObjFallback>(fast)) << "read by the fast reader";
    EXPECT_EQ(std::get<ObjFallback>(fast).line, line) << std::get<ObjFallback>(fast).reason;
    expect_same_scene(test::load_with_warnings(path), io::load_scene_with_assimp(path, {}));
}

std::filesystem::path write_obj(const std::string& test, std::string_view content,
                                const std::string& name = "model.obj") {
    const auto dir = test::temp_dir("io-obj-" + test);
    test::write_bytes(dir / name, content);
    return dir / name;
}

const char* kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

TEST(ObjParser, SharedMeshesMatchTheAssimpPath) {
    ZRASTER_REQUIRE_SHARED_DATA();
    int files = 0;
    for (const auto& entry :
         std::filesystem::recursive_directory_iterator(test::shared_data("meshes/obj"))) {
        if (entry.path().extension() != ".obj") continue;
        const Scene scene = expect_parity(entry.path()).scene;
        EXPECT_GT(scene.triangle_count(), 0u);
        ++files;
    }
    EXPECT_GE(files, 8);
}

TEST(ObjParser, SharedMeshCountsAndWelding) {
    ZRASTER_REQUIRE_SHARED_DATA();
    // bunny.obj: one vertex per `v` line, triangles only, no normals (computed).
    const Scene bunny = expect_parity(test::shared_data("meshes/obj/bunny.obj")).scene;
    ASSERT_EQ(bunny.meshes.size(), 1u);
    EXPECT_EQ(bunny.meshes[0].triangle_count(), 69666u);
    EXPECT_EQ(bunny.meshes[0].vertex_count(), 34835u);
    // suzanne.obj: 468 quads and 32 triangles with v//vn.
    const Scene suzanne = expect_parity(test::shared_data("meshes/obj/suzanne.obj")).scene;
    EXPECT_EQ(suzanne.triangle_count(), 2u * 468 + 32);
}

TEST(ObjParser, CornerFormsAndNegativeIndices) {
    const std::string normals = "vn 0 0 1\nvn 0 0 -2\n";
    const std::string uvs = "vt 0 0\nvt 1 0\nvt 1 1\nvt 0.25 0.75\n";
    expect_parity(write_obj("forms-v", std::string(kSquare) + "f 1 2 3\nf 1 3 4\n"));
    expect_parity(write_obj(
        "forms-vn", std::string(kSquare) + normals + "f 1//1 2//1 3//1\nf 1//2 3//2 4//2\n"));
    expect_parity(
        write_obj("forms-vt", std::string(kSquare) + uvs + "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n"));
    expect_parity(write_obj("forms-vtvn", std::string(kSquare) + uvs + normals +
                                              "f 1/1/1 2/2/1 3/3/1\nf 1/1/2 3/3/2 4/4/2\n"));
    // Relative indices count back from the line; vertices may also come after the faces.
    const Scene negative =
        expect_parity(write_obj("negative", std::string(kSquare) +
                                                "f -4 -3 -2\nv 5 5 5\nf -1 -2 -3\n" + uvs +
                                                normals + "f 1/-4/-2 2/-3/-2 -1/-1/-1\n"))
            .scene;
    EXPECT_EQ(negative.triangle_count(), 3u);
    expect_parity(write_obj("forward", "f 1 2 3\n" + std::string(kSquare)));
}

TEST(ObjParser, QuadsSplitLikeAssimp) {
    // A convex quad is split from its first corner; a concave one from its reflex corner.
    const Scene convex =
        expect_parity(write_obj("quad", std::string(kSquare) + "f 1 2 3 4\n")).scene;
    EXPECT_EQ(convex.meshes.at(0).indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
    const Scene concave =
        expect_parity(
            write_obj("concave",
                      "v 0 0 0\nv 2 0 0\nv 0.5 0.5 0\nv 0 2 0\nf 1 2 3 4\nf 2 3 4 1\nf 4 1 2 3\n"))
            .scene;
    EXPECT_EQ(concave.meshes.at(0).indices,
              (std::vector<std::uint32_t>{2, 3, 0, 2, 0, 1, 2, 3, 0, 2, 0, 1, 2, 3, 0, 2, 0, 1}));
    // With a line or point element in the mesh, Assimp moves the triangles to a mesh of their
    // own corner by corner, so the vertices come in fan order (here from the reflex corner 3).
    const Scene mixed =
        expect_parity(
            write_obj("mixed-quad", "v 0 0 0\nv 1 2 3\nv 1 0 0\nv 1 1 0\nf 1 2 3 4\nl 1 2\n"))
            .scene;
    EXPECT_EQ(mixed.meshes.at(0).positions.at(0), glm::vec3(1, 1, 0));
    EXPECT_EQ(mixed.meshes.at(0).indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
    // Degenerate quads (repeated corners, collinear) decide the same way too.
    expect_parity(write_obj("degenerate-quads",
                            std::string(kSquare) + "v 2 0 0\nf 1 1 2 3\nf 1 2 5 3\nf 1 2 2 2\n"));
}

TEST(ObjParser, WeldsEqualValuesLikeTheAssimpPath) {
    // Duplicate `v` lines, per-corner duplicate normals, -0 and +0, and uvs that differ only
    // before the v flip rounds them together: one vertex per distinct value, as welding gives.
    const Scene scene =
        expect_parity(
            write_obj("weld",
                      std::string(kSquare) +
                          "v 0 0 0\nv -0 1 0\nvn 0 0 1\nvn 0 0 1\nvn 0 0 2\nvn 0 0 1\n"
                          "vt 0 0.1\nvt 0 0.10000000001\nvt 0 0.1\n"
                          "f 1/1/1 2/2/2 3/3/3\nf 5/2/4 3/3/1 6/1/2\nf 1/1/1 2/2/1 4/3/3\n"))
            .scene;
    EXPECT_EQ(scene.meshes.at(0).vertex_count(), 4u);
}

TEST(ObjParser, SyntaxVariants) {
    // Comments, blank and indented lines, tabs, extra blanks, exponents and signs, CRLF,
    // trailing blanks, no final newline, vp/s/unknown statements, homogeneous and coloured
    // vertices, an empty face, a UTF-8 byte order mark (Assimp ignores the first line then).
    expect_parity(write_obj("syntax",
                            "# a comment\n\n  v 9 9 9\nv\t1e-3  -2.5E+1\t+3 \nv -0 -.5e1 1. \n"
                            "v 1.0e0 2 3.25 # comment\nv 2 4 6 2\nv 0 1 0 0.5 0.5 0.5\n"
                            "vp 0.5\ns 1\nusemap x\nf\nf  1 2\t3  \n\tf 9 9 9\nf 3 4 5\nf 1 2 5"));
    expect_parity(write_obj("crlf",
                            "o first \r\nv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\n"
                            "g second  \r\nf 1 2 3\r\ng third\r\nf 3 2 1\r\n"));
    expect_parity(write_obj("bom", "\xEF\xBB\xBFv 7 7 7\n" + std::string(kSquare) + "f 2 3 4\n"));
    expect_parity(
        write_obj("nan-unused", "v nan 0 0\nv 1e999 0 0\n" + std::string(kSquare) + "f 3 4 5\n"));
}

TEST(ObjParser, ObjectsGroupsAndMaterialsSplitMeshesLikeAssimp) {
    const auto dir = test::temp_dir("io-obj-structure");
    test::write_bytes(dir / "m.mtl",
                      "newmtl red\nKd 1 0 0\nKs 0.5 0.5 0.5\nNs 10\nd 0.5\n"
                      "newmtl blue\nKd 0 0 1\nTr 0.25\nnewmtl single\nKd 0.5\n");
    const std::string tri = "f 1 2 3\n";
    const std::vector<std::string> files = {
        // Faces without an object create "defaultobject"; usemtl with no material yet only
        // sets the mesh's material.
        tri + "usemtl red\n" + tri,
        // A new material on a mesh with faces starts a mesh named after the material.
        "o a\nusemtl red\n" + tri + "usemtl blue\n" + tri + "usemtl red\n" + tri,
        // Repeating the material, or switching before any face, starts nothing.
        "usemtl red\n" + tri + "usemtl red\n" + tri + "usemtl blue\nusemtl red\n" + tri,
        // `o` reuses an object of the same name without changing the current mesh.
        "o a\n" + tri + "o b\n" + tri + "o a\n" + tri + "usemtl blue\n" + tri,
        // `g` creates an object for each change of group, named by the rest of the line.
        "g a b  \n" + tri + "g\n" + tri + "g a b  \n" + tri + "g # x\n" + tri,
        // Objects without faces, groups inside objects, materials carried into new objects.
        "o empty\no full\ng part\nusemtl blue\n" + tri + "o next\n" + tri,
        // Lines and points count as faces of a mesh but are dropped.
        tri + "l 1 2 3\np 1\nusemtl red\n" + tri + "o lines\nl 1 2\nusemtl blue\np 2 3\n",
        // A material used before the library is read, and one no library defines.
        "usemtl blue\n" + tri + "mtllib m.mtl\nusemtl ghost\n" + tri + "usemtl single\n" + tri,
    };
    for (std::size_t i = 0; i < files.size(); ++i) {
        const std::string name = "s" + std::to_string(i) + ".obj";
        const std::string library = i == 7 ? "" : "mtllib m.mtl\n";
        test::write_bytes(dir / name, library + "v 0 0 0\nv 1 0 0\nv 0 1 0\n" + files[i]);
        expect_parity(dir / name);
    }
}

TEST(ObjParser, MaterialLibrariesAndTexturesLikeTheAssimpPath) {
    const auto dir = test::temp_dir("io-obj-materials");
    std::filesystem::create_directory(dir / "maps");
    std::vector<std::uint8_t> rgb(4 * 2 * 3, 200);
    write_png8(dir / "maps" / "t.png", 4, 2, 3, rgb);
    test::write_bytes(dir / "lib.mtl",
                      "newmtl skin\nKd 0.2 0.4 0.6\nmap_Kd -s 1 1 1 maps\\t.png\n"
                      "newmtl gone\nmap_Kd nothere.png\n");
    const std::string body = std::string(kSquare) + "vt 0 0\nvt 1 0\nvt 1 1\n";
    // Found, missing with the <obj>.mtl fallback, missing altogether, and a used name that is
    // not defined.
    test::write_bytes(dir / "a.obj", "mtllib lib.mtl\n" + body +
                                         "usemtl skin\nf 1/1 2/2 3/3\nusemtl gone\nf 1 3 4\n"
                                         "usemtl ghost\nf 2 3 4\n");
    test::write_bytes(dir / "b.obj", "mtllib other.mtl\n" + body + "usemtl skin\nf 1/1 2/2 3/3\n");
    test::write_bytes(dir / "b.mtl", "newmtl skin\nKd 1 1 0\n");
    test::write_bytes(dir / "c.obj",
                      "mtllib none.mtl\nmtllib none.mtl\n" + body + "usemtl skin\nf 1/1 2/2 3/3\n");
    const io::LoadedScene a = expect_parity(dir / "a.obj");
    EXPECT_EQ(a.warnings.size(), 2u);  // nothere.png, ghost
    const io::LoadedScene b = expect_parity(dir / "b.obj");
    ASSERT_EQ(b.warnings.size(), 1u);
    EXPECT_EQ(b.warnings[0],
              (dir / "b.obj").string() + ": material library 'other.mtl' not found, using 'b.mtl'");
    const io::LoadedScene c = expect_parity(dir / "c.obj");
    ASSERT_EQ(c.warnings.size(), 1u);
    EXPECT_NE(c.warnings[0].find("material library 'none.mtl' not found, using the default"),
              std::string::npos);
}

// MTL alpha (d, Tr, d over Tr, map_d) is the same on both paths, and through the worker that
// runs the Assimp path; a file left to Assimp gets it too.
TEST(ObjParser, MaterialAlphaLikeTheAssimpPath) {
    const auto dir = test::temp_dir("io-obj-alpha");
    std::vector<std::uint8_t> grey = {0, 64, 128, 255};
    write_png8(dir / "grey.png", 2, 2, 1, grey);
    std::vector<std::uint8_t> rgba(16, 255);
    rgba[7] = 0;
    write_png8(dir / "cut.png", 2, 2, 4, rgba);
    test::write_bytes(dir / "alpha.mtl",
                      "newmtl half\nd 0.5\nnewmtl tr\nTr 0.25\nnewmtl both\nd 0.5\nTr 0.9\n"
                      "newmtl grey\nmap_d grey.png\nnewmtl cut\nmap_Kd grey.png\nmap_d cut.png\n");
    const std::string body = "mtllib alpha.mtl\n" + std::string(kSquare) + "vt 0 0\nvt 1 0\n";
    std::string faces;
    for (const char* name : {"half", "tr", "both", "grey", "cut"})
        faces += std::string("usemtl ") + name + "\nf 1/1 2/2 3/1\n";
    test::write_bytes(dir / "fast.obj", body + faces);
    test::write_bytes(dir / "left.obj", body + "f 1 2 3 4 1\n" + faces);  // a degenerate n-gon
    const io::LoadedScene fast = expect_parity(dir / "fast.obj");
    ASSERT_EQ(fast.scene.materials.size(), 6u);
    EXPECT_EQ(fast.scene.materials[1].opacity, 0.5f);
    EXPECT_EQ(fast.scene.materials[2].opacity, 0.75f);
    EXPECT_EQ(fast.scene.materials[3].opacity, 0.5f);  // d over Tr
    EXPECT_TRUE(fast.scene.materials[4].opacity_texture);
    ASSERT_TRUE(fast.scene.materials[5].opacity_texture);
    EXPECT_EQ(fast.scene.materials[5].opacity_texture->level_rgba(0)[4], 0);  // cut.png's alpha
    LoadOptions worker;
    worker.isolation = LoadIsolation::WorkerProcess;
    expect_same_scene(fast, io::load_scene_with_assimp(dir / "fast.obj", worker));
    expect_fallback(dir / "left.obj", 8);
    const Scene left = load_scene(dir / "left.obj");
    ASSERT_EQ(left.materials.size(), fast.scene.materials.size());
    for (const Material& a : fast.scene.materials) {
        const auto b = std::find_if(left.materials.begin(), left.materials.end(),
                                    [&](const Material& m) { return m.name == a.name; });
        ASSERT_NE(b, left.materials.end()) << a.name;
        EXPECT_EQ(b->opacity, a.opacity) << a.name;
        EXPECT_EQ(b->alpha_mode, a.alpha_mode) << a.name;
        EXPECT_EQ(b->opacity_texture != nullptr, a.opacity_texture != nullptr) << a.name;
    }
}

TEST(ObjParser, MissingAndUnusableAttributesLikeTheAssimpPath) {
    // Faces with and without uvs or normals in one mesh (Assimp zeroes the missing ones), zero
    // and non-finite normals (replaced by computed ones): vertices that become equal are welded.
    const std::string v = std::string(kSquare) + "v 0 0 1\n";
    expect_parity(
        write_obj("mixed-uvs", v + "vt 0.5 0.5\nvt 0 0\nf 1/1 2/1 3/1\nf 1 3 4\nf 1/2 2/2 5/2\n"));
    expect_parity(write_obj("mixed-normals", v + "vn 0 0 1\nf 1//1 2//1 3//1\nf 1 3 4\nf 3 4 5\n"));
    expect_parity(
        write_obj("bad-normals", v + "vn 0 0 0\nvn nan 0 1\nvn 1e30 1e30 0\nvn 0 0 1\n"
                                     "f 1//1 2//2 3//3\nf 1//4 3//2 4//1\nf 1//1 4//4 5//4\n"));
    // Assimp reads a non-finite texture coordinate as 0.
    const io::LoadedScene uvs = expect_parity(write_obj(
        "bad-uvs", "o quad\n" + v + "vt nan 0\nvt 0 inf\nvt 0 1\nf 1/1 2/2 3/3\nf 1/3 3/1 4/2\n"));
    EXPECT_EQ(uvs.scene.meshes.at(0).vertex_count(), 6u);
    EXPECT_TRUE(uvs.warnings.empty());
}

TEST(ObjParser, LeavesWhatAssimpBendsToTheAssimpPath) {
    const std::string v = kSquare;
    expect_fallback(write_obj("ngon", v + "v 0.5 -1 0\nf 1 5 2 3 4\n"), 6);
    expect_fallback(write_obj("mixed-forms", v + "vn 0 0 1\nf 1//1 2 3\n"), 6);
    expect_fallback(write_obj("continuation", v + "f 1 2 \\\n3\n"), 5);
    expect_fallback(write_obj("uv-before-uvs", v + "vn 0 0 1\nf 1/1 2/1 3/1\n"), 6);
    expect_fallback(write_obj("cstype", v + "cstype bspline\nf 1 2 3\nend\nf 1 2 3\n"), 5);
    expect_fallback(write_obj("lone-cr", v + "# x\rf 1 2 3\nf 1 3 4\n"), 5);
    // Assimp refuses OBJ files under 16 bytes.
    const auto tiny = write_obj("tiny", "v 0 0 0\nf 1 1 1");
    EXPECT_TRUE(std::holds_alternative<ObjFallback>(io::read_obj(tiny, {})));
    test::expect_input_error([&] { load_scene(tiny); }, tiny, "OBJ-file is too small");
}

TEST(ObjParser, ErrorsNameTheLine) {
    const std::string v = kSquare;
    auto expect_error = [](const std::filesystem::path& path, std::string_view cause) {
        test::expect_input_error([&] { load_scene(path); }, path, cause);
    };
    expect_error(write_obj("range", v + "f 1 2 3\n\nf 1 2 7\n"),
                 "line 7: vertex index out of range (7; the file has 4 vertices)");
    expect_error(write_obj("negative-range", v + "f -5 1 2\n"),
                 "line 5: vertex index out of range (a negative index before the first vertex)");
    expect_error(write_obj("zero", v + "f 1 2 3\nf 0 1 2\n"), "line 6: invalid face index 0");
    expect_error(write_obj("line-range", v + "f 1 2 3\nl 1 9\n"),
                 "line 6: vertex index out of range");
    // Texture and normal indices as vertex indices (Assimp would clamp or drop them silently).
    expect_error(write_obj("normal-range", v + "vn 0 0 1\nf 1//1 2//1 3//2\n"),
                 "line 6: normal index out of range (2; the file has 1 normals)");
    expect_error(write_obj("uv-range", v + "vt 0 0\nvt 1 0\nf 1/1 2/2 3/3\n"),
                 "line 7: texture coordinate index out of range (3; the file has 2 texture "
                 "coordinates)");
    expect_error(write_obj("uv-negative-range", v + "vt 0 0\nf 1/1 2/-2 3/1\n"),
                 "line 6: texture coordinate index out of range (a negative index before the "
                 "first texture coordinate)");
    // The same in a file left to Assimp (a pentagon), checked before Assimp by
    // obj_index_scan.cpp; a texture slot before the first vt is Assimp's normal index.
    expect_error(write_obj("ngon-uv-range", v + "v 0.5 -1 0\nvt 0 0\nf 1/1 5/1 2/9 3/1 4/1\n"),
                 "line 7: texture coordinate index out of range (9; the file has 1 texture "
                 "coordinates)");
    expect_error(
        write_obj("ngon-normal-range", v + "v 0.5 -1 0\nvn 0 0 1\nf 1//1 5//-2 2//1 3//1 4//1\n"),
        "line 7: normal index out of range (a negative index before the first normal)");
    EXPECT_EQ(
        load_scene(write_obj("ngon-in-range",
                             v + "v 0.5 -1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 5/1/1 2/1/1 3/1/1 4/1/1\n"))
            .meshes.size(),
        1u);
    expect_error(write_obj("uv-without-uvs", v + "f 1/1 2/1 3/1\n"),
                 "line 5: texture coordinate index out of range (1; the file has 0 texture "
                 "coordinates)");
    expect_error(write_obj("nan", "v 0 0 0\nv 1 0 0\n\nv nan 0 0\nf 1 2 3\n"),
                 "line 4: non-finite vertex coordinates (mesh defaultobject, vertex 2)");
    expect_error(write_obj("inf", "o thing\nv 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n"),
                 "line 3: non-finite vertex coordinates (mesh thing, vertex 1)");
    expect_error(write_obj("no-triangles", v + "l 1 2 3\np 4\nf\n"), "no triangles");
    // Left to Assimp, which refuses it: the line the fast reader stopped at and why, then
    // Assimp's message.
    expect_error(write_obj("comment-in-face", v + "f 1 2 3 # comment\n"),
                 "malformed OBJ file: line 5: face element that is not v, v/vt, v//vn or v/vt/vn "
                 "(Assimp: OBJ: Invalid face index.)");
    // A word that is not a number: refused (Assimp read "x" as 0 without a word).
    expect_error(write_obj("word-coordinate", "v 0 0 0\nv 1 x 0\nv 0 1 0\nf 1 2 3\n"),
                 "line 2: 'x' is not a number");
    LoadOptions options;
    options.max_triangles = 2;
    const auto three = write_obj("limit", v + "f 1 2 3 4\nf 1 2 3\n");
    test::expect_input_error([&] { load_scene(three, options); }, three,
                             "too many triangles (3, limit 2)");
}

TEST(ObjParser, ChunkBoundariesDoNotMatter) {
    // Large enough for many chunks: faces refer back across chunk boundaries with absolute and
    // relative indices, and objects and materials change in the middle.
    // Coordinates are multiples of 1/8, which both number parsers read exactly, so that
    // computed normals agree closely. Each block is a strip of two rows of 20 vertices.
    const char* eighths[8] = {".0", ".125", ".25", ".375", ".5", ".625", ".75", ".875"};
    std::string obj;
    int vertices = 0;
    for (int block = 0; block < 3000; ++block) {
        if (block % 700 == 0)
            obj +=
                "o part" + std::to_string(block) + "\nusemtl m" + std::to_string(block % 3) + "\n";
        for (int row = 0; row < 2; ++row) {
            for (int k = 0; k < 20; ++k) {
                obj += "v " + std::to_string(k) + eighths[(k * k + block) % 8] + " " +
                       std::to_string(block + row) + " 0" + eighths[(block * 3 + k) % 8] + "\n";
                ++vertices;
            }
        }
        for (int k = 0; k < 19; ++k) {
            const int a = vertices - 39 + k;  // row 0, column k (1-based)
            obj += "f " + std::to_string(a) + " " + std::to_string(a + 1) + " -" +
                   std::to_string(19 - k) + "\nf " + std::to_string(a) + " -" +
                   std::to_string(19 - k) + " " + std::to_string(a + 20) + "\n";
        }
    }
    const Scene scene = expect_parity(write_obj("chunks", obj)).scene;
    EXPECT_EQ(scene.meshes.size(), 5u);
    EXPECT_EQ(scene.triangle_count(), 3000u * 38);
    EXPECT_EQ(scene.vertex_count(), 3000u * 40);
}

}  // namespace
}  // namespace zraster
