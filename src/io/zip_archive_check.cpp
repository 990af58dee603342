#include "io/zip_archive_check.hpp"

#include <zraster/error.hpp>

#include <cctype>
#include <unordered_map>
#include <vector>

#include "io/collada_instances_check.hpp"
#include "io/collada_values_check.hpp"
#include "io/node_graph_expansion.hpp"
#include "io/xml_scan.hpp"
#include "io/zip_archive.hpp"

namespace zraster::io {

namespace {

bool ends_with_lower(const std::string& name, std::string_view suffix) {
    if (name.size() < suffix.size()) return false;
    for (std::size_t i = 0; i < suffix.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(name[name.size() - suffix.size() + i])) !=
            suffix[i])
            return false;
    return true;
}

std::string mib(std::uint64_t bytes) {
    return std::to_string(bytes >> 20) + " MiB";
}

std::string count_text(std::uint64_t n) {
    return n >= kManyNodes ? "more than 2^62" : std::to_string(n);
}

}  // namespace

void check_3mf_model(std::string_view doc, const std::string& file, const std::string& member,
                     const LoadOptions& options) {
    // Objects by their id; each places its own mesh and its components' objects.
    std::vector<GraphNode> graph;
    std::vector<std::string> ids;
    std::unordered_map<std::string, std::uint32_t> by_id;
    std::vector<std::vector<std::string>> components;
    std::vector<std::string> items;
    constexpr std::uint32_t kNoObject = ~std::uint32_t{0};
    std::uint32_t object = kNoObject;  // the enclosing <object>
    auto object_index = [&](const std::string& id) {
        const auto [it, added] = by_id.emplace(id, static_cast<std::uint32_t>(graph.size()));
        if (added) {
            graph.emplace_back();
            ids.push_back(id);
            components.emplace_back();
        }
        return it->second;
    };
    for_each_xml_tag(doc, [&](const XmlTag& tag) {
        if (tag.end) {
            if (tag.name == "object") object = kNoObject;
            return;
        }
        if (tag.name == "object") {
            const std::uint32_t index = object_index(xml_attribute(tag.attributes, "id"));
            if (!tag.empty) object = index;
        } else if (tag.name == "mesh" && object != kNoObject) {
            graph[object].meshes = 1;
        } else if (tag.name == "component" && object != kNoObject) {
            components[object].push_back(xml_attribute(tag.attributes, "objectid"));
        } else if (tag.name == "item") {
            items.push_back(xml_attribute(tag.attributes, "objectid"));
        }
    });
    for (std::size_t n = 0; n < graph.size(); ++n)
        for (const std::string& id : components[n])
            if (const auto it = by_id.find(id); it != by_id.end())
                graph[n].children.push_back(it->second);  // (unknown: the importer refuses it)
    std::vector<std::uint32_t> roots;
    for (const std::string& id : items)
        if (const auto it = by_id.find(id); it != by_id.end()) roots.push_back(it->second);

    constexpr std::uint64_t kMaxDepth = 1000;
    const GraphExpansion expansion = expand_node_graph(graph, roots, kMaxDepth);
    const std::string where = "malformed 3MF file: " + member + ": ";
    if (expansion.loop)
        throw InputError(file, where + "object " + ids[*expansion.loop] +
                                   " contains itself (through its components)");
    if (expansion.too_deep)
        throw InputError(file, where + "its components nest more than " +
                                   std::to_string(kMaxDepth) +
                                   " levels deep (the importer reads them recursively)");
    std::uint64_t placements = 0;
    std::uint64_t nodes = 0;
    for (const std::uint32_t root : roots) {
        placements = saturating_sum(placements, expansion.of[root].placements);
        nodes = saturating_sum(nodes, expansion.of[root].nodes);
    }
    if (items.size() > options.max_instances / k3mfBuildItemWeight)
        throw LimitExceeded(file, "max_instances",
                            member + ": its build has " + std::to_string(items.size()) +
                                " items, more than max_instances / " +
                                std::to_string(k3mfBuildItemWeight) + " (" +
                                std::to_string(options.max_instances / k3mfBuildItemWeight) +
                                "; the importer adds items in time quadratic in their number)");
    if (placements > options.max_instances)
        throw LimitExceeded(file, "max_instances",
                            member + ": its build places " + count_text(placements) +
                                " meshes (components placing objects with components "
                                "multiply), more than max_instances (" +
                                std::to_string(options.max_instances) + ")");
    const long double bytes = static_cast<long double>(nodes) * k3mfBytesPerPlacement;
    if (bytes > static_cast<long double>(options.max_geometry_bytes))
        throw LimitExceeded(
            file, "max_geometry_bytes",
            member + ": its build expands to " + count_text(nodes) + " object placements, about " +
                std::to_string(static_cast<std::uint64_t>(bytes / (1 << 20))) +
                " MiB, more than max_geometry_bytes (" + mib(options.max_geometry_bytes) + ")");
}

void check_zip_archive(const std::filesystem::path& path, const LoadOptions& options) {
    const auto members = zip_members(path);
    if (!members) return;
    const std::string file = path.string();
    std::uint64_t inflated = 0;
    for (const ZipMember& m : *members) inflated = saturating_sum(inflated, m.size);
    if (inflated > options.max_geometry_bytes)
        throw LimitExceeded(file, "max_geometry_bytes",
                            "its archive's members inflate to " + mib(inflated) +
                                ", which the importer reads whole: more than "
                                "max_geometry_bytes (" +
                                mib(options.max_geometry_bytes) + ")");
    for (const ZipMember& m : *members) {
        const bool model = ends_with_lower(m.name, ".model");
        const bool collada = ends_with_lower(m.name, ".dae");
        if (!model && !collada) continue;
        // (A member that inflates past its declared size is cut there, as the importer reads it.)
        const auto doc = read_zip_member(path, m.name, m.size);
        if (!doc) continue;  // the importer says what is wrong with it
        if (model) {
            check_3mf_model(*doc, file, m.name, options);
        } else {
            check_collada_values(*doc, file);
            check_collada_instances(*doc, file, options);
        }
    }
}

}  // namespace zraster::io
