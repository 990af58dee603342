// Helpers for renderer tests: scenes from raw triangles, and a double-precision ray caster as
// the reference for what each pixel should see.
#pragma once
#include <zraster/render.hpp>
#include <zraster/scene.hpp>

#include <glm/gtc/matrix_inverse.hpp>

#include <optional>
#include <vector>

namespace zraster::test {

// One mesh (and instance) per triangle list; indices 0..n-1.
inline Scene scene_from_triangles(const std::vector<std::vector<glm::vec3>>& meshes) {
    std::vector<Mesh> out;
    for (const auto& positions : meshes) {
        Mesh m;
        m.positions = positions;
        for (std::uint32_t i = 0; i < positions.size(); ++i) m.indices.push_back(i);
        compute_angle_weighted_normals(m);
        update_bounds(m);
        out.push_back(std::move(m));
    }
    return scene_from_meshes(std::move(out));
}

struct RayHit {
    double t;         // along the ray, in world units from the eye
    glm::dvec3 bary;  // barycentric weights of the hit point
    double ndc_z;     // depth of the hit in NDC
};

// The ray through the center of pixel (px, py) (row 0 at the top) of a camera.
struct PixelRay {
    glm::dvec3 origin, direction;
};

class RayCaster {
  public:
    RayCaster(const Camera& camera, int width, int height) : width_(width), height_(height) {
        const double aspect = double(width) / double(height);
        view_projection_ = glm::dmat4(camera.projection_matrix(aspect)) * camera.view();
        inverse_ = glm::inverse(view_projection_);
    }

    PixelRay ray(int px, int py) const {
        const double x = (px + 0.5) / width_ * 2.0 - 1.0;
        const double y = 1.0 - (py + 0.5) / height_ * 2.0;
        glm::dvec4 a = inverse_ * glm::dvec4(x, y, -1.0, 1.0);
        glm::dvec4 b = inverse_ * glm::dvec4(x, y, 0.0, 1.0);
        a /= a.w;
        b /= b.w;
        return {glm::dvec3(a), glm::normalize(glm::dvec3(b - a))};
    }

    // Möller-Trumbore in double. Returns the hit even slightly outside the triangle (the
    // caller classifies by bary) but only in front of the ray origin.
    std::optional<RayHit> intersect(const PixelRay& r, glm::dvec3 a, glm::dvec3 b,
                                    glm::dvec3 c) const {
        const glm::dvec3 e1 = b - a, e2 = c - a;
        const glm::dvec3 p = glm::cross(r.direction, e2);
        const double det = glm::dot(e1, p);
        if (std::abs(det) < 1e-300) return std::nullopt;
        const glm::dvec3 s = r.origin - a;
        const double u = glm::dot(s, p) / det;
        const glm::dvec3 q = glm::cross(s, e1);
        const double v = glm::dot(r.direction, q) / det;
        const double t = glm::dot(e2, q) / det;
        if (t <= 0) return std::nullopt;
        const glm::dvec3 hit = r.origin + t * r.direction;
        const glm::dvec4 clip = view_projection_ * glm::dvec4(hit, 1.0);
        return RayHit{t, {1.0 - u - v, u, v}, clip.z / clip.w};
    }

  private:
    int width_, height_;
    glm::dmat4 view_projection_, inverse_;
};

}  // namespace zraster::test
