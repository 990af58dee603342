// The scene, camera and pipeline flags of `zraster render` (most shared with `zraster svg`) and
// the RenderOptions they make. The Python module (python/) parses its keywords with these same
// flags and functions, so that names, value syntax and validation cannot drift apart.
#pragma once
#include <zraster/abuffer.hpp>
#include <zraster/camera.hpp>
#include <zraster/render.hpp>
#include <zraster/scene.hpp>
#include <zraster/visibility.hpp>

#include <CLI/CLI.hpp>
#include <glm/glm.hpp>

#include "depth_camera_outputs.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace zraster::cli {

struct RenderArguments {
    std::string scene = "builtin:default";
    std::string output = "zraster.png";
    std::string size = "1920x1080";
    std::uint64_t max_pixels = RenderLimits{}.max_pixels;
    std::uint64_t max_bin_bytes = RenderLimits{}.max_bin_bytes;
    std::uint64_t max_covered_samples = RenderLimits{}.max_covered_samples;
    std::string max_frame_bytes_text = "4G";  // RenderLimits::max_frame_bytes, as a size
    // Budgets of the object-space algorithms (0: automatic, scaled to the input).
    std::uint64_t max_painter_comparisons = 0, max_bsp_polygons = 0;
    std::uint64_t max_warnock_classifications = 0;
    std::uint64_t max_bsp_classifications = 0;
    std::uint64_t max_projected_polygons = 0, max_painted_fragments = 0;
    std::uint64_t max_abuffer_fragments = ABufferOptions{}.max_fragments;
    int threads = 0;
    std::string eye, target, up = "0,1,0", orbit;
    std::optional<double> fovy, near, far;
    std::optional<double> ortho_height;  // --ortho-height: with --ortho, the view's height
    bool ortho = false, reversed_z = false, infinite_far = false;
    std::string shading = "phong", reflection = "blinn-phong";
    bool infinite_viewer = false;
    std::vector<std::string> light_dirs, point_lights;
    std::string cull = "auto";  // auto | back | front | none
    bool no_cull = false;
    bool occlusion_cull = false;
    std::string portal_cull = "off";  // off | rectangles | frustum (the flag alone: frustum)
    std::string pvs;                  // --pvs FILE (`render` attaches it: attach_pvs)
    bool front_to_back = false;
    std::string strategy = "auto";
    std::string alpha_mode = "auto";
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
    std::string view = "none";          // --view: a debug view's name (debug_view.hpp)
    DepthCameraArguments depth_camera;  // `render` only (add_depth_camera_options)
};

// The scene (positional), size, threads, camera and pipeline options.
void add_render_arguments(CLI::App& cmd, RenderArguments& arguments);
// The check of the budget flags: digits only, at most 19 (CLI11 reads "-5" into an unsigned as
// 2^64 - 5).
CLI::Validator whole_number(bool zero_allowed);
// How `render` draws a frame: --visibility, --aa, --msaa.
void add_frame_arguments(CLI::App& cmd, RenderArguments& arguments);

// The camera without camera flags: builtin_camera(spec) for a builtin scene, else fit_camera over
// the scene's world-space vertices.
Camera default_camera(const std::string& spec, std::span<const glm::vec3> world_positions);

// The options the flags ask for. The camera is default_camera(arguments.scene, ...) placed by
// --orbit, --eye, --target, --up, --fovy and --ortho; with `camera` given, that camera instead,
// and those flags are not read. --near, --far, --reversed-z and --infinite-far apply to either.
// Throws InputError naming the flag.
RenderOptions make_render_options(const RenderArguments& arguments, const Scene& scene);
RenderOptions make_render_options(const RenderArguments& arguments,
                                  std::span<const glm::vec3> world_positions,
                                  const std::optional<Camera>& camera);

// Throws InputError for combinations of --visibility, --aa, --msaa, --wireframe and
// --hidden-line that do not go together.
void check_frame_arguments(const RenderArguments& arguments);
// True when the frame is the pipeline's own (z-buffer, no antialiasing): what
// Renderer::render draws.
bool renders_with_pipeline(const RenderArguments& arguments);
// One frame as --visibility, --aa and --msaa ask (checked first).
RenderResult render_frame(const RenderArguments& arguments, const Scene& scene,
                          const RenderOptions& options, VisibilityStats* visibility_stats,
                          ABufferStats* abuffer_stats);

}  // namespace zraster::cli
