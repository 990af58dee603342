// libFuzzer target: `*.cells.json` files (docs/portals.md) through load_scene, and PVS files
// through load_pvs against the graph of a scene that loaded. The bytes up to the first NUL are
// written as input.cells.json; what follows the NUL, if anything, as input.pvs.json (JSON text
// holds no raw NUL, so neither part can contain the separator). Beside them: a.obj (a unit
// cube), b.ply (a unit square facing up), other.cells.json (a valid cells file, which a cells
// file may not place) and the fixtures of fuzz_support.hpp.
//
// Oracles besides the sanitizers:
//  - a refused file is one line naming the cells file (or the mesh file it names, when that
//    file is the one refused), and a refused PVS file names the PVS file;
//  - a scene that loads keeps load.hpp's promises, its cell graph passes validate_cell_graph
//    again with the same derived tables, and a PVS that loads has one sorted set per cell, in
//    range, each holding its own cell;
//  - rendered at 24x16 from the middle of the first cells, portal culling (both variants, with
//    and without the PVS compute_pvs makes) only ever removes whole instances, and a pixel whose
//    instance or primitive id differs from the unculled frame's is explained by the graph
//    breaking the contract culling relies on (the ray from the eye to the unculled frame's
//    visible point leaves a cell other than through a portal), which a fuzzed graph may do; a
//    ray that reaches its point from cell to cell through portals must find the same ids.
#include <zraster/portals.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "fuzz_support.hpp"

namespace zraster::fuzz {
namespace {

const std::filesystem::path& cells_dir() {
    static const std::filesystem::path dir = [] {
        const std::filesystem::path d = work_dir();
        write_file(d / "a.obj",
                   "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                   "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 3 4 8 7\nf 2 3 7 6\nf 1 5 8 4\n");
        write_file(d / "b.ply",
                   "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float "
                   "y\nproperty float z\nelement face 1\nproperty list uchar int "
                   "vertex_indices\nend_header\n0 0 0\n0 0 1\n1 0 1\n1 0 0\n4 0 1 2 3\n");
        write_file(d / "other.cells.json",
                   R"({"zraster_cells": 1, "meshes": {"a": "a.obj"},
 "instances": [{"name": "a", "mesh": "a"}],
 "cells": [{"name": "c", "box": [[0, 0, 0], [1, 1, 1]], "instances": ["a"]}]})");
        return d;
    }();
    return dir;
}

std::vector<Bounds3f> instance_boxes(const Scene& scene) {
    std::vector<Bounds3f> boxes;
    for (const Instance& instance : scene.instances)
        boxes.push_back(scene.meshes[instance.mesh].bounds.transformed(instance.transform));
    return boxes;
}

// What validate_cell_graph promises about a graph it accepted, and that it accepts it again.
void check_cell_graph(const Scene& scene) {
    if (!scene.cells) fail("a cells file gave a scene without a cell graph");
    const CellGraph& graph = *scene.cells;
    if (graph.cells.empty()) fail("a validated graph without cells");
    if (graph.cell_portals.size() != graph.cells.size()) fail("cell_portals not one per cell");
    if (graph.instance_cells.size() != scene.instances.size())
        fail("instance_cells not one per instance");
    for (const Cell& cell : graph.cells)
        for (std::uint32_t i : cell.instances)
            if (i >= scene.instances.size())
                fail("cell '" + cell.name + "' names a missing instance");
    for (const Portal& portal : graph.portals) {
        if (portal.cells[0] >= graph.cells.size() || portal.cells[1] >= graph.cells.size() ||
            portal.cells[0] == portal.cells[1])
            fail("a portal joining missing cells or a cell to itself");
        if (portal.corners.size() < 3) fail("a portal of fewer than 3 corners");
        for (const glm::dvec3& c : portal.corners)
            if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z))
                fail("a portal corner not finite");
    }
    for (const auto& cells : graph.instance_cells)
        if (cells.empty()) fail("an instance in no cell passed validation");
    CellGraph again = graph;
    again.cell_portals.clear();
    again.instance_cells.clear();
    std::vector<std::string> names;
    for (const Instance& instance : scene.instances) names.push_back(instance.name);
    try {
        validate_cell_graph(again, instance_boxes(scene), names, scene.name);
    } catch (const InputError& e) {
        fail(std::string("a loaded graph fails validation again: ") + e.what());
    }
    if (again.cell_portals != graph.cell_portals || again.instance_cells != graph.instance_cells)
        fail("validating a loaded graph again derives other tables");
}

