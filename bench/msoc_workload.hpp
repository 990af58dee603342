// Masked Software Occlusion Culling's classic fill-rate workload, as occlusion_bench and the
// side-by-side comparison with MSOC itself (scripts/msoc_compare.sh) render it: 100,000
// triangles of about 50 pixels each at 1920 x 1080, deterministic (splitmix64 seeded with 1).
// Each triangle is equilateral with circumradius R = sqrt(200 / (3 sqrt 3)) = 6.20 px, so its
// area is (3 sqrt 3 / 4) R^2 = 50 px^2, rotated by a random angle, centered at a uniformly random
// point of the screen; its vertices are counter-clockwise on screen (front-facing, none culled)
// at a random NDC depth in [-0.9, 0.9] (plus up to +-0.01 per vertex) and given in clip space
// with a random w in [1, 4] (so x, y, z are NDC * w).
#pragma once
#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

namespace zraster::bench {

constexpr int kWidth = 1920, kHeight = 1080;
constexpr int kTriangles = 100'000;

struct SplitMix64 {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    double uniform() { return static_cast<double>(next() >> 11) * 0x1p-53; }  // [0, 1)
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
};

struct Workload {
    std::vector<glm::vec4> clip;
    std::vector<glm::vec3> ndc;  // the same vertices with w = 1, for the matrix path
    std::vector<std::uint32_t> indices;
};

inline const Workload& msoc_workload() {
    static const Workload w = [] {
        Workload out;
        SplitMix64 rng{1};
        const double radius = std::sqrt(200.0 / (3.0 * std::sqrt(3.0)));
        for (int t = 0; t < kTriangles; ++t) {
            const double cx = rng.uniform(0.0, kWidth), cy = rng.uniform(0.0, kHeight);
            const double angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
            const double depth = rng.uniform(-0.9, 0.9);
            const double w = rng.uniform(1.0, 4.0);
            for (int k = 0; k < 3; ++k) {
                // Counter-clockwise with y up: increasing angle in NDC.
                const double a = angle + k * 2.0 * std::numbers::pi / 3.0;
                const double px = cx + radius * std::cos(a), py = cy - radius * std::sin(a);
                const double nx = px / kWidth * 2.0 - 1.0, ny = 1.0 - py / kHeight * 2.0;
                const double nz = depth + rng.uniform(-0.01, 0.01);
                out.clip.emplace_back(nx * w, ny * w, nz * w, w);
                out.ndc.emplace_back(nx, ny, nz);
                out.indices.push_back(static_cast<std::uint32_t>(out.indices.size()));
            }
        }
        return out;
    }();
    return w;
}

}  // namespace zraster::bench
