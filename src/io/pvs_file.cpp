// PVS files of `zraster pvs` (load.hpp, docs/portals.md): written and read back with checks.
#include <zraster/error.hpp>
#include <zraster/load.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>

#include "io/input_file_check.hpp"
#include "io/json_errors.hpp"
#include "io/read_file.hpp"

namespace zraster {

using nlohmann::json;

std::string pvs_to_json(const PotentiallyVisibleSets& sets, const CellGraph& graph,
                        const std::string& scene, const PvsOptions& options) {
    json document;
    document["zraster_pvs"] = 1;
    document["scene"] = scene;
    document["method"] =
        "portal sequences clipped to separating planes (Teller & Sequin 1991), conservative";
    document["slack"] = options.slack;
    document["cells"] = graph.cells.size();
    document["steps"] = sets.steps;
    json visible = json::array();
    for (std::size_t c = 0; c < sets.visible.size(); ++c)
        visible.push_back({{"cell", graph.cells[c].name},
                           {"bounded", sets.bounded[c] != 0},
                           {"visible", sets.visible[c]}});
    document["sets"] = std::move(visible);
    return document.dump(1) + "\n";
}

std::vector<std::vector<std::uint32_t>> load_pvs(const std::filesystem::path& path,
                                                 const CellGraph& graph) {
    const std::string file = path.string();
    const auto fail = [&](const std::string& where, const std::string& cause) {
        return InputError(file, where + ": " + cause);
    };
    io::check_input_file(path, std::size_t{1} << 30, nullptr);  // a fixed limit, not LoadOptions'

    const std::vector<std::uint8_t> bytes = io::read_file_bytes(path);
    json document;
    try {
        document = json::parse(bytes.begin(), bytes.end());
    } catch (const json::exception& e) {
        throw InputError(file, "malformed JSON: " + io::json_error_text(e));
    }
    if (!document.is_object() || !document.contains("zraster_pvs") || document["zraster_pvs"] != 1)
        throw fail("zraster_pvs", "expected 1 (not a file of zraster pvs?)");
    if (!document.contains("sets") || !document["sets"].is_array() ||
        document["sets"].size() != graph.cells.size())
        throw fail("sets", "expected one set per cell of the scene (" +
                               std::to_string(graph.cells.size()) + ")");
    std::vector<std::vector<std::uint32_t>> sets(graph.cells.size());
    for (std::size_t c = 0; c < sets.size(); ++c) {
        const std::string at = "sets[" + std::to_string(c) + "]";
        const json& set = document["sets"][c];
        if (!set.is_object() || !set.contains("cell") || set["cell"] != graph.cells[c].name)
            throw fail(at + ".cell",
                       "expected '" + graph.cells[c].name + "' (the file is for another scene?)");
        if (!set.contains("visible") || !set["visible"].is_array())
            throw fail(at + ".visible", "expected an array of cell indices");
        for (const json& index : set["visible"]) {
            if (!index.is_number_unsigned() || index.get<std::uint64_t>() >= graph.cells.size())
                throw fail(at + ".visible",
                           "expected cell indices below " + std::to_string(graph.cells.size()));
            sets[c].push_back(index.get<std::uint32_t>());
        }
        std::sort(sets[c].begin(), sets[c].end());
        sets[c].erase(std::unique(sets[c].begin(), sets[c].end()), sets[c].end());
        if (!std::binary_search(sets[c].begin(), sets[c].end(), std::uint32_t(c)))
            throw fail(at + ".visible", "does not hold its own cell");
    }
    return sets;
}

}  // namespace zraster
