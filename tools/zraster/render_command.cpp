// `zraster render`: a scene to a PNG, with optional depth, normal and id outputs.
#include "render_command.hpp"

#include <zraster/abuffer.hpp>
#include <zraster/output_files.hpp>
#include <zraster/render.hpp>
#include <zraster/visibility.hpp>

#include <fmt/format.h>

#include <chrono>
#include <numeric>

#include "command_line.hpp"
#include "flag_effects.hpp"
#include "progress.hpp"
#include "pvs_command.hpp"
#include "render_outputs.hpp"
#include "run_inputs.hpp"

namespace zraster::cli {

void add_render_command(CLI::App& app, RenderArguments& a) {
    CLI::App* cmd =
        app.add_subcommand("render", "Render a mesh file or a procedural scene to a PNG");
    add_render_arguments(*cmd, a);
    cmd->add_option("-o,--output", a.output, "Output PNG (color)")->capture_default_str();
    cmd->add_option("--depth-out", a.depth_out,
                    "Depth map: .npy (float32, HxW, window depth in [0,1], 1 = empty) or .png "
                    "(16-bit gray)");
    cmd->add_option("--normal-out", a.normal_out, "World-space normals as PNG (n * 0.5 + 0.5)");
    cmd->add_option("--id-out", a.id_out,
                    "Instance/primitive ids: .npy (int32 primitive id, -1 empty) or .png "
                    "(false color by instance and primitive)");
    cmd->add_flag("--stats", a.print_stats, "Print pipeline statistics");
    cmd->add_option("--pvs", a.pvs,
                    "Potentially visible sets from `zraster pvs` for the scene: instances outside "
                    "the camera cell's set are skipped (same image)");
    add_frame_arguments(*cmd, a);
    add_depth_camera_options(*cmd, a.depth_camera);
}

namespace {

// The portal walk's line of --stats (none when there was no walk and no PVS).
void print_portal_stats(const RenderStats& s, const Scene& scene) {
    if (s.portal_outcome == PortalOutcome::NotRun || !scene.cells) return;
    const CellGraph& graph = *scene.cells;
    const std::string cell = s.portal_camera_cell >= 0
                                 ? fmt::format("cell {} '{}'", s.portal_camera_cell,
                                               graph.cells[std::size_t(s.portal_camera_cell)].name)
                                 : std::string("no cell");
    const std::string pvs =
        graph.pvs.empty() ? std::string() : fmt::format(", PVS {} cells", s.portal_pvs_cells);
    switch (s.portal_outcome) {
        case PortalOutcome::Culled:
            fmt::print("  portals: camera in {}, {} of {} cells visited ({} visits){}, {:.3f} ms\n",
                       cell, s.portal_cells_visited, graph.cells.size(), s.portal_visits, pvs,
                       s.portal_ms);
            break;
        case PortalOutcome::CameraOutside:
            fmt::print("  portals: camera outside every cell: not culled\n");
            break;
        case PortalOutcome::OverBound:
            fmt::print("  portals: camera in {}, walk past its bound ({} visits): not culled\n",
                       cell, s.portal_visits);
            break;
        default:
            fmt::print(
                "  portals: not culled (needs D32F less/lequal depth with writes, no clip "
                "planes, no edges)\n");
    }
}

}  // namespace

int run_render(const RenderArguments& a) {
    OutputFiles outputs;  // written together at the end, or not at all
    check_render_outputs(a, outputs);
    check_run_inputs(a, outputs);
    for (const std::string& w : check_flags_take_effect(a)) fmt::print(stderr, "warning: {}\n", w);
    // Wall-clock times of the stages, for --stats.
    using Clock = std::chrono::steady_clock;
    const auto since = [](Clock::time_point start) {
        return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    };
    const Clock::time_point load_start = Clock::now();
    Scene scene = load_scene_or_procedural(a.scene, nullptr, &outputs);
    if (!a.pvs.empty()) attach_pvs(a.pvs, scene);
    const double load_ms = since(load_start);
    for (const std::string& w : scene_flag_warnings(a, scene, !a.normal_out.empty()))
        fmt::print(stderr, "warning: {}\n", w);
    const RenderedFrame frame = render_outputs(a, scene, outputs, stderr_progress(), stderr);
    const VisibilityStats& visibility_stats = frame.visibility;
    const ABufferStats& abuffer_stats = frame.abuffer;
    const double render_ms = frame.render_ms;
    const Clock::time_point commit_start = Clock::now();
    outputs.commit();
    const double write_ms = frame.encode_ms + since(commit_start);

    if (a.print_stats && a.visibility == "abuffer")
        fmt::print("abuffer: {} fragments over {} pixels, longest list {}\n",
                   abuffer_stats.fragments, abuffer_stats.pixels_with_fragments,
                   abuffer_stats.max_list_length);
    if (a.print_stats && a.visibility != "zbuffer" && a.visibility != "abuffer") {
        const VisibilityStats& v = visibility_stats;
        std::uint64_t regions = 0;
        for (const std::uint64_t n : v.warnock.regions_per_level) regions += n;
        if (a.visibility == "painter")
            fmt::print(
                "painter: {} polygons, {} comparisons, {} swaps, {} splits ({} forced by "
                "cycles)\n",
                v.polygons, v.painter.comparisons, v.painter.swaps, v.painter.splits,
                v.painter.cycle_splits);
        else if (a.visibility == "bsp")
            fmt::print(
                "bsp: {} input polygons, {} nodes, depth {}, {} splits, {} classifications\n",
                v.bsp.input_polygons, v.bsp.nodes, v.bsp.depth, v.bsp.splits,
                v.bsp.classifications);
        else
            fmt::print("warnock: {} polygons, {} regions in {} levels, {} classifications\n",
                       v.polygons, regions, v.warnock.regions_per_level.size(),
                       std::accumulate(v.warnock.classifications.begin(),
                                       v.warnock.classifications.end(), std::uint64_t{0}));
    }
    if (a.print_stats) {
        const RenderStats& s = frame.stats;
        fmt::print(
            "scene {}: {} instances ({} frustum-culled, {} occlusion-culled, {} portal-culled), "
            "{} triangles in\n",
            a.scene, s.instances, s.instances_frustum_culled, s.instances_occlusion_culled,
            s.instances_portal_culled, s.triangles_in);
        print_portal_stats(s, scene);
        fmt::print(
            "  trivially rejected {}, clipped {}, back-face culled {}, degenerate {}, "
            "no pixel covered {}, non-finite {}, rasterized {}\n",
            s.triangles_trivially_rejected, s.triangles_clipped, s.triangles_backface_culled,
            s.triangles_degenerate, s.triangles_no_coverage, s.triangles_non_finite,
            s.triangles_rasterized);
        fmt::print(
            "  fragments shaded {} ({}); setup {:.1f} ms, raster {:.1f} ms, total {:.1f} ms\n",
            s.fragments_shaded, s.deferred ? "deferred" : "forward", s.setup_ms, s.raster_ms,
            s.total_ms);
        if (s.fragments_alpha_discarded + s.fragments_blended > 0)
            fmt::print(
                "  alpha: fragments discarded by the alpha test {}, blended {} over {} "
                "pixels\n",
                s.fragments_alpha_discarded, s.fragments_blended, s.pixels_blended);
        fmt::print(
            "  camera eye ({:.6g}, {:.6g}, {:.6g}) target ({:.6g}, {:.6g}, {:.6g}) near "
            "{:.6g} far {:.6g}\n",
            s.camera.eye.x, s.camera.eye.y, s.camera.eye.z, s.camera.target.x, s.camera.target.y,
            s.camera.target.z, s.camera.near, s.camera.far);
        fmt::print("  wall time: load {:.1f} ms, camera and render {:.1f} ms, write {:.1f} ms\n",
                   load_ms, render_ms, write_ms);
    }
    return kExitOk;
}

}  // namespace zraster::cli
