// Binary space partitioning trees for visibility: Fuchs, Kedem & Naylor (1980), "On visible
// surface generation by a priori tree structures" (SIGGRAPH '80).
//
// What: the scene's polygons, in world space, are organized once into a tree whose every node
// holds a plane (that of one of its polygons), the polygons lying in that plane, and two subtrees
// for what lies in front of and behind it; polygons crossing a node's plane are split in two.
// From any viewpoint, the polygons on the viewer's far side of a plane can never hide those on
// its near side, so an in-order walk that visits the far subtree, the node, then the near subtree
// lists the polygons back to front: a painter's order with no per-frame sorting or overlap tests.
//
// Splitter choice (the build's only heuristic): at each node, k candidates spread over the node's
// polygons are scored by splits + balance_weight * |front - back| against all of them, and the
// lowest wins (Fuchs et al. suggest trying a few candidates; Naylor's later work refines the
// score). Splits make the tree bigger (each adds a polygon); balance keeps it shallow.
//
// Cost: building is O(k * n * depth) classifications plus the splits (O(n log n)-ish for typical
// scenes, O(n^2) worst case: 500 random triangles split into 440,000 pieces, so the pool has a
// budget, BspOptions::max_polygons / RenderLimits::max_bsp_polygons); every frame is then O(n) for
// the walk, plus filling every polygon (no early rejection of hidden surfaces: overdraw is total).
// Memory O(n + splits).
//
// When to use: static geometry seen from many viewpoints (the walk is viewpoint-independent to
// build: Doom's and Quake's levels), transparency sorting, or as a spatial index for ray casting
// and collision. For dynamic scenes the rebuild cost is prohibitive.
//
// Both the build and the walk use explicit stacks, so a degenerate tree (a chain of n nodes)
// costs memory, never the call stack; BspOptions::max_depth turns runaway depth into an error.
#include <zraster/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "platform/memory_size.hpp"
#include "visibility/frame_context.hpp"

