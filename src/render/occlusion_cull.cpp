// Instance culling before the vertex stage (occlusion_cull.hpp). Occlusion culling follows the
// usual engine recipe for Masked Software Occlusion Culling: the instances that cover the most
// screen become occluders (within a triangle budget), then every other instance's box is tested
// nearest first, and visible instances of modest size join the occluders as they are found.
#include "render/occlusion_cull.hpp"

#include "render/material_alpha.hpp"

#include <zraster/instance_bvh.hpp>
#include <zraster/occlusion_buffer.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace zraster::detail {
namespace {

// Instances covering at least this fraction of the screen (by their projected box) are
// occluders from the start; visible instances covering kLateOccluderFraction, with at most
// kLateOccluderTriangles triangles, are added as they are found.
constexpr double kOccluderFraction = 0.01;
constexpr double kLateOccluderFraction = 0.002;
constexpr std::size_t kLateOccluderTriangles = 4096;
// Occluder triangles per frame: about 1 ms of occlusion rendering on one core.
constexpr std::size_t kOccluderTriangleBudget = 40'000;

}  // namespace

bool culling_keeps_image(const Frame& frame) {
    const RenderOptions& o = *frame.options;
    const CompareFunc compare = effective_depth_compare(o);
    return o.depth_test && o.depth_write &&
           (compare == CompareFunc::Less || compare == CompareFunc::LessEqual) &&
           o.depth_format == DepthFormat::D32F && !frame.camera.reversed_z &&
           frame.camera.clip_depth_range() == ClipDepthRange::NegativeOneToOne &&
           o.clip_planes.empty() && o.edges == RenderOptions::Edges::None;
}

namespace {

using Candidate = InstanceCulling::Candidate;

double screen_fraction(const Bounds3f& box, const glm::mat4& mvp) {
    glm::vec2 lo(HUGE_VALF), hi(-HUGE_VALF);
    for (int i = 0; i < 8; ++i) {
        const glm::vec4 p =
            mvp * glm::vec4((i & 1) ? box.hi.x : box.lo.x, (i & 2) ? box.hi.y : box.lo.y,
                            (i & 4) ? box.hi.z : box.lo.z, 1.0f);
        if (!(p.w > 0.0f) || p.z < -p.w) return 1.0;  // around the eye: as large as it gets
        const glm::vec2 ndc = glm::vec2(p) / p.w;
        lo = glm::min(lo, ndc);
        hi = glm::max(hi, ndc);
    }
    lo = glm::clamp(lo, glm::vec2(-1.0f), glm::vec2(1.0f));
    hi = glm::clamp(hi, glm::vec2(-1.0f), glm::vec2(1.0f));
    const double area = double(hi.x - lo.x) * double(hi.y - lo.y) / 4.0;
    return std::isfinite(area) ? std::max(area, 0.0) : 0.0;
}

OccluderOptions occluder_options(const RenderOptions& o) {
    OccluderOptions out;
    out.cull = o.cull == CullMode::Back    ? OccluderCull::Back
               : o.cull == CullMode::Front ? OccluderCull::Front
                                           : OccluderCull::None;
    out.front_face_clockwise = o.front_face == FrontFace::Clockwise;
    out.subpixel_margin = 1.0f / 256.0f;  // the Renderer snaps vertices to 1/256 pixel
    return out;
}

// Tightly packed positions and 32-bit indices are drawn in place; other layouts are copied,
// one position per corner (occluders are small: kOccluderTriangleBudget triangles a frame).
void draw_occluder(InstanceCulling& culling, const FrameMesh& mesh, const Candidate& c,
                   const OccluderOptions& options) {
    OcclusionBuffer& buffer = *culling.buffer;
    const std::size_t corners = c.triangles * 3;
    if (mesh.positions != nullptr && mesh.indices != nullptr) {
        buffer.render_occluders(std::span(mesh.positions, mesh.vertex_count()),
                                std::span(mesh.indices, corners), c.mvp, options);
        return;
    }
    std::vector<glm::vec3>& positions = culling.occluder_positions;
    std::vector<std::uint32_t>& indices = culling.occluder_indices;
    positions.resize(corners);
    indices.resize(corners);
    const std::size_t vertices = mesh.vertex_count();
    for (std::size_t k = 0; k < corners; ++k) {
        const std::uint32_t index = mesh.index(k);
        // An index past the vertices skips its triangle, as in place.
        positions[k] = index < vertices ? mesh.position(index) : glm::vec3(0.0f);
        indices[k] = index < vertices ? static_cast<std::uint32_t>(k) : ~std::uint32_t{0};
    }
    buffer.render_occluders(std::span<const glm::vec3>(positions),
                            std::span<const std::uint32_t>(indices), c.mvp, options);
}

// Portal culling asked for (a walk or a PVS) and a cell graph to do it with.
bool wants_portal_culling(const Frame& frame) {
    const CellGraph* graph = frame.scene->cells;
    return graph != nullptr &&
           (frame.options->portal_cull != PortalCull::Off || !graph->pvs.empty());
}

// Marks the instances of `inside` that the walk does not reach, and drops them from it.
void cull_by_portals(Frame& frame, const glm::mat4& view_projection) {
    InstanceCulling& culling = frame.culling;
    PortalWalk& walk = culling.portal;
    if (!culling_keeps_image(frame)) {
        walk.outcome = PortalOutcome::NotExact;
        return;
    }
    PortalWalkInput input;
    input.graph = frame.scene->cells;
    input.mode = frame.options->portal_cull;
    input.camera = frame.camera;
    input.view_projection = view_projection;
    input.width = frame.options->width;
    input.height = frame.options->height;
    input.world_boxes = culling.world_boxes;
    walk_portals(input, walk);
    if (walk.outcome != PortalOutcome::Culled) return;
    std::size_t kept = 0;
    for (const std::uint32_t i : culling.inside) {
        if (walk.kept[i])
            culling.inside[kept++] = i;
        else
            culling.verdicts[i] = std::uint8_t(InstanceCull::Portal);
    }
    culling.inside.resize(kept);
}

}  // namespace

