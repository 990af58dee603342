// Instance culling before the vertex stage (occlusion_cull.hpp). Occlusion culling follows the
// usual engine recipe for Masked Software Occlusion Culling: the instances that cover the most
// screen become occluders (within a triangle budget), then every other instance's box is tested
// nearest first, and visible instances of modest size join the occluders as they are found.
#include "render/occlusion_cull.hpp"

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

bool occlusion_applies(const Frame& frame) {
    const RenderOptions& o = *frame.options;
    const CompareFunc compare = effective_depth_compare(o);
    return o.depth_test && o.depth_write &&
           (compare == CompareFunc::Less || compare == CompareFunc::LessEqual) &&
           o.depth_format == DepthFormat::D32F && !frame.camera.reversed_z &&
           frame.camera.clip_depth_range() == ClipDepthRange::NegativeOneToOne &&
           o.clip_planes.empty() && o.edges == RenderOptions::Edges::None;
}

struct Candidate {
    std::uint32_t instance = 0;
    glm::mat4 mvp{1.0f};
    double screen_fraction = 0.0;  // of the projected box, clamped to the screen
    double distance = 0.0;         // eye to the world box's center
    std::size_t triangles = 0;
};

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

void draw_occluder(OcclusionBuffer& buffer, const Mesh& mesh, const Candidate& c,
                   const OccluderOptions& options) {
    buffer.render_occluders(std::span<const glm::vec3>(mesh.positions),
                            std::span<const std::uint32_t>(mesh.indices.data(), c.triangles * 3),
                            c.mvp, options);
}

}  // namespace

std::vector<InstanceCull> cull_instances(const Frame& frame, const glm::mat4& view_projection) {
    const Scene& scene = *frame.scene;
    const RenderOptions& options = *frame.options;
    const std::size_t n = scene.instances.size();
    const bool occlusion = options.occlusion_cull && occlusion_applies(frame);
    std::vector<InstanceCull> verdict(n, InstanceCull::Keep);
    if (n < kBvhMinInstances && !occlusion) return verdict;

    std::vector<std::uint32_t> inside;
    if (n >= kBvhMinInstances) {
        std::vector<Bounds3f> world(n);
        for (std::size_t i = 0; i < n; ++i) {
            const Instance& instance = scene.instances[i];
            world[i] = scene.meshes.at(instance.mesh).bounds.transformed(instance.transform);
        }
        const InstanceBvh bvh(world);
        bvh.query(frustum_planes(view_projection, frame.camera.clip_depth_range()), inside);
        std::fill(verdict.begin(), verdict.end(), InstanceCull::Frustum);
        for (const std::uint32_t i : inside) verdict[i] = InstanceCull::Keep;
    } else {
        inside.resize(n);
        std::iota(inside.begin(), inside.end(), 0u);
    }
    if (!occlusion) return verdict;

    std::vector<Candidate> candidates;
    candidates.reserve(inside.size());
    for (const std::uint32_t i : inside) {
        const Instance& instance = scene.instances[i];
        const Mesh& mesh = scene.meshes.at(instance.mesh);
        if (mesh.bounds.empty()) continue;
        Candidate c;
        c.instance = i;
        c.mvp = view_projection * instance.transform;  // as the vertex stage computes it
        c.screen_fraction = screen_fraction(mesh.bounds, c.mvp);
        const glm::vec3 center(instance.transform * glm::vec4(mesh.bounds.center(), 1.0f));
        c.distance = glm::length(glm::dvec3(center) - frame.camera.eye);
        if (!std::isfinite(c.distance)) c.distance = 0.0;
        c.triangles = mesh.triangle_count();
        candidates.push_back(c);
    }
    // Occluders first: the largest on screen, within the triangle budget.
    std::vector<std::size_t> by_size(candidates.size());
    std::iota(by_size.begin(), by_size.end(), std::size_t{0});
    std::stable_sort(by_size.begin(), by_size.end(), [&](std::size_t a, std::size_t b) {
        return candidates[a].screen_fraction > candidates[b].screen_fraction;
    });
    OcclusionBuffer buffer(options.width, options.height);
    buffer.set_simd(options.simd);
    const OccluderOptions occluder = occluder_options(options);
    std::vector<bool> is_occluder(candidates.size(), false);
    std::vector<std::size_t> occluders;
    std::size_t budget = kOccluderTriangleBudget;
    for (const std::size_t k : by_size) {
        const Candidate& c = candidates[k];
        if (c.screen_fraction < kOccluderFraction) break;
        if (c.triangles > budget) continue;
        budget -= c.triangles;
        is_occluder[k] = true;
        occluders.push_back(k);
    }
    // Drawn nearest first: the buffer keeps two depth layers per row, and a far surface drawn
    // before a near one can cost the near one's detail.
    std::stable_sort(occluders.begin(), occluders.end(), [&](std::size_t a, std::size_t b) {
        return candidates[a].distance < candidates[b].distance;
    });
    for (const std::size_t k : occluders) {
        const Candidate& c = candidates[k];
        draw_occluder(buffer, scene.meshes[scene.instances[c.instance].mesh], c, occluder);
    }
    // Then everything else, nearest first.
    std::vector<std::size_t> by_distance;
    for (std::size_t k = 0; k < candidates.size(); ++k)
        if (!is_occluder[k]) by_distance.push_back(k);
    std::stable_sort(by_distance.begin(), by_distance.end(), [&](std::size_t a, std::size_t b) {
        return candidates[a].distance < candidates[b].distance;
    });
    for (const std::size_t k : by_distance) {
        const Candidate& c = candidates[k];
        const Mesh& mesh = scene.meshes[scene.instances[c.instance].mesh];
        const OcclusionResult r = buffer.test_box(mesh.bounds, c.mvp);
        if (r == OcclusionResult::Occluded) {
            verdict[c.instance] = InstanceCull::Occluded;
        } else if (r == OcclusionResult::Visible && c.screen_fraction >= kLateOccluderFraction &&
                   c.triangles <= kLateOccluderTriangles && c.triangles <= budget) {
            budget -= c.triangles;
            draw_occluder(buffer, mesh, c, occluder);
        }
    }
    return verdict;
}

}  // namespace zraster::detail
