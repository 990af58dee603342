// The texture budget (LoadOptions::max_texture_side, max_texture_bytes): large textures are
// reduced as their mip chain would be, and a model's textures never take more than the budget.
#include <zraster/image_io.hpp>
#include <zraster/load.hpp>

#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

namespace zraster {
namespace {

std::vector<std::uint8_t> gradient(int width, int height) {
    std::vector<std::uint8_t> rgba(std::size_t(width) * std::size_t(height) * 4);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            std::uint8_t* p = &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4];
            p[0] = std::uint8_t(x * 7), p[1] = std::uint8_t(y * 3), p[2] = std::uint8_t(x ^ y),
            p[3] = 255;
        }
    return rgba;
}

// A quad in two materials, each with its own texture: a.png (w x h) and b.png (64 x 64).
std::filesystem::path write_model(const std::string& name, int w, int h) {
    const auto dir = test::temp_dir(name);
    write_png8(dir / "a.png", w, h, 4, gradient(w, h));
    write_png8(dir / "b.png", 64, 64, 4, gradient(64, 64));
    test::write_bytes(dir / "m.mtl", "newmtl a\nmap_Kd a.png\nnewmtl b\nmap_Kd b.png\n");
    test::write_bytes(dir / "quad.obj",
                      "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                      "usemtl a\nf 1/1 2/2 3/3\nusemtl b\nf 1/1 3/3 4/4\n");
    return dir / "quad.obj";
}

const Texture* texture_of(const Scene& scene, std::size_t material) {
    return scene.materials.at(material).base_color_texture.get();
}

std::vector<const Texture*> textures_of(const Scene& scene) {
    std::vector<const Texture*> textures;
    for (std::size_t m = 0; m < scene.materials.size(); ++m)
        if (const Texture* t = texture_of(scene, m)) textures.push_back(t);
    return textures;
}

TEST(TextureBudget, LargeTexturesAreReducedLikeTheirMipChain) {
    const auto path = write_model("io-texture-side", 300, 200);
    LoadOptions options;
    options.max_texture_side = 64;
    for (const LoadIsolation isolation : {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
        options.isolation = isolation;
        std::vector<std::string> warnings;
        const Scene scene = load_scene(path, options, &warnings);
        const Texture* a = nullptr;
        for (std::size_t m = 0; m < scene.materials.size(); ++m)
            if (texture_of(scene, m) != nullptr && texture_of(scene, m)->width() != 64)
                a = texture_of(scene, m);
        ASSERT_NE(a, nullptr);
        // 300x200 -> 150x100 -> 75x50 -> 37x25: level 3 of the full chain, bit for bit.
        EXPECT_EQ(a->width(), 37);
        EXPECT_EQ(a->height(), 25);
        const Texture full(300, 200, gradient(300, 200));
        ASSERT_EQ(full.level_width(3), 37);
        const auto reduced = a->level_rgba(0), level3 = full.level_rgba(3);
        EXPECT_TRUE(std::equal(reduced.begin(), reduced.end(), level3.begin(), level3.end()));
        ASSERT_EQ(warnings.size(), 1u);
        EXPECT_NE(warnings[0].find("texture 'a.png' is 300x200, reduced to 37x25 (at most "
                                   "64 texels a side"),
                  std::string::npos)
            << warnings[0];
    }
}

TEST(TextureBudget, AModelsTexturesStayWithinTheBudget) {
    // 64x64 with its mips: 21,844 bytes. A 600x400 image decodes to 960,000 bytes.
    const auto path = write_model("io-texture-bytes", 600, 400);
    LoadOptions options;
    options.max_texture_bytes = 30'000;
    std::vector<std::string> warnings;
    const Scene scene = load_scene(path, options, &warnings);
    const std::vector<const Texture*> kept = textures_of(scene);
    ASSERT_EQ(kept.size(), 1u);
    EXPECT_EQ(kept[0]->width(), 64);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("texture 'a.png' is 600x400 (938 KiB decoded), more than the "
                               "textures' budget of 29 KiB: using the material color"),
              std::string::npos)
        << warnings[0];

    // Both fit one at a time, not together: the second one used is not kept.
    options.max_texture_bytes = 40'000;
    const auto small = write_model("io-texture-bytes-small", 64, 64);
    std::vector<std::string> both_warnings;
    const Scene both = load_scene(small, options, &both_warnings);
    EXPECT_EQ(textures_of(both).size(), 1u);
    ASSERT_EQ(both_warnings.size(), 1u);
    EXPECT_NE(both_warnings[0].find("not kept: the model's textures would take 43 KiB, more than "
                                    "their budget of 39 KiB"),
              std::string::npos)
        << both_warnings[0];

    // The second one does not fit what is left of a smaller budget: refused before it is decoded
    // (a model of many large textures decoded each in turn only to drop it).
    options.max_texture_bytes = 30'000;
    std::vector<std::string> left_warnings;
    const Scene left = load_scene(small, options, &left_warnings);
    EXPECT_EQ(textures_of(left).size(), 1u);
    ASSERT_EQ(left_warnings.size(), 1u);
    EXPECT_NE(left_warnings[0].find("is 64x64 (16 KiB decoded), more than the 8 KiB left of the "
                                    "textures' budget of 29 KiB: using the material color"),
              std::string::npos)
        << left_warnings[0];
}

// A texture file larger than the whole budget is not read (a 3 GB file named as a texture was
// read whole before its size was looked at): its image could not fit once decoded either.
TEST(TextureBudget, AFileLargerThanTheBudgetIsNotRead) {
    const auto path = write_model("io-texture-file-bytes", 8, 8);
    test::write_bytes(path.parent_path() / "a.png", std::string(50'000, 'x'));
    LoadOptions options;
    options.max_texture_bytes = 30'000;
    std::vector<std::string> warnings;
    const Scene scene = load_scene(path, options, &warnings);
    EXPECT_EQ(textures_of(scene).size(), 1u);  // b.png
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("texture 'a.png' cannot be read (the file is 49 KiB, more than the "
                               "textures' budget of 29 KiB"),
              std::string::npos)
        << warnings[0];
}

}  // namespace
}  // namespace zraster