void cull_instances(Frame& frame, const glm::mat4& view_projection) {
    const SceneView& scene = *frame.scene;
    const RenderOptions& options = *frame.options;
    InstanceCulling& culling = frame.culling;
    const std::size_t n = scene.instances.size();
    const bool occlusion = options.occlusion_cull && culling_keeps_image(frame);
    const bool portals = wants_portal_culling(frame);
    std::vector<std::uint8_t>& verdict = culling.verdicts;
    verdict.assign(n, std::uint8_t(InstanceCull::Keep));
    PortalWalk& walk = culling.portal;
    walk.outcome = PortalOutcome::NotRun;
    walk.camera_cell = -1;
    walk.cells_visited = walk.visits = walk.pvs_cells = 0;
    walk.ms = 0.0;
    if (n < kBvhMinInstances && !occlusion && !portals) return;

    std::vector<std::uint32_t>& inside = culling.inside;
    inside.clear();
    if (n >= kBvhMinInstances || portals) {
        culling.world_boxes.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            const InstanceView& instance = scene.instances[i];
            culling.world_boxes[i] =
                frame.meshes[instance.mesh].bounds.transformed(instance.transform);
        }
    }
    if (n >= kBvhMinInstances) {
        culling.bvh.build(culling.world_boxes);
        culling.bvh.query(frustum_planes(view_projection, frame.camera.clip_depth_range()), inside);
        std::fill(verdict.begin(), verdict.end(), std::uint8_t(InstanceCull::Frustum));
        for (const std::uint32_t i : inside) verdict[i] = std::uint8_t(InstanceCull::Keep);
    } else {
        inside.resize(n);
        std::iota(inside.begin(), inside.end(), 0u);
    }
    if (portals) cull_by_portals(frame, view_projection);
    if (!occlusion) return;

    std::vector<Candidate>& candidates = culling.candidates;
    candidates.clear();
    for (const std::uint32_t i : inside) {
        const InstanceView& instance = scene.instances[i];
        const FrameMesh& mesh = frame.meshes[instance.mesh];
        if (mesh.bounds.empty()) continue;
        Candidate c;
        c.instance = i;
        c.mvp = view_projection * instance.transform;  // as the vertex stage computes it
        c.screen_fraction = screen_fraction(mesh.bounds, c.mvp);
        const glm::vec3 center(instance.transform * glm::vec4(mesh.bounds.center(), 1.0f));
        c.distance = glm::length(glm::dvec3(center) - frame.camera.position());
        if (!std::isfinite(c.distance)) c.distance = 0.0;
        c.triangles = mesh.triangle_count();
        c.opaque = effective_alpha_mode(scene.materials[mesh.view->material],
                                        options.textures && mesh.has_uvs(), mesh.least_vertex_alpha,
                                        options) == AlphaMode::Opaque;
        candidates.push_back(c);
    }
    // (Sorts with ties in candidate order: stable, without stable_sort's buffer.)
    const auto by = [&](auto key) {
        return [&candidates, key](std::size_t a, std::size_t b) {
            const double ka = key(candidates[a]), kb = key(candidates[b]);
            return ka < kb || (ka == kb && a < b);
        };
    };
    // Occluders first: the largest on screen, within the triangle budget.
    std::vector<std::size_t>& by_size = culling.by_size;
    by_size.resize(candidates.size());
    std::iota(by_size.begin(), by_size.end(), std::size_t{0});
    std::sort(by_size.begin(), by_size.end(),
              by([](const Candidate& c) { return -c.screen_fraction; }));
    if (!culling.buffer) culling.buffer = std::make_unique<OcclusionBuffer>();
    OcclusionBuffer& buffer = *culling.buffer;
    if (buffer.width() != options.width || buffer.height() != options.height)
        buffer.set_resolution(options.width, options.height);
    else
        buffer.clear();
    buffer.set_simd(options.simd);
    const OccluderOptions occluder = occluder_options(options);
    std::vector<std::uint8_t>& is_occluder = culling.is_occluder;
    is_occluder.assign(candidates.size(), 0);
    std::vector<std::size_t>& occluders = culling.occluders;
    occluders.clear();
    std::size_t budget = kOccluderTriangleBudget;
    for (const std::size_t k : by_size) {
        const Candidate& c = candidates[k];
        if (c.screen_fraction < kOccluderFraction) break;
        if (c.triangles > budget || !c.opaque) continue;
        budget -= c.triangles;
        is_occluder[k] = 1;
        occluders.push_back(k);
    }
    const auto distance = [](const Candidate& c) { return c.distance; };
    // Drawn nearest first: the buffer keeps two depth layers per row, and a far surface drawn
    // before a near one can cost the near one's detail.
    std::sort(occluders.begin(), occluders.end(), by(distance));
    for (const std::size_t k : occluders) {
        const Candidate& c = candidates[k];
        draw_occluder(culling, frame.meshes[scene.instances[c.instance].mesh], c, occluder);
    }
    // Then everything else, nearest first.
    std::vector<std::size_t>& by_distance = culling.by_distance;
    by_distance.clear();
    for (std::size_t k = 0; k < candidates.size(); ++k)
        if (!is_occluder[k]) by_distance.push_back(k);
    std::sort(by_distance.begin(), by_distance.end(), by(distance));
    for (const std::size_t k : by_distance) {
        const Candidate& c = candidates[k];
        const FrameMesh& mesh = frame.meshes[scene.instances[c.instance].mesh];
        const OcclusionResult r = buffer.test_box(mesh.bounds, c.mvp);
        if (r == OcclusionResult::Occluded) {
            verdict[c.instance] = std::uint8_t(InstanceCull::Occluded);
        } else if (r == OcclusionResult::Visible && c.opaque &&
                   c.screen_fraction >= kLateOccluderFraction &&
                   c.triangles <= kLateOccluderTriangles && c.triangles <= budget) {
            budget -= c.triangles;
            draw_occluder(culling, mesh, c, occluder);
        }
    }
}

}  // namespace zraster::detail
