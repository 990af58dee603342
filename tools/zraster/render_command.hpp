// `zraster render`: a scene to a PNG, with optional depth, normal and id outputs.
#pragma once
#include <zraster/scene.hpp>

#include <CLI/CLI.hpp>

#include <string>

#include "render_arguments.hpp"

namespace zraster::cli {

void add_render_command(CLI::App& app, RenderArguments& arguments);
int run_render(const RenderArguments& arguments);

}  // namespace zraster::cli
