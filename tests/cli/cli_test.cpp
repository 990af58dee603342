// The zraster command as a user runs it: exit codes, one-line errors naming the file and the
// cause, and no output file left behind on failure.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include <zraster/version.hpp>

#include "support/test_support.hpp"

namespace zraster::test {
namespace {

CommandResult run(const std::string& arguments, const std::filesystem::path& cwd = {}) {
    return run_zraster(arguments, cwd);
}

TEST(Cli, NoArgumentsRendersTheDefaultSceneToZrasterPng) {
    const auto dir = temp_dir("cli-default");
    const CommandResult plain = run("", dir);
    ASSERT_EQ(plain.exit_code, 0) << plain.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "zraster.png"));
    EXPECT_GT(std::filesystem::file_size(dir / "zraster.png"), 10000u);
}

TEST(Cli, HelpOnEverySubcommand) {
    for (const char* sub : {"", "render ", "info ", "batch "}) {
        const CommandResult r = run(std::string(sub) + "--help");
        EXPECT_EQ(r.exit_code, 0) << sub;
        EXPECT_NE(r.output.find("Usage"), std::string::npos) << sub;
    }
}

TEST(Cli, VersionIsTheLibrarysVersion) {
    const CommandResult r = run("--version");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.output, std::string("zraster ") + ZRASTER_VERSION_STRING + "\n");
}

