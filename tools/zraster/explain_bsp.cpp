// `zraster explain bsp`: the tree's cells level by level, the back-to-front order, the diagram.
#include <zraster/visibility.hpp>

#include <fmt/format.h>

#include "explain_algorithms.hpp"
#include "explain_scene.hpp"

namespace zraster::cli {
namespace {

struct TreeLayout {
    std::vector<std::size_t> depth;    // per node, root 0
    std::vector<std::size_t> rank;     // in-order position
    std::vector<std::int32_t> parent;  // -1 for the root
    std::vector<std::int32_t> node_of_polygon;
};

TreeLayout layout(const BspTree& tree) {
    const auto& nodes = tree.nodes();
    TreeLayout t;
    t.depth.assign(nodes.size(), 0);
    t.rank.assign(nodes.size(), 0);
    t.parent.assign(nodes.size(), -1);
    t.node_of_polygon.assign(tree.polygons().size(), -1);
    if (nodes.empty()) return t;
    // In-order walk with an explicit stack (trees may be deep).
    std::vector<std::int32_t> stack;
    std::int32_t current = 0;
    std::size_t next_rank = 0;
    while (current >= 0 || !stack.empty()) {
        while (current >= 0) {
            stack.push_back(current);
            const std::int32_t child = nodes[std::size_t(current)].back;
            if (child >= 0) {
                t.parent[std::size_t(child)] = current;
                t.depth[std::size_t(child)] = t.depth[std::size_t(current)] + 1;
            }
            current = child;
        }
        const std::int32_t node = stack.back();
        stack.pop_back();
        t.rank[std::size_t(node)] = next_rank++;
        for (const std::uint32_t p : nodes[std::size_t(node)].polygons) t.node_of_polygon[p] = node;
        current = nodes[std::size_t(node)].front;
        if (current >= 0) {
            t.parent[std::size_t(current)] = node;
            t.depth[std::size_t(current)] = t.depth[std::size_t(node)] + 1;
        }
    }
    return t;
}

// The ancestor of `node` at `level` (the node itself when it is shallower).
std::int32_t ancestor_at(const TreeLayout& t, std::int32_t node, std::size_t level) {
    while (t.depth[std::size_t(node)] > level) node = t.parent[std::size_t(node)];
    return node;
}

std::string tree_svg(const BspTree& tree, const TreeLayout& t) {
    const auto& nodes = tree.nodes();
    const double dx = 12.0, dy = 40.0;
    std::size_t depth = 0;
    for (const std::size_t d : t.depth) depth = std::max(depth, d);
    const double width = std::max(300.0, dx * double(nodes.size() + 2));
    const double height = dy * double(depth + 2);
    std::string s = fmt::format(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
        "width=\"{0:.0f}\" height=\"{1:.0f}\" viewBox=\"0 0 {0:.0f} {1:.0f}\">\n"
        "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        "<text x=\"4\" y=\"14\" font-family=\"sans-serif\" font-size=\"12\">BSP tree: {2} "
        "nodes, depth {3}; green: front child, red: back child; the root at the top</text>\n",
        width, height, nodes.size(), depth + 1);
    const auto x = [&](std::size_t n) { return dx * double(t.rank[n] + 1); };
    const auto y = [&](std::size_t n) { return dy * double(t.depth[n] + 1); };
    for (std::size_t n = 0; n < nodes.size(); ++n)
        for (const auto& [child, color] :
             {std::pair{nodes[n].front, "#2a9d3a"}, std::pair{nodes[n].back, "#d03030"}})
            if (child >= 0)
                s += fmt::format(
                    "<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" "
                    "stroke=\"{}\"/>\n",
                    x(n), y(n), x(std::size_t(child)), y(std::size_t(child)), color);
    for (std::size_t n = 0; n < nodes.size(); ++n)
        s += fmt::format(
            "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"4\" fill=\"#4060c0\"><title>node {}: {} "
            "polygon(s) on its plane</title></circle>\n",
            x(n), y(n), n, nodes[n].polygons.size());
    return s + "</svg>\n";
}

// Paints the tree's polygons in back-to-front order, colored by `color_of(polygon index)`.
RgbaImage paint(const BspTree& tree, const std::vector<std::uint32_t>& order, std::size_t count,
                const Camera& camera, const RenderOptions& o, auto color_of) {
    const glm::vec3 bg = o.background * 255.0f;
    RgbaImage image(o.width, o.height,
                    Rgba{std::uint8_t(bg.x), std::uint8_t(bg.y), std::uint8_t(bg.z), 255});
    for (std::size_t i = 0; i < count; ++i) {
        const BspPolygon& p = tree.polygons()[order[i]];
        std::vector<glm::dvec2> points;
        for (const BspVertex& v : p.vertices)
            if (const auto w = project_point(camera, o.width, o.height, v.world))
                points.push_back(*w);
        if (points.size() != p.vertices.size()) continue;  // behind the eye
        fill_polygon(image, points, color_of(order[i]));
        outline_polygon(image, points, Rgba{0, 0, 0, 60});
    }
    return image;
}

}  // namespace

void explain_bsp(const ExplainInput& in, ExplainOutput& out) {
    check_bsp_budget(in.scene, in.options.limits);
    std::vector<BspPolygon> polygons = bsp_polygons_from_scene(in.scene);
    BspOptions options;
    options.max_polygons = bsp_polygon_budget(in.options.limits, polygons.size());
    options.max_classifications = bsp_classification_budget(in.options.limits, polygons.size());
    options.progress = in.options.progress;
    const BspTree tree = BspTree::build(std::move(polygons), options);
    const TreeLayout t = layout(tree);
    const Camera camera = effective_camera(in.scene, in.options);
    const std::vector<std::uint32_t> order = tree.back_to_front(bsp_eye(camera));
    const std::size_t levels = std::min<std::size_t>(tree.stats().depth, 8);
    const std::vector<std::size_t> counts = frame_counts(order.size(), in.step);
    // The levels, the walk's frames and its last frame again.
    check_explain_pixels(
        levels + counts.size() + 1,
        std::uint64_t(in.options.width) * std::uint64_t(in.options.height), in.max_pixels,
        fmt::format("explain bsp's {} pictures", levels + counts.size() + 1), "or raise --step");
    std::vector<RgbaImage> frames;
    for (std::size_t level = 0; level < levels; ++level) {
        in.report("explain bsp: drawing the levels", double(level) / double(levels));
        const RgbaImage image =
            paint(tree, order, order.size(), camera, in.options, [&](std::uint32_t p) {
                const std::int32_t node = t.node_of_polygon[p];
                if (t.depth[std::size_t(node)] < level)
                    return Rgba{40, 40, 40, 255};  // a splitter above
                return palette(std::size_t(ancestor_at(t, node, level)));
            });
        frames.push_back(
            captioned(image, fmt::format("level {}: dark = the splitting polygons of levels 0-{},\n"
                                         "colors = the subtrees (cells of space) at level {}",
                                         level, level == 0 ? 0 : level - 1, level)));
    }
    in.report("explain bsp: encoding the levels", 0.0);
    for (std::size_t i = 0; i < frames.size(); ++i)
        out.still(fmt::format("bsp-level-{:02}", i), frames[i],
                  fmt::format("the partition at tree level {}", i));
    if (!frames.empty()) out.animation("bsp-levels", frames, 900, "the levels in sequence");
    std::vector<std::size_t> rank_of(tree.polygons().size(), 0);
    for (std::size_t i = 0; i < order.size(); ++i) rank_of[order[i]] = i;
    std::vector<RgbaImage> walk;
    for (const std::size_t n : counts) {
        in.report("explain bsp: drawing the walk", double(walk.size()) / double(counts.size()));
        const RgbaImage image = paint(tree, order, n, camera, in.options, [&](std::uint32_t p) {
            const auto far =
                std::uint8_t(255 * rank_of[p] / std::max<std::size_t>(order.size(), 1));
            return Rgba{far, 60, std::uint8_t(255 - far), 255};  // first (far) blue, last red
        });
        walk.push_back(captioned(image, fmt::format("back to front from the eye: {} of {} "
                                                    "polygons painted (blue far, red near)",
                                                    n, order.size())));
    }
    in.report("explain bsp: encoding the pictures", 0.0);
    out.animation("bsp-order", walk, 700, "the back-to-front walk of the tree from the camera");
    out.still("bsp-order-final", walk.back(), "the whole back-to-front order");
    out.svg("bsp-tree", tree_svg(tree, t),
            fmt::format("the tree: {} nodes, depth {}, {} splits", tree.stats().nodes,
                        tree.stats().depth, tree.stats().splits));
}

}  // namespace zraster::cli
