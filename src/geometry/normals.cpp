// Vertex and face normals.
//
// Angle-weighted vertex normals: G. Thürmer, C. A. Wüthrich, "Computing Vertex Normals from
// Polygonal Facets", Journal of Graphics Tools 3(1), 1998. Weighting each incident face by its
// angle at the vertex makes the normal depend only on the surface's shape, not on how it was
// triangulated (area or uniform weighting both change when a face is split).
#include <zraster/mesh.hpp>

#include <cassert>
#include <cmath>

namespace zraster {

namespace {

// Angle between u and v; atan2 stays accurate near 0 and pi where acos(dot) loses all precision.
double angle_between(const glm::dvec3& u, const glm::dvec3& v) {
    return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
}

}  // namespace

void compute_angle_weighted_normals(Mesh& mesh) {
    std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0.0));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t i[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
        assert(i[0] < mesh.positions.size() && i[1] < mesh.positions.size() &&
               i[2] < mesh.positions.size());
        const glm::dvec3 p[3] = {glm::dvec3(mesh.positions[i[0]]), glm::dvec3(mesh.positions[i[1]]),
                                 glm::dvec3(mesh.positions[i[2]])};
        const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        const double len = glm::length(n);
        if (!(len > 0.0) || !std::isfinite(len)) continue;  // degenerate: no defined orientation
        const glm::dvec3 unit = n / len;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3& here = p[k];
            const double angle = angle_between(p[(k + 1) % 3] - here, p[(k + 2) % 3] - here);
            sum[i[k]] += unit * angle;
        }
    }
    mesh.normals.resize(mesh.positions.size());
    for (std::size_t v = 0; v < sum.size(); ++v) {
        const double len = glm::length(sum[v]);
        mesh.normals[v] = len > 0.0 ? glm::vec3(sum[v] / len) : glm::vec3(0.0f, 1.0f, 0.0f);
    }
}

std::vector<glm::vec3> compute_face_normals(const Mesh& mesh) {
    std::vector<glm::vec3> out;
    out.reserve(mesh.triangle_count());
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::dvec3 a{mesh.positions[mesh.indices[t]]};
        const glm::dvec3 b{mesh.positions[mesh.indices[t + 1]]};
        const glm::dvec3 c{mesh.positions[mesh.indices[t + 2]]};
        const glm::dvec3 n = glm::cross(b - a, c - a);
        const double len = glm::length(n);
        out.push_back(len > 0.0 && std::isfinite(len) ? glm::vec3(n / len)
                                                      : glm::vec3(0.0f, 1.0f, 0.0f));
    }
    return out;
}

}  // namespace zraster
