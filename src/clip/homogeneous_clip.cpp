// Sutherland-Hodgman clipping in homogeneous coordinates (Sutherland & Hodgman 1974;
// Blinn & Newell 1978). See include/zraster/clip.hpp for the contract.
#include <zraster/clip.hpp>

#include <cassert>

namespace zraster {
namespace {

// A polygon vertex during clipping: position, barycentric weights, and its distance to each user
// plane. The distances travel with the vertex (interpolated with the same t) instead of being
// recomputed from the weights, so a shared edge is cut at bit-identical points in both triangles.
struct WorkVertex {
    glm::vec4 position;
    glm::vec3 weights;
    std::array<float, kMaxUserClipPlanes> user;
};

float distance_to(const WorkVertex& v, int bit_index, const ClipSettings& s) {
    if (bit_index >= 6) return v.user[static_cast<std::size_t>(bit_index - 6)];
    return frustum_plane_distance(bit_index, v.position, s);
}

WorkVertex intersect(const WorkVertex& inside, float d_inside, const WorkVertex& outside,
                     float d_outside) {
    // From the inside vertex towards the outside one: the same edge always gives the same point.
    const float t = d_inside / (d_inside - d_outside);
    WorkVertex r;
    r.position = inside.position + t * (outside.position - inside.position);
    r.weights = inside.weights + t * (outside.weights - inside.weights);
    for (std::size_t k = 0; k < r.user.size(); ++k)
        r.user[k] = inside.user[k] + t * (outside.user[k] - inside.user[k]);
    return r;
}

int clip_work_polygon(const WorkVertex* in, int n, int bit_index, const ClipSettings& s,
                      WorkVertex* out) {
    int count = 0;
    for (int i = 0; i < n; ++i) {
        const WorkVertex& a = in[i];
        const WorkVertex& b = in[(i + 1) % n];
        const float da = distance_to(a, bit_index, s);
        const float db = distance_to(b, bit_index, s);
        const bool a_in = da >= 0.0f;
        const bool b_in = db >= 0.0f;
        if (a_in) out[count++] = a;
        if (a_in != b_in) out[count++] = a_in ? intersect(a, da, b, db) : intersect(b, db, a, da);
    }
    return count;
}

}  // namespace

std::uint32_t clip_outcode(const glm::vec4& v, const ClipSettings& s,
                           std::span<const float> user_distances) {
    std::uint32_t code = frustum_outcode(v, s);
    for (int k = 0; k < s.user_plane_count && k < static_cast<int>(user_distances.size()); ++k)
        if (!(user_distances[static_cast<std::size_t>(k)] >= 0.0f)) code |= kClipUser0 << k;
    return code;
}

void clip_triangle(const std::array<glm::vec4, 3>& v, std::uint32_t planes,
                   const ClipSettings& settings,
                   std::span<const std::array<float, 3>> user_distances, ClippedPolygon& out) {
    WorkVertex buffers[2][kMaxClippedVertices];
    WorkVertex* current = buffers[0];
    WorkVertex* next = buffers[1];
    for (int i = 0; i < 3; ++i) {
        current[i].position = v[static_cast<std::size_t>(i)];
        current[i].weights = glm::vec3(0.0f);
        current[i].weights[i] = 1.0f;
        current[i].user.fill(0.0f);
        for (std::size_t k = 0; k < user_distances.size() && k < kMaxUserClipPlanes; ++k)
            current[i].user[k] = user_distances[k][static_cast<std::size_t>(i)];
    }
    int n = 3;
    const int plane_count = 6 + settings.user_plane_count;
    for (int bit = 0; bit < plane_count && n > 0; ++bit) {
        if (!(planes & (1u << bit))) continue;
        n = clip_work_polygon(current, n, bit, settings, next);
        assert(n <= kMaxClippedVertices);
        std::swap(current, next);
    }
    out.count = n;
    for (int i = 0; i < n; ++i)
        out.vertices[static_cast<std::size_t>(i)] = {current[i].position, current[i].weights};
}

int clip_polygon_against_plane(std::span<const ClipVertex> in, const glm::vec4& plane,
                               std::span<ClipVertex> out) {
    const int n = static_cast<int>(in.size());
    int count = 0;
    for (int i = 0; i < n; ++i) {
        const ClipVertex& a = in[static_cast<std::size_t>(i)];
        const ClipVertex& b = in[static_cast<std::size_t>((i + 1) % n)];
        const float da = glm::dot(plane, a.position);
        const float db = glm::dot(plane, b.position);
        const bool a_in = da >= 0.0f;
        const bool b_in = db >= 0.0f;
        if (a_in) {
            assert(std::size_t(count) < out.size());
            out[static_cast<std::size_t>(count++)] = a;
        }
        if (a_in != b_in) {
            assert(std::size_t(count) < out.size());
            const ClipVertex& p = a_in ? a : b;  // inside
            const ClipVertex& q = a_in ? b : a;  // outside
            const float dp = a_in ? da : db;
            const float dq = a_in ? db : da;
            const float t = dp / (dp - dq);
            out[static_cast<std::size_t>(count++)] = {p.position + t * (q.position - p.position),
                                                      p.weights + t * (q.weights - p.weights)};
        }
    }
    return count;
}

}  // namespace zraster
