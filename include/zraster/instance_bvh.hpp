// A bounding volume hierarchy over the world-space boxes of a scene's instances, for frustum
// culling scenes of many instances in O(visible + log n) box tests instead of n.
//
// Built top-down by median split on the longest axis of the boxes' centers (Kay & Kajiya 1986
// bound the nodes; the split is the classic object median), at most kLeafSize boxes per leaf,
// nodes stored depth-first so the left child follows its parent.
//
// A box is "outside" a set of planes when all of it lies on the negative side of one plane by
// more than a small slack (see outside_planes): the test is conservative (a box the exact test
// would keep is kept) and monotone (a node containing a kept box is kept), so a query returns
// exactly the boxes outside_planes keeps.
#pragma once
#include <zraster/bounds.hpp>
#include <zraster/camera.hpp>
#include <zraster/export.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace zraster {

// The six planes (n.x, n.y, n.z, d) of the view frustum of a view-projection matrix, world
// space; points with dot(n, p) + d >= 0 are inside (Gribb & Hartmann 2001). Order: left, right,
// bottom, top, near, far.
ZRASTER_API std::array<glm::vec4, 6> frustum_planes(const glm::mat4& view_projection,
                                                    ClipDepthRange range);

// True when `box` lies entirely on the outside of one of `planes` by more than a slack of
// 2^-16 * (2 |n| . max(|lo|, |hi|) + |d|) (covers float rounding of transforms and plane
// extraction). Empty or non-finite boxes are never outside (the caller decides about them).
ZRASTER_API bool outside_planes(const Bounds3f& box, std::span<const glm::vec4> planes);

class ZRASTER_API InstanceBvh {
  public:
    static constexpr int kLeafSize = 4;

    InstanceBvh() = default;
    explicit InstanceBvh(std::span<const Bounds3f> boxes) { build(boxes); }
    void build(std::span<const Bounds3f> boxes);

    // Appends to `out`, in increasing order, the index of every box not outside `planes`.
    void query(std::span<const glm::vec4> planes, std::vector<std::uint32_t>& out) const;

    std::size_t size() const { return order_.size(); }
    std::size_t node_count() const { return nodes_.size(); }

  private:
    struct Node {
        Bounds3f bounds;
        std::uint32_t first = 0;  // leaf: first index into order_; inner: right child
        std::uint32_t count = 0;  // leaf: number of boxes; inner: 0
        bool keep = false;        // holds an empty or non-finite box: never rejected whole
    };
    std::uint32_t build_node(std::span<const Bounds3f> boxes, std::uint32_t begin,
                             std::uint32_t end);
    std::vector<Node> nodes_;
    std::vector<std::uint32_t> order_;  // box indices, leaves' ranges
    std::vector<Bounds3f> leaf_boxes_;  // boxes[order_[i]]
};

}  // namespace zraster
