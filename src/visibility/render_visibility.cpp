// One frame with a chosen visible-surface algorithm, and BSP frames from a prebuilt tree.
//
// This file only wires the algorithms to the renderer's inputs and outputs (see visibility.hpp);
// the algorithms live one per file: painter.cpp, bsp_tree.cpp, warnock.cpp.
//
// Cost: that of the chosen algorithm plus projection (O(triangles)) and filling (O(fragments)).
#include <chrono>

#include "visibility/back_to_front.hpp"
#include "visibility/canvas.hpp"
#include "visibility/frame_context.hpp"

namespace zraster {

namespace visibility_detail {

void for_each_bsp_piece(const BspTree& tree, const FrameContext& frame,
                        const std::function<void(const ScreenPolygon&)>& fn) {
    const Scene& scene = *frame.scene;
    std::vector<glm::mat4> mvp(scene.instances.size());
    for (std::size_t i = 0; i < mvp.size(); ++i)
        mvp[i] = frame.view_projection * scene.instances[i].transform;
    ScreenPolygon piece;
    const std::vector<BspPolygon>& polygons = tree.polygons();
    for (const std::uint32_t index : tree.back_to_front(frame.viewer)) {
        const BspPolygon& polygon = polygons[index];
        const auto instance = static_cast<std::size_t>(polygon.instance);
        const glm::mat4& model = scene.instances.at(instance).transform;
        // Each fan triangle goes through the renderer's clipping and setup. For an unsplit scene
        // triangle this is exactly what render() does with it; clip_triangle only takes triangles.
        for (std::size_t k = 1; k + 1 < polygon.vertices.size(); ++k) {
            TriangleSource source;
            source.instance = polygon.instance;
            source.primitive = polygon.primitive;
            source.plane = polygon.plane;
            const std::size_t corner[3] = {0, k, k + 1};
            for (std::size_t c = 0; c < 3; ++c) {
                const BspVertex& v = polygon.vertices[corner[c]];
                const glm::vec4 p(v.object, 1.0f);
                source.clip[c] = mvp[instance] * p;
                source.world[c] = v.world;
                source.world_f[c] = glm::vec3(model * p);
                source.weights[c] = v.weights;
            }
            if (project_triangle(frame, source, piece)) fn(piece);
        }
    }
}

}  // namespace visibility_detail

RenderResult render_bsp(const BspTree& tree, const Scene& scene, const RenderOptions& options) {
    using namespace visibility_detail;
    const auto start = std::chrono::steady_clock::now();
    const FrameContext frame = make_frame_context(scene, options);
    Canvas canvas(options, frame.camera, &scene);
    BackToFront painting(canvas, options, "BSP tree", tree.stats().polygons);
    for_each_bsp_piece(tree, frame, [&](const ScreenPolygon& piece) { painting.draw(piece); });
    RenderResult result;
    result.targets = canvas.take();
    canvas.count_fragments(result.stats);
    finish_stats(result.stats, frame.camera, scene, start);
    return result;
}

namespace {

RenderResult render_frame(const Scene& scene, const RenderOptions& options,
                          VisibilityAlgorithm algorithm, VisibilityStats* stats) {
    const auto start = std::chrono::steady_clock::now();
    VisibilityStats local;
    VisibilityStats& out = stats ? *stats : local;
    out = VisibilityStats{};
    RenderResult result;
    switch (algorithm) {
        case VisibilityAlgorithm::ZBuffer:
            return render(scene, options);
        case VisibilityAlgorithm::Painter: {
            const Camera camera = effective_camera(scene, options);
            std::vector<ScreenPolygon> polygons = project_scene(scene, options);
            out.polygons = polygons.size();
            const PainterOptions painter =
                visibility_detail::painter_options(options, polygons.size());
            PainterResult sorted =
                painter_sort(std::move(polygons), Viewport{options.width, options.height}, painter);
            out.painter = sorted.stats;
            visibility_detail::Canvas canvas(options, camera, &scene);
            visibility_detail::BackToFront painting(canvas, options, "painter's algorithm",
                                                    sorted.order.size());
            for (const ScreenPolygon& polygon : sorted.order) painting.draw(polygon);
            result.targets = canvas.take();
            canvas.count_fragments(result.stats);
            result.stats.camera = camera;
            break;
        }
        case VisibilityAlgorithm::Bsp: {
            check_bsp_budget(scene, options.limits);
            std::vector<BspPolygon> polygons = bsp_polygons_from_scene(scene);
            const BspOptions bsp = visibility_detail::bsp_options(options, polygons.size());
            const BspTree tree = BspTree::build(std::move(polygons), bsp);
            out.bsp = tree.stats();
            out.polygons = tree.stats().polygons;
            result = render_bsp(tree, scene, options);
            break;
        }
        case VisibilityAlgorithm::Warnock: {
            const Camera camera = effective_camera(scene, options);
            const std::vector<ScreenPolygon> polygons = project_scene(scene, options);
            out.polygons = polygons.size();
            WarnockResult w = warnock_render(polygons, options, camera, nullptr, &scene);
            out.warnock = std::move(w.stats);
            result.targets = std::move(w.targets);
            result.stats.fragments_shaded = w.fragments.fragments_shaded;
            result.stats.fragments_alpha_discarded = w.fragments.fragments_alpha_discarded;
            result.stats.fragments_blended = w.fragments.fragments_blended;
            result.stats.pixels_blended = w.fragments.pixels_blended;
            result.stats.camera = camera;
            break;
        }
    }
    visibility_detail::finish_stats(result.stats, result.stats.camera, scene, start);
    return result;
}

}  // namespace

RenderResult render_with_visibility(const Scene& scene, const RenderOptions& options,
                                    VisibilityAlgorithm algorithm, VisibilityStats* stats) {
    return visibility_detail::naming_the_scene(
        scene, [&] { return render_frame(scene, options, algorithm, stats); });
}

}  // namespace zraster