void check_pvs_sets(const std::vector<std::vector<std::uint32_t>>& sets, std::size_t cells) {
    if (sets.size() != cells) fail("PVS not one set per cell");
    for (std::size_t c = 0; c < sets.size(); ++c) {
        if (!std::is_sorted(sets[c].begin(), sets[c].end()) ||
            std::adjacent_find(sets[c].begin(), sets[c].end()) != sets[c].end())
            fail("PVS set not sorted and unique");
        if (!sets[c].empty() && sets[c].back() >= cells) fail("PVS index out of range");
        if (!std::binary_search(sets[c].begin(), sets[c].end(), std::uint32_t(c)))
            fail("PVS set without its own cell");
    }
}

// --- The exactness oracle: why a pixel may differ between culled and unculled frames ---

double graph_extent(const CellGraph& graph) {
    double extent = 1.0;
    for (const Cell& cell : graph.cells)
        for (const glm::dvec3& c : cell.volume.corners)
            extent = std::max({extent, std::abs(c.x), std::abs(c.y), std::abs(c.z)});
    return extent;
}

bool in_cell(const Cell& cell, const glm::dvec3& p, double tolerance) {
    for (const glm::dvec4& plane : cell.volume.planes)
        if (glm::dot(glm::dvec3(plane), p) + plane.w < -tolerance * glm::length(glm::dvec3(plane)))
            return false;
    return true;
}

enum class Inside { Yes, No, Unsure };

// Whether x (on or near the portal's plane) lies inside the convex portal polygon, with a band
// of `band` around its edges counted as unsure.
Inside in_portal(const Portal& portal, const glm::dvec3& x, double band) {
    const auto& c = portal.corners;
    glm::dvec3 normal(0.0);
    for (std::size_t i = 0; i < c.size(); ++i)
        normal += glm::cross(c[i] - c[0], c[(i + 1) % c.size()] - c[0]);
    const double length = glm::length(normal);
    if (!(length > 0.0)) return Inside::Unsure;
    normal /= length;
    const double off_plane = std::abs(glm::dot(x - c[0], normal));
    if (off_plane > band) return Inside::No;
    double nearest = 1e300;
    bool outside = false;
    for (std::size_t i = 0; i < c.size(); ++i) {
        const glm::dvec3 edge = c[(i + 1) % c.size()] - c[i];
        const double edge_length = glm::length(edge);
        if (!(edge_length > 0.0)) continue;
        const glm::dvec3 inward = glm::normalize(glm::cross(normal, edge));
        const double d = glm::dot(x - c[i], inward);
        nearest = std::min(nearest, std::abs(d));
        if (d < 0.0) outside = true;
    }
    if (nearest <= band) return Inside::Unsure;
    return outside ? Inside::No : Inside::Yes;
}

