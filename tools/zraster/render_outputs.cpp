// See render_outputs.hpp.
#include "render_outputs.hpp"

#include <zraster/error.hpp>
#include <zraster/image_io.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "debug_view_legend.hpp"
#include "depth_camera_outputs.hpp"
#include "flag_effects.hpp"
#include "output_maps.hpp"

namespace zraster::cli {

namespace {

// Whether no surface of the scene can show: each instanced mesh's material blended at opacity
// 0 or masked below its cutoff, or its vertex colors all of alpha 0 (textures aside: they may
// hold alpha 1).
bool fully_transparent(const Scene& scene) {
    if (scene.instances.empty()) return false;
    for (const Instance& instance : scene.instances) {
        const Mesh& mesh = scene.meshes[instance.mesh];
        const Material& m = scene.materials[mesh.material];
        if (m.alpha_mode == AlphaMode::Opaque) return false;
        const bool untextured = m.base_color_texture == nullptr && m.opacity_texture == nullptr;
        const bool clear = untextured && (m.alpha_mode == AlphaMode::Mask
                                              ? m.opacity < m.alpha_cutoff && mesh.colors.empty()
                                              : m.opacity == 0.0f);
        const bool colors_clear =
            !mesh.colors.empty() && std::all_of(mesh.colors.begin(), mesh.colors.end(),
                                                [](const glm::vec4& c) { return c.w == 0.0f; });
        if (!clear && !colors_clear) return false;
    }
    return true;
}

// Every pixel the background's color (to the rounding of its conversion): nothing drawn.
bool only_background(const RenderTargets& t, const glm::vec3& background) {
    if (t.color.size() < 4) return false;
    for (int k = 0; k < 3; ++k) {
        const long expected = std::lround(std::clamp(background[k], 0.0f, 1.0f) * 255.0f);
        if (std::labs(long(t.color[std::size_t(k)]) - expected) > 1) return false;
    }
    for (std::size_t i = 4; i < t.color.size(); i += 4)
        if (std::memcmp(&t.color[i], t.color.data(), 4) != 0) return false;
    return true;
}

}  // namespace

void check_render_outputs(const RenderArguments& a, OutputFiles& outputs) {
    if (a.output.empty()) throw InputError("-o", "the output path is empty");
    check_output(outputs, a.output, {".png"}, "-o");
    check_output(outputs, a.depth_out, {".npy", ".png"}, "--depth-out");
    check_output(outputs, a.normal_out, {".png"}, "--normal-out");
    check_output(outputs, a.id_out, {".npy", ".png"}, "--id-out");
    check_depth_camera_arguments(a.depth_camera, a.visibility, a.aa, a.msaa, a.ortho,
                                 a.fovy.has_value(), outputs);
}

RenderedFrame render_outputs(const RenderArguments& a, const Scene& scene, OutputFiles& outputs,
                             ProgressReporter* progress, std::FILE* notes, Renderer* renderer) {
    using Clock = std::chrono::steady_clock;
    const auto since = [](Clock::time_point start) {
        return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    };
    RenderedFrame frame;
    const Clock::time_point render_start = Clock::now();
    RenderOptions options = make_render_options(a, scene);
    options.camera =
        apply_intrinsics(a.depth_camera, *options.camera, options.width, options.height);
    options.progress = progress;
    options.normal_target = !a.normal_out.empty();
    options.id_targets = !a.id_out.empty();
    options.normal_target |= depth_camera_needs_normals(a.depth_camera);
    check_frame_arguments(a);
    RenderResult own;
    const RenderResult* result = &own;
    try {
        if (renderer != nullptr && renders_with_pipeline(a)) {
            // The renderer draws one scene after another: cluster bounds kept for one mesh would
            // be matched to the next by its address and hash only, and are never reused anyway
            // (the image is the same without them).
            options.cluster_culling = false;
            result = &renderer->render(scene, options);
        } else {
            own = render_frame(a, scene, options, &frame.visibility, &frame.abuffer);
        }
    } catch (const LimitExceeded& e) {
        if (!e.file().empty()) throw;
        throw LimitExceeded(scene.name, e.limit(), e.cause());  // (a frame's limit: the scene's)
    } catch (const InputError& e) {
        if (!e.file().empty()) throw;
        throw InputError(scene.name, e.cause());
    }
    const RenderTargets& t = result->targets;
    frame.stats = result->stats;
    frame.render_ms = since(render_start);
    // A camera or clip planes that exclude everything give the background alone: legal, but
    // rarely meant (a near plane of 1e29, opposing clip planes).
    const RenderStats& s = frame.stats;
    if (notes != nullptr && renders_with_pipeline(a) && options.view == DebugView::None &&
        s.triangles_rasterized == 0 && s.triangles_backface_culled == 0 &&
        scene.triangle_count() > 0)
        fmt::print(notes,
                   "warning: {}: none of its {} triangles is in view ({} of {} instances outside "
                   "the view volume, {} triangles outside it or the clip planes, {} covering no "
                   "pixel center): the image shows only the background\n",
                   scene.name, scene.triangle_count(), s.instances_frustum_culled, s.instances,
                   s.triangles_trivially_rejected + s.triangles_clipped, s.triangles_no_coverage);
    // Every triangle in view turned away: the camera inside a closed mesh, or a model wound
    // the other way round.
    else if (notes != nullptr && renders_with_pipeline(a) && options.view == DebugView::None &&
             s.triangles_rasterized == 0 && s.triangles_backface_culled > 0)
        fmt::print(notes,
                   "warning: {}: the {} triangles in view all face away from the camera and were "
                   "culled (--cull {}): the image shows only the background (--cull none draws "
                   "both sides)\n",
                   scene.name, s.triangles_backface_culled,
                   options.cull == CullMode::Front ? "front" : "back");
    // The object-space algorithms, MSAA and supersampling keep no pipeline counts: an image of
    // the background alone says the same (a camera or clip planes that exclude everything).
    else if (notes != nullptr && !renders_with_pipeline(a) && options.view == DebugView::None &&
             !a.wireframe && scene.triangle_count() > 0 && only_background(t, options.background))
        fmt::print(notes,
                   "warning: {}: nothing of its {} triangles was drawn: the image shows only the "
                   "background (is the camera or a clip plane leaving it out?)\n",
                   scene.name, scene.triangle_count());
    // Surfaces that draw nothing: every material fully transparent, or every vertex color's
    // alpha 0 (an AMF file without colors, as Assimp reads it).
    else if (notes != nullptr && renders_with_pipeline(a) && options.view == DebugView::None &&
             s.triangles_rasterized > 0 && s.fragments_passed == 0 && fully_transparent(scene))
        fmt::print(notes,
                   "warning: {}: every surface in it is fully transparent (opacity 0 or below its "
                   "alpha cutoff, or vertex colors of alpha 0): the image shows only the "
                   "background (--alpha-mode opaque draws them opaque)\n",
                   scene.name);
    // Every fragment in view cut by the alpha test: a cutoff above every alpha the textures and
    // vertex colors give (glTF MASK with alphaCutoff 1).
    else if (notes != nullptr && renders_with_pipeline(a) && options.view == DebugView::None &&
             s.triangles_rasterized > 0 && s.fragments_passed == 0 && s.fragments_blended == 0 &&
             s.fragments_alpha_discarded > 0)
        fmt::print(notes,
                   "warning: {}: every fragment of its {} triangles in view was cut out by the "
                   "alpha test (alpha below its material's cutoff): the image shows only the "
                   "background (--alpha-mode opaque draws them opaque)\n",
                   scene.name, s.triangles_rasterized);
    // Triangles in view, none of whose fragments passed: a depth format too coarse for the
    // near/far ratio rounds every depth to the cleared far plane (d16, near 1e-20); or slivers
    // that cover no pixel center at all. The frame drawn again without the depth test tells
    // them apart (only here: the image is blank).
    else if (notes != nullptr && renders_with_pipeline(a) && options.view == DebugView::None &&
             !a.no_depth_test && s.triangles_rasterized > 0 && s.fragments_passed == 0 &&
             s.fragments_blended == 0 && s.fragments_alpha_discarded == 0 &&
             check_flags_take_effect(a).empty()) {
        // Drawn opaque without the depth test: nothing means slivers; drawn opaque with it,
        // something means the surfaces' alpha hid them (a texture or colors of alpha 0).
        RenderOptions probe = options;
        probe.progress = nullptr;
        probe.alpha_mode = MaterialAlpha::Opaque;
        probe.depth_test = false;
        const bool covered = render(scene, probe).stats.fragments_passed > 0;
        probe.depth_test = true;
        if (!covered)
            fmt::print(notes,
                       "warning: {}: its {} triangles in view cover no pixel center (too thin or "
                       "too small for --size {}x{}): the image shows only the background\n",
                       scene.name, s.triangles_rasterized, options.width, options.height);
        else if (a.alpha_mode != "opaque" && render(scene, probe).stats.fragments_passed > 0)
            fmt::print(notes,
                       "warning: {}: its {} triangles in view are drawn fully transparent (their "
                       "textures' or colors' alpha is 0 where they cover pixels): the image "
                       "shows only the background (--alpha-mode opaque draws them opaque)\n",
                       scene.name, s.triangles_rasterized);
        else
            fmt::print(notes,
                       "warning: {}: {} triangles in view, but none of their fragments passed "
                       "the depth test: the image shows only the background (is --depth-format "
                       "{} too coarse for the near and far planes?)\n",
                       scene.name, s.triangles_rasterized, a.depth_format);
    }

    const Clock::time_point encode_start = Clock::now();
    // RGBA -> RGB: the alpha channel is always opaque. Byte by byte: a 3-byte copy_n per pixel
    // was a memmove call each, 5% of a batch of small images.
    std::vector<std::uint8_t> rgb(std::size_t(t.width) * std::size_t(t.height) * 3);
    RgbaImage legend_image;
    const std::uint8_t* in = t.color.data();
    if (options.view != DebugView::None) {
        if (notes != nullptr)
            fmt::print(notes, "{}\n", debug_view_legend(options.view, frame.stats.view_scale));
        legend_image.width = t.width;
        legend_image.height = t.height;
        legend_image.pixels = t.color;
        draw_debug_view_legend(legend_image, options.view, frame.stats.view_scale);
        in = legend_image.pixels.data();
    }
    std::uint8_t* out = rgb.data();
    for (std::size_t i = 0, n = rgb.size() / 3; i < n; ++i, in += 4, out += 3) {
        out[0] = in[0];
        out[1] = in[1];
        out[2] = in[2];
    }
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
    frame.encode_ms = since(encode_start);
    return frame;
}

}  // namespace zraster::cli
