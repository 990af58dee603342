// Vertex stage: view-frustum culling of instance bounds, then object -> clip space, outcodes and
// snapped screen positions (once per vertex, so shared vertices snap identically in every
// triangle), world-space positions and normals (by the inverse-transpose) and per-vertex
// lighting for Gouraud, only where a later stage needs them.
#include <tbb/parallel_for.h>

#include <array>
#include <cmath>

#include "render/frame.hpp"
#include "render/occlusion_cull.hpp"

namespace zraster::detail {
namespace {

// True when the 8 corners of the box are all outside one plane of the view frustum.
bool outside_frustum(const Bounds3f& box, const glm::mat4& mvp, ClipDepthRange range) {
    if (box.empty()) return true;
    std::uint32_t all = ~0u;
    ClipSettings frustum;
    frustum.depth_range = range;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 p((i & 1) ? box.hi.x : box.lo.x, (i & 2) ? box.hi.y : box.lo.y,
                          (i & 4) ? box.hi.z : box.lo.z);
        all &= frustum_outcode(mvp * glm::vec4(p, 1.0f), frustum);
        if (all == 0) return false;
    }
    return true;
}

// m * (p, 1), written out: glm's operator* is not always inlined at -O2, and this is the
// innermost loop of the vertex stage. Same operations in the same order as glm's
// (m0 x + m1 y) + (m2 z + m3 w) with w = 1, so results equal m * vec4(p, 1) bit for bit.
inline glm::vec4 transform(const glm::mat4& m, const glm::vec3& p) {
    return glm::vec4((m[0].x * p.x + m[1].x * p.y) + (m[2].x * p.z + m[3].x),
                     (m[0].y * p.x + m[1].y * p.y) + (m[2].y * p.z + m[3].y),
                     (m[0].z * p.x + m[1].z * p.y) + (m[2].z * p.z + m[3].z),
                     (m[0].w * p.x + m[1].w * p.y) + (m[2].w * p.z + m[3].w));
}

bool finite(const glm::vec4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

}  // namespace

void run_vertex_stage(Frame& frame, RenderStats& stats) {
    const Scene& scene = *frame.scene;
    const RenderOptions& options = *frame.options;
    const double aspect = double(options.width) / double(options.height);
    const glm::mat4 view_projection = frame.camera.view_projection(aspect);

    const std::vector<InstanceCull> culled = cull_instances(frame, view_projection);
    std::uint32_t vertex_count = 0;
    for (std::uint32_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& instance = scene.instances[i];
        ++stats.instances;
        const Mesh& mesh = scene.meshes.at(instance.mesh);
        const glm::mat4 mvp = view_projection * instance.transform;
        if (culled[i] == InstanceCull::Frustum ||
            outside_frustum(mesh.bounds, mvp, frame.camera.clip_depth_range())) {
            ++stats.instances_frustum_culled;
            continue;
        }
        if (culled[i] == InstanceCull::Occluded) {
            ++stats.instances_occlusion_culled;
            continue;
        }
        FrameInstance fi;
        fi.scene_instance = i;
        fi.mesh = &mesh;
        fi.material =
            &scene.materials.at(mesh.material < scene.materials.size() ? mesh.material : 0);
        fi.shading = instance.shading.value_or(options.shading);
        fi.first_vertex = vertex_count;
        fi.mvp = mvp;
        fi.textured = options.textures && fi.material->base_color_texture && !mesh.uvs.empty();
        frame.instances.push_back(fi);
        vertex_count += static_cast<std::uint32_t>(mesh.positions.size());
    }

    FrameVertices& v = frame.vertices;
    const bool attributes = frame.needs_attributes;
    const bool world = attributes || !options.clip_planes.empty();
    v.clip.resize(vertex_count);
    v.screen.resize(vertex_count);
    v.outcode.resize(vertex_count);
    if (world) v.world.resize(vertex_count);
    if (attributes) {
        v.normal.resize(vertex_count);
        v.uv.resize(vertex_count);
    }
    bool any_gouraud = false;
    for (const FrameInstance& fi : frame.instances)
        any_gouraud |= fi.shading == ShadingMode::Gouraud;
    if (any_gouraud && attributes) v.gouraud.resize(vertex_count);

    for (const FrameInstance& fi : frame.instances) {
        const Mesh& mesh = *fi.mesh;
        const glm::mat4 model = scene.instances[fi.scene_instance].transform;
        const glm::mat3 to_world_normal = normal_matrix(model);
        const bool lit_per_vertex = fi.shading == ShadingMode::Gouraud && attributes;
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, mesh.positions.size(), 8192),
            [&](const tbb::blocked_range<std::size_t>& r) {
                for (std::size_t k = r.begin(); k < r.end(); ++k) {
                    const std::size_t out = fi.first_vertex + k;
                    const glm::vec4 p(mesh.positions[k], 1.0f);
                    const glm::vec4 clip = transform(fi.mvp, mesh.positions[k]);
                    v.clip[out] = clip;
                    std::uint32_t code = kNonFinite;
                    if (finite(clip)) {
                        code = frustum_outcode(clip, frame.clip_settings);
                        if (code == 0 && !to_screen(clip, frame.setup_settings, v.screen[out]))
                            code = kClipLeft;  // not representable: let the clipper handle it
                    }
                    v.outcode[out] = code;
                    if (!world) continue;
                    v.world[out] = glm::vec3(model * p);
                    if (!attributes) continue;
                    glm::vec3 n = mesh.normals.empty() ? glm::vec3(0, 1, 0) : mesh.normals[k];
                    n = to_world_normal * n;
                    const float len = glm::length(n);
                    v.normal[out] = len > 0.0f ? n / len : glm::vec3(0, 1, 0);
                    v.uv[out] = mesh.uvs.empty() ? glm::vec2(0.0f) : mesh.uvs[k];
                    if (lit_per_vertex)
                        v.gouraud[out] =
                            evaluate_lighting(options.lighting, *fi.material, v.world[out],
                                              v.normal[out], frame.eye, frame.view_axis);
                }
            });
    }
}

}  // namespace zraster::detail
