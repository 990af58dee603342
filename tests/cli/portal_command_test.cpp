// `zraster render --portal-cull` and `--pvs`, `zraster pvs`, and cells.json files: the same PNG
// as without culling, the --stats lines, the PVS file's schema, and one-line errors.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "support/test_support.hpp"

namespace zraster::test {
namespace {

TEST(PortalCommand, RenderStatsAndTheSameImage) {
    const auto dir = temp_dir("portal_render");
    const std::string common = "render building:4x4 --size 160x90 --stats ";
    const CommandResult plain = run_zraster(common + "-o plain.png", dir);
    const CommandResult culled = run_zraster(common + "--portal-cull -o culled.png", dir);
    const CommandResult boxes = run_zraster(common + "--portal-cull=rectangles -o boxes.png", dir);
    ASSERT_EQ(plain.exit_code, 0) << plain.output;
    ASSERT_EQ(culled.exit_code, 0) << culled.output;
    ASSERT_EQ(boxes.exit_code, 0) << boxes.output;
    EXPECT_NE(plain.output.find("occlusion-culled, 0 portal-culled)"), std::string::npos);
    EXPECT_EQ(plain.output.find("portals:"), std::string::npos);
    EXPECT_NE(culled.output.find("scene building:4x4: 99 instances (14 frustum-culled, 0 "
                                 "occlusion-culled, 70 portal-culled)"),
              std::string::npos)
        << culled.output;
    EXPECT_NE(culled.output.find("  portals: camera in cell 0 'room_0_0', 7 of 37 cells visited"),
              std::string::npos)
        << culled.output;
    EXPECT_EQ(read_bytes(dir / "plain.png"), read_bytes(dir / "culled.png"));
    EXPECT_EQ(read_bytes(dir / "plain.png"), read_bytes(dir / "boxes.png"));
}

TEST(PortalCommand, CameraOutsideEveryCellSaysSo) {
    const auto dir = temp_dir("portal_outside");
    const CommandResult r = run_zraster(
        "render building:2x2 --size 64x48 --stats --portal-cull --eye 4,20,-10 --target 4,0,4",
        dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("0 portal-culled"), std::string::npos);
    EXPECT_NE(r.output.find("portals: camera outside every cell: not culled"), std::string::npos)
        << r.output;
}

TEST(PortalCommand, PvsFileSchemaAndUse) {
    const auto dir = temp_dir("portal_pvs");
    const CommandResult made = run_zraster("pvs building:3x3 -o sets.json", dir);
    ASSERT_EQ(made.exit_code, 0) << made.output;
    EXPECT_NE(made.output.find("pvs: "), std::string::npos);
    const nlohmann::json pvs = nlohmann::json::parse(read_bytes(dir / "sets.json"));
    EXPECT_EQ(pvs["zraster_pvs"], 1);
    EXPECT_EQ(pvs["scene"], "building:3x3");
    ASSERT_TRUE(pvs["sets"].is_array());
    EXPECT_EQ(pvs["sets"].size(), pvs["cells"].get<std::size_t>());
    EXPECT_EQ(pvs["sets"][0]["cell"], "room_0_0");
    EXPECT_FALSE(pvs["sets"][0]["bounded"].get<bool>());
    EXPECT_EQ(pvs["sets"][0]["visible"][0], 0);
    const std::string common = "render building:3x3 --size 160x90 --stats ";
    const CommandResult plain = run_zraster(common + "-o plain.png", dir);
    const CommandResult with = run_zraster(common + "--pvs sets.json -o pvs.png", dir);
    ASSERT_EQ(with.exit_code, 0) << with.output;
    EXPECT_NE(with.output.find(", PVS "), std::string::npos) << with.output;
    EXPECT_EQ(read_bytes(dir / "plain.png"), read_bytes(dir / "pvs.png"));
    // A PVS for another scene is refused, naming the file and the element.
    const CommandResult other = run_zraster("render building:2x2 --pvs sets.json -o x.png", dir);
    EXPECT_EQ(other.exit_code, 2);
    EXPECT_TRUE(single_line(other.output)) << other.output;
    EXPECT_NE(other.output.find("sets.json: sets: expected one set per cell"), std::string::npos)
        << other.output;
}

TEST(PortalCommand, SceneWithoutCellsIsRefused) {
    const auto dir = temp_dir("portal_nocells");
    const CommandResult r = run_zraster("render builtin:cube --portal-cull -o x.png", dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_TRUE(single_line(r.output)) << r.output;
    EXPECT_NE(r.output.find("--portal-cull: the scene has no cells"), std::string::npos)
        << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

// Two rooms of one unit along x with a floor each and a crate, a doorway between them. The
// floors meet at x = 1, so each touches both cells and is listed in both.
void write_cells_file(const std::filesystem::path& dir, const std::string& second_cell) {
    std::ofstream(dir / "floor.obj") << "v 0 0 0\nv 0 0 1\nv 1 0 1\nv 1 0 0\nf 1 2 3 4\n";
    std::ofstream(dir / "crate.obj")
        << "v 0 0 0\nv 0.2 0 0\nv 0.2 0.2 0\nv 0 0.2 0\nv 0 0 0.2\nv 0.2 0 0.2\nv 0.2 0.2 0.2\nv 0 "
           "0.2 0.2\n"
           "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 3 4 8 7\nf 2 3 7 6\nf 1 5 8 4\n";
    std::ofstream(dir / "two.cells.json")
        << R"({
  "zraster_cells": 1,
  "meshes": {"floor": "floor.obj", "crate": "crate.obj"},
  "instances": [
    {"name": "floor_a", "mesh": "floor"},
    {"name": "floor_b", "mesh": "floor", "translate": [1, 0, 0]},
    {"name": "crate_b", "mesh": "crate", "translate": [1.4, 0, 0.4]}
  ],
  "cells": [
    {"name": "a", "box": [[0, 0, 0], [1, 1, 1]], "instances": ["floor_a", "floor_b"]},
    {"name": "b", "box": [[1, 0, 0], [2, 1, 1]], "instances": ["floor_a", "floor_b", "crate_b"]}
  ],
  "portals": [
    {"cells": ["a", ")" +
               second_cell +
               R"("], "corners": [[1, 0, 0.3], [1, 0, 0.7], [1, 0.8, 0.7], [1, 0.8, 0.3]]}
  ]
})";
}

TEST(PortalCommand, CellsFileLoadsAndRenders) {
    const auto dir = temp_dir("portal_cells_file");
    write_cells_file(dir, "b");
    const CommandResult r = run_zraster(
        "render two.cells.json --size 64x48 --stats --portal-cull --eye 0.5,0.5,0.5 --target "
        "2,0.3,0.5 -o x.png",
        dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("3 instances"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("portals: camera in cell 0 'a', 2 of 2 cells visited"),
              std::string::npos)
        << r.output;
}

TEST(PortalCommand, CellsFileErrorsNameTheElement) {
    const auto dir = temp_dir("portal_cells_errors");
    write_cells_file(dir, "c");
    const CommandResult r = run_zraster("render two.cells.json -o x.png", dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_TRUE(single_line(r.output)) << r.output;
    EXPECT_NE(r.output.find("two.cells.json: portals[0].cells[1]: no cell named 'c'"),
              std::string::npos)
        << r.output;
}

// A field the format does not have (a misspelt "translate") is refused by name, not skipped.
TEST(PortalCommand, CellsFileUnknownFieldIsRefusedByName) {
    const auto dir = temp_dir("portal_cells_unknown_field");
    write_cells_file(dir, "b");
    std::ifstream in(dir / "two.cells.json");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.replace(text.find("\"translate\": [1, 0, 0]"), 11, "\"translation\"");
    std::ofstream(dir / "typo.cells.json") << text;
    const CommandResult r = run_zraster("render typo.cells.json -o x.png", dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_TRUE(single_line(r.output)) << r.output;
    EXPECT_NE(r.output.find("typo.cells.json: instances[1]: \"translation\" is not a field of an "
                            "instance (name, mesh, matrix, translate, rotate_y_degrees, scale: "
                            "docs/portals.md)"),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

TEST(PortalCommand, InstanceInNoCellNamesItsElement) {
    const auto dir = temp_dir("portal_cells_no_cell");
    write_cells_file(dir, "b");
    std::string text = read_bytes(dir / "two.cells.json");
    const std::string crate = R"({"name": "crate_b", "mesh": "crate", "translate": [1.4, 0, 0.4]})";
    ASSERT_NE(text.find(crate), std::string::npos);
    text.replace(text.find(crate), crate.size(),
                 crate + R"(, {"name": "lamp", "mesh": "crate", "translate": [5, 5, 5]})");
    std::ofstream(dir / "two.cells.json") << text;
    const CommandResult r = run_zraster("render two.cells.json -o x.png", dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_TRUE(single_line(r.output)) << r.output;
    EXPECT_NE(r.output.find("two.cells.json: instances[3]: 'lamp' is in no cell"),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

}  // namespace
}  // namespace zraster::test
