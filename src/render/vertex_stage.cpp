// Vertex stage: view-frustum culling of instance bounds, then object -> clip space, outcodes and
// snapped screen positions (once per vertex, so shared vertices snap identically in every
// triangle), world-space positions and normals (by the inverse-transpose) and per-vertex
// lighting for Gouraud, only where a later stage needs them.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>

#include "memory/huge_pages.hpp"
#include "render/frame.hpp"
#include "render/material_alpha.hpp"
#include "render/material_sides.hpp"
#include "render/mesh_access.hpp"
#include "render/occlusion_cull.hpp"
#include "render/shade_kernel.hpp"
#include "render/vertex_blocks.hpp"
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
        if (fi.shading != ShadingMode::Phong || fi.textured || fi.vertex_colored || !options.simd ||
            !phong_kernel_applies(options.lighting, *fi.material))
            continue;
        fi.phong_kernel = static_cast<int>(frame.phong_constants.size());
        frame.phong_constants.push_back(
            make_phong_constants(options.lighting, *fi.material, frame.eye, frame.view_axis));
    }
}

// Strided positions and normals reach the vertex kernel through local copies of this many
// vertices (the kernel reads tightly packed arrays).
constexpr std::size_t kGatherVertices = 256;

// Vertex blocks are skipped only when that spares at least 1 / kMinSkipDivisor of the
// vertices: before skipping, every cluster's indices are hashed, which costs about what
// transforming a few percent of the vertices would.
constexpr std::size_t kMinSkipDivisor = 8;

// What the vertex stage learns from bounds kept from earlier frames, before it transforms.
struct EarlyClusters {
    bool verdicts = false;  // `culled` holds every cluster's verdict (1: culled)
    bool skip = false;      // `needed` says which vertex blocks to transform; indices checked
    std::size_t skipped = 0;
};

// The clusters' verdicts and, when it pays, the vertex blocks only culled clusters use. Every
// cluster's indices are checked before any block is skipped (a changed index could point into
// one); on a mismatch the bounds are marked stale and nothing is culled.
EarlyClusters cull_clusters_early(const Frame& frame, const FrameInstance& fi,
                                  const MeshClusters& kept, std::vector<std::uint8_t>& culled,
                                  std::vector<std::uint8_t>& needed) {
    const MeshView& mesh = *fi.mesh->view;
    const ClusterArrays& arrays = kept.arrays;
    const std::size_t clusters = arrays.count;
    const bool simd = frame.options->simd;
    const ClusterView view =
        make_cluster_view(fi.mvp, frame.clip_settings, instance_setup(frame, fi));
    culled.resize(clusters);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, clusters, 1024),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          (simd ? clusters_culled : clusters_culled_scalar)(
                              view, arrays, r.begin(), r.size(), culled.data() + r.begin());
                      });
    EarlyClusters early;
    early.verdicts = true;
    needed.resize(kept.blocks.blocks);
    const std::size_t skipped =
        needed_vertex_blocks(kept.blocks, culled.data(), mesh.positions.count, needed.data());
    if (skipped * kMinSkipDivisor < mesh.positions.count) return early;
    std::atomic<bool> changed{false};
    if (!frame.options->static_meshes)  // (a static mesh's indices are taken as unchanged)
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, clusters, 1024),
                          [&](const tbb::blocked_range<std::size_t>& r) {
                              for (std::size_t c = r.begin(); c < r.end(); ++c)
                                  if (cluster_index_hash(mesh, c) != arrays.index_hash[c])
                                      changed = true;
                          });
    if (changed) {
        kept.stale = true;
        return {};
    }
    early.skip = true;
    early.skipped = skipped;
    return early;
}

}  // namespace

