// Every subcommand's outputs go through OutputFiles: checked before any work (name limits, a
// FIFO or device in the way, an input of the run), written all or nothing with one temporary
// naming scheme; a failed run is exit 2, one line on stderr, and leaves no file or folder.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <sys/stat.h>

#include "support/test_support.hpp"

namespace zraster::test {
namespace {

const char kTriangle[] =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

void write_text(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::string> names_in(const std::filesystem::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

TEST(CommandOutputs, AnOutputNameOverTheLimitIsExitTwo) {
    const auto dir = temp_dir("outputs-long-name");
    const std::string name = std::string(252, 'n') + ".svg";
    const CommandResult r = run_zraster("svg builtin:cube --size 16x16 -o " + name, dir);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(r.output, "zraster: -o " + name +
                            ": cannot write: the file name is 256 bytes long, more than the file "
                            "system's limit of 255\n");
    EXPECT_TRUE(names_in(dir).empty());
}

// The temporary is ".zraster-PID-N.tmp", whatever the output's name: a name of 255 bytes works
// for every subcommand.
TEST(CommandOutputs, ANameOfTheLongestLengthIsWritten) {
    const auto dir = temp_dir("outputs-longest-name");
    const std::string svg = std::string(251, 's') + ".svg";
    const CommandResult a = run_zraster("svg builtin:cube --size 16x16 -o " + svg, dir);
    EXPECT_EQ(a.exit_code, 0) << a.output;
    const std::string png = std::string(251, 'b') + ".png";
    const CommandResult b =
        run_zraster("bench builtin:cube --size 16x16 --frames 1 --warmup 0 --out " + png, dir);
    EXPECT_EQ(b.exit_code, 0) << b.output;
    EXPECT_EQ(names_in(dir), (std::vector<std::string>{png, svg}));
}

TEST(CommandOutputs, AnOutputMayNotOverwriteAnInput) {
    const auto dir = temp_dir("outputs-input");
    for (const char* name :
         {"m.ply", "m.json", "m.png", "m.svg", "g.obj", "p.json", "bsp-tree.svg", "c.cells.json"})
        write_text(dir / name, kTriangle);
    const std::string tail = ": an output may not overwrite a file the run reads\n";
    struct Case {
        std::string arguments, message;
    };
    const std::vector<Case> cases = {
        {"render m.ply --size 8x8 --points-out m.ply",
         "zraster: --points-out m.ply: is the same file as the input m.ply" + tail},
        {"render m.json --size 8x8 --camera-json m.json",
         "zraster: --camera-json m.json: is the same file as the input m.json" + tail},
        {"render m.png --size 8x8 -o ./m.png",
         "zraster: -o ./m.png: is the same file as the input m.png" + tail},
        {"svg m.svg --size 8x8 -o m.svg",
         "zraster: -o m.svg: is the same file as the input m.svg" + tail},
        {"render building:2x2 --pvs p.json --size 8x8 --camera-json p.json",
         "zraster: --camera-json p.json: is the same file as the input --pvs p.json" + tail},
        {"bench m.png --size 8x8 --frames 1 --warmup 0 --out m.png",
         "zraster: --out m.png: is the same file as the input m.png" + tail},
        {"batch g.obj -o out --size 8x8 --log g.obj",
         "zraster: --log g.obj: is the same file as the input g.obj" + tail},
        {"explain bsp bsp-tree.svg -o .",
         "zraster: -o ./bsp-tree.svg: is the same file as the input bsp-tree.svg" + tail},
        {"pvs c.cells.json -o ./c.cells.json",
         "zraster: -o ./c.cells.json: is the same file as the input c.cells.json" + tail},
    };
    for (const Case& c : cases) {
        const CommandResult r = run_zraster(c.arguments, dir);
        EXPECT_EQ(r.exit_code, 2) << c.arguments << ": " << r.output;
        EXPECT_EQ(r.output, c.message) << c.arguments;
    }
    for (const char* name :
         {"m.ply", "m.json", "m.png", "m.svg", "g.obj", "p.json", "bsp-tree.svg", "c.cells.json"})
        EXPECT_EQ(read_text(dir / name), kTriangle) << name;
    EXPECT_EQ(names_in(dir),
              (std::vector<std::string>{"bsp-tree.svg", "c.cells.json", "g.obj", "m.json", "m.ply",
                                        "m.png", "m.svg", "p.json"}));
}

// The files a model names (textures, buffers, material libraries) are inputs of the run too, read
// in process or by the loader's worker process alike.
TEST(CommandOutputs, AnOutputMayNotOverwriteAFileTheModelReads) {
    const auto dir = temp_dir("outputs-model-files");
    ASSERT_EQ(run_zraster("render builtin:cube --size 4x4 -o m.png", dir).exit_code, 0);
    std::filesystem::copy_file(dir / "m.png", dir / "img.png");
    const std::string texture = read_text(dir / "m.png");
    write_text(dir / "m.mtl", "newmtl t\nKd 1 1 1\nmap_Kd m.png\n");
    write_text(dir / "m.obj",
               "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl t\nf 1/1 2/1 3/1\n");
    const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    write_text(dir / "g.bin", std::string(reinterpret_cast<const char*>(xyz), sizeof xyz));
    write_text(
        dir / "g.gltf",
        R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
        R"("min":[0,0,0],"max":[1,1,0]}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
        R"("buffers":[{"uri":"g.bin","byteLength":36}],)"
        R"("materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],)"
        R"("textures":[{"source":0}],"images":[{"uri":"img.png"}]})");
    const std::string canonical = std::filesystem::canonical(dir).string();
    const std::string tail = ": an output may not overwrite a file the run reads\n";
    const std::pair<std::string, std::string> cases[] = {
        {"render m.obj --size 8x8 -o m.png",
         "zraster: -o m.png: is the same file as the input file named by m.obj " + canonical +
             "/m.png" + tail},
        {"--load-in-process render m.obj --size 8x8 -o c.png --normal-out ./m.png",
         "zraster: --normal-out ./m.png: is the same file as the input file named by m.obj " +
             canonical + "/m.png" + tail},
        {"render g.gltf --size 8x8 -o img.png",
         "zraster: -o img.png: is the same file as the input file named by g.gltf " + canonical +
             "/img.png" + tail},
    };
    for (const auto& [arguments, message] : cases) {
        SCOPED_TRACE(arguments);
        const CommandResult r = run_zraster(arguments, dir);
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_EQ(r.output, message);
    }
    // batch: m.obj's image would be ./m.png, its own texture: that file fails, the rest is kept.
    const CommandResult batch = run_zraster("batch m.obj -o . --size 8x8 --progress none", dir);
    EXPECT_EQ(batch.exit_code, 3) << batch.output;
    EXPECT_NE(read_text(dir / "batch.jsonl").find("is the same file as the input file named by"),
              std::string::npos)
        << read_text(dir / "batch.jsonl");
    // The log is appended to: not over a file that is not a log (the texture, which the plan
    // cannot know of before the model is read), nor where an output goes.
    std::filesystem::remove(dir / "batch.jsonl");
    const CommandResult log = run_zraster("batch g.gltf -o out --size 8x8 --log img.png", dir);
    EXPECT_EQ(log.exit_code, 2) << log.output;
    EXPECT_EQ(log.output,
              "zraster: --log img.png: the file exists and is not a batch log (JSON Lines): the "
              "log is appended to; choose another path\n");
    const CommandResult at_output =
        run_zraster("batch g.gltf -o out --size 8x8 --log out/g.png", dir);
    EXPECT_EQ(at_output.exit_code, 2) << at_output.output;
    EXPECT_EQ(at_output.output,
              "zraster: --log out/g.png: is where g.gltf's output out/g.png goes: each output "
              "needs a path of its own\n");
    EXPECT_FALSE(std::filesystem::exists(dir / "out"));
    EXPECT_EQ(read_text(dir / "m.png"), texture);
    EXPECT_EQ(read_text(dir / "img.png"), texture);
}

// A texture outside the model's folder is not read (refused, with a warning), but it is still a
// file the model names: an output over it is refused as over one it read.
TEST(CommandOutputs, AnOutputMayNotOverwriteATextureRefusedAsOutsideTheFolder) {
    const auto dir = temp_dir("outputs-outside-texture");
    std::filesystem::create_directories(dir / "model");
    ASSERT_EQ(run_zraster("render builtin:cube --size 4x4 -o outside.png", dir).exit_code, 0);
    const std::string texture = read_text(dir / "outside.png");
    write_text(dir / "model" / "m.mtl", "newmtl t\nKd 1 1 1\nmap_Kd ../outside.png\n");
    write_text(dir / "model" / "m.obj",
               "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl t\nf 1/1 2/1 3/1\n");
    const std::string canonical = std::filesystem::canonical(dir).string();
    for (const char* isolation : {"", "--load-in-process "}) {
        SCOPED_TRACE(isolation);
        const CommandResult r = run_zraster(
            std::string(isolation) + "render model/m.obj --size 8x8 -o outside.png", dir);
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_NE(r.output.find("zraster: -o outside.png: is the same file as the input file "
                                "named by model/m.obj " +
                                canonical +
                                "/outside.png: an output may not overwrite a file "
                                "the run reads\n"),
                  std::string::npos)
            << r.output;
        EXPECT_EQ(read_text(dir / "outside.png"), texture);
    }
}

TEST(CommandOutputs, ABadLogLeavesNoOutputFolder) {
    const auto dir = temp_dir("outputs-batch-log");
    write_text(dir / "m.ply", kTriangle);
    std::filesystem::create_directory(dir / "folder");
    const CommandResult missing =
        run_zraster("batch m.ply -o out --size 8x8 --log nodir/l.jsonl", dir);
    EXPECT_EQ(missing.exit_code, 2) << missing.output;
    EXPECT_EQ(missing.output,
              "zraster: --log nodir/l.jsonl: cannot write: directory 'nodir' does not exist\n");
    const CommandResult folder = run_zraster("batch m.ply -o out --size 8x8 --log folder", dir);
    EXPECT_EQ(folder.exit_code, 2) << folder.output;
    EXPECT_EQ(folder.output, "zraster: --log folder: cannot write: is a directory\n");
    EXPECT_EQ(names_in(dir), (std::vector<std::string>{"folder", "m.ply"}));
}

// docs/batch.md: the batch stops with exit 2; the inputs finished before keep their outputs.
TEST(CommandOutputs, ALogThatCannotBeWrittenIsExitTwo) {
    if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
    const auto dir = temp_dir("outputs-batch-full");
    write_text(dir / "m.ply", kTriangle);
    const CommandResult r =
        run_zraster("batch m.ply -o out --size 8x8 --progress none --log /dev/full", dir);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(r.output,
              "zraster: /dev/full: cannot write the log: No space left on device (the batch "
              "stopped; the outputs of the inputs finished before stay, the same command again "
              "does the rest)\n");
}

// A BSP tree of 10^4 random intersecting triangles is past its automatic budget.
TEST(CommandOutputs, AFailedExplainLeavesNoFolder) {
    const auto dir = temp_dir("outputs-explain");
    std::mt19937 random(7);
    std::uniform_real_distribution<float> coordinate(-1.0f, 1.0f);
    std::ostringstream ply;
    ply << "ply\nformat ascii 1.0\nelement vertex 30000\nproperty float x\nproperty float y\n"
           "property float z\nelement face 10000\nproperty list uchar int vertex_indices\n"
           "end_header\n";
    for (int i = 0; i < 30000; ++i)
        ply << coordinate(random) << ' ' << coordinate(random) << ' ' << coordinate(random) << '\n';
    for (int i = 0; i < 10000; ++i)
        ply << "3 " << 3 * i << ' ' << 3 * i + 1 << ' ' << 3 * i + 2 << '\n';
    write_text(dir / "soup.ply", ply.str());
    const CommandResult r = run_zraster("explain bsp soup.ply -o ex/deeper", dir);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_NE(r.output.find("BSP tree: more than"), std::string::npos) << r.output;
    EXPECT_EQ(names_in(dir), std::vector<std::string>{"soup.ply"});
}

// The folder is made only when the pictures are written: SIGTERM during the frames leaves none.
TEST(CommandOutputs, AKilledExplainLeavesNoFolder) {
    const auto dir = temp_dir("outputs-explain-killed");
    const CommandResult r = run_shell_line(
        "cd '" + dir.string() + "' && { '" + ZRASTER_CLI +
        "' explain zbuffer city:20000 --size 2048x2048 -o ex/deeper 2>/dev/null & pid=$!; "
        "sleep 1; kill -TERM $pid; wait $pid; echo rc=$?; }");
    EXPECT_NE(r.output.find("rc=143"), std::string::npos) << r.output;  // 128 + SIGTERM
    EXPECT_TRUE(names_in(dir).empty());
}

// Past `ulimit -f` a write fails with EFBIG (SIGXFSZ is ignored): exit 2, no temporary left.
TEST(CommandOutputs, AFileSizeLimitIsExitTwoAndLeavesNoTemporary) {
    const auto dir = temp_dir("outputs-ulimit");
    for (const std::string arguments : {"render sphere:2000 --size 512x512 -o a.png",
                                        "svg sphere:2000 --size 256x256 -o a.svg"}) {
        const CommandResult r = run_shell_line("cd '" + dir.string() + "' && ulimit -f 8 && '" +
                                               ZRASTER_CLI + "' " + arguments + " 2>&1");
        EXPECT_EQ(r.exit_code, 2) << arguments << ": " << r.output;
        EXPECT_NE(r.output.find("cannot write: File too large (no output of this run was "
                                "written)\n"),
                  std::string::npos)
            << r.output;
        EXPECT_TRUE(names_in(dir).empty()) << arguments;
    }
}

TEST(CommandOutputs, AFifoAtTheOutputIsRefused) {
    const auto dir = temp_dir("outputs-fifo");
    ASSERT_EQ(::mkfifo((dir / "d.png").c_str(), 0600), 0);
    ASSERT_EQ(::mkfifo((dir / "d.svg").c_str(), 0600), 0);
    const CommandResult bench =
        run_zraster("bench builtin:cube --size 16x16 --frames 1 --warmup 0 --out d.png", dir);
    EXPECT_EQ(bench.exit_code, 2) << bench.output;
    EXPECT_EQ(bench.output,
              "zraster: --out d.png: cannot write: exists and is not a regular file\n");
    const CommandResult svg = run_zraster("svg builtin:cube --size 16x16 -o d.svg", dir);
    EXPECT_EQ(svg.exit_code, 2) << svg.output;
    EXPECT_EQ(svg.output, "zraster: -o d.svg: cannot write: exists and is not a regular file\n");
    EXPECT_TRUE(std::filesystem::is_fifo(dir / "d.png"));
    EXPECT_TRUE(std::filesystem::is_fifo(dir / "d.svg"));
    EXPECT_EQ(names_in(dir), (std::vector<std::string>{"d.png", "d.svg"}));
    // batch --log may be a FIFO (its reader takes the records), but not one nothing reads:
    // opening it would wait for ever. Refused before the output folder is made.
    ASSERT_EQ(::mkfifo((dir / "l.jsonl").c_str(), 0600), 0);
    const CommandResult batch =
        run_zraster("batch builtin:cube --size 8x8 -o out --log l.jsonl --progress none", dir);
    EXPECT_EQ(batch.exit_code, 2) << batch.output;
    EXPECT_EQ(batch.output,
              "zraster: --log l.jsonl: is a FIFO that nothing reads: start its reader first, or "
              "give a file\n");
    EXPECT_FALSE(std::filesystem::exists(dir / "out"));
    // --views-json and --list FIFOs nothing writes read as empty (opening them waited for ever).
    ASSERT_EQ(::mkfifo((dir / "v.json").c_str(), 0600), 0);
    ASSERT_EQ(::mkfifo((dir / "list.txt").c_str(), 0600), 0);
    write_text(dir / "m.ply", kTriangle);
    const CommandResult views =
        run_zraster("batch m.ply --size 8x8 -o out --views-json v.json --progress none", dir);
    EXPECT_EQ(views.exit_code, 2) << views.output;
    EXPECT_EQ(views.output,
              "zraster: v.json: not valid JSON: line 1, column 1: unexpected end of "
              "input; expected '[', '{', or a literal\n");
    const CommandResult list =
        run_zraster("batch --list list.txt --size 8x8 -o out --progress none", dir);
    EXPECT_EQ(list.exit_code, 2) << list.output;
    EXPECT_EQ(list.output, "zraster: batch: no inputs: give files, folders or --list FILE\n");
    EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

}  // namespace
}  // namespace zraster::test
