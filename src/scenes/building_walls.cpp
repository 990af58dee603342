// Watertight wall slabs with an optional doorway (building_walls.hpp).
#include "scenes/building_walls.hpp"

#include <array>
#include <vector>

namespace zraster::detail {
namespace {

class SlabBuilder {
  public:
    explicit SlabBuilder(const WallSlab& wall) : wall_(wall) {
        along_ = {wall.start, wall.end};
        if (wall.door) along_ = {wall.start, wall.door->first, wall.door->second, wall.end};
        up_ = {0.0, wall.door_height, wall.height};
    }

    Mesh build() {
        const int columns = int(along_.size()) - 1, rows = int(up_.size()) - 1;
        const double t = wall_.half_thickness;
        for (int a = 0; a < columns; ++a)
            for (int r = 0; r < rows; ++r) {
                if (!filled(a, r)) continue;
                const double a0 = along_[a], a1 = along_[a + 1], u0 = up_[r], u1 = up_[r + 1];
                // Both broad faces, then every side that borders empty space.
                face({0, 0, 1}, {a0, u0, t}, {a1, u0, t}, {a1, u1, t}, {a0, u1, t});
                face({0, 0, -1}, {a0, u0, -t}, {a1, u0, -t}, {a1, u1, -t}, {a0, u1, -t});
                if (!filled(a - 1, r))
                    face({-1, 0, 0}, {a0, u0, -t}, {a0, u0, t}, {a0, u1, t}, {a0, u1, -t});
                if (!filled(a + 1, r))
                    face({1, 0, 0}, {a1, u0, -t}, {a1, u0, t}, {a1, u1, t}, {a1, u1, -t});
                if (!filled(a, r - 1))
                    face({0, -1, 0}, {a0, u0, -t}, {a1, u0, -t}, {a1, u0, t}, {a0, u0, t});
                if (!filled(a, r + 1))
                    face({0, 1, 0}, {a0, u1, -t}, {a1, u1, -t}, {a1, u1, t}, {a0, u1, t});
            }
        update_bounds(mesh_);
        return std::move(mesh_);
    }

  private:
    bool filled(int a, int r) const {
        if (a < 0 || r < 0 || a + 1 >= int(along_.size()) || r + 1 >= int(up_.size())) return false;
        return !(wall_.door && a == 1 && r == 0);  // the doorway
    }

    // Local (along, up, across) to world.
    glm::dvec3 world(const glm::dvec3& local) const {
        return wall_.constant_x ? glm::dvec3(wall_.center + local.z, local.y, local.x)
                                : glm::dvec3(local.x, local.y, wall_.center + local.z);
    }

    // A quad, wound counter-clockwise seen from the side its outward normal points to.
    void face(const glm::dvec3& local_normal, const glm::dvec3& q0, const glm::dvec3& q1,
              const glm::dvec3& q2, const glm::dvec3& q3) {
        const glm::dvec3 n = world(local_normal) - world(glm::dvec3(0.0));
        std::array<glm::dvec3, 4> q{world(q0), world(q1), world(q2), world(q3)};
        if (glm::dot(glm::cross(q[1] - q[0], q[2] - q[0]), n) < 0.0) std::swap(q[1], q[3]);
        const auto base = std::uint32_t(mesh_.positions.size());
        for (const glm::dvec3& p : q) {
            mesh_.positions.push_back(glm::vec3(p));
            mesh_.normals.push_back(glm::vec3(n));
        }
        mesh_.indices.insert(mesh_.indices.end(),
                             {base, base + 1, base + 2, base, base + 2, base + 3});
    }

    const WallSlab& wall_;
    std::vector<double> along_, up_;
    Mesh mesh_;
};

}  // namespace

Mesh make_wall_slab(const WallSlab& wall) {
    return SlabBuilder(wall).build();
}

}  // namespace zraster::detail
