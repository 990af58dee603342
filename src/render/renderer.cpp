// The Renderer: joins the stages for one frame (see include/zraster/render.hpp).
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include <zraster/error.hpp>

#include "render/frame.hpp"

namespace zraster {

CompareFunc effective_depth_compare(const RenderOptions& options) {
    if (options.depth_compare) return *options.depth_compare;
    const bool reversed = options.camera && options.camera->reversed_z;
    return reversed ? CompareFunc::Greater : CompareFunc::Less;
}

float depth_clear_value(const RenderOptions& options) {
    const bool reversed = options.camera && options.camera->reversed_z;
    return reversed ? 0.0f : 1.0f;
}

namespace {

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The largest index, as a branch-free max the compiler vectorizes, in parallel for big meshes:
// this check runs every frame, over every index.
std::uint32_t largest_index(std::span<const std::uint32_t> indices) {
    const auto serial = [&](std::size_t begin, std::size_t end) {
        std::uint32_t largest = 0;
        for (std::size_t i = begin; i < end; ++i)
            largest = indices[i] > largest ? indices[i] : largest;
        return largest;
    };
    if (indices.size() < (std::size_t{1} << 18)) return serial(0, indices.size());
    return tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, indices.size(), std::size_t{1} << 16), std::uint32_t{0},
        [&](const tbb::blocked_range<std::size_t>& r, std::uint32_t largest) {
            return std::max(largest, serial(r.begin(), r.end()));
        },
        [](std::uint32_t a, std::uint32_t b) { return std::max(a, b); });
}

// Throws for the first of the scene's meshes (in mesh order) with a vertex index out of range;
// `check[m]` says which meshes to scan.
void refuse_bad_indices(const Scene& scene, const std::vector<bool>& check) {
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        if (!check[m]) continue;
        const Mesh& mesh = scene.meshes[m];
        const std::size_t used = mesh.triangle_count() * 3;  // a partial last triple is ignored
        const std::uint32_t largest = largest_index(std::span(mesh.indices.data(), used));
        if (used > 0 && largest >= mesh.positions.size())
            throw InputError(scene.source,
                             "mesh " + std::to_string(m) + " '" + mesh.name + "': vertex index " +
                                 std::to_string(largest) + " out of range (" +
                                 std::to_string(mesh.positions.size()) + " positions)");
    }
}

// Vertex indices out of range make the scene invalid. Scanning every index each frame costs as
// much as a tenth of a million-triangle frame, so the front end checks the indices of the
// triangles it assembles (it loads them anyway) and this scans only what it did not see: meshes
// whose instances were all culled. On a find, every used mesh is scanned, so the message names
// the same mesh whichever instances the camera sees.
void check_indices(const detail::Frame& frame) {
    const Scene& scene = *frame.scene;
    std::vector<bool> drawn(scene.meshes.size(), false), culled_only(scene.meshes.size(), false);
    for (const detail::FrameInstance& fi : frame.instances)
        drawn[scene.instances[fi.scene_instance].mesh] = true;
    bool bad = false;
    for (const detail::Chunk& c : frame.chunks) bad |= c.bad_index_instance != c.kNoBadIndex;
    for (const Instance& instance : scene.instances)
        culled_only[instance.mesh] = !drawn[instance.mesh];
    if (!bad) {
        refuse_bad_indices(scene, culled_only);
        return;
    }
    std::vector<bool> used(scene.meshes.size(), false);
    for (const Instance& instance : scene.instances) used[instance.mesh] = true;
    refuse_bad_indices(scene, used);
}

