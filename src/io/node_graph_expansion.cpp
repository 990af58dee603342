#include "io/node_graph_expansion.hpp"

#include <algorithm>

namespace zraster::io {

GraphExpansion expand_node_graph(const std::vector<GraphNode>& graph,
                                 const std::vector<std::uint32_t>& roots, std::uint64_t max_depth) {
    enum : std::uint8_t { kNew, kActive, kDone };
    std::vector<std::uint8_t> state(graph.size(), kNew);
    GraphExpansion result;
    result.of.resize(graph.size());
    struct Frame {
        std::uint32_t node;
        std::size_t next;  // the next child to visit
    };
    std::vector<Frame> stack;
    for (const std::uint32_t root : roots) {
        if (state[root] != kNew) continue;
        stack.push_back({root, 0});
        state[root] = kActive;
        while (!stack.empty()) {
            Frame& f = stack.back();
            const GraphNode& node = graph[f.node];
            if (f.next < node.children.size()) {
                const std::uint32_t child = node.children[f.next++];
                if (state[child] == kActive) {
                    result.loop = child;
                    return result;
                }
                if (state[child] == kNew) {
                    state[child] = kActive;
                    stack.push_back({child, 0});
                    // (The stack holds the levels above: deeper than max_depth already.)
                    if (stack.size() > max_depth) {
                        result.too_deep = true;
                        return result;
                    }
                }
                continue;
            }
            NodeExpansion e{1, std::min(kManyNodes, node.meshes), 1};
            for (const std::uint32_t c : node.children) {
                e.nodes = saturating_sum(e.nodes, result.of[c].nodes);
                e.placements = saturating_sum(e.placements, result.of[c].placements);
                e.depth = std::max(e.depth, result.of[c].depth + 1);
            }
            result.of[f.node] = e;
            state[f.node] = kDone;
            stack.pop_back();
            if (e.depth > max_depth) {
                result.too_deep = true;
                return result;
            }
        }
    }
    return result;
}

}  // namespace zraster::io
