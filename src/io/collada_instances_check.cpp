#include "io/collada_instances_check.hpp"

#include <zraster/error.hpp>

#include "io/node_graph_expansion.hpp"
#include "io/xml_scan.hpp"

#include <algorithm>
#include <string>
#include <unordered_map>
#include <vector>

namespace zraster::io {

namespace {

constexpr std::uint32_t kNoVisualScene = ~std::uint32_t{0};

struct Node {
    std::string id;
    std::uint64_t geometries = 0;          // <instance_geometry>, <instance_controller>
    std::vector<std::uint32_t> children;   // nested <node>s
    std::vector<std::string> instanced;    // <instance_node url="#..."> targets
    std::vector<std::uint32_t> instances;  // resolved
};

struct VisualScene {
    std::string id;
    std::vector<std::uint32_t> roots;
};

// Assimp reads nested nodes, and the nodes <instance_node> places, recursively: 100,000 levels
// overflowed its stack. No model needs a thousand.
constexpr std::size_t kMaxColladaDepth = 1000;
InputError too_deep(const std::string& file) {
    return InputError(file, "malformed COLLADA file: its nodes nest more than " +
                                std::to_string(kMaxColladaDepth) +
                                " levels deep (within each other or placed by <instance_node>; "
                                "the importer reads them recursively)");
}

}  // namespace

ColladaExpansion count_collada_expansion(std::string_view doc, const std::string& file) {
    std::vector<Node> nodes;
    std::vector<VisualScene> scenes;
    std::uint64_t materials = 0;
    std::string chosen_scene;
    std::vector<std::uint32_t> open;       // enclosing <node>s
    std::uint32_t scene = kNoVisualScene;  // enclosing <visual_scene>
    for_each_xml_tag(doc, [&](const XmlTag& tag) {
        const std::string_view name = tag.name;
        if (tag.end) {
            if (name == "node" && !open.empty()) open.pop_back();
            if (name == "visual_scene") scene = kNoVisualScene;
            return;
        }
        const std::string_view rest = tag.attributes;
        if (name == "material") ++materials;
        if (name == "node") {
            const auto index = static_cast<std::uint32_t>(nodes.size());
            nodes.push_back(Node{xml_attribute(rest, "id"), 0, {}, {}, {}});
            if (!open.empty())
                nodes[open.back()].children.push_back(index);
            else if (scene != kNoVisualScene)
                scenes[scene].roots.push_back(index);
            if (!tag.empty) open.push_back(index);
            if (open.size() > kMaxColladaDepth) throw too_deep(file);
        } else if (name == "visual_scene") {
            scenes.push_back(VisualScene{xml_attribute(rest, "id"), {}});
            scene = tag.empty ? kNoVisualScene : static_cast<std::uint32_t>(scenes.size() - 1);
        } else if (name == "instance_visual_scene") {
            const std::string url = xml_attribute(rest, "url");
            if (url.starts_with('#')) chosen_scene = url.substr(1);
        } else if (!open.empty()) {
            if (name == "instance_geometry" || name == "instance_controller")
                ++nodes[open.back()].geometries;
            else if (name == "instance_node") {
                const std::string url = xml_attribute(rest, "url");
                if (url.starts_with('#')) nodes[open.back()].instanced.push_back(url.substr(1));
            }
        }
    });
    if (scenes.empty()) return {0, 0, materials};

    std::unordered_map<std::string, std::uint32_t> by_id;
    for (std::uint32_t n = 0; n < nodes.size(); ++n)
        if (!nodes[n].id.empty()) by_id.emplace(nodes[n].id, n);
    for (Node& node : nodes)
        for (const std::string& target : node.instanced)
            if (auto it = by_id.find(target); it != by_id.end())
                node.instances.push_back(it->second);  // (unresolved: Assimp warns, skips)

    std::vector<GraphNode> graph(nodes.size());
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        graph[n].meshes = nodes[n].geometries;
        graph[n].children = nodes[n].children;
        graph[n].children.insert(graph[n].children.end(), nodes[n].instances.begin(),
                                 nodes[n].instances.end());
    }
    const VisualScene* shown = &scenes.front();
    for (const VisualScene& s : scenes)
        if (!chosen_scene.empty() && s.id == chosen_scene) shown = &s;
    const GraphExpansion expansion = expand_node_graph(graph, shown->roots, kMaxColladaDepth);
    if (expansion.loop)
        throw InputError(file, "malformed COLLADA file: node '" + nodes[*expansion.loop].id +
                                   "' places itself (through <instance_node>)");
    if (expansion.too_deep) throw too_deep(file);
    ColladaExpansion total;
    total.materials = materials;
    for (std::uint32_t root : shown->roots) {
        total.nodes = saturating_sum(total.nodes, expansion.of[root].nodes);
        total.placements = saturating_sum(total.placements, expansion.of[root].placements);
    }
    return total;
}

void check_collada_instances(std::string_view doc, const std::string& file,
                             const LoadOptions& options) {
    const ColladaExpansion e = count_collada_expansion(doc, file);
    auto count = [](std::uint64_t n) {
        return n >= kManyColladaNodes ? "more than 2^62" : std::to_string(n);
    };
    // (As the count after an import is worded, load_scene.cpp.)
    if (e.materials > options.max_materials)
        throw LimitExceeded(file, "max_materials",
                            "it defines " + std::to_string(e.materials) +
                                " materials, more than max_materials (" +
                                std::to_string(options.max_materials) + ")");
    // (The parenthesis only where the file has <instance_node>s: they are what multiplies.)
    const bool copies = doc.find("<instance_node") != std::string_view::npos;
    if (e.placements > options.max_instances)
        throw LimitExceeded(
            file, "max_instances",
            "its nodes place " + count(e.placements) + " meshes" +
                (copies ? " (nodes placed again by <instance_node> multiply)" : "") +
                ", more than max_instances (" + std::to_string(options.max_instances) + ")");
    // (e.nodes is at most 2^62: in long double the product is exact enough and cannot wrap.)
    const long double bytes = static_cast<long double>(e.nodes) * kColladaBytesPerNode;
    if (bytes > static_cast<long double>(options.max_geometry_bytes))
        throw LimitExceeded(
            file, "max_geometry_bytes",
            "its node hierarchy expands to " + count(e.nodes) + " nodes" +
                (copies ? " (nodes placed again by <instance_node> are copied)" : "") + ", about " +
                std::to_string(static_cast<std::uint64_t>(bytes / (1 << 20))) +
                " MiB, more than max_geometry_bytes (" +
                std::to_string(options.max_geometry_bytes >> 20) + " MiB)");
}

}  // namespace zraster::io
