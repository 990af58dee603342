// What Assimp decodes from a glTF file, bounded before it reads the file. Assimp's glTF2 importer
// copies an accessor into every primitive that reads it: one accessor of a million vertices read
// by 3000 primitives of a 1 KB document asks for tens of gigabytes, which ended in std::bad_alloc
// inside Assimp. Two budgets: the triangle budget's (at most LoadOptions::max_triangles faces and
// 3 x max_triangles vertices, an unindexed triangle list at the triangle budget, over the file's
// primitives), and the bytes those decode to (LoadOptions::max_geometry_bytes): counts alone let
// a 600-byte sparse accessor of 150 million vertices reach 7.6 GB, at the triangle budget. The
// bytes count everything else a small file can expand into as well: the buffers (read whole,
// whatever the accessors use), the animations' keys, the skins' inverse bind matrices and the
// bones the importer makes per joint each time a skinned mesh is placed, and the materials the
// primitives use.
#pragma once
#include <zraster/load.hpp>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

namespace zraster::io {

// What the importer makes of the node graph (gltf_bounds_check.cpp counts it without expanding
// it): `importer_nodes` nodes (one per path from a scene root to a node, meshes or not), and per
// node the number of those paths (saturated at 2^64 - 1); and a GLB's BIN chunk length, which
// it reads whole as buffer 0 whatever that buffer's byteLength says.
struct GltfImporterCounts {
    std::uint64_t importer_nodes = 0;
    std::vector<std::uint64_t> paths_to_node;
    std::optional<std::uint64_t> glb_binary;
};

// Throws LimitExceeded(limit "max_triangles" or "max_geometry_bytes") naming the counts or the
// bytes, the limit and what dominates them. Primitives of every mesh count (Assimp decodes all of
// them, placed or not), once each (node placements share them); so do the nodes the importer makes
// of the node graph, about 1.1 KB each, and a skinned mesh's bones once per path to its node.
// Malformed members are left to the other checks and to Assimp.
void check_gltf_decode_budget(const std::filesystem::path& path, const nlohmann::json& document,
                              const LoadOptions& options, const GltfImporterCounts& nodes);

}  // namespace zraster::io
