// The benchmark triangle soup, "soup:N[:SEED]" of docs/bench-scenes.md: small random triangles in
// [-1, 1]^3, in random orientations (about half are back-facing).
#include <zraster/scenes.hpp>

#include <cassert>
#include <cmath>
#include <string>

namespace zraster {

Mesh make_bench_soup(long n, std::uint64_t seed) {
    assert(n >= 1);
    const double s = 0.02;  // largest per-axis offset of a corner from the triangle's center
    SplitMix64 rng(seed);

    Mesh mesh;
    mesh.name = "soup:" + std::to_string(n) + ":" + std::to_string(seed);
    mesh.positions.reserve(std::size_t(3 * n));
    mesh.normals.reserve(std::size_t(3 * n));
    mesh.indices.reserve(std::size_t(3 * n));
    for (long i = 0; i < n; ++i) {
        const double cx = rng.uniform(-1, 1);
        const double cy = rng.uniform(-1, 1);
        const double cz = rng.uniform(-1, 1);
        const auto base = std::uint32_t(mesh.positions.size());
        for (std::uint32_t k = 0; k < 3; ++k) {
            const double ox = rng.uniform(-s, s);
            const double oy = rng.uniform(-s, s);
            const double oz = rng.uniform(-s, s);
            mesh.positions.push_back(glm::vec3(glm::dvec3(cx + ox, cy + oy, cz + oz)));
            mesh.indices.push_back(base + k);
        }
        // From the stored float positions, so the normal matches the triangle actually drawn.
        const glm::dvec3 a{mesh.positions[base]};
        const glm::dvec3 n_raw = glm::cross(glm::dvec3(mesh.positions[base + 1]) - a,
                                            glm::dvec3(mesh.positions[base + 2]) - a);
        const double len = std::sqrt(glm::dot(n_raw, n_raw));
        const glm::vec3 normal = len > 0 ? glm::vec3(n_raw / len) : glm::vec3(0, 1, 0);
        mesh.normals.insert(mesh.normals.end(), {normal, normal, normal});
    }
    update_bounds(mesh);
    return mesh;
}

}  // namespace zraster
