#pragma once
#include <zraster/render.hpp>
#include <zraster/scene.hpp>

#include <CLI/CLI.hpp>

#include "depth_camera_outputs.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace zraster::cli {

struct RenderArguments {
    std::string scene = "builtin:default";
    std::string output = "zraster.png";
    std::string size = "1920x1080";
    std::uint64_t max_pixels = RenderLimits{}.max_pixels;
    // Budgets of the object-space algorithms (0: automatic, scaled to the input).
    std::uint64_t max_painter_comparisons = 0, max_bsp_polygons = 0;
    std::uint64_t max_warnock_classifications = 0;
    std::uint64_t max_abuffer_fragments = std::uint64_t{64} << 20;  // ABufferOptions' default
    int threads = 0;
    std::string eye, target, up = "0,1,0", orbit;
    std::optional<double> fovy, near, far;
    bool ortho = false, reversed_z = false, infinite_far = false;
    std::string shading = "phong", reflection = "blinn-phong";
    bool infinite_viewer = false;
    std::vector<std::string> light_dirs, point_lights;
    std::string cull = "back";
    bool no_cull = false;
    bool occlusion_cull = false;
    bool front_to_back = false;
    std::string strategy = "auto";
    std::string front_face = "ccw";
    std::string depth_format = "d32f", depth_compare;
    bool no_depth_test = false, no_depth_write = false;
    std::string interpolation = "perspective", texture_filter = "trilinear";
    bool no_textures = false;
    std::vector<std::string> clip_planes;
    std::string background = "51,51,51";
    std::string depth_out, normal_out, id_out;
    bool print_stats = false;
    std::string visibility = "zbuffer";
    int aa = 1;
    bool msaa = false;
    bool wireframe = false, hidden_line = false;
    std::string edge_color = "0,0,0";
    DepthCameraArguments depth_camera;  // `render` only
};

// The scene, camera and pipeline options shared by `render` and later subcommands.
void add_render_arguments(CLI::App& cmd, RenderArguments& arguments);
void add_render_command(CLI::App& app, RenderArguments& arguments);
RenderOptions make_render_options(const RenderArguments& arguments, const Scene& scene);
int run_render(const RenderArguments& arguments);
// A note on stderr when instances have transparent materials, which `what` draws opaque.
void warn_if_transparent(const Scene& scene, const std::string& what);

}  // namespace zraster::cli
