// `zraster batch` writes what `zraster render` writes: the same bytes for the same file and flags,
// for every output kind, any --jobs and any thread count; --views and --views-json are the
// render command's camera flags, view by view.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include <zraster/render.hpp>

#include "batch_plan.hpp"
#include "batch_test_support.hpp"

namespace zraster::test {
namespace {

std::string exact(double x) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", x);
    return text;
}

// Three formats: OBJ (zraster's reader), STL and PLY (Assimp, in its worker process).
std::filesystem::path write_collection(const std::string& name) {
    const auto dir = temp_dir(name);
    write_sphere_obj(dir / "in" / "ball.obj", 24, 1);
    write_box_stl(dir / "in" / "sub" / "box.stl", 2);
    write_text(dir / "in" / "sub" / "tet.ply",
               "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
               "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
               "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
    return dir;
}

const std::string kFlags = "--size 64x48 --shading gouraud --background 10,20,30";

TEST(BatchOutputs, EveryOutputIsByteForByteWhatRenderWrites) {
    const auto dir = write_collection("batch-identical");
    const CommandResult batch = run_zraster(
        "batch in -o out " + kFlags +
            " --depth npy --z png --range --normal --id npy --points --camera-json --jobs 2 "
            "--progress none",
        dir);
    ASSERT_EQ(batch.exit_code, 0) << batch.output;
    const std::vector<std::string> stems = {"ball", "sub/box", "sub/tet"};
    const std::vector<std::string> sources = {"in/ball.obj", "in/sub/box.stl", "in/sub/tet.ply"};
    const std::vector<std::string> tails = {".png",        "_depth.npy",  "_z.png",
                                            "_range.npy",  "_normal.png", "_id.npy",
                                            "_points.ply", "_camera.json"};
    for (std::size_t i = 0; i < stems.size(); ++i) {
        SCOPED_TRACE(sources[i]);
        const std::string r = "r" + std::to_string(i);
        const CommandResult render = run_zraster(
            "render " + sources[i] + " " + kFlags + " -o " + r + ".png --depth-out " + r +
                "_depth.npy --z-out " + r + "_z.png --range-out " + r + "_range.npy --normal-out " +
                r + "_normal.png --id-out " + r + "_id.npy --points-out " + r +
                "_points.ply --camera-json " + r + "_camera.json",
            dir);
        ASSERT_EQ(render.exit_code, 0) << render.output;
        for (const std::string& tail : tails) {
            const std::string ours = read_bytes(dir / "out" / (stems[i] + tail));
            EXPECT_FALSE(ours.empty()) << tail;
            EXPECT_TRUE(ours == read_bytes(dir / (r + tail))) << stems[i] + tail;
        }
    }
    // The log: one ok record per input, listing exactly the files written.
    const auto records = records_by_input(read_log(dir / "out" / "batch.jsonl"));
    ASSERT_EQ(records.size(), 3u);
    std::set<std::string> listed;
    for (const auto& [input, record] : records) {
        EXPECT_EQ(record.at("status"), "ok") << input;
        EXPECT_TRUE(record.at("error").is_null()) << input;
        EXPECT_GT(record.at("triangles").get<int>(), 0) << input;
        for (const auto& output : record.at("outputs")) listed.insert(output.get<std::string>());
    }
    EXPECT_EQ(records.at("in/sub/tet.ply").at("triangles"), 4);
    EXPECT_EQ(records.at("in/sub/box.stl").at("triangles"), 12);
    std::set<std::string> written;
    for (const std::string& file : files_under(dir / "out"))
        if (file != "batch.jsonl") written.insert("out/" + file);
    EXPECT_EQ(listed, written);
    EXPECT_EQ(written.size(), 3 * tails.size());
}

TEST(BatchOutputs, JobsAndThreadsDoNotChangeABit) {
    const auto dir = temp_dir("batch-jobs");
    for (int i = 0; i < 8; ++i)
        write_sphere_obj(dir / "in" / ("s" + std::to_string(i) + ".obj"), 16 + 4 * i, i);
    const std::string common = "batch in --size 96x64 --depth npy --normal --progress none ";
    const CommandResult one = run_zraster(common + "-o one --jobs 1 --threads 1", dir);
    const CommandResult two = run_zraster(common + "-o two --jobs 2 --threads 2", dir);
    const CommandResult many = run_zraster(common + "-o many --jobs 3 --threads 0", dir);
    ASSERT_EQ(one.exit_code, 0) << one.output;
    ASSERT_EQ(two.exit_code, 0) << two.output;
    ASSERT_EQ(many.exit_code, 0) << many.output;
    std::set<std::string> files = files_under(dir / "one");
    files.erase("batch.jsonl");
    ASSERT_EQ(files.size(), 24u);
    EXPECT_EQ(files_under(dir / "two"), files_under(dir / "one"));
    for (const std::string& file : files) {
        const std::string reference = read_bytes(dir / "one" / file);
        EXPECT_TRUE(read_bytes(dir / "two" / file) == reference) << file;
        EXPECT_TRUE(read_bytes(dir / "many" / file) == reference) << file;
    }
    // Different meshes, different pictures: the comparison above compares something.
    EXPECT_NE(read_bytes(dir / "one" / "s0.png"), read_bytes(dir / "one" / "s1.png"));
}

TEST(BatchOutputs, ViewsAreOrbitCamerasWithSuffixes) {
    const auto dir = temp_dir("batch-views");
    write_sphere_obj(dir / "in" / "ball.obj", 20, 3);
    const CommandResult batch = run_zraster(
        "batch in/ball.obj -o out --size 80x60 --views 3 --elevation 15 --depth npy "
        "--progress none",
        dir);
    ASSERT_EQ(batch.exit_code, 0) << batch.output;
    EXPECT_EQ(files_under(dir / "out"),
              (std::set<std::string>{"ball_v00.png", "ball_v00_depth.npy", "ball_v01.png",
                                     "ball_v01_depth.npy", "ball_v02.png", "ball_v02_depth.npy",
                                     "batch.jsonl"}));
    // View i is --orbit 360*i/3,15,1/sin(fovy/2) at the default fovy of 60 degrees.
    const std::string distance = exact(1.0 / std::sin(60.0 * std::numbers::pi / 360.0));
    for (int i = 0; i < 3; ++i) {
        const std::string v = "ball_v0" + std::to_string(i);
        const CommandResult render =
            run_zraster("render in/ball.obj --size 80x60 --orbit " + exact(360.0 * i / 3) + ",15," +
                            distance + " -o " + v + ".png --depth-out " + v + "_depth.npy",
                        dir);
        ASSERT_EQ(render.exit_code, 0) << render.output;
        EXPECT_TRUE(read_bytes(dir / "out" / (v + ".png")) == read_bytes(dir / (v + ".png"))) << v;
        EXPECT_TRUE(read_bytes(dir / "out" / (v + "_depth.npy")) ==
                    read_bytes(dir / (v + "_depth.npy")))
            << v;
    }
    EXPECT_NE(read_bytes(dir / "out" / "ball_v00.png"), read_bytes(dir / "out" / "ball_v01.png"));
    const auto records = read_log(dir / "out" / "batch.jsonl");
    ASSERT_EQ(records.size(), 1u);
    EXPECT_EQ(records[0].at("outputs").size(), 6u);
}

TEST(BatchOutputs, ViewsJsonTakesLookAtOrbitAndCameraJsonCameras) {
    const auto dir = temp_dir("batch-views-json");
    write_sphere_obj(dir / "in" / "ball.obj", 20, 4);
    // A pinhole camera as `zraster render --camera-json` writes it.
    const CommandResult pinhole = run_zraster(
        "render in/ball.obj --size 64x48 --intrinsics 60,60,31.5,23.5 --eye 0.5,1,3 --target "
        "0,0,0 --near 0.5 --far 10 -o pinhole.png --camera-json pinhole.json",
        dir);
    ASSERT_EQ(pinhole.exit_code, 0) << pinhole.output;
    write_text(dir / "views.json",
               "[{\"eye\": [0, 0.5, 3], \"target\": [0, 0, 0], \"up\": [0, 1, 0], \"fovy\": 40,"
               " \"near\": 0.5, \"far\": 10},\n {\"orbit\": [90, 30, 3]},\n" +
                   read_bytes(dir / "pinhole.json") + "]\n");
    const CommandResult batch = run_zraster(
        "batch in/ball.obj -o out --size 64x48 --views-json views.json --camera-json "
        "--progress none",
        dir);
    ASSERT_EQ(batch.exit_code, 0) << batch.output;
    const CommandResult look = run_zraster(
        "render in/ball.obj --size 64x48 --eye 0,0.5,3 --target 0,0,0 --up 0,1,0 --fovy 40 "
        "--near 0.5 --far 10 -o look.png",
        dir);
    const CommandResult orbit =
        run_zraster("render in/ball.obj --size 64x48 --orbit 90,30,3 -o orbit.png", dir);
    ASSERT_EQ(look.exit_code, 0) << look.output;
    ASSERT_EQ(orbit.exit_code, 0) << orbit.output;
    EXPECT_TRUE(read_bytes(dir / "out" / "ball_v00.png") == read_bytes(dir / "look.png"));
    EXPECT_TRUE(read_bytes(dir / "out" / "ball_v01.png") == read_bytes(dir / "orbit.png"));
    // The camera read back from --camera-json draws the picture it was written with, and writes
    // the same camera again.
    EXPECT_TRUE(read_bytes(dir / "out" / "ball_v02.png") == read_bytes(dir / "pinhole.png"));
    const auto written = nlohmann::json::parse(read_bytes(dir / "out" / "ball_v02_camera.json"));
    const auto original = nlohmann::json::parse(read_bytes(dir / "pinhole.json"));
    EXPECT_EQ(written.at("K"), original.at("K"));
    EXPECT_EQ(written.at("width"), original.at("width"));
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c)
            EXPECT_NEAR(written.at("camera_to_world")[r][c].get<double>(),
                        original.at("camera_to_world")[r][c].get<double>(), 1e-12);
}

// An orthographic camera as --camera-json writes it (--ortho) is a views file too; one whose
// pixels the command's orthographic camera cannot make is refused, naming the field.
TEST(BatchOutputs, ViewsJsonTakesOrthographicCameraJsonCameras) {
    const auto dir = temp_dir("batch-views-ortho");
    write_sphere_obj(dir / "in" / "ball.obj", 20, 4);
    const CommandResult ortho = run_zraster(
        "render in/ball.obj --size 64x48 --ortho --ortho-height 3.5 --eye 0.5,1,3 --target "
        "0,0,0 --near 0.5 --far 10 -o ortho.png --camera-json ortho.json",
        dir);
    ASSERT_EQ(ortho.exit_code, 0) << ortho.output;
    const CommandResult batch = run_zraster(
        "batch in/ball.obj -o out --size 64x48 --views-json ortho.json --camera-json "
        "--progress none",
        dir);
    ASSERT_EQ(batch.exit_code, 0) << batch.output;
    EXPECT_TRUE(read_bytes(dir / "out" / "ball_v00.png") == read_bytes(dir / "ortho.png"));
    const auto written = nlohmann::json::parse(read_bytes(dir / "out" / "ball_v00_camera.json"));
    const auto original = nlohmann::json::parse(read_bytes(dir / "ortho.json"));
    EXPECT_EQ(written.at("projection"), "orthographic");
    EXPECT_NEAR(written.at("pixels_per_unit")[1].get<double>(),
                original.at("pixels_per_unit")[1].get<double>(), 1e-9);
    EXPECT_EQ(written.at("principal_point"), original.at("principal_point"));

    auto off_center = original;
    off_center["principal_point"] = {20.0, 23.5};
    write_text(dir / "off.json", off_center.dump());
    const CommandResult refused =
        run_zraster("batch in/ball.obj -o out2 --views-json off.json --progress none", dir);
    EXPECT_EQ(refused.exit_code, 2) << refused.output;
    EXPECT_NE(refused.output.find("off.json: camera 0: \"principal_point\""), std::string::npos)
        << refused.output;
    const CommandResult alone = run_zraster("render in/ball.obj --ortho-height 2 -o x.png", dir);
    EXPECT_EQ(alone.exit_code, 2) << alone.output;
    EXPECT_NE(alone.output.find("--ortho-height"), std::string::npos) << alone.output;
}

TEST(BatchOutputs, JobsShareTheThreads) {
    EXPECT_EQ(cli::batch_job_threads(4, 2), 2);
    EXPECT_EQ(cli::batch_job_threads(5, 2), 2);
    EXPECT_EQ(cli::batch_job_threads(1, 3), 1);  // at least one each
    EXPECT_EQ(cli::batch_job_threads(6, 0), 6);
    const int all = render_thread_count(0);
    EXPECT_EQ(cli::batch_job_threads(0, 1), all);
    EXPECT_EQ(cli::batch_job_threads(0, all), 1);
}

}  // namespace
}  // namespace zraster::test
