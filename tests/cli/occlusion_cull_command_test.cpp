// `zraster render --occlusion-cull`: the same PNG as without it, and --stats reports the
// instances it skipped.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "support/test_support.hpp"

namespace zraster::test {
namespace {

// A wall at z = 0 facing +z, and three cubes behind it.
void write_wall_scene(const std::filesystem::path& file) {
    std::ofstream out(file);
    out << "o wall\nv -5 -5 0\nv 5 -5 0\nv 5 5 0\nv -5 5 0\nf 1 2 3 4\n";
    int base = 4;
    for (int k = 0; k < 3; ++k) {
        const double cx = -2.0 + 2.0 * k, cz = -3.0, h = 0.5;
        out << "o cube" << k << "\n";
        for (int i = 0; i < 8; ++i) {
            const double x = (i == 1 || i == 2 || i == 5 || i == 6) ? h : -h;
            const double y = (i == 2 || i == 3 || i == 6 || i == 7) ? h : -h;
            const double z = i >= 4 ? h : -h;
            out << "v " << cx + x << " " << y << " " << cz + z << "\n";
        }
        const int faces[6][4] = {{5, 6, 7, 8}, {2, 1, 4, 3}, {1, 5, 8, 4},
                                 {6, 2, 3, 7}, {8, 7, 3, 4}, {1, 2, 6, 5}};
        for (const auto& f : faces)
            out << "f " << base + f[0] << " " << base + f[1] << " " << base + f[2] << " "
                << base + f[3] << "\n";
        base += 8;
    }
}

TEST(CliOcclusion, OcclusionCullGivesTheSameImageAndCountsCulledInstances) {
    const auto dir = temp_dir("cli-occlusion");
    write_wall_scene(dir / "wall.obj");
    const std::string common =
        "render wall.obj --size 160x120 --eye 0,0,10 --target 0,0,0 --near 1 --far 50 --stats";
    const CommandResult plain = run_zraster(common + " -o plain.png", dir);
    ASSERT_EQ(plain.exit_code, 0) << plain.output;
    const CommandResult culled = run_zraster(common + " --occlusion-cull -o culled.png", dir);
    ASSERT_EQ(culled.exit_code, 0) << culled.output;
    EXPECT_NE(plain.output.find("0 occlusion-culled"), std::string::npos) << plain.output;
    EXPECT_NE(culled.output.find("3 occlusion-culled"), std::string::npos) << culled.output;
    EXPECT_EQ(read_bytes(dir / "plain.png"), read_bytes(dir / "culled.png"));
}

}  // namespace
}  // namespace zraster::test
