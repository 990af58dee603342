// The benchmark UV sphere, "sphere:N" of docs/bench-scenes.md. Computed in double in the order the
// document writes it and rounded to float only when stored, so that the geometry (and its
// geometry_hash) is bit-identical to the llvmpipe harness's.
#include <zraster/scenes.hpp>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <string>

namespace zraster {

Mesh make_bench_sphere(long n) {
    assert(n >= 1);
    const long stacks = std::max(2L, std::lround(std::sqrt(double(n) / 4.0)));
    const long slices = 2 * stacks;

    Mesh mesh;
    mesh.name = "sphere:" + std::to_string(n);
    const auto vertices = std::size_t(stacks + 1) * std::size_t(slices + 1);
    mesh.positions.reserve(vertices);
    mesh.normals.reserve(vertices);
    for (long i = 0; i <= stacks; ++i) {
        const double theta = std::numbers::pi * double(i) / double(stacks);
        for (long j = 0; j <= slices; ++j) {
            const double phi = 2.0 * std::numbers::pi * double(j) / double(slices);
            const glm::dvec3 p{std::sin(theta) * std::cos(phi), std::cos(theta),
                               -std::sin(theta) * std::sin(phi)};
            mesh.positions.push_back(glm::vec3(p));
            mesh.normals.push_back(glm::vec3(p));
        }
    }

    auto index = [&](long i, long j) { return std::uint32_t(i * (slices + 1) + j); };
    mesh.indices.reserve(std::size_t(12 * stacks * (stacks - 1)));
    for (long i = 0; i < stacks; ++i) {
        for (long j = 0; j < slices; ++j) {
            const std::uint32_t a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1),
                                d = index(i, j + 1);
            // The first and last rows each have one triangle per quad collapsed onto the pole.
            if (i != stacks - 1) mesh.indices.insert(mesh.indices.end(), {a, b, c});
            if (i != 0) mesh.indices.insert(mesh.indices.end(), {a, c, d});
        }
    }
    update_bounds(mesh);
    return mesh;
}

}  // namespace zraster
