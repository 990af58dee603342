// What Assimp decodes from a glTF file's accessors, bounded before it reads them. Assimp's glTF2
// importer copies an accessor into every primitive that reads it: one accessor of a million
// vertices read by 3000 primitives of a 1 KB document asks for tens of gigabytes, which ended in
// std::bad_alloc inside Assimp. Two budgets: the triangle budget's (at most
// LoadOptions::max_triangles faces and 3 x max_triangles vertices, an unindexed triangle list at
// the triangle budget, over the file's primitives), and the bytes those decode to
// (LoadOptions::max_geometry_bytes): counts alone let a 600-byte sparse accessor of 150 million
// vertices reach 7.6 GB, at the triangle budget.
#pragma once
#include <zraster/load.hpp>

#include <nlohmann/json.hpp>

#include <filesystem>

namespace zraster::io {

// Throws LimitExceeded(limit "max_triangles" or "max_geometry_bytes") naming the counts or the
// bytes and the limit. Primitives of every mesh count (Assimp decodes all of them, placed or
// not), once each (node placements share them); so do the `importer_nodes` nodes the importer
// makes of the node graph (one per path from a root to a node: nodes sharing children multiply,
// meshes or not), about 1.1 KB each. Malformed members are left to the other checks and to
// Assimp.
void check_gltf_decode_budget(const std::filesystem::path& path, const nlohmann::json& document,
                              const LoadOptions& options, std::uint64_t importer_nodes);

}  // namespace zraster::io