void run_vertex_stage(Frame& frame, RenderStats& stats) {
    const SceneView& scene = *frame.scene;
    const RenderOptions& options = *frame.options;
    const double aspect = double(options.width) / double(options.height);
    const glm::mat4 view_projection = frame.camera.view_projection(aspect);

    cull_instances(frame, view_projection);
    const std::vector<std::uint8_t>& culled = frame.culling.verdicts;
    const PortalWalk& walk = frame.culling.portal;
    stats.portal_outcome = walk.outcome;
    if (walk.outcome != PortalOutcome::NotRun) {
        stats.portal_camera_cell = walk.camera_cell;
        stats.portal_cells_visited = walk.cells_visited;
        stats.portal_visits = walk.visits;
        stats.portal_pvs_cells = walk.pvs_cells;
        stats.portal_ms = walk.ms;
    }
    std::uint32_t vertex_count = 0;
    frame.alpha_instances = false;
    bool per_instance_cull = false;
    std::vector<InstanceOutcome>* outcomes = frame.instance_outcomes;
    if (outcomes != nullptr) outcomes->assign(scene.instances.size(), InstanceOutcome::Drawn);
    const auto skipped = [&](std::uint32_t i, InstanceOutcome why) {
        if (outcomes != nullptr) (*outcomes)[i] = why;
    };
    for (std::uint32_t i = 0; i < scene.instances.size(); ++i) {
        const InstanceView& instance = scene.instances[i];
        ++stats.instances;
        const FrameMesh& mesh = frame.meshes[instance.mesh];
        const glm::mat4 mvp = view_projection * instance.transform;
        if (culled[i] == std::uint8_t(InstanceCull::Frustum) ||
            outside_frustum(mesh.bounds, mvp, frame.camera.clip_depth_range())) {
            ++stats.instances_frustum_culled;
            skipped(i, InstanceOutcome::FrustumCulled);
            continue;
        }
        if (culled[i] == std::uint8_t(InstanceCull::Portal)) {
            ++stats.instances_portal_culled;
            skipped(i, InstanceOutcome::PortalCulled);
            continue;
        }
        if (culled[i] == std::uint8_t(InstanceCull::Occluded)) {
            ++stats.instances_occlusion_culled;
            skipped(i, InstanceOutcome::OcclusionCulled);
            continue;
        }
        FrameInstance fi;
        fi.scene_instance = i;
        if (options.instance_order == InstanceOrder::FrontToBack)
            fi.distance = distance_to_box(mesh.bounds.transformed(instance.transform), frame.eye);
        fi.mesh = &mesh;
        fi.material = &scene.materials[mesh.view->material];
        fi.shading = instance.shading.value_or(options.shading);
        fi.mvp = mvp;
        fi.model = instance.transform;
        fi.normal_matrix = normal_matrix(instance.transform);
        fi.textured = options.textures && fi.material->base_color_texture && mesh.has_uvs();
        fi.alpha = effective_alpha_mode(*fi.material, options.textures && mesh.has_uvs(),
                                        mesh.least_vertex_alpha, options);
        fi.alpha_varies.textures =
            fi.alpha != AlphaMode::Opaque && options.textures && mesh.has_uvs() &&
            (fi.material->base_color_texture || fi.material->opacity_texture);
        fi.alpha_varies.vertices = fi.alpha != AlphaMode::Opaque && mesh.least_vertex_alpha < 1.0f;
        fi.vertex_colored = mesh.has_colors();
        frame.alpha_instances |= fi.alpha != AlphaMode::Opaque;
        fi.cull = instance_cull(*fi.material, options);
        fi.two_sided_lighting = instance_two_sided_lighting(*fi.material, options);
        per_instance_cull |= fi.cull != options.cull;
        frame.instances.push_back(fi);
    }
    // Culling decided per instance by the front end: setup_triangle culls nothing afterwards.
    frame.setup_settings.cull = per_instance_cull ? CullMode::None : options.cull;
    // Nearest first, ties in submission order (a sort that needs no buffer, unlike stable_sort).
    if (options.instance_order == InstanceOrder::FrontToBack)
        std::sort(frame.instances.begin(), frame.instances.end(),
                  [](const FrameInstance& a, const FrameInstance& b) {
                      return a.distance < b.distance ||
                             (a.distance == b.distance && a.scene_instance < b.scene_instance);
                  });
    for (FrameInstance& fi : frame.instances) {
        fi.first_vertex = vertex_count;
        vertex_count += static_cast<std::uint32_t>(fi.mesh->vertex_count());
    }

    assign_phong_kernels(frame);
    frame.tagged_shading = tagged_shading(options, frame.targets) && !frame.phong_constants.empty();
    if (options.strategy == ShadingStrategy::Forward)
        frame.tagged_shading &= frame.phong_constants.size() == frame.instances.size();

    FrameVertices& v = frame.vertices;
    // Alpha-tested fragments need their texture coordinates even in a depth-only frame.
    if (frame.alpha_instances && !frame.needs_attributes) {
        frame.needs_attributes = true;
        frame.setup_settings.barycentric_planes = true;
    }
    const bool attributes = frame.needs_attributes;
    const bool world = attributes || !options.clip_planes.empty();
    bool any_gouraud = false, any_textured = false, any_colored = false;
    for (const FrameInstance& fi : frame.instances) {
        any_gouraud |= fi.shading == ShadingMode::Gouraud;
        any_textured |= fi.textured || fi.alpha_varies.textures;
        any_colored |= fi.vertex_colored;
    }
    memory::resize_on_huge_pages(v.screen, vertex_count);
    memory::resize_on_huge_pages(v.outcode, vertex_count);
    // Arrays no instance reads stay empty (a reused Renderer may still hold old ones: the stages
    // index them only for instances that need them).
    if (world) memory::resize_on_huge_pages(v.world, vertex_count);
    if (attributes) memory::resize_on_huge_pages(v.normal, vertex_count);
    if (attributes && any_textured) memory::resize_on_huge_pages(v.uv, vertex_count);
    if (any_gouraud && attributes) memory::resize_on_huge_pages(v.gouraud, vertex_count);
    if (any_colored && attributes) memory::resize_on_huge_pages(v.color, vertex_count);

    // Positions hashed this frame, per scene mesh: instances of the same mesh hash it once.
    frame.mesh_hashed.assign(scene.meshes.size(), 0);
    frame.mesh_hash.resize(scene.meshes.size());
    frame.cluster_verdicts.resize(frame.instances.size());
    for (std::size_t i = 0; i < frame.instances.size(); ++i) {
        FrameInstance& fi = frame.instances[i];
        const FrameMesh& mesh = *fi.mesh;
        const MeshView& view = *mesh.view;
        const std::uint32_t mesh_index = scene.instances[fi.scene_instance].mesh;
        const bool lit_per_vertex = fi.shading == ShadingMode::Gouraud && attributes;
        // The positions' hash for the cluster cache, summed over the blocks in any order.
        fi.positions_hashed = cluster_culling_applies(options, view) &&
                              frame.cluster_cache.wants_positions_hash(view);
        const bool hashed_before = frame.mesh_hashed[mesh_index] != 0;
        // Static meshes (RenderOptions::static_meshes) are not hashed: all have one hash.
        const bool hash_here = fi.positions_hashed && !hashed_before && !options.static_meshes;
        if (fi.positions_hashed && !hash_here)
            fi.positions_hash =
                options.static_meshes ? kStaticMeshHash : frame.mesh_hash[mesh_index];
        // Vertices only culled clusters use are skipped (vertex_blocks.hpp), with the bounds
        // kept from earlier frames; their positions are checked after (hash_here) or before.
        fi.culled_clusters = nullptr;
        fi.cluster_indices_checked = false;
        const std::uint8_t* needed = nullptr;
        std::size_t skipped = 0;
        if (fi.positions_hashed && !lit_per_vertex) {
            const MeshClusters* kept = frame.cluster_cache.kept_clusters(view);
            if (kept != nullptr &&
                (hash_here || frame.cluster_cache.same_positions(view, fi.positions_hash))) {
                const EarlyClusters early = cull_clusters_early(
                    frame, fi, *kept, frame.cluster_verdicts[i], frame.needed_vertex_blocks);
                if (early.verdicts) fi.culled_clusters = frame.cluster_verdicts[i].data();
                if (early.skip) {
                    fi.cluster_indices_checked = true;
                    needed = frame.needed_vertex_blocks.data();
                    skipped = early.skipped;
                }
            }
        }
        const bool normals = world && attributes && mesh.has_normals();
        // Tightly packed arrays go to the kernel in place; strided ones through local copies.
        const bool in_place = mesh.positions != nullptr && (!normals || mesh.normals != nullptr);
        // The vertex kernel on vertices [begin, end) of the mesh, read from `positions` and
        // `object_normals` (null: none), which hold them from `first` on.
        const auto kernel = [&](std::size_t begin, std::size_t end, const glm::vec3* positions,
                                const glm::vec3* object_normals, std::size_t first) {
            VertexJob job;
            job.positions = positions + (begin - first);
            job.count = end - begin;
            job.mvp = fi.mvp;
            job.clip = frame.clip_settings;
            job.setup = frame.setup_settings;
            job.screen_out = v.screen.data() + fi.first_vertex + begin;
            job.outcode_out = v.outcode.data() + fi.first_vertex + begin;
            if (world) {  // user clip planes need the world position, shading both
                job.model = fi.model;
                job.normal_matrix = fi.normal_matrix;
                job.world_out = v.world.data() + fi.first_vertex + begin;
                if (attributes) {
                    job.normal_out = v.normal.data() + fi.first_vertex + begin;
                    if (object_normals != nullptr) job.normals = object_normals + (begin - first);
                }
            }
            if (options.simd)
                transform_vertices(job);
            else
                transform_vertices_scalar(job);
        };
        const auto hash = options.simd ? hash_words : hash_words_scalar;
        // Vertices [begin, end) through the kernel; with `positions_hash`, strided positions
        // are hashed from the same copies (packed ones: hash_positions).
        const auto transform = [&](std::size_t begin, std::size_t end,
                                   std::uint64_t* positions_hash) {
            if (in_place) {
                kernel(begin, end, mesh.positions, normals ? mesh.normals : nullptr, 0);
                return;
            }
            glm::vec3 positions[kGatherVertices], object_normals[kGatherVertices];
            for (std::size_t b = begin; b < end; b += kGatherVertices) {
                const std::size_t n = std::min(kGatherVertices, end - b);
                gather_vec3(view.positions, b, n, positions);
                if (normals) gather_vec3(view.normals, b, n, object_normals);
                kernel(b, b + n, positions, normals ? object_normals : nullptr, b);
                if (positions_hash != nullptr)
                    *positions_hash = combine_word_hashes(
                        *positions_hash, hash(positions, 3 * n, 3 * std::uint64_t{b}));
            }
        };
        // The hash of the positions of vertices [begin, end).
        const auto hash_positions = [&](std::size_t begin, std::size_t end) {
            if (mesh.positions != nullptr)
                return hash(mesh.positions + begin, 3 * (end - begin), 3 * std::uint64_t{begin});
            std::uint64_t h = 0;
            glm::vec3 positions[kGatherVertices];
            for (std::size_t b = begin; b < end; b += kGatherVertices) {
                const std::size_t n = std::min(kGatherVertices, end - b);
                gather_vec3(view.positions, b, n, positions);
                h = combine_word_hashes(h, hash(positions, 3 * n, 3 * std::uint64_t{b}));
            }
            return h;
        };
        std::atomic<std::uint32_t> hash_low{0}, hash_high{0};
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, mesh.vertex_count(), 8192),
            [&](const tbb::blocked_range<std::size_t>& r) {
                // Strided positions transformed whole are hashed as they go.
                std::uint64_t h = 0;
                const bool hash_in_transform = hash_here && !in_place && needed == nullptr;
                if (needed == nullptr) {
                    transform(r.begin(), r.end(), hash_in_transform ? &h : nullptr);
                } else {  // runs of needed blocks
                    for (std::size_t k = r.begin(); k < r.end();) {
                        std::size_t end = std::min(r.end(), (k / kVertexBlock + 1) * kVertexBlock);
                        if (!needed[k / kVertexBlock]) {
                            k = end;
                            continue;
                        }
                        while (end < r.end() && needed[end / kVertexBlock])
                            end = std::min(r.end(), end + kVertexBlock);
                        transform(k, end, nullptr);
                        k = end;
                    }
                }
                if (hash_here) {  // while the block is in cache
                    if (!hash_in_transform) h = hash_positions(r.begin(), r.end());
                    hash_low += static_cast<std::uint32_t>(h);
                    hash_high += static_cast<std::uint32_t>(h >> 32);
                }
                const bool uvs = fi.textured || fi.alpha_varies.textures;
                const bool colors = fi.vertex_colored;
                if (!attributes || (!uvs && !colors && !lit_per_vertex)) return;
                for (std::size_t k = r.begin(); k < r.end(); ++k) {
                    const std::size_t out = fi.first_vertex + k;
                    if (uvs) v.uv[out] = mesh.uv(k);
                    if (colors) v.color[out] = mesh.color(k);
                    if (lit_per_vertex)
                        v.gouraud[out] =
                            evaluate_lighting(options.lighting, *fi.material, v.world[out],
                                              v.normal[out], frame.eye, frame.view_axis);
                }
            });
        if (hash_here) {
            fi.positions_hash = (std::uint64_t{hash_high} << 32) | hash_low;
            frame.mesh_hashed[mesh_index] = 1;
            frame.mesh_hash[mesh_index] = fi.positions_hash;
            // Moved positions: the bounds no longer hold, and the skipped vertices are needed.
            if (fi.culled_clusters != nullptr &&
                !frame.cluster_cache.same_positions(view, fi.positions_hash)) {
                fi.culled_clusters = nullptr;
                fi.cluster_indices_checked = false;
            }
            if (needed != nullptr && fi.culled_clusters == nullptr) {
                skipped = 0;
                tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.vertex_count(), 8192),
                                  [&](const tbb::blocked_range<std::size_t>& r) {
                                      transform(r.begin(), r.end(), nullptr);
                                  });
            }
        }
        stats.vertices_skipped += skipped;
    }
}

}  // namespace zraster::detail
