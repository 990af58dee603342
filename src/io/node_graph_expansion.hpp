// The expansion of a graph of nodes that place other nodes (COLLADA <instance_node>, 3MF
// components): importers copy a node's subtree at every placement, so a few kilobytes of nodes
// each placing the next twice become millions of copies. Counted without recursion (the graph
// may be deep), with saturating sums.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

namespace zraster::io {

inline constexpr std::uint64_t kManyNodes = std::uint64_t{1} << 62;  // sums saturate here

struct GraphNode {
    std::uint64_t meshes = 0;             // meshes the node places itself
    std::vector<std::uint32_t> children;  // nodes it places (indices into the graph)
};

struct NodeExpansion {
    std::uint64_t nodes = 0;       // copies made, the node's own included
    std::uint64_t placements = 0;  // meshes placed
    std::uint64_t depth = 0;       // levels of the expanded subtree
};

struct GraphExpansion {
    std::vector<NodeExpansion> of;      // per node, for the nodes reached from the roots
    std::optional<std::uint32_t> loop;  // a node that places itself, directly or not
    bool too_deep = false;              // a subtree deeper than max_depth
};

// Expands the nodes reached from `roots`; stops at the first loop, or as soon as a subtree is
// deeper than max_depth.
GraphExpansion expand_node_graph(const std::vector<GraphNode>& graph,
                                 const std::vector<std::uint32_t>& roots, std::uint64_t max_depth);

// a + b, saturating at kManyNodes (both at most kManyNodes).
inline std::uint64_t saturating_sum(std::uint64_t a, std::uint64_t b) {
    return a + b < kManyNodes ? a + b : kManyNodes;
}

}  // namespace zraster::io
