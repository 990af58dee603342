// The Renderer: joins the stages for one frame (see include/zraster/render.hpp).
#include <tbb/task_arena.h>

#include "render/thread_arena.hpp"

#include <algorithm>
#include <chrono>
#include <span>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include <zraster/error.hpp>

#include "memory/huge_pages.hpp"
#include "platform/cache_size.hpp"
#include "render/frame.hpp"
#include "render/input_checks.hpp"
#include "render/target_sizing.hpp"

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

// Options and scene are checked before anything is allocated: a frame that would need absurd
// memory, or a scene whose arrays disagree (read out of bounds later), is an InputError here.
// `own_targets`: the frame allocates its targets (counted in its memory).
void validate(detail::Frame& frame, const SceneView& scene, std::string_view source,
              const RenderOptions& options, bool own_targets) {
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
    detail::validate_scene(frame, scene, source, options, own_targets ? pixels : 0);
    if (options.clip_planes.size() > std::size_t(kMaxUserClipPlanes))
        throw InputError("", "at most " + std::to_string(kMaxUserClipPlanes) +
                                 " user clip planes are supported");
    if (options.threads < 0) throw InputError("", "thread count must be >= 0");
    if (options.camera) check_camera(*options.camera, options.width, options.height);
}

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

// Where a frame's images go: the caller's targets, or the Renderer's own (sized by the frame).
struct Destination {
    const TargetViews* caller = nullptr;
    RenderTargets* own = nullptr;
    // Depth rows for caller targets without depth when the edges need them.
    std::vector<float>* depth_rows = nullptr;
    std::vector<InstanceOutcome>* instance_outcomes = nullptr;  // the owning entry points'
};

void render_frame_in_arena(detail::Frame& frame, const SceneView& scene, std::string_view source,
                           const RenderOptions& options, const Destination& destination,
                           RenderStats& stats);

int thread_count(const RenderOptions& options) {
    return render_thread_count(options.threads);
}

// Everything runs in an arena of the requested thread count, the checks too (the index check is
// parallel): a 1-thread frame uses one thread throughout.
void render_frame(tbb::task_arena& arena, detail::Frame& frame, const SceneView& scene,
                  std::string_view source, const RenderOptions& options,
                  const Destination& destination, RenderStats& stats) {
    arena.execute(
        [&] { render_frame_in_arena(frame, scene, source, options, destination, stats); });
}

// The world-space positions of every instanced vertex, as Scene::world_positions() makes them
// (fit_camera's input), into the frame's kept array.
std::span<const glm::vec3> world_points(detail::Frame& frame) {
    const SceneView& scene = *frame.scene;
    std::size_t total = 0;
    for (const InstanceView& instance : scene.instances)
        total += scene.meshes[instance.mesh].positions.count;
    std::vector<glm::vec3>& out = frame.world_points;
    out.clear();
    memory::reserve_on_huge_pages(out, total);
    for (const InstanceView& instance : scene.instances) {
        const detail::FrameMesh& mesh = frame.meshes[instance.mesh];
        for (std::size_t i = 0; i < mesh.vertex_count(); ++i) {
            const glm::vec4 q = instance.transform * glm::vec4(mesh.position(i), 1.0f);
            out.push_back(glm::vec3(q) / q.w);
        }
    }
    return out;
}

void render_frame_in_arena(detail::Frame& frame, const SceneView& scene, std::string_view source,
                           const RenderOptions& options, const Destination& destination,
                           RenderStats& stats) {
    validate(frame, scene, source, options, destination.caller == nullptr);
    frame.instance_outcomes = nullptr;
    if (destination.instance_outcomes != nullptr) {
        destination.instance_outcomes->clear();
        if (options.report_instance_outcomes)
            frame.instance_outcomes = destination.instance_outcomes;
    }
    TargetViews targets;
    if (destination.caller != nullptr) {
        targets = detail::resolve_targets(*destination.caller, options);
        if (targets.depth == nullptr && options.edges == RenderOptions::Edges::HiddenLine) {
            destination.depth_rows->resize(std::size_t(options.width) *
                                           std::size_t(options.height));
            targets.depth = destination.depth_rows->data();
            targets.depth_pitch = std::size_t(options.width) * sizeof(float);
        }
    } else {
        targets = detail::size_targets(*destination.own, options, detail::wanted_targets(options));
    }
    const bool kept = destination.caller == nullptr || targets.unchanged_since_last_frame;
    // A view without a color target to show it in changes nothing.
    if (options.view != DebugView::None && targets.color != nullptr)
        detail::draw_debug_view(frame, scene, source, options, targets, kept, stats);
    else
        detail::draw_frame(frame, scene, source, options, targets, kept, stats);
}

}  // namespace

