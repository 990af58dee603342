// See input_checks.hpp.
#include "render/input_checks.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>

#include <zraster/error.hpp>

namespace zraster::detail {
namespace {

// Frame::mesh_flags.
constexpr std::uint8_t kMeshUsed = 1;   // an instance names it
constexpr std::uint8_t kMeshDrawn = 2;  // a frame instance (not culled) draws it

// Frame vertex indices are 32-bit with the top bit marking clipper-made vertices.
constexpr std::uint64_t kMaxFrameVertices = (std::uint64_t{1} << 31) - 1;

std::string mesh_label(const SceneView& scene, std::size_t m) {
    return "mesh " + std::to_string(m) + " '" + std::string(scene.meshes[m].name) + "'";
}

bool aligned(const void* p, std::size_t alignment) {
    return reinterpret_cast<std::uintptr_t>(p) % alignment == 0;
}

// Whether `count` elements of `element` bytes, `stride` apart from `data`, lie inside the
// address space (a stride so large that the last element's address wraps cannot be memory).
bool addressable(const void* data, std::size_t count, std::size_t stride, std::size_t element) {
    if (count == 0) return true;
    const std::size_t max = std::numeric_limits<std::size_t>::max();
    if (count - 1 > 0 && stride > (max - element) / (count - 1)) return false;
    const std::size_t span = (count - 1) * stride + element;
    return reinterpret_cast<std::uintptr_t>(data) <=
           std::numeric_limits<std::uintptr_t>::max() - span;
}

// One attribute of a mesh: `name` ("positions"), its element ("a position"), its size.
void check_attribute(const SceneView& scene, std::string_view source, std::size_t m,
                     const AttributeView& a, const char* name, const char* element_name,
                     std::size_t element, std::size_t positions) {
    const auto refuse = [&](const std::string& cause) {
        throw InputError(std::string(source),
                         mesh_label(scene, m) + ": " + std::string(name) + cause);
    };
    // (Positions are checked with positions = their own count.)
    if (a.count != 0 && a.count != positions)
        throw InputError(std::string(source), mesh_label(scene, m) + ": " +
                                                  std::to_string(a.count) + " " + name + " for " +
                                                  std::to_string(positions) + " positions (" +
                                                  name + ".count must be 0 or positions.count)");
    if (a.count == 0) return;
    if (a.data == nullptr) refuse(".data is null with " + std::to_string(a.count) + " elements");
    if (a.stride != 0 && a.stride < element)
        refuse(".stride " + std::to_string(a.stride) + " is smaller than " + element_name + " (" +
               std::to_string(element) + " bytes)");
    if (!aligned(a.data, alignof(float))) refuse(".data is not aligned to 4 bytes (a float)");
    if (!addressable(a.data, a.count, stride_of(a, element), element))
        refuse(".stride " + std::to_string(a.stride) + " times " + std::to_string(a.count) +
               " elements passes the end of the address space");
}

}  // namespace

// A non-finite component is refused by its index: shading would spread a NaN over the triangle,
// and the alpha mode could not be decided.
float checked_vertex_colors(const SceneView& scene, std::string_view source, std::size_t m) {
    const AttributeView& colors = scene.meshes[m].colors;
    check_attribute(scene, source, m, colors, "colors", "a color", kColorBytes,
                    scene.meshes[m].positions.count);
    float least = 1.0f;
    for (std::size_t i = 0; i < colors.count; ++i) {
        const glm::vec4 c = load_vec4(colors, i);
        if (!std::isfinite(c.x + c.y + c.z + c.w))
            throw InputError(std::string(source), mesh_label(scene, m) + ": colors[" +
                                                      std::to_string(i) + "] is not finite");
        least = std::min(least, c.w);
    }
    return least;
}

namespace {

void check_indices_view(const SceneView& scene, std::string_view source, std::size_t m) {
    const IndexView& v = scene.meshes[m].indices;
    const auto refuse = [&](const std::string& cause) {
        throw InputError(std::string(source), mesh_label(scene, m) + ": indices" + cause);
    };
    if (v.type != IndexType::UInt16 && v.type != IndexType::UInt32)
        refuse(".type " + std::to_string(int(v.type)) + " is neither UInt16 nor UInt32");
    if (v.count == 0) return;
    const std::size_t size = v.type == IndexType::UInt16 ? 2 : 4;
    if (v.data == nullptr) refuse(".data is null with " + std::to_string(v.count) + " indices");
    if (!aligned(v.data, size))
        refuse(".data is not aligned to " + std::to_string(size) + " bytes (an index)");
    if (!addressable(v.data, v.count, size, size))
        refuse(".count " + std::to_string(v.count) + " passes the end of the address space");
}

// The bounds of the positions, as Bounds3f::of (update_bounds) makes them: in parallel for
// large meshes, the blocks joined in order (so ties, signed zeros among them, resolve as in
// one pass).
Bounds3f position_bounds(const FrameMesh& mesh) {
    const auto serial = [&](std::size_t begin, std::size_t end, Bounds3f b) {
        if (mesh.positions != nullptr)
            for (std::size_t i = begin; i < end; ++i) b.extend(mesh.positions[i]);
        else
            for (std::size_t i = begin; i < end; ++i) b.extend(load_vec3(mesh.view->positions, i));
        return b;
    };
    const std::size_t n = mesh.vertex_count();
    if (n < (std::size_t{1} << 16)) return serial(0, n, Bounds3f{});
    return tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, n, std::size_t{1} << 14), Bounds3f{},
        [&](const tbb::blocked_range<std::size_t>& r, Bounds3f b) {
            return serial(r.begin(), r.end(), b);
        },
        [](Bounds3f a, const Bounds3f& b) {
            a.extend(b);
            return a;
        });
}

