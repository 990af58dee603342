// `zraster explain`: the pixels of its pictures are counted before they are made, against
// --max-explain-pixels; past it, exit 2, one line naming --size and the flag, and no folder.
#include <gtest/gtest.h>

#include <string>

#include "support/test_support.hpp"

namespace zraster::test {
namespace {

// builtin:cube is 12 triangles: --step 3 takes 4 frames, each the color and depth buffers of
// 80x60 side by side (164 x 60 pixels).
constexpr int kZbufferPixels = 4 * 164 * 60;

TEST(ExplainBudget, ZbufferFramesAtTheLimitPassAndOneMoreIsRefused) {
    const auto dir = temp_dir("explain-budget-zbuffer");
    const std::string command = "explain zbuffer builtin:cube --size 80x60 --step 3 -o ex/deeper";
    const CommandResult at =
        run_zraster(command + " --max-explain-pixels " + std::to_string(kZbufferPixels), dir);
    EXPECT_EQ(at.exit_code, 0) << at.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "ex" / "deeper" / "zbuffer-04.png"));
    std::filesystem::remove_all(dir / "ex");
    const CommandResult over =
        run_zraster(command + " --max-explain-pixels " + std::to_string(kZbufferPixels - 1), dir);
    EXPECT_EQ(over.exit_code, 2);
    EXPECT_EQ(over.output,
              "zraster: --size: explain zbuffer's 4 frames are 39360 pixels of pictures, more "
              "than explain's limit of 39359 (lower --size, or raise --step); raise it with "
              "--max-explain-pixels N\n");
    EXPECT_FALSE(std::filesystem::exists(dir / "ex"));  // the folder is made after the work
}

TEST(ExplainBudget, HizCountsItsTwoPictures) {
    const auto dir = temp_dir("explain-budget-hiz");
    const std::string limit = std::to_string((5 * 80 + 12) * 60);
    const CommandResult at = run_zraster(
        "explain hiz builtin:cube --size 80x60 -o ex --max-explain-pixels " + limit, dir);
    EXPECT_EQ(at.exit_code, 0) << at.output;
    const CommandResult over = run_zraster(
        "explain hiz builtin:cube --size 81x60 -o ex2 --max-explain-pixels " + limit, dir);
    EXPECT_EQ(over.exit_code, 2);
    EXPECT_TRUE(single_line(over.output)) << over.output;
    EXPECT_NE(over.output.find("--max-explain-pixels"), std::string::npos) << over.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "ex2"));
}

// The default refuses the z-buffer's frames of a large image before the first frame is drawn.
TEST(ExplainBudget, DefaultRefusesLargeFramesAtOnce) {
    const auto dir = temp_dir("explain-budget-default");
    const CommandResult r = run_zraster("explain zbuffer sphere:2000 --size 8192x8192 -o ex", dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_TRUE(single_line(r.output)) << r.output;
    EXPECT_NE(r.output.find("more than explain's limit of 134217728"), std::string::npos)
        << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "ex"));
}

}  // namespace
}  // namespace zraster::test
