// Vertex stage: view-frustum culling of instance bounds, then object -> clip space, outcodes and
// snapped screen positions (once per vertex, so shared vertices snap identically in every
// triangle), world-space positions and normals (by the inverse-transpose) and per-vertex
// lighting for Gouraud, only where a later stage needs them.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <unordered_map>

#include "memory/huge_pages.hpp"
#include "render/frame.hpp"
#include "render/occlusion_cull.hpp"
#include "render/shade_kernel.hpp"
#include "render/vertex_kernel.hpp"
#include "render/word_hash.hpp"

namespace zraster::detail {
static_assert(sizeof(glm::vec3) == 12);  // positions are hashed as 3 words each

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

// Distance from p to the box (0 inside it): the front-to-back key. NaN bounds sort last.
float distance_to_box(const Bounds3f& box, const glm::vec3& p) {
    const glm::vec3 outside = glm::max(glm::max(box.lo - p, p - box.hi), glm::vec3(0.0f));
    const float d = glm::length(outside);
    return std::isnan(d) ? HUGE_VALF : d;
}

// Instances the SIMD Phong shader can draw get its constants.
void assign_phong_kernels(Frame& frame) {
    const RenderOptions& options = *frame.options;
    frame.phong_constants.clear();
    for (FrameInstance& fi : frame.instances) {
        if (fi.shading != ShadingMode::Phong || fi.textured || !options.simd ||
            !phong_kernel_applies(options.lighting, *fi.material))
            continue;
        fi.phong_kernel = static_cast<int>(frame.phong_constants.size());
        frame.phong_constants.push_back(
            make_phong_constants(options.lighting, *fi.material, frame.eye, frame.view_axis));
    }
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
        if (options.instance_order == InstanceOrder::FrontToBack)
            fi.distance = distance_to_box(mesh.bounds.transformed(instance.transform), frame.eye);
        fi.mesh = &mesh;
        fi.material =
            &scene.materials.at(mesh.material < scene.materials.size() ? mesh.material : 0);
        fi.shading = instance.shading.value_or(options.shading);
        fi.mvp = mvp;
        fi.model = instance.transform;
        fi.normal_matrix = normal_matrix(instance.transform);
        fi.textured = options.textures && fi.material->base_color_texture && !mesh.uvs.empty();
        frame.instances.push_back(fi);
    }
    if (options.instance_order == InstanceOrder::FrontToBack)
        std::stable_sort(
            frame.instances.begin(), frame.instances.end(),
            [](const FrameInstance& a, const FrameInstance& b) { return a.distance < b.distance; });
    for (FrameInstance& fi : frame.instances) {
        fi.first_vertex = vertex_count;
        vertex_count += static_cast<std::uint32_t>(fi.mesh->positions.size());
    }

    assign_phong_kernels(frame);
    frame.tagged_shading = tagged_shading(options) && !frame.phong_constants.empty();
    if (options.strategy == ShadingStrategy::Forward)
        frame.tagged_shading &= frame.phong_constants.size() == frame.instances.size();

    FrameVertices& v = frame.vertices;
    const bool attributes = frame.needs_attributes;
    const bool world = attributes || !options.clip_planes.empty();
    bool any_gouraud = false, any_textured = false;
    for (const FrameInstance& fi : frame.instances) {
        any_gouraud |= fi.shading == ShadingMode::Gouraud;
        any_textured |= fi.textured;
    }
    memory::resize_on_huge_pages(v.screen, vertex_count);
    memory::resize_on_huge_pages(v.outcode, vertex_count);
    // Arrays no instance reads stay empty (a reused Renderer may still hold old ones: the stages
    // index them only for instances that need them).
    if (world) memory::resize_on_huge_pages(v.world, vertex_count);
    if (attributes) memory::resize_on_huge_pages(v.normal, vertex_count);
    if (attributes && any_textured) memory::resize_on_huge_pages(v.uv, vertex_count);
    if (any_gouraud && attributes) memory::resize_on_huge_pages(v.gouraud, vertex_count);

    // Positions hashed this frame, per mesh: instances of the same mesh hash it once.
    std::unordered_map<const Mesh*, std::uint64_t> hashed;
    for (FrameInstance& fi : frame.instances) {
        const Mesh& mesh = *fi.mesh;
        const bool lit_per_vertex = fi.shading == ShadingMode::Gouraud && attributes;
        // The positions' hash for the cluster cache, summed over the blocks in any order.
        fi.positions_hashed = cluster_culling_applies(options, mesh) &&
                              frame.cluster_cache.wants_positions_hash(mesh);
        const auto earlier = hashed.find(&mesh);
        const bool hash_here = fi.positions_hashed && earlier == hashed.end();
        if (fi.positions_hashed && !hash_here) fi.positions_hash = earlier->second;
        std::atomic<std::uint32_t> hash_low{0}, hash_high{0};
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, mesh.positions.size(), 8192),
            [&](const tbb::blocked_range<std::size_t>& r) {
                VertexJob job;
                job.positions = mesh.positions.data() + r.begin();
                job.count = r.end() - r.begin();
                job.mvp = fi.mvp;
                job.clip = frame.clip_settings;
                job.setup = frame.setup_settings;
                job.screen_out = v.screen.data() + fi.first_vertex + r.begin();
                job.outcode_out = v.outcode.data() + fi.first_vertex + r.begin();
                if (world) {  // user clip planes need the world position, shading both
                    job.model = fi.model;
                    job.normal_matrix = fi.normal_matrix;
                    job.world_out = v.world.data() + fi.first_vertex + r.begin();
                    if (attributes) {
                        job.normal_out = v.normal.data() + fi.first_vertex + r.begin();
                        if (!mesh.normals.empty()) job.normals = mesh.normals.data() + r.begin();
                    }
                }
                if (options.simd)
                    transform_vertices(job);
                else
                    transform_vertices_scalar(job);
                if (hash_here) {  // while the block is in cache
                    const std::uint64_t h = (options.simd ? hash_words : hash_words_scalar)(
                        job.positions, 3 * job.count, 3 * std::uint64_t{r.begin()});
                    hash_low += static_cast<std::uint32_t>(h);
                    hash_high += static_cast<std::uint32_t>(h >> 32);
                }
                if (!attributes || (!fi.textured && !lit_per_vertex)) return;
                for (std::size_t k = r.begin(); k < r.end(); ++k) {
                    const std::size_t out = fi.first_vertex + k;
                    if (fi.textured) v.uv[out] = mesh.uvs[k];
                    if (lit_per_vertex)
                        v.gouraud[out] =
                            evaluate_lighting(options.lighting, *fi.material, v.world[out],
                                              v.normal[out], frame.eye, frame.view_axis);
                }
            });
        if (hash_here) {
            fi.positions_hash = (std::uint64_t{hash_high} << 32) | hash_low;
            hashed.emplace(&mesh, fi.positions_hash);
        }
    }
}

}  // namespace zraster::detail
