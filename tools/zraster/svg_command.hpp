// `zraster svg`: a hidden-surface-removed vector drawing (SVG) of a scene, in BSP or painter's
// order, with the scene, camera and shading options of `render`.
#pragma once
#include <CLI/CLI.hpp>

#include <string>

#include "render_command.hpp"

namespace zraster::cli {

struct SvgArguments {
    RenderArguments render;  // scene, size, camera, shading, --edge-color; render.output unused
    std::string output = "zraster.svg";
    std::string order = "bsp";
    bool edges = false;
    float edge_width = 0.5f;
    int precision = 2;
    bool no_merge = false;
};

void add_svg_command(CLI::App& app, SvgArguments& arguments);
int run_svg(const SvgArguments& arguments);

}  // namespace zraster::cli
