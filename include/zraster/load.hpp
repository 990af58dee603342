// Loading scenes from mesh files (OBJ with MTL, PLY, STL, glTF 2.0, 3DS, OFF and the other
// formats Assimp reads).
#pragma once
#include <zraster/scene.hpp>

#include <cstddef>
#include <filesystem>
#include <string>

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

// A human-readable summary (for `zraster info`), one item per line, each line ending in '\n':
// source, meshes (name, triangles, vertices, material, mesh-space bounds), instances, totals
// over instances, exact world bounds, materials (name, base color, texture size) and warnings.
// Long lists are cut after 50 entries with a count of the rest.
std::string describe_scene(const Scene& scene);

}  // namespace zraster