// The largest index, as a branch-free max the compiler vectorizes, in parallel for big meshes:
// this check runs every frame, over every index.
template <class Index>
std::uint32_t largest_index(std::span<const Index> indices) {
    const auto serial = [&](std::size_t begin, std::size_t end) {
        Index largest = 0;
        for (std::size_t i = begin; i < end; ++i)
            largest = indices[i] > largest ? indices[i] : largest;
        return std::uint32_t{largest};
    };
    if (indices.size() < (std::size_t{1} << 18)) return serial(0, indices.size());
    return tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, indices.size(), std::size_t{1} << 16), std::uint32_t{0},
        [&](const tbb::blocked_range<std::size_t>& r, std::uint32_t largest) {
            return std::max(largest, serial(r.begin(), r.end()));
        },
        [](std::uint32_t a, std::uint32_t b) { return std::max(a, b); });
}

std::uint32_t largest_index(const IndexView& v, std::size_t used) {
    if (v.type == IndexType::UInt16)
        return largest_index(std::span(static_cast<const std::uint16_t*>(v.data), used));
    return largest_index(std::span(static_cast<const std::uint32_t*>(v.data), used));
}

// Throws for the first of the scene's meshes (in mesh order) with a vertex index out of range,
// among the used ones (all_used) or those used but not drawn.
void refuse_bad_indices(const Frame& frame, bool all_used) {
    const SceneView& scene = *frame.scene;
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        const std::uint8_t flags = frame.mesh_flags[m];
        if (all_used ? (flags & kMeshUsed) == 0 : flags != kMeshUsed) continue;
        const MeshView& mesh = scene.meshes[m];
        const std::size_t used = triangle_count(mesh) * 3;  // a partial last triple is ignored
        if (used == 0) continue;
        const std::uint32_t largest = largest_index(mesh.indices, used);
        if (largest >= mesh.positions.count)
            throw InputError(std::string(frame.source),
                             mesh_label(scene, m) + ": vertex index " + std::to_string(largest) +
                                 " out of range (" + std::to_string(mesh.positions.count) +
                                 " positions)");
    }
}

// What a target's rows hold, for messages: "floats".
struct TargetField {
    const char* name;     // "depth"
    const char* element;  // "floats"
    std::size_t bytes;    // per element
};

template <class T>
void resolve_target(T* data, std::size_t& pitch, const TargetField& field, int width, int height) {
    if (data == nullptr) return;
    const auto refuse = [&](const std::string& cause) {
        throw InputError("", "targets: " + cause);
    };
    const auto pitch_name = [&] { return std::string(field.name) + "_pitch"; };
    const std::size_t row = std::size_t(width) * field.bytes;
    if (pitch == 0) pitch = row;
    if (pitch < row)
        refuse(pitch_name() + " " + std::to_string(pitch) + " is smaller than a row of " +
               std::to_string(width) + " " + field.element + " (" + std::to_string(row) +
               " bytes)");
    if (!aligned(data, alignof(T)))
        refuse(std::string(field.name) + " is not aligned to " + std::to_string(alignof(T)) +
               " bytes");
    if (pitch % alignof(T) != 0)
        refuse(pitch_name() + " " + std::to_string(pitch) + " is not a multiple of " +
               std::to_string(alignof(T)) + " (every row must stay aligned)");
    if (!addressable(data, std::size_t(height), pitch, row))
        refuse(pitch_name() + " " + std::to_string(pitch) + " times the height passes the end of " +
               "the address space");
}

}  // namespace