// Options and scene are checked before anything is allocated: a frame that would need absurd
// memory, or a scene whose arrays disagree (read out of bounds later), is an InputError here.
void validate(const Scene& scene, const RenderOptions& options) {
    if (options.width < 1 || options.height < 1 || options.width > kMaxViewport ||
        options.height > kMaxViewport)
        throw InputError("", "image size " + std::to_string(options.width) + "x" +
                                 std::to_string(options.height) + " out of range (1.." +
                                 std::to_string(kMaxViewport) + " per side)");
    const RenderLimits& limits = options.limits;
    const std::uint64_t pixels = std::uint64_t(options.width) * std::uint64_t(options.height);
    if (pixels > limits.max_pixels)
        throw InputError("", "image size " + std::to_string(options.width) + "x" +
                                 std::to_string(options.height) + " is " + std::to_string(pixels) +
                                 " pixels, more than the limit of " +
                                 std::to_string(limits.max_pixels));
    // Frame vertex indices are 32-bit with the top bit marking clipper-made vertices.
    constexpr std::uint64_t kMaxFrameVertices = (std::uint64_t{1} << 31) - 1;
    const std::string& source = scene.source;
    if (scene.materials.empty()) throw InputError(source, "the scene has no materials");
    std::uint64_t triangles = 0, vertices = 0;
    std::vector<bool> mesh_used(scene.meshes.size(), false);
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const std::uint32_t m = scene.instances[i].mesh;
        if (m >= scene.meshes.size())
            throw InputError(source, "instance " + std::to_string(i) + " refers to mesh " +
                                         std::to_string(m) + " of " +
                                         std::to_string(scene.meshes.size()));
        triangles += scene.meshes[m].triangle_count();
        vertices += scene.meshes[m].positions.size();
        mesh_used[m] = true;
    }
    if (triangles > limits.max_triangles)
        throw InputError(source, std::to_string(triangles) +
                                     " triangles over all instances, more than the limit of " +
                                     std::to_string(limits.max_triangles));
    if (vertices > std::min(limits.max_vertices, kMaxFrameVertices))
        throw InputError(source,
                         std::to_string(vertices) +
                             " vertices over all instances, more than the limit of " +
                             std::to_string(std::min(limits.max_vertices, kMaxFrameVertices)));
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        if (!mesh_used[m]) continue;
        const Mesh& mesh = scene.meshes[m];
        const std::size_t n = mesh.positions.size();
        const std::string label = "mesh " + std::to_string(m) + " '" + mesh.name + "'";
        if (!mesh.normals.empty() && mesh.normals.size() != n)
            throw InputError(source, label + ": " + std::to_string(mesh.normals.size()) +
                                         " normals for " + std::to_string(n) + " positions");
        if (!mesh.uvs.empty() && mesh.uvs.size() != n)
            throw InputError(source, label + ": " + std::to_string(mesh.uvs.size()) + " uvs for " +
                                         std::to_string(n) + " positions");
    }
    if (options.clip_planes.size() > std::size_t(kMaxUserClipPlanes))
        throw InputError("", "at most " + std::to_string(kMaxUserClipPlanes) +
                                 " user clip planes are supported");
    if (options.threads < 0) throw InputError("", "thread count must be >= 0");
    if (options.camera) {
        const Camera& c = *options.camera;
        if (!finite(c.eye) || !finite(c.target) || !finite(c.up) || !std::isfinite(c.near) ||
            !std::isfinite(c.far) || !std::isfinite(c.fovy_degrees))
            throw InputError("", "camera parameters must be finite");
        if (glm::length(c.target - c.eye) == 0.0)
            throw InputError("", "camera eye and target coincide");
        if (glm::length(glm::cross(c.target - c.eye, c.up)) == 0.0)
            throw InputError("", "camera up vector is parallel to the view direction");
        if (!(c.near > 0.0) || (!c.infinite_far && !(c.far > c.near)))
            throw InputError("", "camera needs 0 < near < far");
        if (c.projection == Camera::Projection::Perspective &&
            !(c.fovy_degrees > 0.0 && c.fovy_degrees < 180.0))
            throw InputError("", "field of view must be in (0, 180) degrees");
    }
}

}  // namespace

