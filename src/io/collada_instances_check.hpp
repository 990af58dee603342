// COLLADA node graphs: a node may place another node's subtree again (<instance_node
// url="#id">), and Assimp's importer expands every such placement into copied nodes while it
// reads the file, before zraster counts instances: a 4.4 KB file of 24 levels, each node
// placing the next twice, reached 7.8 GB. A light scan of the XML counts the expansion first.
#pragma once
#include <zraster/load.hpp>

#include <cstdint>
#include <string>
#include <string_view>

namespace zraster::io {

// The expansion of a COLLADA document's scene: nodes the importer creates (each placement of a
// node's subtree copies it) and geometry placements (<instance_geometry>,
// <instance_controller>). Saturates at kManyColladaNodes.
struct ColladaExpansion {
    std::uint64_t nodes = 0;
    std::uint64_t placements = 0;
    std::uint64_t materials = 0;  // <material> elements (the importer makes one each)
};
inline constexpr std::uint64_t kManyColladaNodes = std::uint64_t{1} << 62;  // = kManyNodes

// Bytes a copied node takes in the import and the conversion (measured: 24 levels of nodes each
// placing the next twice, 786,000 copies at 18 levels: 1.0 GB).
inline constexpr std::uint64_t kColladaBytesPerNode = 1300;

// Counts the expansion of the visual scene <scene><instance_visual_scene url> names (else the
// first). Throws InputError when a node places itself through <instance_node> (Assimp recursed
// until the stack overflowed).
ColladaExpansion count_collada_expansion(std::string_view document, const std::string& file);

// Refuses a COLLADA document defining more than max_materials materials (LimitExceeded
// max_materials: 200,000 took the importer to 3.1 GB before its count was checked); whose expansion
// places more than max_instances meshes (LimitExceeded max_instances), or whose copied nodes take
// more than max_geometry_bytes at kColladaBytesPerNode (LimitExceeded max_geometry_bytes), before
// Assimp reads it.
void check_collada_instances(std::string_view document, const std::string& file,
                             const LoadOptions& options);

}  // namespace zraster::io