// Follows the segment from the eye to `point` (on instance `instance`) through the cells: true
// when it goes from cell to cell only through portals, clear of every edge and boundary by a
// band, and ends in a cell that lists the instance. Then culling the instance was a mistake.
bool reached_through_portals(const CellGraph& graph, const glm::dvec3& eye, const glm::dvec3& point,
                             std::uint32_t instance) {
    const double band = 1e-4 * graph_extent(graph);
    const std::int64_t first = find_cell(graph, eye);
    if (first < 0) return false;
    auto cell = std::uint32_t(first);
    const glm::dvec3 segment = point - eye;
    const double length = glm::length(segment);
    if (!(length > band)) return false;
    for (std::size_t step = 0; step <= graph.cells.size() + 1; ++step) {
        // Where the segment leaves the convex cell (planes' normals point inward).
        double exit = 1.0;
        for (const glm::dvec4& plane : graph.cells[cell].volume.planes) {
            const double scale = glm::length(glm::dvec3(plane));
            const double f0 = (glm::dot(glm::dvec3(plane), eye) + plane.w) / scale;
            const double f1 = (glm::dot(glm::dvec3(plane), point) + plane.w) / scale;
            if (f1 < f0 && f1 < 0.0) exit = std::min(exit, std::max(0.0, f0 / (f0 - f1)));
        }
        if (exit == 1.0) {  // the point lies in this cell: it must list the instance
            const auto& held = graph.cells[cell].instances;
            return std::find(held.begin(), held.end(), instance) != held.end();
        }
        if ((1.0 - exit) * length <= band) return false;  // it leaves right at the point
        const glm::dvec3 x = eye + exit * segment;
        std::optional<std::uint32_t> through;
        for (std::uint32_t p : graph.cell_portals[cell]) {
            const Inside inside = in_portal(graph.portals[p], x, band);
            if (inside == Inside::Unsure) return false;
            if (inside == Inside::Yes) through = p;
        }
        if (!through) return false;  // it leaves through a wall the graph says is opaque
        const Portal& portal = graph.portals[*through];
        const std::uint32_t next = portal.cells[0] == cell ? portal.cells[1] : portal.cells[0];
        if (!in_cell(graph.cells[next], x, band)) return false;
        cell = next;
    }
    return false;
}

struct Frame {
    std::vector<std::int32_t> instance_id, primitive_id;
    RenderStats stats;
};

// The triangle's world-space plane hit by the ray through the pixel's center.
std::optional<glm::dvec3> visible_point(const Scene& scene, const Camera& camera, int width,
                                        int height, int x, int y, std::int32_t instance,
                                        std::int32_t primitive) {
    const glm::dmat4 inverse =
        glm::inverse(glm::dmat4(camera.view_projection(double(width) / double(height))));
    const double nx = 2.0 * (x + 0.5) / width - 1.0, ny = 1.0 - 2.0 * (y + 0.5) / height;
    const glm::dvec4 a = inverse * glm::dvec4(nx, ny, 0.0, 1.0);
    const glm::dvec4 b = inverse * glm::dvec4(nx, ny, 0.5, 1.0);
    const glm::dvec3 eye = camera.position();
    const glm::dvec3 direction = glm::dvec3(b) / b.w - glm::dvec3(a) / a.w;
    const Instance& placed = scene.instances[std::size_t(instance)];
    const Mesh& mesh = scene.meshes[placed.mesh];
    glm::dvec3 corner[3];
    for (int k = 0; k < 3; ++k)
        corner[k] = glm::dvec3(
            glm::dmat4(placed.transform) *
            glm::dvec4(mesh.positions[mesh.indices[3 * std::size_t(primitive) + std::size_t(k)]],
                       1.0));
    const glm::dvec3 normal = glm::cross(corner[1] - corner[0], corner[2] - corner[0]);
    const double facing = glm::dot(normal, direction);
    if (!(std::abs(facing) > 0.0)) return std::nullopt;
    const double t = glm::dot(normal, corner[0] - eye) / facing;
    if (!(t > 0.0) || !std::isfinite(t)) return std::nullopt;
    return eye + t * direction;
}