namespace {

// Empties a frame for reuse, keeping the capacity of its arrays.
void reset(detail::Frame& frame) {
    frame.instances.clear();
    frame.instance_first_triangle.clear();
    for (detail::Chunk& c : frame.chunks) {
        c.refs.clear();
        c.extra_vertices.clear();
        c.pieces.clear();
        c.stats = RenderStats{};
        c.bad_index_instance = detail::Chunk::kNoBadIndex;
    }
}

void render_frame_in_arena(detail::Frame& frame, const Scene& scene, const RenderOptions& options,
                           RenderResult& result);

int thread_count(const RenderOptions& options) {
    return options.threads > 0
               ? options.threads
               : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

// Everything runs in an arena of the requested thread count, the checks too (the index check is
// parallel): a 1-thread frame uses one thread throughout.
void render_frame(tbb::task_arena& arena, detail::Frame& frame, const Scene& scene,
                  const RenderOptions& options, RenderResult& result) {
    arena.execute([&] { render_frame_in_arena(frame, scene, options, result); });
}

void render_frame_in_arena(detail::Frame& frame, const Scene& scene, const RenderOptions& options,
                           RenderResult& result) {
    validate(scene, options);
    const auto start = std::chrono::steady_clock::now();
    result.stats = RenderStats{};
    reset(frame);
    frame.scene = &scene;
    frame.options = &options;
    frame.camera = options.camera ? *options.camera : fit_camera(scene.world_positions());
    frame.eye = glm::vec3(frame.camera.eye);
    const glm::dvec3 axis = frame.camera.eye - frame.camera.target;
    frame.view_axis = glm::vec3(glm::normalize(axis));
    frame.clip_settings.depth_range = frame.camera.clip_depth_range();
    frame.clip_settings.guard_x = static_cast<float>(kGuardBand / (0.5 * options.width));
    frame.clip_settings.guard_y = static_cast<float>(kGuardBand / (0.5 * options.height));
    frame.clip_settings.user_plane_count = static_cast<int>(options.clip_planes.size());
    frame.setup_settings.viewport = {options.width, options.height};
    frame.setup_settings.depth_range = frame.camera.clip_depth_range();
    frame.setup_settings.cull = options.cull;
    frame.setup_settings.front_face = options.front_face;
    frame.setup_settings.screen_linear_planes =
        options.interpolation == Interpolation::ScreenLinear;
    frame.needs_attributes = options.color_target || options.normal_target;
    frame.setup_settings.barycentric_planes = frame.needs_attributes;
    frame.tiles_x = (options.width + detail::kTileSize - 1) / detail::kTileSize;
    frame.tiles_y = (options.height + detail::kTileSize - 1) / detail::kTileSize;
    result.stats.camera = frame.camera;

    detail::run_vertex_stage(frame, result.stats);
    result.stats.vertex_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    detail::attach_clusters(frame);
    detail::assemble_and_bin(frame, result.stats);
    detail::drop_stale_clusters(frame);
    check_indices(frame);
    const auto setup_done = std::chrono::steady_clock::now();
    result.stats.setup_ms = std::chrono::duration<double, std::milli>(setup_done - start).count();
    detail::rasterize_tiles(frame, result.targets, result.stats, frame.cleared_tiles);
    if (options.edges != RenderOptions::Edges::None) detail::draw_edges(frame, result.targets);
    result.stats.raster_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - setup_done)
            .count();
    result.stats.total_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

struct Renderer::State {
    detail::Frame frame;
    RenderResult result;
    // Kept from frame to frame while the thread count stays: a new arena per frame made the
    // workers join it anew, and a small scene's front end paid for that (bunny, 2 threads:
    // front end 0.59 -> 0.50 ms, frame -4%).
    std::unique_ptr<tbb::task_arena> arena;
    int arena_threads = 0;
};

Renderer::Renderer() : state_(std::make_unique<State>()) {}
Renderer::~Renderer() = default;

const RenderResult& Renderer::render(const Scene& scene, const RenderOptions& options) {
    const int threads = thread_count(options);
    if (!state_->arena || state_->arena_threads != threads) {
        state_->arena = std::make_unique<tbb::task_arena>(threads);
        state_->arena_threads = threads;
    }
    render_frame(*state_->arena, state_->frame, scene, options, state_->result);
    return state_->result;
}

RenderResult render(const Scene& scene, const RenderOptions& options) {
    detail::Frame frame;
    frame.cluster_cache.kept = false;
    RenderResult result;
    tbb::task_arena arena(thread_count(options));
    render_frame(arena, frame, scene, options, result);
    return result;
}

}  // namespace zraster
