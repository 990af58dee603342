// `zraster pvs`: the potentially visible sets of a scene's cells, as JSON (docs/portals.md); and
// `--pvs FILE` of `zraster render`, which attaches such a file to the scene.
#pragma once
#include <zraster/scene.hpp>

#include <CLI/CLI.hpp>

#include <string>

namespace zraster::cli {

struct PvsArguments {
    std::string scene;
    std::string output = "pvs.json";
    double slack = PvsOptions{}.slack;
};

void add_pvs_command(CLI::App& app, PvsArguments& arguments);
int run_pvs(const PvsArguments& arguments);

// The scene's cell graph with the sets of `path` attached (load_pvs). Throws InputError naming
// --pvs when the scene has no cell graph.
void attach_pvs(const std::string& path, Scene& scene);

}  // namespace zraster::cli
