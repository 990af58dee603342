// `zraster svg`: a scene to an SVG of polygons painted back to front, one color each as --shading
// says.
#include "svg_command.hpp"

#include <zraster/error.hpp>
#include <zraster/output_files.hpp>
#include <zraster/svg.hpp>

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <filesystem>

#include "command_line.hpp"
#include "flag_effects.hpp"
#include "output_maps.hpp"
#include "progress.hpp"
#include "render/material_alpha.hpp"
#include "render_outputs.hpp"
#include "run_inputs.hpp"

namespace zraster::cli {
namespace {

// SVG fills hold one opacity: say so when a material's alpha varies over its surfaces, from
// textures or vertex alpha (svg.hpp).
void note_varying_alpha(const Scene& scene, const RenderOptions& options) {
    std::size_t varying = 0;
    std::string first;
    for (const Instance& instance : scene.instances) {
        const Mesh& mesh = scene.meshes.at(instance.mesh);
        const Material& m =
            scene.materials.at(mesh.material < scene.materials.size() ? mesh.material : 0);
        const bool uvs = options.textures && !mesh.uvs.empty();
        const float least_vertex_alpha = detail::least_vertex_alpha(mesh.colors);
        const bool textures = uvs && (m.base_color_texture || m.opacity_texture);
        if ((textures || least_vertex_alpha < 1.0f) &&
            detail::effective_alpha_mode(m, uvs, least_vertex_alpha, options) !=
                AlphaMode::Opaque &&
            varying++ == 0)
            first = m.name;
    }
    if (varying > 0)
        fmt::print(stderr,
                   "note: {} instance(s) take their alpha from textures or vertex colors (e.g. "
                   "'{}'): zraster svg approximates it, a blended polygon by one fill-opacity (its "
                   "mean alpha), a cut-out by a clip path of whole pixels\n",
                   varying, first);
}

}  // namespace

void add_svg_command(CLI::App& app, SvgArguments& a) {
    CLI::App* cmd = app.add_subcommand(
        "svg",
        "Render a scene to an SVG: hidden-surface-removed polygons in BSP or painter's order, "
        "each filled with one color shaded as --shading says");
    add_render_arguments(*cmd, a.render);
    cmd->add_option("-o,--output", a.output, "Output SVG")->capture_default_str();
    cmd->add_option("--order", a.order,
                    "Back-to-front order: bsp (BSP tree walk) or painter (Newell's painter's "
                    "algorithm)")
        ->check(CLI::IsMember({"bsp", "painter"}))
        ->capture_default_str();
    cmd->add_flag("--edges", a.edges, "Stroke the visible polygon outlines with --edge-color");
    cmd->add_option("--edge-width", a.edge_width, "Edge width in pixels")->capture_default_str();
    cmd->add_option("--precision", a.precision, "Decimal places of coordinates (0..6)")
        ->capture_default_str();
    cmd->add_flag("--no-merge", a.no_merge,
                  "Do not merge adjacent coplanar polygons of the same color");
}

int run_svg(const SvgArguments& a) {
    // Every option is checked before any work, so a bad one leaves no file.
    if (a.output.empty()) throw InputError("-o", "the output path is empty");
    OutputFiles outputs;
    check_output(outputs, a.output, {".svg"}, "-o");
    check_run_inputs(a.render, outputs);
    if (a.precision < 0 || a.precision > 6)
        throw InputError("--precision", "must be 0..6, not " + std::to_string(a.precision));
    if (!std::isfinite(a.edge_width) || a.edge_width < 0.0f)
        throw InputError("--edge-width", "must be finite and >= 0");
    if (a.render.wireframe || a.render.hidden_line)
        throw InputError(a.render.wireframe ? "--wireframe" : "--hidden-line",
                         "not available for svg (use --edges)");
    check_svg_flags_take_effect(a.render, a.edges, a.edge_width != SvgArguments{}.edge_width);

    const Scene scene = load_scene_or_procedural(a.render.scene, nullptr, &outputs);
    RenderOptions options = make_render_options(a.render, scene);
    options.progress = stderr_progress();
    note_varying_alpha(scene, options);

    SvgOptions svg;
    svg.order = a.order == "painter" ? SvgOptions::Order::Painter : SvgOptions::Order::Bsp;
    svg.edges = a.edges;
    svg.edge_width = a.edge_width;
    svg.edge_color = options.edge_color;  // --edge-color, checked there
    svg.precision = a.precision;
    svg.merge_coplanar = !a.no_merge;
    SvgStats stats;
    const std::string document = render_svg(scene, options, svg, &stats);
    // No polygon in view (a camera or clip planes that exclude everything, or every triangle
    // facing away): legal, but rarely meant, as render warns for the same frame.
    if (stats.polygons_in == 0 && scene.triangle_count() > 0)
        fmt::print(stderr,
                   "warning: {}: none of its {} triangles is drawn (outside the view or the clip "
                   "planes, or facing away): the SVG shows only the background\n",
                   scene.name, scene.triangle_count());
    outputs.add(a.output, std::vector<std::uint8_t>(document.begin(), document.end()));
    outputs.commit();
    fmt::print("wrote {}: {} polygons ({} after merging, {} paths), {} bytes\n", a.output,
               stats.polygons_in, stats.polygons_out, stats.paths, stats.bytes);
    return kExitOk;
}

}  // namespace zraster::cli
