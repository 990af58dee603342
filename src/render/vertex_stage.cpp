// Vertex stage: view-frustum culling of instance bounds, then object -> clip space, world-space
// positions and normals (by the inverse-transpose), and per-vertex lighting for Gouraud.
#include <tbb/parallel_for.h>

#include <array>

#include "render/frame.hpp"

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
        all &= clip_outcode(mvp * glm::vec4(p, 1.0f), frustum, {});
        if (all == 0) return false;
    }
    return true;
}

}  // namespace

void run_vertex_stage(Frame& frame, RenderStats& stats) {
    const Scene& scene = *frame.scene;
    const RenderOptions& options = *frame.options;
    const double aspect = double(options.width) / double(options.height);
    const glm::mat4 view_projection = frame.camera.view_projection(aspect);

    std::uint32_t vertex_count = 0;
    for (std::uint32_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& instance = scene.instances[i];
        ++stats.instances;
        const Mesh& mesh = scene.meshes.at(instance.mesh);
        const glm::mat4 mvp = view_projection * instance.transform;
        if (outside_frustum(mesh.bounds, mvp, frame.camera.clip_depth_range())) {
            ++stats.instances_frustum_culled;
            continue;
        }
        FrameInstance fi;
        fi.scene_instance = i;
        fi.mesh = &mesh;
        fi.material = &scene.materials.at(mesh.material < scene.materials.size() ? mesh.material : 0);
        fi.shading = instance.shading.value_or(options.shading);
        fi.first_vertex = vertex_count;
        fi.mvp = mvp;
        fi.textured = options.textures && fi.material->base_color_texture && !mesh.uvs.empty();
        frame.instances.push_back(fi);
        vertex_count += static_cast<std::uint32_t>(mesh.positions.size());
    }

    FrameVertices& v = frame.vertices;
    v.clip.resize(vertex_count);
    v.world.resize(vertex_count);
    v.normal.resize(vertex_count);
    v.uv.resize(vertex_count);
    bool any_gouraud = false;
    for (const FrameInstance& fi : frame.instances) any_gouraud |= fi.shading == ShadingMode::Gouraud;
    if (any_gouraud) v.gouraud.resize(vertex_count);

    for (const FrameInstance& fi : frame.instances) {
        const Mesh& mesh = *fi.mesh;
        const glm::mat4 model = scene.instances[fi.scene_instance].transform;
        const glm::mat3 to_world_normal = normal_matrix(model);
        const bool lit_per_vertex = fi.shading == ShadingMode::Gouraud;
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.positions.size(), 4096),
                          [&](const tbb::blocked_range<std::size_t>& r) {
            for (std::size_t k = r.begin(); k < r.end(); ++k) {
                const std::size_t out = fi.first_vertex + k;
                const glm::vec4 p(mesh.positions[k], 1.0f);
                v.clip[out] = fi.mvp * p;
                v.world[out] = glm::vec3(model * p);
                glm::vec3 n = mesh.normals.empty() ? glm::vec3(0, 1, 0) : mesh.normals[k];
                n = to_world_normal * n;
                const float len = glm::length(n);
                v.normal[out] = len > 0.0f ? n / len : glm::vec3(0, 1, 0);
                v.uv[out] = mesh.uvs.empty() ? glm::vec2(0.0f) : mesh.uvs[k];
                if (lit_per_vertex)
                    v.gouraud[out] = evaluate_lighting(options.lighting, *fi.material, v.world[out],
                                                       v.normal[out], frame.eye, frame.view_axis);
            }
        });
    }
}

}  // namespace zraster::detail
