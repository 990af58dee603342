// InstanceBvh and frustum planes (include/zraster/instance_bvh.hpp).
#include <zraster/instance_bvh.hpp>

#include <algorithm>
#include <cmath>

namespace zraster {

std::array<glm::vec4, 6> frustum_planes(const glm::mat4& view_projection, ClipDepthRange range) {
    // Row i of the matrix dotted with (p, 1) is clip coordinate i (Gribb & Hartmann 2001).
    const glm::dmat4 m(view_projection);
    const auto row = [&](int i) { return glm::dvec4(m[0][i], m[1][i], m[2][i], m[3][i]); };
    const glm::dvec4 x = row(0), y = row(1), z = row(2), w = row(3);
    const glm::dvec4 near = range == ClipDepthRange::ZeroToOne ? z : w + z;
    const std::array<glm::dvec4, 6> planes = {w + x, w - x, w + y, w - y, near, w - z};
    std::array<glm::vec4, 6> out;
    for (int i = 0; i < 6; ++i) {
        const double length = glm::length(glm::dvec3(planes[i]));
        out[i] = glm::vec4(length > 0.0 ? planes[i] / length : planes[i]);
    }
    return out;
}

namespace {

// Empty, NaN or infinite boxes are never rejected; nodes holding one are not either.
bool ordinary(const Bounds3f& box) {
    return !box.empty() && std::isfinite(box.lo.x) && std::isfinite(box.lo.y) &&
           std::isfinite(box.lo.z) && std::isfinite(box.hi.x) && std::isfinite(box.hi.y) &&
           std::isfinite(box.hi.z);
}

}  // namespace

bool outside_planes(const Bounds3f& box, std::span<const glm::vec4> planes) {
    if (!ordinary(box)) return false;
    for (const glm::vec4& p : planes) {
        // The corner furthest along the normal; if even it is outside, the whole box is.
        const glm::vec3 corner(p.x >= 0.0f ? box.hi.x : box.lo.x, p.y >= 0.0f ? box.hi.y : box.lo.y,
                               p.z >= 0.0f ? box.hi.z : box.lo.z);
        const float distance = (p.x * corner.x + p.y * corner.y) + (p.z * corner.z + p.w);
        const glm::vec3 n = glm::abs(glm::vec3(p));
        // max(|lo|, |hi|) never grows from a node to its children: the test stays monotone.
        const glm::vec3 reach = glm::max(glm::abs(box.lo), glm::abs(box.hi));
        const float extent = 2.0f * glm::dot(n, reach) + std::abs(p.w);
        if (distance < -0x1p-16f * extent) return true;
    }
    return false;
}

void InstanceBvh::build(std::span<const Bounds3f> boxes) {
    nodes_.clear();
    order_.resize(boxes.size());
    for (std::uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
    if (boxes.empty()) return;
    nodes_.reserve(2 * boxes.size() / kLeafSize + 2);
    build_node(boxes, 0, static_cast<std::uint32_t>(boxes.size()));
    leaf_boxes_.resize(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) leaf_boxes_[i] = boxes[order_[i]];
}

std::uint32_t InstanceBvh::build_node(std::span<const Bounds3f> boxes, std::uint32_t begin,
                                      std::uint32_t end) {
    const std::uint32_t index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    Bounds3f bounds, centers;
    bool keep = false;
    for (std::uint32_t i = begin; i < end; ++i) {
        const Bounds3f& b = boxes[order_[i]];
        if (!ordinary(b)) {
            keep = true;
            continue;
        }
        bounds.extend(b);
        centers.extend(b.center());
    }
    nodes_[index].bounds = bounds;
    nodes_[index].keep = keep || bounds.empty();
    if (end - begin <= static_cast<std::uint32_t>(kLeafSize) || centers.empty()) {
        nodes_[index].first = begin;
        nodes_[index].count = end - begin;
        return index;
    }
    const glm::vec3 extent = centers.extent();
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::uint32_t middle = begin + (end - begin) / 2;
    // Unusual boxes sort first (a strict weak order even with NaN), then by center.
    const auto key = [&](std::uint32_t i) {
        const Bounds3f& b = boxes[i];
        return ordinary(b) ? b.lo[axis] + b.hi[axis] : -HUGE_VALF;
    };
    std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
    build_node(boxes, begin, middle);  // the left child is index + 1
    const std::uint32_t right = build_node(boxes, middle, end);
    nodes_[index].first = right;
    nodes_[index].count = 0;
    return index;
}

void InstanceBvh::query(std::span<const glm::vec4> planes, std::vector<std::uint32_t>& out) const {
    if (nodes_.empty()) return;
    const std::size_t start = out.size();
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (!node.keep && outside_planes(node.bounds, planes)) continue;
        if (node.count > 0) {
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
                if (!outside_planes(leaf_boxes_[i], planes)) out.push_back(order_[i]);
            continue;
        }
        const std::uint32_t self = static_cast<std::uint32_t>(&node - nodes_.data());
        stack[top++] = node.first;  // right
        stack[top++] = self + 1;    // left
    }
    std::sort(out.begin() + static_cast<std::ptrdiff_t>(start), out.end());
}

}  // namespace zraster
