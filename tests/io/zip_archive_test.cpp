// Zip archives (3MF, ZAE) are checked as the files they hold before Assimp inflates them (issue
// 27, hostile run 5's K3-K5 and K8): a model member inflating past the geometry budget, a 3MF
// component naming its own object (a crash in process), components sharing children (7.8 GB from
// 1.2 KB), 200,000 build items (quadratic time), and COLLADA inside a ZAE.
#include <zraster/load.hpp>

#include <zip.h>

#include <string>
#include <utility>
#include <vector>

#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

namespace zraster {
namespace {

// A deflated zip archive of `members` (name, content), written with minizip.
void write_zip(const std::filesystem::path& path,
               const std::vector<std::pair<std::string, std::string>>& members) {
    zipFile zip = zipOpen64(path.c_str(), APPEND_STATUS_CREATE);
    ASSERT_NE(zip, nullptr) << path;
    for (const auto& [name, content] : members) {
        ASSERT_EQ(zipOpenNewFileInZip64(zip, name.c_str(), nullptr, nullptr, 0, nullptr, 0, nullptr,
                                        Z_DEFLATED, Z_DEFAULT_COMPRESSION, 1),
                  ZIP_OK);
        ASSERT_EQ(zipWriteInFileInZip(zip, content.data(), static_cast<unsigned>(content.size())),
                  ZIP_OK);
        ASSERT_EQ(zipCloseFileInZip(zip), ZIP_OK);
    }
    ASSERT_EQ(zipClose(zip, nullptr), ZIP_OK);
}

const std::string kTriangleMesh =
    R"(<mesh><vertices><vertex x="0" y="0" z="0"/><vertex x="1" y="0" z="0"/><vertex x="0" y="1" z="0"/></vertices><triangles><triangle v1="0" v2="1" v3="2"/></triangles></mesh>)";

// A 3MF package of one model member holding `objects` and `items`.
void write_3mf(const std::filesystem::path& path, const std::string& objects,
               const std::string& items) {
    write_zip(
        path,
        {{"[Content_Types].xml",
          R"(<?xml version="1.0" encoding="UTF-8"?><Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types"><Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/><Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/></Types>)"},
         {"_rels/.rels",
          R"(<?xml version="1.0" encoding="UTF-8"?><Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships"><Relationship Target="/3D/3dmodel.model" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/></Relationships>)"},
         {"3D/3dmodel.model",
          R"(<?xml version="1.0" encoding="UTF-8"?><model unit="millimeter" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02"><resources>)" +
              objects + "</resources><build>" + items + "</build></model>"}});
}

std::string mesh_object(int id) {
    return "<object id=\"" + std::to_string(id) + "\" type=\"model\">" + kTriangleMesh +
           "</object>";
}

// Object `id` placing each of `children` once.
std::string component_object(int id, const std::vector<int>& children) {
    std::string s = "<object id=\"" + std::to_string(id) + "\" type=\"model\"><components>";
    for (int c : children) s += "<component objectid=\"" + std::to_string(c) + "\"/>";
    return s + "</components></object>";
}

TEST(ZipArchives, ThreeMfComponentGraphsAreCheckedBeforeTheImport) {
    const auto dir = test::temp_dir("zip-3mf");
    write_3mf(dir / "ok.3mf", mesh_object(1) + component_object(2, {1, 1}),
              R"(<item objectid="2"/>)");
    write_3mf(dir / "self.3mf", mesh_object(1) + component_object(2, {1, 2}),
              R"(<item objectid="2"/>)");
    std::string doubling = mesh_object(1);  // each object places the one before twice
    for (int k = 2; k <= 25; ++k) doubling += component_object(k, {k - 1, k - 1});
    write_3mf(dir / "doubling.3mf", doubling, R"(<item objectid="25"/>)");
    std::string chain = mesh_object(1);
    for (int k = 2; k <= 1002; ++k) chain += component_object(k, {k - 1});
    write_3mf(dir / "chain.3mf", chain, R"(<item objectid="1002"/>)");
    std::string items;
    for (int k = 0; k < 101; ++k) items += R"(<item objectid="1"/>)";
    write_3mf(dir / "items.3mf", mesh_object(1), items);
    for (const LoadIsolation isolation : test::kBothIsolations) {
        LoadOptions o;
        o.isolation = isolation;
        EXPECT_EQ(load_scene(dir / "ok.3mf", o).triangle_count(), 2u);
        test::expect_input_error([&] { load_scene(dir / "self.3mf", o); }, dir / "self.3mf",
                                 "malformed 3MF file: 3D/3dmodel.model: object 2 contains itself "
                                 "(through its components)");
        test::expect_input_error([&] { load_scene(dir / "chain.3mf", o); }, dir / "chain.3mf",
                                 "malformed 3MF file: 3D/3dmodel.model: its components nest more "
                                 "than 1000 levels deep");
        test::expect_limit_exceeded([&] { load_scene(dir / "doubling.3mf", o); },
                                    dir / "doubling.3mf", "max_instances",
                                    "3D/3dmodel.model: its build places 16777216 meshes");
        LoadOptions few = o;
        few.max_instances = 1000;  // 100 build items
        test::expect_limit_exceeded([&] { load_scene(dir / "items.3mf", few); }, dir / "items.3mf",
                                    "max_instances",
                                    "3D/3dmodel.model: its build has 101 items, more than "
                                    "max_instances / 10 (100;");
    }
}

TEST(ZipArchives, MembersInflatingPastTheGeometryBudgetAreRefusedUnread) {
    const auto dir = test::temp_dir("zip-inflate");
    // 3 MiB of spaces before the model: deflated to a few KB.
    write_3mf(dir / "wide.3mf", std::string(3 << 20, ' ') + mesh_object(1),
              R"(<item objectid="1"/>)");
    for (const LoadIsolation isolation : test::kBothIsolations) {
        LoadOptions o;
        o.isolation = isolation;
        EXPECT_EQ(load_scene(dir / "wide.3mf", o).triangle_count(), 1u);
        o.max_geometry_bytes = 2 << 20;
        test::expect_limit_exceeded([&] { load_scene(dir / "wide.3mf", o); }, dir / "wide.3mf",
                                    "max_geometry_bytes",
                                    "its archive's members inflate to 3 MiB, which the importer "
                                    "reads whole: more than max_geometry_bytes (2 MiB)");
    }
}

TEST(ZipArchives, ColladaInsideAZaeIsCheckedAsADaeFile) {
    const auto dir = test::temp_dir("zip-zae");
    const std::string dae =
        R"(<?xml version="1.0"?><COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1"><asset><up_axis>Y_UP</up_axis></asset><library_geometries><geometry id="g"><mesh><source id="p"><float_array id="pa" count="-1">0 0 0 1 0 0 0 1 0</float_array><technique_common><accessor source="#pa" count="3" stride="3"><param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source><vertices id="v"><input semantic="POSITION" source="#p"/></vertices><triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p></triangles></mesh></geometry></library_geometries><library_visual_scenes><visual_scene id="s"><node id="a"><instance_geometry url="#g"/></node></visual_scene></library_visual_scenes><scene><instance_visual_scene url="#s"/></scene></COLLADA>)";
    write_zip(
        dir / "m.zae",
        {{"manifest.xml", R"(<?xml version="1.0"?><dae_root>./m.dae</dae_root>)"}, {"m.dae", dae}});
    test::expect_refused_both_ways(
        dir / "m.zae", R"(malformed COLLADA file: <float_array id="pa"> has count="-1")");
}

}  // namespace
}  // namespace zraster