// Instance-level culling only removes: a pixel that differs shows, in the unculled frame, an
// instance the culled frame drew nowhere, and (unless the graph's contract is broken along the
// pixel's ray) not even there.
void check_culled_frame(const Scene& scene, const CellGraph& graph, const Camera& camera,
                        const Frame& plain, const Frame& culled, const std::string& what,
                        bool exact) {
    const int width = 24, height = 16;
    std::vector<std::uint8_t> drawn(scene.instances.size(), 0);
    for (std::int32_t id : culled.instance_id)
        if (id >= 0) drawn[std::size_t(id)] = 1;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t i = std::size_t(y) * width + std::size_t(x);
            if (plain.instance_id[i] == culled.instance_id[i] &&
                plain.primitive_id[i] == culled.primitive_id[i])
                continue;
            const std::string at = what + ", pixel (" + std::to_string(x) + ", " +
                                   std::to_string(y) + "): unculled instance " +
                                   std::to_string(plain.instance_id[i]) + " primitive " +
                                   std::to_string(plain.primitive_id[i]) + ", culled instance " +
                                   std::to_string(culled.instance_id[i]) + " primitive " +
                                   std::to_string(culled.primitive_id[i]);
            if (plain.instance_id[i] < 0) fail(at + " (culling added a surface)");
            if (drawn[std::size_t(plain.instance_id[i])])
                fail(at +
                     " (the unculled instance is drawn elsewhere: culling is not per instance)");
            if (culled.stats.portal_outcome != PortalOutcome::Culled)
                fail(at + " (the walk did not cull, outcome " +
                     std::to_string(int(culled.stats.portal_outcome)) + ")");
            if (!exact) continue;
            const std::optional<glm::dvec3> point = visible_point(
                scene, camera, width, height, x, y, plain.instance_id[i], plain.primitive_id[i]);
            if (point && reached_through_portals(graph, camera.position(), *point,
                                                 std::uint32_t(plain.instance_id[i])))
                fail(at + " (the pixel's ray reaches it through portals)");
        }
}

std::optional<Frame> draw(const Scene& scene, const Camera& camera, PortalCull mode) {
    RenderOptions options;
    options.width = 24;
    options.height = 16;
    options.threads = 1;
    options.camera = camera;
    options.id_targets = true;
    options.portal_cull = mode;
    try {
        RenderResult result = render(scene, options);
        return Frame{std::move(result.targets.instance_id), std::move(result.targets.primitive_id),
                     result.stats};
    } catch (const InputError&) {
        return std::nullopt;
    }
}

// A camera in the middle of `cell` (a convex volume holds the mean of its corners), looking at
// the middle of its first portal, or along a fixed slanted direction.
std::optional<Camera> camera_in(const CellGraph& graph, std::uint32_t c) {
    const Cell& cell = graph.cells[c];
    glm::dvec3 eye(0.0);
    for (const glm::dvec3& corner : cell.volume.corners) eye += corner;
    eye /= double(cell.volume.corners.size());
    glm::dvec3 direction(1.0, -0.2, 0.3);
    if (!graph.cell_portals[c].empty()) {
        glm::dvec3 middle(0.0);
        const Portal& portal = graph.portals[graph.cell_portals[c].front()];
        for (const glm::dvec3& corner : portal.corners) middle += corner;
        middle /= double(portal.corners.size());
        if (glm::length(middle - eye) > 1e-9 * graph_extent(graph)) direction = middle - eye;
    }
    direction = glm::normalize(direction);
    const double size = glm::length(cell.volume.hi - cell.volume.lo);
    const double extent = graph_extent(graph);
    if (!std::isfinite(eye.x + eye.y + eye.z) || !(size > 0.0) || extent > 1e6) return std::nullopt;
    Camera camera;
    camera.eye = eye;
    camera.target = eye + direction;
    camera.up = std::abs(direction.y) > 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
    camera.fovy_degrees = 90.0;
    camera.near = 1e-3 * size;
    camera.far = 8.0 * extent + 8.0;
    return camera;
}

