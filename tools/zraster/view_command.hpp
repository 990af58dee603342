// `zraster view SCENE`: an interactive window on zraster's frames (docs/viewer.md).
#pragma once
#include <CLI/CLI.hpp>

#include <string>

#include "render_arguments.hpp"

namespace zraster::cli {

struct ViewArguments {
    RenderArguments render;  // the scene, camera and pipeline flags of `zraster render`
    long long frames = 0;
    std::string screenshot, script;
    bool no_hud = false;
};

void add_view_command(CLI::App& app, ViewArguments& arguments);
int run_view(const ViewArguments& arguments);

}  // namespace zraster::cli
