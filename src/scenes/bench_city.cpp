// The benchmark city, "city:N[:SEED]" of docs/bench-scenes.md: random boxes on a ground quad.
// Every random draw and every arithmetic step follows the document's order exactly (in double,
// rounded to float when stored); changing either changes the geometry_hash.
#include <zraster/scenes.hpp>

#include <cassert>
#include <cmath>
#include <string>

namespace zraster {

namespace {

// Corners counter-clockwise seen from the front: triangles (q0, q1, q2), (q0, q2, q3).
void add_quad(Mesh& mesh, const glm::dvec3& q0, const glm::dvec3& q1, const glm::dvec3& q2,
              const glm::dvec3& q3, const glm::vec3& normal) {
    const auto base = std::uint32_t(mesh.positions.size());
    for (const glm::dvec3& q : {q0, q1, q2, q3}) {
        mesh.positions.push_back(glm::vec3(q));
        mesh.normals.push_back(normal);
    }
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

}  // namespace

Mesh make_bench_city(long n, std::uint64_t seed) {
    assert(n >= 1);
    SplitMix64 rng(seed);
    const double size = 1.5 * std::sqrt(double(n));
    const double half = size / 2;

    Mesh mesh;
    mesh.name = "city:" + std::to_string(n) + ":" + std::to_string(seed);
    mesh.positions.reserve(std::size_t(20 * n + 4));
    mesh.normals.reserve(std::size_t(20 * n + 4));
    mesh.indices.reserve(std::size_t(30 * n + 6));

    add_quad(mesh, {-half, 0, half}, {half, 0, half}, {half, 0, -half}, {-half, 0, -half},
             {0, 1, 0});
    for (long i = 0; i < n; ++i) {
        // Separate statements: the draws must happen in exactly this order.
        const double cx = rng.uniform(-half + 1, half - 1);
        const double cz = rng.uniform(-half + 1, half - 1);
        const double sx = rng.uniform(0.6, 2.0);
        const double sz = rng.uniform(0.6, 2.0);
        const double u = rng.unit();
        const double h = 1.0 + ((15.0 * u) * u);  // most boxes low, a few tall
        const double x0 = cx - sx / 2, x1 = cx + sx / 2, z0 = cz - sz / 2, z1 = cz + sz / 2;
        add_quad(mesh, {x0, h, z1}, {x1, h, z1}, {x1, h, z0}, {x0, h, z0}, {0, 1, 0});
        add_quad(mesh, {x1, 0, z1}, {x1, 0, z0}, {x1, h, z0}, {x1, h, z1}, {1, 0, 0});
        add_quad(mesh, {x0, 0, z0}, {x0, 0, z1}, {x0, h, z1}, {x0, h, z0}, {-1, 0, 0});
        add_quad(mesh, {x0, 0, z1}, {x1, 0, z1}, {x1, h, z1}, {x0, h, z1}, {0, 0, 1});
        add_quad(mesh, {x1, 0, z0}, {x0, 0, z0}, {x0, h, z0}, {x1, h, z0}, {0, 0, -1});
    }
    update_bounds(mesh);
    return mesh;
}

}  // namespace zraster
