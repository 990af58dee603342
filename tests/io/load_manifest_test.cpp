// Every mesh of ../shared/data/meshes/MANIFEST.md loads with the MANIFEST's triangle count and
// bounding box, and a vertex count explained per format (the MANIFEST counts position records in
// the file; Assimp's importers do not all keep them as they are).
#include <zraster/load.hpp>

#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

#include <array>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace zraster {
namespace {

struct ManifestRow {
    std::size_t vertices = 0;
    std::size_t triangles = 0;
    std::string bounds;  // as printed
};

std::size_t parse_count(std::string s) {
    std::erase(s, ',');
    return std::stoull(s);
}

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(' '), e = s.find_last_not_of(' ');
    return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

// The "## Meshes" table: | File | Format | Size | Vertices | Triangles | Bounding box | ...
std::map<std::string, ManifestRow> read_manifest() {
    std::map<std::string, ManifestRow> rows;
    std::istringstream text(test::read_bytes(test::shared_data("meshes/MANIFEST.md")));
    std::string line;
    bool in_table = false;
    while (std::getline(text, line)) {
        if (line.starts_with("## ")) in_table = line == "## Meshes";
        if (!in_table || !line.starts_with("| `")) continue;
        std::vector<std::string> cells;
        std::istringstream row(line.substr(1));
        for (std::string cell; std::getline(row, cell, '|');) cells.push_back(trim(cell));
        const std::string file = cells.at(0).substr(1, cells.at(0).size() - 2);  // strip ``
        rows[file] = {parse_count(cells.at(3)), parse_count(cells.at(4)), cells.at(5)};
    }
    return rows;
}

// "[a, b, c] – [d, e, f]"
std::optional<Bounds3f> parse_bounds(const std::string& text) {
    Bounds3f b;
    if (std::sscanf(text.c_str(), "[%f, %f, %f] – [%f, %f, %f]", &b.lo.x, &b.lo.y, &b.lo.z, &b.hi.x,
                    &b.hi.y, &b.hi.z) != 6)
        return std::nullopt;
    return b;
}

// Printed to 4 significant digits: relative 1e-3, plus a floor relative to the box's size for
// values printed as tiny non-zeros (-1.407e-14 is float noise of a rotation by 90 degrees).
void expect_bounds_near(const Bounds3f& actual, const Bounds3f& printed) {
    const float scale = glm::max(glm::max(glm::abs(printed.lo), glm::abs(printed.hi)).x,
                                 glm::max(glm::max(glm::abs(printed.lo), glm::abs(printed.hi)).y,
                                          glm::max(glm::abs(printed.lo), glm::abs(printed.hi)).z));
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(actual.lo[k], printed.lo[k], 1e-3f * std::abs(printed.lo[k]) + 1e-6f * scale)
            << "lo[" << k << "]";
        EXPECT_NEAR(actual.hi[k], printed.hi[k], 1e-3f * std::abs(printed.hi[k]) + 1e-6f * scale)
            << "hi[" << k << "]";
    }
}

using Key = std::array<float, 8>;

std::size_t distinct_positions(const Scene& scene) {
    std::set<std::array<float, 3>> set;
    for (const Mesh& m : scene.meshes)
        for (const glm::vec3& p : m.positions) set.insert({p.x + 0.0f, p.y + 0.0f, p.z + 0.0f});
    return set.size();
}

// An independent count of what an OBJ's faces reference: `v` lines, distinct referenced
// positions, and distinct (position, uv, normal) corner values (what welding should produce).
struct ObjCensus {
    std::size_t v_lines = 0;
    std::size_t distinct_positions = 0;
    std::size_t distinct_corners = 0;
};

