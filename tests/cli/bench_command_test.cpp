// `zraster bench` as scripts use it: the last line is the machine-readable RESULT.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <regex>
#include <string>

#include "support/test_support.hpp"

namespace zraster::test {
namespace {

using BenchRun = CommandResult;

std::string last_line(const std::string& text) {
    std::string s = text;
    while (!s.empty() && s.back() == '\n') s.pop_back();
    const std::size_t nl = s.rfind('\n');
    return nl == std::string::npos ? s : s.substr(nl + 1);
}

TEST(BenchCommand, PrintsTheResultLineLast) {
    const BenchRun r = run_zraster("bench sphere:20000 --mode phong --size 320x240 --frames 3");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    // S = lround(sqrt(20000 / 4)) = lround(70.71) = 71 stacks: 4 * 71 * 70 triangles.
    const long stacks = std::lround(std::sqrt(20000 / 4.0));
    ASSERT_EQ(stacks, 71);
    const std::string tris = std::to_string(4 * stacks * (stacks - 1));
    const std::regex format(
        "RESULT scene=sphere:20000 mode=phong w=320 h=240 threads=[1-9][0-9]* "
        "tris=" +
        tris + " ms_median=[0-9]+\\.[0-9]{3} ms_min=[0-9]+\\.[0-9]{3}");
    EXPECT_TRUE(std::regex_match(last_line(r.output), format)) << r.output;
}

TEST(BenchCommand, DepthModeWithThreadsAndDepthPng) {
    const auto dir = temp_dir("bench-depth");
    const BenchRun r = run_zraster(
        "bench sphere:2000 --mode depth --size 64x48 --frames 2 --warmup 0 --threads 2 --out d.png",
        dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(last_line(r.output).find("mode=depth w=64 h=48 threads=2 tris="), std::string::npos)
        << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "d.png"));
}

TEST(BenchCommand, PrintsTheReferenceGeometryAndFraming) {
    // BENCH-SCENES.md's table for sphere:1000000 (a fraction of a second at 32x32).
    const BenchRun r =
        run_zraster("bench sphere:1000000 --mode depth --size 32x32 --frames 1 --warmup 0");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("998000 triangles, geometry_hash a006c80ed0f36341"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("eye (0.816496611 0.816496611 1.63299322) target (0 0 0) near "
                            "0.990000069 far 3.01000023"),
              std::string::npos)
        << r.output;
}

TEST(BenchCommand, BunnyHasTheReferenceFraming) {
    ZRASTER_REQUIRE_SHARED_DATA();
    const BenchRun r = run_zraster("bench '" + shared_data("meshes/obj/bunny.obj").string() +
                                   "' --mode depth --size 64x48 --frames 1 --warmup 0");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("34835 vertices, 69666 triangles"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("eye (1.09894478 1.09894478 2.19788957) target (0 0 0) near "
                            "1.33246779 far 4.05124044"),
              std::string::npos)
        << r.output;
}

// zraster's OBJ parser rounds coordinates correctly (Assimp's fast_atof misrounded the two `v`
// lines written with exponents, giving hash a87e88ed72c3a76f), so the bunny hashes like
// glbench's strtof-based loader.
TEST(BenchCommand, BunnyHasTheReferenceGeometryHash) {
    ZRASTER_REQUIRE_SHARED_DATA();
    const BenchRun r = run_zraster("bench '" + shared_data("meshes/obj/bunny.obj").string() +
                                   "' --mode depth --size 64x48 --frames 1 --warmup 0");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("geometry_hash ffbd53754430e6f7"), std::string::npos) << r.output;
}

TEST(BenchCommand, BadArgumentsAreExitTwo) {
    const auto dir = temp_dir("bench-bad");
    for (const char* c : {
             "bench sphere:1000 --mode toon",
             "bench sphere:1000 --size 0x10",
             "bench sphere:1000 --frames 0",
             "bench sphere:1000 --warmup -1",
             "bench sphere:1000 --threads -2",
             "bench sphere:1000 --out out.jpg",
             "bench sphere:abc",
             "bench /nonexistent/mesh.obj",
             "bench",
         }) {
        const BenchRun r = run_zraster(c, dir);
        EXPECT_EQ(r.exit_code, 2) << c << "\n" << r.output;
        EXPECT_EQ(r.output.find("RESULT"), std::string::npos) << c;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "out.jpg"));
}

}  // namespace
}  // namespace zraster::test
