// Loading scenes from mesh files (OBJ with MTL, PLY, STL, glTF 2.0, 3DS, OFF and the other
// formats Assimp reads).
#pragma once
#include <zraster/scene.hpp>

#include <cstddef>
#include <filesystem>

namespace zraster {

struct LoadOptions {
    // Larger files are refused before their geometry is allocated.
    std::size_t max_triangles = 50'000'000;
    std::size_t max_file_bytes = std::size_t{4} << 30;
};

// Loads every mesh with its material (base color, specular, shininess, opacity, base-color
// texture) and the node hierarchy as instances (node transforms applied). Computes
// angle-weighted normals when the file has none, and bounds.
// Missing material libraries or textures become Scene::warnings (default material used).
// Throws InputError (one line naming the file and the cause) for a missing or unreadable file,
// an unknown format, malformed or truncated content, no triangles, or NaN/Inf coordinates.
Scene load_scene(const std::filesystem::path& path, const LoadOptions& options = {});

}  // namespace zraster
