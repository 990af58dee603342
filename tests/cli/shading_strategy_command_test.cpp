// `zraster render --shading-strategy`: forward and deferred give the same PNG, --stats says which
// ran, and a value that is not a strategy is refused naming the option.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "support/test_support.hpp"

namespace zraster::test {
namespace {

TEST(CliShadingStrategy, ForwardAndDeferredGiveTheSameImage) {
    const auto dir = temp_dir("cli-shading-strategy");
    const std::string common = "render sphere:20000 --size 160x120 --shading phong --stats";
    const CommandResult deferred =
        run_zraster(common + " --shading-strategy deferred -o deferred.png", dir);
    ASSERT_EQ(deferred.exit_code, 0) << deferred.output;
    const CommandResult forward =
        run_zraster(common + " --shading-strategy forward -o forward.png", dir);
    ASSERT_EQ(forward.exit_code, 0) << forward.output;
    const CommandResult automatic = run_zraster(common + " -o auto.png", dir);
    ASSERT_EQ(automatic.exit_code, 0) << automatic.output;
    EXPECT_NE(deferred.output.find("(deferred)"), std::string::npos) << deferred.output;
    EXPECT_NE(forward.output.find("(forward)"), std::string::npos) << forward.output;
    EXPECT_NE(automatic.output.find("(deferred)"), std::string::npos) << automatic.output;
    EXPECT_EQ(read_bytes(dir / "deferred.png"), read_bytes(dir / "forward.png"));
    EXPECT_EQ(read_bytes(dir / "deferred.png"), read_bytes(dir / "auto.png"));

    const CommandResult bad = run_zraster(common + " --shading-strategy sideways -o x.png", dir);
    EXPECT_EQ(bad.exit_code, 2) << bad.output;
    EXPECT_NE(bad.output.find("--shading-strategy"), std::string::npos) << bad.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

}  // namespace
}  // namespace zraster::test
