// Where `zraster batch` finds its inputs and puts their outputs: folders searched for every mesh
// format, their tree mirrored under OUTDIR, file arguments by name, --list files and standard
// input; the log's record schema; progress modes.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "batch_test_support.hpp"

namespace zraster::test {
namespace {

TEST(BatchInputs, FoldersAreMirroredAndFileArgumentsKeepTheirNames) {
    const auto dir = temp_dir("batch-mirror");
    write_sphere_obj(dir / "models" / "a.obj", 8, 1);
    write_sphere_obj(dir / "models" / "sub" / "deep" / "B.OBJ", 8, 2);
    write_box_stl(dir / "models" / "sub" / "c.stl", 3);
    write_text(dir / "models" / "sub" / "notes.txt", "not a mesh\n");
    write_text(dir / "models" / "sub" / "texture.png", "not a mesh either");
    write_sphere_obj(dir / "elsewhere" / "d.obj", 8, 4);
    const CommandResult r =
        run_zraster("batch models/ elsewhere/d.obj -o out --size 16x16 --progress none", dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(
        files_under(dir / "out"),
        (std::set<std::string>{"a.png", "sub/deep/B.png", "sub/c.png", "d.png", "batch.jsonl"}));
    const auto records = records_by_input(read_log(dir / "out" / "batch.jsonl"));
    EXPECT_EQ(records.size(), 4u);
    EXPECT_EQ(records.at("models/sub/deep/B.OBJ").at("outputs"),
              nlohmann::json::array({"out/sub/deep/B.png"}));
    EXPECT_EQ(records.at("elsewhere/d.obj").at("outputs"), nlohmann::json::array({"out/d.png"}));
}

TEST(BatchInputs, AnOutputFolderInsideAnInputFolderIsNotSearched) {
    const auto dir = temp_dir("batch-nested-output");
    write_sphere_obj(dir / "models" / "a.obj", 8, 1);
    // The point clouds written into models/renders are .ply files, a mesh format.
    const std::string batch =
        "batch models -o models/renders --size 16x16 --points --progress none --force";
    ASSERT_EQ(run_zraster(batch, dir).exit_code, 0);
    ASSERT_TRUE(std::filesystem::exists(dir / "models" / "renders" / "a_points.ply"));
    const CommandResult again = run_zraster(batch, dir);
    ASSERT_EQ(again.exit_code, 0) << again.output;
    const auto log = read_log(dir / "models" / "renders" / "batch.jsonl");
    ASSERT_EQ(log.size(), 2u);
    EXPECT_EQ(log[1].at("input"), "models/a.obj");
    EXPECT_FALSE(std::filesystem::exists(dir / "models" / "renders" / "renders"));
}

TEST(BatchInputs, NamesThatAreNotUtf8AreRenderedAndLoggedReplaced) {
    const auto dir = temp_dir("batch-latin1");
    const std::string name = "caf\xe9";  // ISO 8859-1, not UTF-8
    write_sphere_obj(dir / "in" / (name + ".obj"), 8, 1);
    const CommandResult r = run_zraster("batch in -o out --size 16x16 --progress none", dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / (name + ".png")));
    const auto log = read_log(dir / "out" / "batch.jsonl");  // valid JSON
    ASSERT_EQ(log.size(), 1u);
    EXPECT_EQ(log[0].at("input"), "in/caf\ufffd.obj");
    EXPECT_EQ(log[0].at("status"), "ok");
}

TEST(BatchInputs, ListFilesAndStandardInput) {
    const auto dir = temp_dir("batch-list");
    for (int i = 0; i < 3; ++i)
        write_sphere_obj(dir / "in" / ("m" + std::to_string(i) + ".obj"), 8, i);
    // Relative and absolute paths, a blank line, Windows line ends.
    write_text(dir / "list.txt", "in/m0.obj\r\n\r\n" + (dir / "in" / "m1.obj").string() + "\r\n");
    const CommandResult listed =
        run_zraster("batch --list list.txt -o out --size 16x16 --progress none", dir);
    ASSERT_EQ(listed.exit_code, 0) << listed.output;
    EXPECT_EQ(files_under(dir / "out"), (std::set<std::string>{"m0.png", "m1.png", "batch.jsonl"}));

    const CommandResult piped =
        run_shell("printf 'in/m2.obj\\nin/m0.obj\\n' | " + zraster_command() +
                      " batch --list - -o piped --size 16x16 --progress none",
                  dir);
    ASSERT_EQ(piped.exit_code, 0) << piped.output;
    EXPECT_EQ(files_under(dir / "piped"),
              (std::set<std::string>{"m0.png", "m2.png", "batch.jsonl"}));
    EXPECT_TRUE(read_bytes(dir / "piped" / "m0.png") == read_bytes(dir / "out" / "m0.png"));

    const CommandResult missing =
        run_zraster("batch --list nolist.txt -o out2 --progress none", dir);
    EXPECT_EQ(missing.exit_code, 2) << missing.output;
    EXPECT_NE(missing.output.find("nolist.txt"), std::string::npos) << missing.output;
}

// A list is text of paths: a device or a binary file is refused at its first line that cannot be
// a path, without reading on (/dev/zero was read until 4 GB), and no output folder is made.
TEST(BatchInputs, AListThatIsNotTextIsRefusedAtItsFirstBadLine) {
    const auto dir = temp_dir("batch-list-bad");
    write_text(dir / "long.txt", "in/m0.obj\n" + std::string(5000, 'a') + "\n");
    for (const auto& [list, cause] :
         {std::pair{"/dev/zero", "line 1 holds a NUL byte: not a text list of paths"},
          {"long.txt", "line 2 is longer than 4096 bytes: not a list of paths"}}) {
        const CommandResult r =
            run_zraster(std::string("batch --list ") + list + " -o out --progress none", dir);
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_EQ(r.output, std::string("zraster: --list ") + list + ": " + cause + "\n");
        EXPECT_FALSE(std::filesystem::exists(dir / "out"));
    }
}

TEST(BatchInputs, RecordsHaveTheDocumentedFieldsInOrder) {
    const auto dir = temp_dir("batch-schema");
    write_sphere_obj(dir / "in" / "good.obj", 8, 1);
    write_text(dir / "in" / "bad.obj", "v 1 2\n");
    const CommandResult r = run_zraster("batch in -o out --size 16x16 --progress none", dir);
    EXPECT_EQ(r.exit_code, 3) << r.output;
    const auto log = read_log(dir / "out" / "batch.jsonl");
    ASSERT_EQ(log.size(), 2u);
    const std::vector<std::string> fields = {"input",     "status",  "error",     "outputs",
                                             "triangles", "load_ms", "render_ms", "write_ms",
                                             "warnings",  "reads"};
    std::ifstream in(dir / "out" / "batch.jsonl");
    for (std::string line; std::getline(in, line);) {
        std::size_t at = 0;
        for (const std::string& field : fields) {
            const std::size_t next = line.find("\"" + field + "\":", at);
            EXPECT_NE(next, std::string::npos) << field << " in " << line;
            at = next;
        }
    }
    for (const auto& record : log) {
        EXPECT_EQ(record.size(), fields.size());
        EXPECT_TRUE(record.at("outputs").is_array());
        EXPECT_TRUE(record.at("warnings").is_array());
        EXPECT_TRUE(record.at("reads").is_array());
        for (const char* time : {"load_ms", "render_ms", "write_ms"}) {
            EXPECT_TRUE(record.at(time).is_number()) << time;
            EXPECT_GE(record.at(time).get<double>(), 0.0) << time;
        }
    }
}

TEST(BatchInputs, ProgressModes) {
    const auto dir = temp_dir("batch-progress");
    write_sphere_obj(dir / "in" / "a.obj", 8, 1);
    const CommandResult bar = run_zraster("batch in -o bar --size 16x16 --progress bar", dir);
    ASSERT_EQ(bar.exit_code, 0) << bar.output;
    EXPECT_NE(bar.output.find("\r\033[K"), std::string::npos) << bar.output;
    EXPECT_NE(bar.output.find("1/1 files"), std::string::npos) << bar.output;
    // Not a terminal: no escape sequences, the summary alone for a short batch.
    const CommandResult automatic = run_zraster("batch in -o auto --size 16x16", dir);
    ASSERT_EQ(automatic.exit_code, 0) << automatic.output;
    EXPECT_EQ(automatic.output.find('\033'), std::string::npos) << automatic.output;
    EXPECT_TRUE(automatic.output.starts_with("zraster batch: 1 ok, 0 failed, 0 skipped in "))
        << automatic.output;
    EXPECT_EQ(automatic.output.find('\n'), automatic.output.size() - 1) << automatic.output;
}

}  // namespace
}  // namespace zraster::test
