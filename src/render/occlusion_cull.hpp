// Instance culling before the vertex stage: a BVH over instance bounds for frustum culling
// scenes of many instances, and, with RenderOptions::occlusion_cull, occlusion culling with an
// OcclusionBuffer (src/occlusion/).
#pragma once
#include <cstdint>
#include <vector>

#include "render/frame.hpp"

namespace zraster::detail {

enum class InstanceCull : std::uint8_t {
    Keep,      // still goes through the vertex stage's own frustum test
    Frustum,   // outside the view frustum (found by the instance BVH)
    Occluded,  // hidden behind occluders that are drawn this frame
    Portal,    // reached by no portal sequence from the eye's cell (or outside its PVS)
};

// Scenes with at least this many instances use the BVH for frustum culling.
inline constexpr std::size_t kBvhMinInstances = 64;

// One verdict per scene instance, into frame.culling.verdicts (InstanceCull values). Occlusion
// culling only runs when the frame's result cannot change: D32F depth with the LESS or LEQUAL
// test and depth writes, a standard (not reversed) depth range, no user clip planes, no
// wireframe or hidden-line edges. Occluders (the largest instances on screen, then visible ones
// tested front to back) are rendered at the frame's resolution with its face culling, and are
// never culled themselves, so an Occluded instance has no pixel in the image.
// With RenderOptions::portal_cull or a cell graph's PVS, under the same conditions, instances no
// portal sequence reaches are marked Portal (portal_cull.hpp) before occlusion culling.
void cull_instances(Frame& frame, const glm::mat4& view_projection);

// Whether skipping instances that have no visible pixel leaves the image as it is: what
// occlusion and portal culling require.
bool culling_keeps_image(const Frame& frame);

}  // namespace zraster::detail