ObjCensus census_obj(const std::filesystem::path& path) {
    std::vector<std::array<float, 3>> v, vn;
    std::vector<std::array<float, 2>> vt;
    std::set<std::array<float, 3>> positions;
    std::set<Key> corners;
    std::istringstream text(test::read_bytes(path));
    std::string line;
    auto resolve = [](long i, std::size_t n) {
        return i < 0 ? n + i : static_cast<std::size_t>(i - 1);
    };
    while (std::getline(text, line)) {
        std::istringstream words(line);
        std::string kind;
        words >> kind;
        if (kind == "v") {
            float x, y, z;
            words >> x >> y >> z;
            v.push_back({x, y, z});
        } else if (kind == "vt") {
            float s, t;
            words >> s >> t;
            vt.push_back({s, 1.0f - t});
        } else if (kind == "vn") {
            float x, y, z;
            words >> x >> y >> z;
            vn.push_back({x, y, z});
        } else if (kind == "f") {
            for (std::string corner; words >> corner;) {
                Key key{};
                long idx[3] = {0, 0, 0};
                std::istringstream parts(corner);
                std::string part;
                for (int k = 0; k < 3 && std::getline(parts, part, '/'); ++k)
                    idx[k] = part.empty() ? 0 : std::stol(part);
                const auto& p = v.at(resolve(idx[0], v.size()));
                key = {p[0], p[1], p[2], 0, 0, 0, 0, 0};
                if (idx[1]) {
                    const auto& t = vt.at(resolve(idx[1], vt.size()));
                    key[3] = t[0];
                    key[4] = t[1];
                }
                if (idx[2]) {
                    const auto& n = vn.at(resolve(idx[2], vn.size()));
                    key[5] = n[0];
                    key[6] = n[1];
                    key[7] = n[2];
                }
                positions.insert(p);
                corners.insert(key);
            }
        }
    }
    return {v.size(), positions.size(), corners.size()};
}

enum class Vertices {
    AsInFile,      // indexed formats (glTF, PLY, OFF): Assimp keeps the file's vertices
    ObjWelded,     // OBJ: welded back, one vertex per distinct referenced corner value
    OnePerCorner,  // STL, 3DS: a vertex per face corner (flat or smoothing-group normals)
};

struct Case {
    const char* file;
    Vertices vertices;
};

// 3DS bounds are in object-local coordinates in the MANIFEST; Assimp's 3DS importer adds a root
// node turning 3ds Max's z-up into y-up, so the mesh-space box is compared there.
bool mesh_space_bounds(const std::string& file) {
    return file.ends_with(".3ds");
}

const Case kCases[] = {
    {"3ds/cat.3ds", Vertices::OnePerCorner},
    {"gltf/BoxTextured.glb", Vertices::AsInFile},
    {"gltf/BoxTextured/BoxTextured.gltf", Vertices::AsInFile},
    {"gltf/Duck.glb", Vertices::AsInFile},
    {"gltf/Duck/Duck.gltf", Vertices::AsInFile},
    {"gltf/no_indices_3storybuilding.glb", Vertices::AsInFile},
    {"obj/bunny-small.obj", Vertices::ObjWelded},
    {"obj/bunny.obj", Vertices::ObjWelded},
    {"obj/nefertiti.obj", Vertices::ObjWelded},
    {"obj/spider/spider.obj", Vertices::ObjWelded},
    {"obj/spot/spot_triangulated.obj", Vertices::ObjWelded},
    {"obj/stanford-bunny.obj", Vertices::ObjWelded},
    {"obj/suzanne.obj", Vertices::ObjWelded},
    {"obj/teapot.obj", Vertices::ObjWelded},
    {"off/degtri_sliding.off", Vertices::AsInFile},
    {"off/elephant-with-holes.off", Vertices::AsInFile},
    {"ply/bunny.ply", Vertices::AsInFile},
    {"ply/cube_binary.ply", Vertices::AsInFile},
    {"ply/fuze.ply", Vertices::AsInFile},
    {"stl/Spider_ascii.stl", Vertices::OnePerCorner},
    {"stl/Spider_binary.stl", Vertices::OnePerCorner},
    {"stl/sphereWithHole.stl", Vertices::OnePerCorner},
    {"stl/teapot.stl", Vertices::OnePerCorner},
};

// BROKEN entries that must be refused rather than loaded.
const std::map<std::string, std::string> kMustFail = {
    {"gltf/BoxWithInfinites.glb", "non-finite vertex coordinates (mesh Mesh, vertex 0)"},
};