TEST(Cli, MissingFileIsExitTwoWithTheFileNamed) {
    const auto dir = temp_dir("cli-missing");
    const CommandResult r = run("render /nonexistent/model.obj -o out.png", dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_TRUE(single_line(r.output)) << r.output;
    EXPECT_NE(r.output.find("/nonexistent/model.obj"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("not found"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

// Assimp runs in a worker process by default (RELIABILITY.md); --load-in-process skips it. Both
// give the same scene, and the flag is accepted after the subcommand and its arguments.
TEST(Cli, WorkerAndInProcessLoadingAgree) {
    const auto dir = temp_dir("cli-worker");
    std::ofstream(dir / "quad.ply")
        << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
           "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
           "end_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
    const CommandResult worker = run("info quad.ply", dir);
    const CommandResult in_process = run("info quad.ply --load-in-process", dir);
    ASSERT_EQ(worker.exit_code, 0) << worker.output;
    ASSERT_EQ(in_process.exit_code, 0) << in_process.output;
    EXPECT_EQ(worker.output, in_process.output);
    ASSERT_EQ(run("render quad.ply -o w.png --size 32x24", dir).exit_code, 0);
    ASSERT_EQ(run("render quad.ply -o p.png --size 32x24 --load-in-process", dir).exit_code, 0);
    std::ifstream w(dir / "w.png", std::ios::binary), p(dir / "p.png", std::ios::binary);
    const std::string wb{std::istreambuf_iterator<char>(w), {}};
    const std::string pb{std::istreambuf_iterator<char>(p), {}};
    EXPECT_FALSE(wb.empty());
    EXPECT_EQ(wb, pb);
}

// The loading flags before the subcommand, as --help shows them, or before render's flags alone.
TEST(Cli, LoadingFlagsComeBeforeOrAfterTheSubcommand) {
    const auto dir = temp_dir("cli-global-flags");
    std::ofstream(dir / "tri.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const char* forms[] = {
        "--load-in-process render tri.obj -o a.png",
        "--load-in-process --allow-outside-references --max-instances 5 render tri.obj -o b.png",
        "--max-instances=5 render tri.obj -o f.png",
        "--load-in-process -o d.png",
        "render tri.obj -o e.png --load-in-process",
    };
    for (const char* form : forms) {
        const CommandResult r = run(std::string(form) + " --size 32x24", dir);
        EXPECT_EQ(r.exit_code, 0) << form << "\n" << r.output;
    }
    for (const char* png : {"a.png", "b.png", "d.png", "e.png", "f.png"})
        EXPECT_TRUE(std::filesystem::exists(dir / png)) << png;
    EXPECT_EQ(read_bytes(dir / "a.png"), read_bytes(dir / "e.png"));
    // A file where the subcommand goes: what to type instead, not CLI11's reversed leftovers.
    const CommandResult file_first = run("--load-in-process tri.obj -o c.png", dir);
    EXPECT_EQ(file_first.exit_code, 2);
    EXPECT_EQ(file_first.output,
              "zraster: 'tri.obj' is not a subcommand (render, info, bench, svg, batch, explain, "
              "view, pvs): to render it, zraster --load-in-process render tri.obj -o c.png\n");
    EXPECT_FALSE(std::filesystem::exists(dir / "c.png"));
}

TEST(Cli, MalformedFileIsExitTwo) {
    const auto dir = temp_dir("cli-malformed");
    std::ofstream(dir / "bad.stl") << "solid x\nfacet normal 0 0 1\nouter loop\nvertex 1 2\n";
    const CommandResult r = run("render bad.stl -o out.png", dir);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("bad.stl"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

TEST(Cli, BadOptionsAreExitTwoAndWriteNothing) {
    const auto dir = temp_dir("cli-options");
    const char* cases[] = {
        "render builtin:cube --size 0x10 -o out.png",
        "render builtin:cube --size 1000000x1000000 -o out.png",
        "render builtin:cube --size abc -o out.png",
        "render builtin:cube --eye nan,0,0 -o out.png",
        "render builtin:cube --eye 1,2 -o out.png",
        "render builtin:cube --shading toon -o out.png",
        "render builtin:cube --threads -3 -o out.png",
        "render builtin:cube --background 300,0,0 -o out.png",
        "render builtin:cube --depth-out depth.txt -o out.png",
        "render builtin:cube -o out.jpg",
        "render builtin:cube -o missing-dir/out.png",
        "render builtin:cube --near 5 --far 1 -o out.png",
        "render sphere:0 -o out.png",
        "render sphere:abc -o out.png",
        "render builtin:nothing -o out.png",
        "render --no-such-option",
        "frobnicate",
    };
    for (const char* c : cases) {
        const CommandResult r = run(c, dir);
        EXPECT_EQ(r.exit_code, 2) << c << "\n" << r.output;
        EXPECT_FALSE(r.output.empty()) << c;
        EXPECT_FALSE(std::filesystem::exists(dir / "out.png")) << c;
        EXPECT_FALSE(std::filesystem::exists(dir / "out.jpg")) << c;
    }
}

// A run's outputs appear together or not at all: two outputs naming one file, a name the file
// system refuses, or a write failing after the first output was ready leave no file behind.
TEST(Cli, OutputsAreAllOrNothing) {
    const auto dir = temp_dir("cli-outputs-transaction");
    const CommandResult same =
        run("render builtin:cube --size 32x24 -o x.png --depth-out x.png", dir);
    EXPECT_EQ(same.exit_code, 2) << same.output;
    EXPECT_TRUE(single_line(same.output)) << same.output;
    EXPECT_NE(same.output.find("--depth-out x.png: is the same file as -o x.png"),
              std::string::npos)
        << same.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));

    const std::string long_name(300, 'n');
    const CommandResult too_long =
        run("render builtin:cube --size 32x24 -o c.png --depth-out " + long_name + ".npy", dir);
    EXPECT_EQ(too_long.exit_code, 2) << too_long.output;
    EXPECT_NE(too_long.output.find("more than the file system's limit"), std::string::npos)
        << too_long.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "c.png"));

    // The normal map's place is taken by a directory holding a file: its rename fails after the
    // color and depth files were written to temporaries; none of them may stay.
    std::filesystem::create_directory(dir / "n.png");
    std::ofstream(dir / "n.png" / "keep") << "x";
    const CommandResult late =
        run("render builtin:cube --size 32x24 -o c.png --depth-out d.npy --normal-out n.png", dir);
    EXPECT_EQ(late.exit_code, 2) << late.output;
    EXPECT_NE(late.output.find("n.png: cannot write: is a directory"), std::string::npos)
        << late.output;
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        names.push_back(entry.path().filename().string());
    EXPECT_EQ(names, std::vector<std::string>{"n.png"});
}

TEST(Cli, DepthNormalAndIdOutputs) {
    const auto dir = temp_dir("cli-outputs");
    const CommandResult r =
        run("render builtin:sphere --size 64x48 -o c.png --depth-out d.npy "
            "--normal-out n.png --id-out i.npy",
            dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    // float32 (48, 64): header then 64*48*4 bytes.
    std::ifstream npy(dir / "d.npy", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(npy)), {});
    ASSERT_GT(bytes.size(), std::size_t(64 * 48 * 4));
    EXPECT_EQ(bytes.substr(1, 5), "NUMPY");
    EXPECT_NE(bytes.find("'descr': '<f4'"), std::string::npos);
    EXPECT_NE(bytes.find("'shape': (48, 64)"), std::string::npos);
    const std::size_t header = bytes.size() - 64 * 48 * 4;
    float corner, center;
    std::memcpy(&corner, bytes.data() + header, 4);
    std::memcpy(&center, bytes.data() + header + (24 * 64 + 32) * 4, 4);
    EXPECT_EQ(corner, 1.0f);  // nothing drawn
    EXPECT_GT(center, 0.0f);
    EXPECT_LT(center, 1.0f);
    EXPECT_TRUE(std::filesystem::exists(dir / "n.png"));
    EXPECT_TRUE(std::filesystem::exists(dir / "i.npy"));
}

TEST(Cli, InfoPrintsCounts) {
    const CommandResult r = run("info sphere:1000");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    // S = lround(sqrt(250)) = 16 stacks: 4 * 16 * 15 = 960 triangles.
    EXPECT_NE(r.output.find("960"), std::string::npos) << r.output;
}

// Each material's alpha: an OBJ read in process, a glTF through the worker process.
TEST(Cli, InfoReportsMaterialAlpha) {
    const auto dir = temp_dir("cli-info-alpha");
    std::ofstream(dir / "m.mtl") << "newmtl glass\nKd 1 1 1\nd 0.5\nnewmtl paper\nKd 1 1 1\n";
    std::ofstream(dir / "m.obj") << "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl glass\n"
                                    "f 1 2 3\nusemtl paper\nf 1 3 2\n";
    const CommandResult obj = run("info m.obj", dir);
    ASSERT_EQ(obj.exit_code, 0) << obj.output;
    EXPECT_NE(obj.output.find("'glass': base color (1, 1, 1), texture none, alpha blend (opacity "
                              "0.5), alpha below 1 from opacity\n"),
              std::string::npos)
        << obj.output;
    EXPECT_NE(obj.output.find("'paper': base color (1, 1, 1), texture none, alpha blend (opacity "
                              "1), alpha 1 everywhere\n"),
              std::string::npos)
        << obj.output;

    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::ofstream(dir / "t.bin", std::ios::binary)
        .write(reinterpret_cast<const char*>(positions), sizeof positions);
    std::ofstream(dir / "t.gltf")
        << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0,1]}],)"
           R"("nodes":[{"mesh":0},{"mesh":1}],"meshes":[)"
           R"({"primitives":[{"attributes":{"POSITION":0},"material":0}]},)"
           R"({"primitives":[{"attributes":{"POSITION":0},"material":1}]}],)"
           R"("materials":[{"name":"leaf","alphaMode":"MASK","alphaCutoff":0.25},)"
           R"({"name":"wall","pbrMetallicRoughness":{"baseColorFactor":[1,1,1,0.5]}}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
           R"("min":[0,0,0],"max":[1,1,0]}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
           R"("buffers":[{"uri":"t.bin","byteLength":36}]})";
    const CommandResult gltf = run("info t.gltf", dir);
    ASSERT_EQ(gltf.exit_code, 0) << gltf.output;
    EXPECT_NE(gltf.output.find("'leaf': base color (1, 1, 1), texture none, alpha mask (cutoff "
                               "0.25), alpha 1 everywhere\n"),
              std::string::npos)
        << gltf.output;
    EXPECT_NE(gltf.output.find("'wall': base color (1, 1, 1), texture none, alpha opaque\n"),
              std::string::npos)
        << gltf.output;
    EXPECT_EQ(gltf.output, run("info t.gltf --load-in-process", dir).output);
}

TEST(Cli, InfoOnSharedMeshReportsManifestCounts) {
    ZRASTER_REQUIRE_SHARED_DATA();
    const CommandResult r = run("info '" + shared_data("meshes/obj/bunny.obj").string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("69666"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace zraster::test
