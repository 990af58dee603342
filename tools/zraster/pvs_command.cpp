// `zraster pvs` (pvs_command.hpp).
#include "pvs_command.hpp"

#include <zraster/error.hpp>
#include <zraster/load.hpp>
#include <zraster/output_files.hpp>

#include <fmt/format.h>

#include <chrono>
#include <cmath>

#include "command_line.hpp"

namespace zraster::cli {

void add_pvs_command(CLI::App& app, PvsArguments& a) {
    CLI::App* cmd = app.add_subcommand(
        "pvs", "Potentially visible sets of a scene's cells (building:RxC or a .cells.json file)");
    cmd->add_option("scene", a.scene, "building:RxC[:SEED] or a .cells.json file")->required();
    cmd->add_option("-o,--output", a.output, "Output JSON")->capture_default_str();
    cmd->add_option("--slack", a.slack,
                    "World units by which portals are taken as larger (covers rounding)")
        ->capture_default_str();
}

int run_pvs(const PvsArguments& a) {
    if (!(std::isfinite(a.slack) && a.slack >= 0.0))
        throw InputError("--slack", "must be a finite number >= 0");
    OutputFiles outputs;
    outputs.check(a.output, "-o");
    outputs.check_input(a.scene, "");  // (a procedural spec names no file)
    const Scene scene = load_scene_or_procedural(a.scene, nullptr, &outputs);
    if (!scene.cells)
        throw InputError(a.scene, "the scene has no cells (building:RxC or a .cells.json file)");
    const auto start = std::chrono::steady_clock::now();
    PvsOptions options;
    options.slack = a.slack;
    const PotentiallyVisibleSets sets = compute_pvs(*scene.cells, options);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const std::string json = pvs_to_json(sets, *scene.cells, a.scene, options);
    outputs.add(a.output, std::vector<std::uint8_t>(json.begin(), json.end()));
    outputs.commit();
    std::size_t total = 0, bounded = 0;
    for (std::size_t c = 0; c < sets.visible.size(); ++c) {
        total += sets.visible[c].size();
        bounded += sets.bounded[c];
    }
    const std::size_t cells = sets.visible.size();
    fmt::print(
        "pvs: {} cells, {:.1f} visible per cell on average, {} bounded, {} steps, {:.0f} ms\n",
        cells, double(total) / double(cells), bounded, sets.steps, ms);
    return kExitOk;
}

void attach_pvs(const std::string& path, Scene& scene) {
    if (!scene.cells)
        throw InputError("--pvs", "the scene has no cells (building:RxC or a .cells.json file)");
    auto graph = std::make_shared<CellGraph>(*scene.cells);
    graph->pvs = load_pvs(path, *graph);
    scene.cells = std::move(graph);
}

}  // namespace zraster::cli