void validate_scene(Frame& frame, const SceneView& scene, std::string_view source,
                    const RenderOptions& options, std::uint64_t target_samples) {
    const RenderLimits& limits = options.limits;
    const auto refuse = [&](const std::string& cause) {
        throw InputError(std::string(source), cause);
    };
    if (scene.materials.empty()) refuse("the scene has no materials");
    if (scene.cells != nullptr && (scene.cells->instance_cells.size() != scene.instances.size() ||
                                   scene.cells->cell_portals.size() != scene.cells->cells.size()))
        refuse("the cell graph is for " + std::to_string(scene.cells->instance_cells.size()) +
               " instances (validated: validate_cell_graph), the scene has " +
               std::to_string(scene.instances.size()));
    frame.mesh_flags.assign(scene.meshes.size(), 0);
    std::uint64_t triangles = 0, vertices = 0;
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const std::uint32_t m = scene.instances[i].mesh;
        if (m >= scene.meshes.size())
            refuse("instance " + std::to_string(i) + " refers to mesh " + std::to_string(m) +
                   " of " + std::to_string(scene.meshes.size()));
        triangles += triangle_count(scene.meshes[m]);
        vertices += scene.meshes[m].positions.count;
        frame.mesh_flags[m] = kMeshUsed;
    }
    if (triangles > limits.max_triangles)
        refuse(std::to_string(triangles) +
               " triangles over all instances, more than the limit of " +
               std::to_string(limits.max_triangles));
    if (vertices > std::min(limits.max_vertices, kMaxFrameVertices))
        refuse(std::to_string(vertices) + " vertices over all instances, more than the limit of " +
               std::to_string(std::min(limits.max_vertices, kMaxFrameVertices)));
    check_frame_memory(source, vertices, triangles, target_samples, limits);
    frame.meshes.resize(scene.meshes.size());
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        frame.meshes[m] = FrameMesh{};
        if (frame.mesh_flags[m] == 0) continue;
        const MeshView& mesh = scene.meshes[m];
        const std::size_t n = mesh.positions.count;
        check_attribute(scene, source, m, mesh.positions, "positions", "a position", kPositionBytes,
                        n);
        check_attribute(scene, source, m, mesh.normals, "normals", "a normal", kPositionBytes, n);
        check_attribute(scene, source, m, mesh.uvs, "uvs", "a uv", kUvBytes, n);
        check_indices_view(scene, source, m);
        if (mesh.material >= scene.materials.size())
            refuse(mesh_label(scene, m) + ": material " + std::to_string(mesh.material) +
                   " past the scene's " + std::to_string(scene.materials.size()) + " materials");
        FrameMesh& frame_mesh = frame.meshes[m];
        frame_mesh = detail::frame_mesh(mesh);
        frame_mesh.least_vertex_alpha = checked_vertex_colors(scene, source, m);
        if ((!mesh.bounds || mesh.bounds->empty()) && n > 0)
            frame_mesh.bounds = position_bounds(frame_mesh);
    }
}

TargetViews resolve_targets(const TargetViews& targets, const RenderOptions& options) {
    if (targets.width != options.width || targets.height != options.height)
        throw InputError("", "targets: size " + std::to_string(targets.width) + "x" +
                                 std::to_string(targets.height) + " differs from the options' " +
                                 std::to_string(options.width) + "x" +
                                 std::to_string(options.height));
    TargetViews t = targets;
    const int w = t.width, h = t.height;
    resolve_target(t.color, t.color_pitch, {"color", "RGBA8 pixels", 4}, w, h);
    resolve_target(t.depth, t.depth_pitch, {"depth", "floats", sizeof(float)}, w, h);
    resolve_target(t.normal, t.normal_pitch, {"normal", "vec3 normals", sizeof(glm::vec3)}, w, h);
    resolve_target(t.instance_id, t.instance_id_pitch, {"instance_id", "int32 ids", 4}, w, h);
    resolve_target(t.primitive_id, t.primitive_id_pitch, {"primitive_id", "int32 ids", 4}, w, h);
    resolve_target(t.front_hits, t.front_hits_pitch, {"front_hits", "uint32 counts", 4}, w, h);
    resolve_target(t.back_hits, t.back_hits_pitch, {"back_hits", "uint32 counts", 4}, w, h);
    return t;
}

// Scanning every index each frame costs as much as a tenth of a million-triangle frame, so the
// front end checks the indices of the triangles it assembles (it loads them anyway) and this
// scans only what it did not see: meshes whose instances were all culled. On a find, every used
// mesh is scanned, so the message names the same mesh whichever instances the camera sees.
void check_indices(Frame& frame) {
    for (std::uint8_t& flags : frame.mesh_flags) flags &= ~kMeshDrawn;
    for (const FrameInstance& fi : frame.instances)
        frame.mesh_flags[frame.scene->instances[fi.scene_instance].mesh] |= kMeshDrawn;
    bool bad = false;
    for (const Chunk& c : frame.chunks) bad |= c.bad_index_instance != c.kNoBadIndex;
    refuse_bad_indices(frame, bad);
}

}  // namespace zraster::detail