namespace zraster {
namespace {

enum class Side { Coplanar, Front, Back, Spanning };

Side classify(const BspPolygon& polygon, const glm::dvec4& plane, double eps) {
    bool front = false, back = false;
    for (const BspVertex& v : polygon.vertices) {
        const double d = visibility_detail::plane_distance(plane, v.world);
        front |= d > eps;
        back |= d < -eps;
    }
    if (front && back) return Side::Spanning;
    if (front) return Side::Front;
    if (back) return Side::Back;
    return Side::Coplanar;
}

// Splits a spanning polygon. New vertices are interpolated from the front vertex towards the back
// one (world, object space and weights with the same t), so neighbors sharing an edge get the
// same new vertex.
void split(const BspPolygon& polygon, const glm::dvec4& plane, double eps, BspPolygon& front,
           BspPolygon& back) {
    front.plane = back.plane = polygon.plane;
    front.instance = back.instance = polygon.instance;
    front.primitive = back.primitive = polygon.primitive;
    visibility_detail::split_by_plane(
        polygon.vertices, plane, eps, front.vertices, back.vertices,
        [](const BspVertex& f, const BspVertex& b, double t, BspVertex& c) {
            c.world = f.world + t * (b.world - f.world);
            const glm::dvec3 of(f.object), ob(b.object);
            c.object = glm::vec3(of + t * (ob - of));
            const glm::dvec3 wf(f.weights), wb(b.weights);
            c.weights = glm::vec3(wf + t * (wb - wf));
            return true;
        });
}

}  // namespace

glm::dvec4 bsp_eye(const Camera& camera) {
    if (camera.is_orthographic()) return {-camera.view_direction(), 0.0};
    return {camera.position(), 1.0};
}

BspTree BspTree::build(std::vector<BspPolygon> polygons, const BspOptions& options) {
    BspTree tree;
    tree.stats_.input_polygons = polygons.size();
    const std::uint64_t max_polygons = options.max_polygons
                                           ? options.max_polygons
                                           : bsp_polygon_budget(RenderLimits{}, polygons.size());
    if (polygons.size() > max_polygons)
        throw LimitExceeded("", "max_bsp_polygons",
                            "BSP tree: " + std::to_string(polygons.size()) +
                                " input polygons, more than the budget of " +
                                std::to_string(max_polygons));
    tree.polygons_ = std::move(polygons);
    if (tree.polygons_.empty()) return tree;
    const std::uint64_t max_classifications =
        options.max_classifications
            ? options.max_classifications
            : bsp_classification_budget(RenderLimits{}, tree.polygons_.size());
    // Every classification is counted: a convex mesh (each plane has every other polygon behind
    // it) builds a chain of n nodes, n^2 classifications (a 100,000-triangle sphere ran for
    // minutes before the depth limit stopped it).
    auto classified = [&] {
        if (++tree.stats_.classifications > max_classifications)
            throw LimitExceeded(
                "", "max_bsp_classifications",
                "BSP tree: more than " + std::to_string(max_classifications) +
                    " polygon-plane classifications for " +
                    std::to_string(tree.stats_.input_polygons) +
                    " input polygons (the budget; depth " + std::to_string(tree.stats_.depth) +
                    " so far): the input's planes divide it badly for a BSP tree (a convex "
                    "shape makes a chain)");
    };
    std::size_t placed = 0;  // polygons stored in nodes so far (progress)
    std::uint64_t next_report = 0;
    double reported = 0.0;

    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (const BspPolygon& p : tree.polygons_)
        for (const BspVertex& v : p.vertices) {
            lo = glm::min(lo, v.world);
            hi = glm::max(hi, v.world);
        }
    const double extent = glm::length(hi - lo);
    const double eps = options.plane_epsilon * (std::isfinite(extent) ? extent : 0.0);
    const int k_max = std::max(1, options.candidates);

    struct Task {
        std::vector<std::uint32_t> polygons;
        std::int32_t node;
        std::size_t depth;
    };
    std::vector<Task> tasks;
    {
        Task root{{}, 0, 1};
        root.polygons.resize(tree.polygons_.size());
        for (std::uint32_t i = 0; i < root.polygons.size(); ++i) root.polygons[i] = i;
        tree.nodes_.emplace_back();
        tasks.push_back(std::move(root));
    }
    std::vector<Side> sides;
    while (!tasks.empty()) {
        Task task = std::move(tasks.back());
        tasks.pop_back();
        if (task.depth > options.max_depth)
            throw InputError(
                "", "BSP tree deeper than max_depth = " + std::to_string(options.max_depth) + " (" +
                        std::to_string(task.polygons.size()) +
                        " polygons left at that depth); raise BspOptions::max_depth");
        tree.stats_.depth = std::max(tree.stats_.depth, task.depth);
        const std::vector<std::uint32_t>& set = task.polygons;
        const std::size_t m = set.size();

        // Choose the splitter. Scoring against every polygon of the node is what makes the choice
        // informed; a candidate is abandoned as soon as its splits alone exceed the best score.
        std::uint32_t splitter = set[0];
        const std::size_t k = std::min<std::size_t>(std::size_t(k_max), m);
        if (k > 1) {
            double best = std::numeric_limits<double>::infinity();
            for (std::size_t c = 0; c < k; ++c) {
                const std::uint32_t candidate = set[c * m / k];
                const glm::dvec4& plane = tree.polygons_[candidate].plane;
                std::size_t front = 0, back = 0, spanning = 0;
                bool abandoned = false;
                for (const std::uint32_t i : set) {
                    classified();
                    switch (classify(tree.polygons_[i], plane, eps)) {
                        case Side::Front:
                            ++front;
                            break;
                        case Side::Back:
                            ++back;
                            break;
                        case Side::Spanning:
                            ++spanning;
                            break;
                        case Side::Coplanar:
                            break;
                    }
                    if (double(spanning) >= best) {
                        abandoned = true;
                        break;
                    }
                }
                if (abandoned) continue;
                const double score = double(spanning) + options.balance_weight *
                                                            std::abs(double(front) - double(back));
                if (score < best) {
                    best = score;
                    splitter = candidate;
                }
            }
        }

        const glm::dvec4 plane = tree.polygons_[splitter].plane;
        std::vector<std::uint32_t> front_set, back_set, here;
        for (const std::uint32_t i : set) {
            classified();
            switch (classify(tree.polygons_[i], plane, eps)) {
                case Side::Coplanar:
                    here.push_back(i);
                    break;
                case Side::Front:
                    front_set.push_back(i);
                    break;
                case Side::Back:
                    back_set.push_back(i);
                    break;
                case Side::Spanning: {
                    if (tree.polygons_.size() + 2 > max_polygons)
                        throw LimitExceeded(
                            "", "max_bsp_polygons",
                            "BSP tree: more than " + std::to_string(max_polygons) +
                                " polygons after " + std::to_string(tree.stats_.splits) +
                                " splits of " + std::to_string(tree.stats_.input_polygons) +
                                " input polygons (the budget): the input has too many "
                                "intersecting polygons for a BSP tree");
                    BspPolygon f, b;
                    split(tree.polygons_[i], plane, eps, f, b);
                    ++tree.stats_.splits;
                    // The original stays in the pool, unreferenced (indices must not move).
                    front_set.push_back(static_cast<std::uint32_t>(tree.polygons_.size()));
                    tree.polygons_.push_back(std::move(f));
                    back_set.push_back(static_cast<std::uint32_t>(tree.polygons_.size()));
                    tree.polygons_.push_back(std::move(b));
                    break;
                }
            }
        }
        placed += here.size();
        if (options.progress != nullptr && tree.stats_.classifications >= next_report) {
            next_report = tree.stats_.classifications + (1 << 16);
            // Of the live polygons (a split retires one and adds two).
            const std::size_t live = tree.polygons_.size() - tree.stats_.splits;
            // Or the classification budget used, where that is further.
            const double used = double(tree.stats_.classifications) / double(max_classifications);
            reported = std::max({reported, double(placed) / double(live), std::min(used, 1.0)});
            options.progress->report("BSP tree", reported);
        }
        Node& node = tree.nodes_[static_cast<std::size_t>(task.node)];
        node.plane = plane;
        node.polygons = std::move(here);
        for (int child = 0; child < 2; ++child) {
            std::vector<std::uint32_t>& subset = child == 0 ? front_set : back_set;
            if (subset.empty()) continue;
            const auto index = static_cast<std::int32_t>(tree.nodes_.size());
            (child == 0 ? tree.nodes_[static_cast<std::size_t>(task.node)].front
                        : tree.nodes_[static_cast<std::size_t>(task.node)].back) = index;
            tree.nodes_.emplace_back();
            tasks.push_back({std::move(subset), index, task.depth + 1});
        }
    }
    tree.stats_.nodes = tree.nodes_.size();
    std::size_t stored = 0;
    for (const Node& node : tree.nodes_) stored += node.polygons.size();
    tree.stats_.polygons = stored;
    return tree;
}

std::vector<std::uint32_t> BspTree::back_to_front(const glm::dvec4& eye) const {
    std::vector<std::uint32_t> order;
    if (nodes_.empty()) return order;
    order.reserve(stats_.polygons);
    // (node, expanded): an expanded node emits its own polygons; otherwise it is replaced by
    // near subtree, itself expanded, far subtree, pushed so that the far one pops first.
    std::vector<std::pair<std::int32_t, bool>> stack{{0, false}};
    while (!stack.empty()) {
        const auto [index, expanded] = stack.back();
        stack.pop_back();
        const Node& node = nodes_[static_cast<std::size_t>(index)];
        if (expanded) {
            // Coplanar polygons cannot hide each other except where they coincide; there the
            // z-buffer's LESS test keeps the first one drawn, so draw the first one last.
            order.insert(order.end(), node.polygons.rbegin(), node.polygons.rend());
            continue;
        }
        const double side =
            glm::dot(glm::dvec3(node.plane), glm::dvec3(eye)) + node.plane.w * eye.w;
        const std::int32_t near = side >= 0.0 ? node.front : node.back;
        const std::int32_t far = side >= 0.0 ? node.back : node.front;
        if (near >= 0) stack.emplace_back(near, false);
        stack.emplace_back(index, true);
        if (far >= 0) stack.emplace_back(far, false);
    }
    return order;
}

void check_bsp_budget(const Scene& scene, const RenderLimits& limits) {
    // A budget raised past what the machine holds would end, after minutes of splitting, in an
    // allocation the system refuses: refused now, naming what to lower. (At its peak the tree
    // takes about 400 bytes a polygon: 1.18 GB for 3,000,000 pieces of a random soup.)
    constexpr std::uint64_t kPeakBytesPerPolygon = 400;
    const std::uint64_t usable = platform::usable_memory_bytes() / kPeakBytesPerPolygon;
    if (limits.max_bsp_polygons > usable)
        throw InputError(scene.name,
                         "BSP tree: the budget of " + std::to_string(limits.max_bsp_polygons) +
                             " polygons (max_bsp_polygons) is more than the memory this process "
                             "may use holds at about " +
                             std::to_string(kPeakBytesPerPolygon) +
                             " bytes each: lower --max-bsp-polygons to at most " +
                             std::to_string(usable) + " (0: automatic)");
    const std::uint64_t triangles = scene.triangle_count();
    const std::uint64_t budget = bsp_polygon_budget(limits, triangles);
    if (triangles > budget)
        throw LimitExceeded(scene.name, "max_bsp_polygons",
                            "BSP tree: " + std::to_string(triangles) +
                                " input triangles, more than the budget of " +
                                std::to_string(budget) + " polygons");
}

std::vector<BspPolygon> bsp_polygons_from_scene(const Scene& scene) {
    std::vector<BspPolygon> out;
    out.reserve(scene.triangle_count());
    visibility_detail::for_each_scene_triangle(
        scene, [&](std::size_t i, const Instance& instance, const Mesh& mesh, std::size_t t,
                   const std::array<std::uint32_t, 3>& index) {
            const glm::dmat4 model(instance.transform);
            BspPolygon polygon;
            polygon.instance = static_cast<std::int32_t>(i);
            polygon.primitive = static_cast<std::int32_t>(t);
            for (std::size_t k = 0; k < 3; ++k) {
                BspVertex v;
                v.object = mesh.positions[index[k]];
                v.weights[static_cast<glm::length_t>(k)] = 1.0f;
                v.world = glm::dvec3(model * glm::dvec4(glm::dvec3(v.object), 1.0));
                if (!std::isfinite(v.world.x + v.world.y + v.world.z)) return;
                polygon.vertices.push_back(v);
            }
            polygon.plane = visibility_detail::plane_through(
                polygon.vertices[0].world, polygon.vertices[1].world, polygon.vertices[2].world);
            if (polygon.plane == glm::dvec4(0.0)) return;  // degenerate: covers nothing
            out.push_back(std::move(polygon));
        });
    return out;
}

}  // namespace zraster
