// A bad file is a record, never the end of `zraster batch`: unreadable, malformed and oversized
// files each get an error record naming them, the others are rendered, and the exit status is 3.
// Bad usage (clashing output names, bad flags) is refused with status 2 before anything is
// rendered.
#include <gtest/gtest.h>

#include <string>

#include "batch_test_support.hpp"

namespace zraster::test {
namespace {

TEST(BatchErrors, BrokenFilesAreErrorRecordsAndTheRestIsRendered) {
    const auto dir = temp_dir("batch-broken");
    write_sphere_obj(dir / "in" / "good1.obj", 12, 1);
    write_box_stl(dir / "in" / "good2.stl", 2);
    write_text(dir / "in" / "empty.obj", "");
    write_text(dir / "in" / "bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n");
    write_text(dir / "in" / "garbage.ply", "ply\nformat nonsense 7\nend_header\n\x01\x02");
    // A binary STL claiming 1000 triangles, holding one.
    std::string stl(80, ' ');
    stl += std::string("\xe8\x03\x00\x00", 4) + std::string(50, '\0');
    write_text(dir / "in" / "truncated.stl", stl);
    write_text(dir / "list.txt", "in/missing.obj\n");
    const CommandResult r =
        run_zraster("batch in --list list.txt -o out --size 32x32 --progress none", dir);
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(r.output.find("2 ok, 5 failed, 0 skipped"), std::string::npos) << r.output;

    const auto records = records_by_input(read_log(dir / "out" / "batch.jsonl"));
    ASSERT_EQ(records.size(), 7u) << r.output;
    for (const char* good : {"in/good1.obj", "in/good2.stl"})
        EXPECT_EQ(records.at(good).at("status"), "ok") << good;
    for (const char* bad : {"in/empty.obj", "in/bad_index.obj", "in/garbage.ply",
                            "in/truncated.stl", "in/missing.obj"}) {
        SCOPED_TRACE(bad);
        const auto& record = records.at(bad);
        EXPECT_EQ(record.at("status"), "error");
        const std::string error = record.at("error").get<std::string>();
        EXPECT_TRUE(error.starts_with(std::string(bad) + ": ")) << error;
        EXPECT_GT(error.size(), std::string(bad).size() + 4) << error;
        EXPECT_EQ(error.find('\n'), std::string::npos);
        EXPECT_TRUE(record.at("outputs").empty());
        EXPECT_TRUE(record.at("triangles").is_null());
    }
    EXPECT_NE(records.at("in/missing.obj").at("error").get<std::string>().find("not found"),
              std::string::npos);
    EXPECT_EQ(files_under(dir / "out"),
              (std::set<std::string>{"batch.jsonl", "good1.png", "good2.png"}));
}

// A frame's warnings (here: nothing in view) reach the record, as render prints them.
TEST(BatchErrors, FrameWarningsAreInTheRecord) {
    const auto dir = temp_dir("batch-frame-warnings");
    write_box_stl(dir / "in" / "box.stl", 2);
    const CommandResult r =
        run_zraster("batch in -o out --size 16x16 --progress none --clip-plane 0,0,1,-100", dir);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    const auto records = records_by_input(read_log(dir / "out" / "batch.jsonl"));
    const auto& warnings = records.at("in/box.stl").at("warnings");
    ASSERT_FALSE(warnings.empty());
    EXPECT_TRUE(warnings.back().get<std::string>().starts_with(
        "in/box.stl: none of its 12 triangles is in view"))
        << warnings;
}

// An input whose model reads a file another input's output goes to (m.mtl's texture t.png, t.obj's
// image) fails, whichever job runs first: its image would otherwise depend on the order.
TEST(BatchErrors, AModelReadingAnotherInputsOutputFailsInEveryOrder) {
    for (const char* order : {"t.obj m.obj", "m.obj t.obj"}) {
        SCOPED_TRACE(order);
        const auto dir = temp_dir("batch-reads-an-output");
        write_box_stl(dir / "t.stl", 1);
        ASSERT_EQ(run_zraster("render t.stl --size 8x8 -o t.png", dir).exit_code, 0);
        write_text(dir / "m.mtl", "newmtl t\nKd 1 1 1\nmap_Kd t.png\n");
        write_text(dir / "m.obj",
                   "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl t\nf 1/1 2/1 3/1\n");
        write_text(dir / "t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        const CommandResult r = run_zraster(
            std::string("batch ") + order + " -o . --size 16x16 --progress none --jobs 1", dir);
        EXPECT_EQ(r.exit_code, 3) << r.output;
        const auto records = records_by_input(read_log(dir / "batch.jsonl"));
        EXPECT_EQ(records.at("t.obj").at("status"), "ok");
        EXPECT_EQ(records.at("m.obj").at("error"),
                  "m.obj: it reads " + std::filesystem::canonical(dir / "t.png").string() +
                      ", which this batch writes as t.obj's output: give -o a folder apart from "
                      "the models");
    }
}

TEST(BatchErrors, FilesOverTheLimitsAreErrorRecords) {
    const auto dir = temp_dir("batch-limits");
    write_sphere_obj(dir / "in" / "small.obj", 6, 1);   // 24 triangles
    write_sphere_obj(dir / "in" / "large.obj", 40, 2);  // 1520 triangles
    const CommandResult triangles =
        run_zraster("batch in -o tri --size 32x32 --max-triangles 100 --progress none", dir);
    EXPECT_EQ(triangles.exit_code, 3) << triangles.output;
    auto records = records_by_input(read_log(dir / "tri" / "batch.jsonl"));
    EXPECT_EQ(records.at("in/small.obj").at("status"), "ok");
    EXPECT_EQ(records.at("in/large.obj").at("status"), "error");
    EXPECT_NE(records.at("in/large.obj").at("error").get<std::string>().find("--max-triangles"),
              std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(dir / "tri" / "large.png"));

    // 512 x 512 pixels need more than 4 MiB of targets: refused before rendering.
    const CommandResult memory =
        run_zraster("batch in -o mem --size 512x512 --max-memory 4M --progress none", dir);
    EXPECT_EQ(memory.exit_code, 3) << memory.output;
    records = records_by_input(read_log(dir / "mem" / "batch.jsonl"));
    for (const char* input : {"in/small.obj", "in/large.obj"}) {
        EXPECT_EQ(records.at(input).at("status"), "error") << input;
        EXPECT_NE(records.at(input).at("error").get<std::string>().find("--max-memory"),
                  std::string::npos);
    }
    const CommandResult enough =
        run_zraster("batch in -o mem --size 512x512 --max-memory 1G --progress none", dir);
    EXPECT_EQ(enough.exit_code, 0) << enough.output;
}

TEST(BatchErrors, OutputNameClashesAreRefusedBeforeAnyWork) {
    const auto dir = temp_dir("batch-clash");
    write_sphere_obj(dir / "a" / "x.obj", 8, 1);
    write_sphere_obj(dir / "b" / "x.obj", 8, 2);
    write_box_stl(dir / "c" / "y.stl", 1);
    write_sphere_obj(dir / "c" / "y.obj", 8, 3);
    write_sphere_obj(dir / "d" / "z.obj", 8, 4);
    write_sphere_obj(dir / "d" / "z_depth.obj", 8, 5);
    const std::pair<std::string, std::string> cases[] = {
        {"a/x.obj b/x.obj", "a/x.obj"},    // two file arguments of one name
        {"c", "y."},                       // one folder, one name in two formats
        {"d --depth png", "z_depth.png"},  // a depth map named as another file's picture
    };
    for (const auto& [arguments, named] : cases) {
        SCOPED_TRACE(arguments);
        std::filesystem::remove_all(dir / "out");
        const CommandResult r =
            run_zraster("batch " + arguments + " -o out --size 16x16 --progress none", dir);
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_TRUE(single_line(r.output)) << r.output;
        EXPECT_NE(r.output.find(named), std::string::npos) << r.output;
        // Not even the output folder (fuzz_cli found it left behind).
        EXPECT_FALSE(std::filesystem::exists(dir / "out"));
    }
    // Nor the folders above it that the run would have created.
    const CommandResult nested =
        run_zraster("batch a/x.obj b/x.obj -o new/deeper/out --size 16x16 --progress none", dir);
    EXPECT_EQ(nested.exit_code, 2) << nested.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "new"));
    // Without the depth map the names in d/ do not clash.
    EXPECT_EQ(run_zraster("batch d -o out --size 16x16 --progress none", dir).exit_code, 0);
}

