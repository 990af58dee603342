// `zraster render`: a scene to a PNG, with optional depth, normal and id outputs.
#include "render_command.hpp"

#include <zraster/abuffer.hpp>
#include <zraster/image_io.hpp>
#include <zraster/output_files.hpp>
#include <zraster/render.hpp>
#include <zraster/visibility.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <numeric>

#include "command_line.hpp"
#include "output_maps.hpp"
#include "progress.hpp"

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
    add_frame_arguments(*cmd, a);
    add_depth_camera_options(*cmd, a.depth_camera);
}

// Material opacity only counts in the A-buffer: say so when the scene has any to ignore.
void warn_if_transparent(const Scene& scene, const std::string& what) {
    std::size_t transparent = 0;
    std::string first;
    for (const Instance& instance : scene.instances) {
        const Mesh& mesh = scene.meshes.at(instance.mesh);
        const Material& m =
            scene.materials.at(mesh.material < scene.materials.size() ? mesh.material : 0);
        if (m.opacity < 1.0f && transparent++ == 0) first = m.name;
    }
    if (transparent > 0)
        fmt::print(stderr,
                   "note: {} instance(s) have a transparent material (opacity < 1, e.g. '{}'): "
                   "{} draws them opaque; `zraster render --visibility abuffer` blends them\n",
                   transparent, first, what);
}

int run_render(const RenderArguments& a) {
    OutputFiles outputs;  // written together at the end, or not at all
    if (a.output.empty()) throw InputError("-o", "the output path is empty");
    check_output(outputs, a.output, {".png"}, "-o");
    check_output(outputs, a.depth_out, {".npy", ".png"}, "--depth-out");
    check_output(outputs, a.normal_out, {".png"}, "--normal-out");
    check_output(outputs, a.id_out, {".npy", ".png"}, "--id-out");
    check_depth_camera_arguments(a.depth_camera, a.visibility, a.aa, a.msaa, a.ortho,
                                 a.fovy.has_value(), outputs);
    // Wall-clock times of the stages, for --stats.
    using Clock = std::chrono::steady_clock;
    const auto since = [](Clock::time_point start) {
        return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    };
    const Clock::time_point load_start = Clock::now();
    const Scene scene = load_scene_or_procedural(a.scene);
    const double load_ms = since(load_start);
    for (const std::string& w : scene.warnings) fmt::print(stderr, "warning: {}\n", w);
    const Clock::time_point render_start = Clock::now();
    RenderOptions options = make_render_options(a, scene);
    options.camera =
        apply_intrinsics(a.depth_camera, *options.camera, options.width, options.height);
    options.progress = stderr_progress();
    options.normal_target = !a.normal_out.empty();
    options.id_targets = !a.id_out.empty();
    options.normal_target |= depth_camera_needs_normals(a.depth_camera);
    VisibilityStats visibility_stats;
    ABufferStats abuffer_stats;
    check_frame_arguments(a);
    if (a.visibility != "abuffer") warn_if_transparent(scene, "--visibility " + a.visibility);
    const RenderResult result = render_frame(a, scene, options, &visibility_stats, &abuffer_stats);
    const RenderTargets& t = result.targets;
    const double render_ms = since(render_start);

    const Clock::time_point write_start = Clock::now();
    // RGBA -> RGB: the alpha channel is always opaque.
    std::vector<std::uint8_t> rgb(std::size_t(t.width) * std::size_t(t.height) * 3);
    for (std::size_t i = 0, n = rgb.size() / 3; i < n; ++i)
        std::copy_n(&t.color[i * 4], 3, &rgb[i * 3]);
    outputs.add(a.output, encode_png8(t.width, t.height, 3, rgb));
    if (!a.depth_out.empty()) outputs.add(a.depth_out, encode_depth_map(a.depth_out, t));
    if (!a.normal_out.empty()) outputs.add(a.normal_out, encode_normal_map(a.normal_out, t));
    if (!a.id_out.empty()) {
        std::vector<std::int64_t> first_triangle;
        std::int64_t total = 0;
        for (const Instance& instance : scene.instances) {
            first_triangle.push_back(total);
            total += static_cast<std::int64_t>(scene.meshes[instance.mesh].triangle_count());
        }
        outputs.add(a.id_out, encode_id_map(a.id_out, t, first_triangle));
    }
    add_depth_camera_outputs(a.depth_camera, scene, options, t, outputs);
    outputs.commit();
    const double write_ms = since(write_start);

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
        const RenderStats& s = result.stats;
        fmt::print(
            "scene {}: {} instances ({} frustum-culled, {} occlusion-culled), {} triangles "
            "in\n",
            a.scene, s.instances, s.instances_frustum_culled, s.instances_occlusion_culled,
            s.triangles_in);
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