namespace detail {

void draw_frame(Frame& frame, const SceneView& scene, std::string_view source,
                const RenderOptions& options, const TargetViews& targets, bool kept,
                RenderStats& stats) {
    const auto start = std::chrono::steady_clock::now();
    stats = RenderStats{};
    reset(frame);
    frame.scene = &scene;
    frame.source = source;
    frame.options = &options;
    frame.targets = detail::FrameTargets(targets, kept);
    if (options.camera) {
        frame.camera = *options.camera;
    } else {
        try {
            frame.camera = fit_camera(world_points(frame));
        } catch (const InputError& e) {
            throw InputError(std::string(source), e.cause());
        }
    }
    frame.eye = glm::vec3(frame.camera.position());
    frame.view_axis = glm::vec3(-frame.camera.view_direction());
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
    frame.needs_attributes = frame.targets.color || frame.targets.normal;
    frame.setup_settings.barycentric_planes = frame.needs_attributes;
    frame.tiles_x = (options.width + detail::kTileSize - 1) / detail::kTileSize;
    frame.tiles_y = (options.height + detail::kTileSize - 1) / detail::kTileSize;
    stats.camera = frame.camera;

    detail::prepare_slots(frame);
    detail::run_vertex_stage(frame, stats);
    stats.vertex_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    detail::attach_clusters(frame);
    detail::assemble_and_bin(frame, stats);
    detail::drop_stale_clusters(frame);
    detail::check_indices(frame);
    const auto setup_done = std::chrono::steady_clock::now();
    stats.setup_ms = std::chrono::duration<double, std::milli>(setup_done - start).count();
    detail::rasterize_tiles(frame, stats);
    if (options.edges != RenderOptions::Edges::None) detail::draw_edges(frame);
    stats.raster_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - setup_done)
            .count();
    stats.total_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace detail

int render_thread_count(int requested) {
    const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    return requested > 0 ? std::min(requested, kMaxThreadsPerHardwareThread * hardware) : hardware;
}

TargetViews view_of(RenderTargets& targets) {
    TargetViews v;
    v.width = targets.width;
    v.height = targets.height;
    const std::size_t width = targets.width > 0 ? std::size_t(targets.width) : 0;
    // (Pixels of `per_pixel` elements: RGBA8 is four bytes.)
    const auto view = [&](auto& array, auto*& data, std::size_t& pitch, std::size_t per_pixel = 1) {
        if (array.empty()) return;
        data = array.data();
        pitch = width * per_pixel * sizeof(array[0]);
    };
    view(targets.color, v.color, v.color_pitch, 4);
    view(targets.depth, v.depth, v.depth_pitch);
    view(targets.normal, v.normal, v.normal_pitch);
    view(targets.instance_id, v.instance_id, v.instance_id_pitch);
    view(targets.primitive_id, v.primitive_id, v.primitive_id_pitch);
    view(targets.front_hits, v.front_hits, v.front_hits_pitch);
    view(targets.back_hits, v.back_hits, v.back_hits_pitch);
    return v;
}

struct Renderer::State {
    detail::Frame frame;
    RenderResult result;
    RenderStats view_stats;  // of the last frame into caller targets
    // The views of the last owning Scene (their capacity kept: no allocation per frame).
    std::vector<MeshView> mesh_views;
    std::vector<InstanceView> instance_views;
    std::vector<float> depth_rows;  // Destination::depth_rows
    // Kept from frame to frame while the thread count stays: with a new arena per frame the
    // workers join it anew every frame, which a small scene's front end pays for.
    std::unique_ptr<detail::ThreadArena> arena;
    int arena_threads = 0;

    tbb::task_arena& arena_for(const RenderOptions& options) {
        const int threads = thread_count(options);
        if (!arena || arena_threads != threads) {
            arena.reset();  // (its parallelism limit first)
            arena = std::make_unique<detail::ThreadArena>(threads);
            arena_threads = threads;
        }
        return arena->arena();
    }
};

Renderer::Renderer() : Renderer(RendererConfig{}) {}

Renderer::Renderer(const RendererConfig& config) : state_(std::make_unique<State>()) {
    state_->frame.streaming_threshold = config.streaming_threshold_bytes != 0
                                            ? config.streaming_threshold_bytes
                                            : platform::last_level_cache_bytes();
}
Renderer::~Renderer() = default;

const RenderResult& Renderer::render(const Scene& scene, const RenderOptions& options) {
    State& s = *state_;
    const SceneView view = view_of(scene, s.mesh_views, s.instance_views);
    Destination destination;
    destination.own = &s.result.targets;
    destination.instance_outcomes = &s.result.instance_outcomes;
    render_frame(s.arena_for(options), s.frame, view, scene.name, options, destination,
                 s.result.stats);
    return s.result;
}

const RenderStats& Renderer::render(const SceneView& scene, const RenderOptions& options,
                                    const TargetViews& targets) {
    State& s = *state_;
    Destination destination;
    destination.caller = &targets;
    destination.depth_rows = &s.depth_rows;
    render_frame(s.arena_for(options), s.frame, scene, "", options, destination, s.view_stats);
    return s.view_stats;
}

RenderResult render(const Scene& scene, const RenderOptions& options) {
    detail::Frame frame;
    frame.cluster_cache.kept = false;
    std::vector<MeshView> meshes;
    std::vector<InstanceView> instances;
    const SceneView view = view_of(scene, meshes, instances);
    RenderResult result;
    Destination destination;
    destination.own = &result.targets;
    destination.instance_outcomes = &result.instance_outcomes;
    detail::ThreadArena arena(thread_count(options));
    render_frame(arena.arena(), frame, view, scene.name, options, destination, result.stats);
    return result;
}

RenderStats render(const SceneView& scene, const RenderOptions& options,
                   const TargetViews& targets) {
    detail::Frame frame;
    frame.cluster_cache.kept = false;
    std::vector<float> depth_rows;
    Destination destination;
    destination.caller = &targets;
    destination.depth_rows = &depth_rows;
    RenderStats stats;
    detail::ThreadArena arena(thread_count(options));
    render_frame(arena.arena(), frame, scene, "", options, destination, stats);
    return stats;
}

}  // namespace zraster