TEST(BatchErrors, BadUsageIsExitTwoWithNothingWritten) {
    const auto dir = temp_dir("batch-usage");
    write_sphere_obj(dir / "in" / "a.obj", 8, 1);
    write_text(dir / "empty" / "notes.txt", "no meshes here\n");
    write_text(dir / "bad-views.json", "[{\"eye\": [0, 0, 3]}]");
    write_text(dir / "typo-views.json",
               "[{\"eye\": [0, 0, 3], \"target\": [0, 0, 0], \"fov\": 30}]");
    // Cameras the library would refuse later, in the flags' terms: refused here in the file's.
    write_text(dir / "same-views.json", "[{\"eye\": [1, 1, 1], \"target\": [1, 1, 1]}]");
    write_text(dir / "up-views.json",
               "[{\"eye\": [0, 3, 0], \"target\": [0, 0, 0], \"up\": [0, 2, 0]}]");
    const std::string pose = "\"near\": 0.1, \"far\": 10, \"width\": 8, \"height\": 8";
    write_text(dir / "k-views.json",
               "[{\"K\": [[0, 0, 0], [0, 0, 0], [0, 0, 1]], \"camera_to_world\": [[1, 0, 0, 0], "
               "[0, 1, 0, 0], [0, 0, 1, 5], [0, 0, 0, 1]], " +
                   pose + "}]");
    write_text(dir / "pose-views.json",
               "[{\"K\": [[8, 0, 4], [0, 8, 4], [0, 0, 1]], \"camera_to_world\": [[0, 0, 0, 0], "
               "[0, 0, 0, 0], [0, 0, 0, 5], [0, 0, 0, 1]], " +
                   pose + "}]");
    const std::pair<std::string, std::string> cases[] = {
        {"in -o out --views-json same-views.json",
         "same-views.json: camera 0: \"target\": the eye and the target are the same point"},
        {"in -o out --views-json up-views.json",
         "up-views.json: camera 0: \"up\": the up direction is parallel"},
        {"in -o out --views-json k-views.json",
         "k-views.json: camera 0: \"K\": fx must be in 0.001..1e9 pixels, not 0"},
        {"in -o out --views-json pose-views.json",
         "pose-views.json: camera 0: \"camera_to_world\": the rotation's forward (z)"},
        {"in -o out --shard 3/3", "--shard"},
        {"in -o out --shard two", "--shard"},
        {"in -o out --depth tiff", "--depth"},
        {"in -o out --max-memory 12Q", "--max-memory"},
        {"in -o out --views 0", "--views"},
        {"in -o out --views 2 --eye 1,2,3", "--views"},
        {"in -o out --views-json bad-views.json", "bad-views.json: camera 0: \"target\""},
        {"in -o out --views-json typo-views.json",
         "typo-views.json: camera 0: \"fov\": is not a camera field"},
        {"in -o out --views-json missing.json", "missing.json"},
        {"in -o out --intrinsics 50,50,8,8 --fovy 40", "--intrinsics"},
        {"in -o out --size 0x10", "--size"},
        {"in -o out --aa 3 --msaa", "--aa"},
        {"empty -o out", "no mesh files"},
        {"builtin:cube -o out",
         "builtin:cube: batch renders model files and folders of them; a procedural scene "
         "(builtin:, sphere:, city:, soup:, building:) is for zraster render"},
        {"in city:20 -o out", "city:20: batch renders model files"},
        {"-o out", "no inputs"},
        {"in", "--output-dir"},
    };
    for (const auto& [arguments, named] : cases) {
        SCOPED_TRACE(arguments);
        std::filesystem::remove_all(dir / "out");
        const CommandResult r = run_zraster("batch " + arguments + " --progress none", dir);
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_TRUE(single_line(r.output)) << r.output;
        EXPECT_NE(r.output.find(named), std::string::npos) << r.output;
        EXPECT_FALSE(std::filesystem::exists(dir / "out"));
    }
}

}  // namespace
}  // namespace zraster::test
