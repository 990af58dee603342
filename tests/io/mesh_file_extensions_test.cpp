// The extensions a folder search takes are the loader's: the formats the repository's meshes come
// in, in any case, and nothing that only sits beside a model (buffers, textures, materials).
#include <zraster/load.hpp>

#include <gtest/gtest.h>

#include <algorithm>

namespace zraster {
namespace {

TEST(MeshFileExtensions, ListsTheFormatsTheLoaderReads) {
    const std::vector<std::string>& list = mesh_file_extensions();
    for (const char* e : {".obj", ".ply", ".stl", ".gltf", ".glb", ".3ds", ".off"})
        EXPECT_TRUE(std::binary_search(list.begin(), list.end(), e)) << e;
    EXPECT_TRUE(std::is_sorted(list.begin(), list.end()));
    EXPECT_EQ(std::adjacent_find(list.begin(), list.end()), list.end());
    for (const std::string& e : list) {
        EXPECT_TRUE(e.starts_with(".")) << e;
        EXPECT_FALSE(std::any_of(e.begin(), e.end(), [](char c) { return c >= 'A' && c <= 'Z'; }))
            << e;
    }
}

TEST(MeshFileExtensions, MatchesNamesInAnyCase) {
    EXPECT_TRUE(has_mesh_file_extension("a/b/Bunny.OBJ"));
    EXPECT_TRUE(has_mesh_file_extension("duck.glb"));
    EXPECT_TRUE(has_mesh_file_extension("scan.Ply"));
    for (const char* other :
         {"a/buffer.bin", "texture.png", "lib.mtl", "README.md", "obj", ".obj", "notes.obj.txt"})
        EXPECT_FALSE(has_mesh_file_extension(other)) << other;
}

}  // namespace
}  // namespace zraster
