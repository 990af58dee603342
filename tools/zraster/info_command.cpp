// `zraster info`: what a mesh file holds.
#include "info_command.hpp"

#include <zraster/load.hpp>

#include <fmt/format.h>

#include "command_line.hpp"

namespace zraster::cli {

void add_info_command(CLI::App& app, InfoArguments& a) {
    CLI::App* cmd =
        app.add_subcommand("info", "Print meshes, triangles, vertices, bounds and materials");
    cmd->add_option("scene", a.scene, "Mesh file or procedural scene spec")->required();
}

int run_info(const InfoArguments& a) {
    std::vector<std::string> warnings;
    const Scene scene = load_scene_or_procedural(a.scene, &warnings);
    fmt::print("{}", describe_scene(scene, warnings));
    return kExitOk;
}

}  // namespace zraster::cli