class ManifestMesh : public ::testing::TestWithParam<Case> {};

TEST_P(ManifestMesh, MatchesTheManifest) {
    ZRASTER_REQUIRE_SHARED_DATA();
    const Case& c = GetParam();
    const auto manifest = read_manifest();
    ASSERT_TRUE(manifest.contains(c.file)) << "not in MANIFEST.md: " << c.file;
    const ManifestRow& row = manifest.at(c.file);
    const auto path = test::shared_data(std::string("meshes/") + c.file);

    const Scene scene = load_scene(path);
    EXPECT_EQ(scene.name, path.string());
    EXPECT_EQ(scene.triangle_count(), row.triangles);

    const auto printed = parse_bounds(row.bounds);
    ASSERT_TRUE(printed) << row.bounds;
    if (mesh_space_bounds(c.file)) {
        Bounds3f local;
        for (const Mesh& m : scene.meshes) local.extend(m.bounds);
        expect_bounds_near(local, *printed);
    } else {
        const std::vector<glm::vec3> world = scene.world_positions();
        expect_bounds_near(Bounds3f::of(world), *printed);
    }

    switch (c.vertices) {
        case Vertices::AsInFile:
            EXPECT_EQ(scene.vertex_count(), row.vertices);
            break;
        case Vertices::ObjWelded: {
            // Assimp's OBJ importer gives one vertex per face corner; the loader welds equal
            // ones. Duplicated `v` lines (teapot's patch seams: 403, spider: 40, suzanne: 2) and
            // unreferenced ones (stanford-bunny: 1,113) therefore do not count, and uv or normal
            // seams split a position (spot: 3,225 vertices at 2,930 positions).
            const ObjCensus census = census_obj(path);
            EXPECT_EQ(census.v_lines, row.vertices);
            EXPECT_EQ(scene.vertex_count(), census.distinct_corners);
            EXPECT_EQ(distinct_positions(scene), census.distinct_positions);
            break;
        }
        case Vertices::OnePerCorner:
            // Triangle soups: the MANIFEST counts STL positions after exact welding, and 3DS
            // position records, which are all distinct in cat.3ds.
            EXPECT_EQ(scene.vertex_count(), 3 * row.triangles);
            EXPECT_EQ(distinct_positions(scene), row.vertices);
            break;
    }

    for (const Mesh& mesh : scene.meshes) {
        ASSERT_EQ(mesh.normals.size(), mesh.positions.size()) << mesh.name;
        for (const glm::vec3& n : mesh.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
        EXPECT_TRUE(mesh.uvs.empty() || mesh.uvs.size() == mesh.positions.size());
        for (std::uint32_t i : mesh.indices) ASSERT_LT(i, mesh.positions.size());
        EXPECT_LT(mesh.material, scene.materials.size());
        const Bounds3f exact = Bounds3f::of(mesh.positions);
        EXPECT_EQ(mesh.bounds.lo, exact.lo);
        EXPECT_EQ(mesh.bounds.hi, exact.hi);
    }
}

INSTANTIATE_TEST_SUITE_P(SharedData, ManifestMesh, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case>& info) {
                             std::string name = info.param.file;
                             for (char& ch : name)
                                 if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                             return name;
                         });

TEST(Manifest, EveryMeshIsCovered) {
    ZRASTER_REQUIRE_SHARED_DATA();
    const auto manifest = read_manifest();
    EXPECT_EQ(manifest.size(), std::size(kCases) + kMustFail.size());
    for (const auto& [file, row] : manifest) {
        const bool covered = kMustFail.contains(file) ||
                             std::any_of(std::begin(kCases), std::end(kCases),
                                         [&file = file](const Case& c) { return c.file == file; });
        EXPECT_TRUE(covered) << file << " has no expectation here";
    }
}

TEST(Manifest, BrokenMeshesThatMustFailDo) {
    ZRASTER_REQUIRE_SHARED_DATA();
    for (const auto& [file, cause] : kMustFail) {
        const auto path = test::shared_data("meshes/" + file);
        test::expect_input_error([&] { load_scene(path); }, path, cause);
    }
}

}  // namespace
}  // namespace zraster