void check_portal_culling(const Scene& scene) {
    const CellGraph& graph = *scene.cells;
    Scene plain_scene = scene;
    plain_scene.cells = nullptr;
    // The sets compute_pvs makes (bounded for speed: a bounded set is every connected cell;
    // past 256 cells the search would dominate the run, and the walk is checked without them).
    auto with_pvs = std::make_shared<CellGraph>(graph);
    if (graph.cells.size() <= 256) {
        PvsOptions pvs_options;
        pvs_options.max_steps_per_cell = 2000;
        with_pvs->pvs = compute_pvs(graph, pvs_options).visible;
        check_pvs_sets(with_pvs->pvs, graph.cells.size());
    }
    Scene pvs_scene = scene;
    pvs_scene.cells = with_pvs;
    const std::uint32_t cameras = std::min<std::uint32_t>(2, std::uint32_t(graph.cells.size()));
    for (std::uint32_t c = 0; c < cameras; ++c) {
        const std::optional<Camera> camera = camera_in(graph, c);
        if (!camera) continue;
        const std::optional<Frame> plain = draw(plain_scene, *camera, PortalCull::Off);
        if (!plain) continue;  // a camera the renderer refuses for this scene
        const std::string where = " from cell " + std::to_string(c);
        const struct {
            const Scene* scene;
            PortalCull mode;
            const char* name;
        } variants[] = {{&scene, PortalCull::Frustum, "exact portals"},
                        {&scene, PortalCull::Rectangles, "cull rectangles"},
                        {&pvs_scene, PortalCull::Off, "computed PVS"},
                        {&pvs_scene, PortalCull::Frustum, "computed PVS + exact portals"}};
        for (const auto& variant : variants) {
            const std::optional<Frame> culled = draw(*variant.scene, *camera, variant.mode);
            if (!culled) fail(std::string(variant.name) + " refused a frame drawn without it");
            check_culled_frame(scene, graph, *camera, *plain, *culled, variant.name + where, true);
        }
    }
}

// A PVS file for the loaded scene: its promises; then, attached, it may cull anything (a file's
// sets are trusted), but only whole instances.
void fuzz_pvs(const Scene& scene, std::string_view bytes) {
    const std::filesystem::path path = cells_dir() / "input.pvs.json";
    write_file(path, bytes);
    std::vector<std::vector<std::uint32_t>> sets;
    try {
        sets = load_pvs(path, *scene.cells);
    } catch (const InputError& e) {
        check_input_error(e, path.string());
        return;
    }
    check_pvs_sets(sets, scene.cells->cells.size());
    auto graph = std::make_shared<CellGraph>(*scene.cells);
    graph->pvs = std::move(sets);
    Scene with = scene;
    with.cells = graph;
    Scene plain_scene = scene;
    plain_scene.cells = nullptr;
    const std::optional<Camera> camera = camera_in(*graph, 0);
    if (!camera) return;
    const std::optional<Frame> plain = draw(plain_scene, *camera, PortalCull::Off);
    if (!plain) return;
    const std::optional<Frame> culled = draw(with, *camera, PortalCull::Frustum);
    if (!culled) fail("a PVS file's sets refused a frame drawn without them");
    check_culled_frame(scene, *graph, *camera, *plain, *culled, "PVS file", false);
}

}  // namespace
}  // namespace zraster::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace zraster;
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    const std::size_t separator = bytes.find('\0');
    const std::filesystem::path& dir = fuzz::cells_dir();
    const std::filesystem::path path = dir / "input.cells.json";
    fuzz::write_file(path, bytes.substr(0, separator));
    const LoadOptions options = fuzz::fuzz_load_options();
    Scene scene;
    std::vector<std::string> warnings;
    try {
        scene = load_scene(path, options, &warnings);
    } catch (const InputError& e) {
        // A mesh file the cells file names may be the one refused (its own message).
        const std::filesystem::path named(e.file());
        if (named.parent_path() == dir && named.filename() != "input.cells.json")
            fuzz::check_input_error(e, e.file());
        else
            fuzz::check_input_error(e, path.string());
        return 0;
    }
    fuzz::check_loaded_scene(scene, warnings);
    fuzz::check_cell_graph(scene);
    fuzz::check_renders(scene, "a loaded cells file");
    fuzz::check_portal_culling(scene);
    if (separator != std::string_view::npos) fuzz::fuzz_pvs(scene, bytes.substr(separator + 1));
    return 0;
}
