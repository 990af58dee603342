// fit_camera against the reference table of ../shared/docs/BENCH-SCENES.md ("Camera"): the
// scenes' float positions are regenerated here exactly as that document specifies (only the
// positions: the framing depends on nothing else) and the framing must match to the last float bit.
#include <zraster/camera.hpp>

#include "support/test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <initializer_list>
#include <numbers>
#include <string>
#include <vector>

namespace zraster {
namespace {

struct SplitMix64 {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    double unit() { return double(next() >> 11) * 0x1.0p-53; }
    double uniform(double a, double b) { return a + (b - a) * unit(); }
};

glm::vec3 to_float(double x, double y, double z) {
    return {float(x), float(y), float(z)};
}

std::vector<glm::vec3> sphere_positions(long n) {
    const long stacks = std::max(2L, std::lround(std::sqrt(double(n) / 4.0))), slices = 2 * stacks;
    std::vector<glm::vec3> out;
    for (long i = 0; i <= stacks; ++i) {
        const double theta = std::numbers::pi * double(i) / double(stacks);
        for (long j = 0; j <= slices; ++j) {
            const double phi = 2.0 * std::numbers::pi * double(j) / double(slices);
            out.push_back(to_float(std::sin(theta) * std::cos(phi), std::cos(theta),
                                   -std::sin(theta) * std::sin(phi)));
        }
    }
    return out;
}

// Corner positions only (the framing uses every vertex; the quads' order does not matter).
std::vector<glm::vec3> city_positions(long n, std::uint64_t seed) {
    SplitMix64 rng{seed};
    const double half = 1.5 * std::sqrt(double(n)) / 2.0;
    std::vector<glm::vec3> out = {to_float(-half, 0, half), to_float(half, 0, half),
                                  to_float(half, 0, -half), to_float(-half, 0, -half)};
    for (long i = 0; i < n; ++i) {
        const double cx = rng.uniform(-half + 1, half - 1);
        const double cz = rng.uniform(-half + 1, half - 1);
        const double sx = rng.uniform(0.6, 2.0);
        const double sz = rng.uniform(0.6, 2.0);
        const double u = rng.unit();
        const double h = 1.0 + 15.0 * u * u;
        const double x0 = cx - sx / 2, x1 = cx + sx / 2, z0 = cz - sz / 2, z1 = cz + sz / 2;
        for (double x : {x0, x1})
            for (double y : {0.0, h})
                for (double z : {z0, z1}) out.push_back(to_float(x, y, z));
    }
    return out;
}

std::vector<glm::vec3> soup_positions(long n, std::uint64_t seed) {
    const double s = 0.02;
    SplitMix64 rng{seed};
    std::vector<glm::vec3> out;
    out.reserve(std::size_t(n) * 3);
    for (long i = 0; i < n; ++i) {
        const double cx = rng.uniform(-1, 1), cy = rng.uniform(-1, 1), cz = rng.uniform(-1, 1);
        for (int k = 0; k < 3; ++k) {
            const double ox = rng.uniform(-s, s), oy = rng.uniform(-s, s), oz = rng.uniform(-s, s);
            out.push_back(to_float(cx + ox, cy + oy, cz + oz));
        }
    }
    return out;
}

struct Reference {
    glm::vec3 center;
    float radius;
    glm::vec3 eye;
    float near, far;
};

void expect_framing(std::span<const glm::vec3> points, const Reference& ref) {
    const Camera cam = fit_camera(points);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(float(cam.target[k]), ref.center[k]) << "center " << k;
        EXPECT_EQ(float(cam.eye[k]), ref.eye[k]) << "eye " << k;
    }
    // radius = (far - near) / 2.02 up to rounding; the table prints it rounded to float.
    EXPECT_NEAR((cam.far - cam.near) / 2.02, double(ref.radius), 1e-6 * ref.radius);
    EXPECT_EQ(float(cam.near), ref.near);
    EXPECT_EQ(float(cam.far), ref.far);
}

TEST(BenchFraming, SplitMixFirstOutputs) {
    SplitMix64 rng{1};
    EXPECT_EQ(rng.next(), 0x910a2dec89025cc1ull);
    EXPECT_EQ(rng.next(), 0xbeeb8da1658eec67ull);
    EXPECT_EQ(rng.next(), 0xf893a2eefb32555eull);
}

TEST(BenchFraming, SphereMillion) {
    const std::vector<glm::vec3> points = sphere_positions(1000000);
    ASSERT_EQ(points.size(), 501501u);
    expect_framing(points, {{0.0f, 0.0f, 0.0f},
                            1.0f,
                            {0.816496611f, 0.816496611f, 1.63299322f},
                            0.990000069f,
                            3.01000023f});
}

TEST(BenchFraming, City20000) {
    expect_framing(city_positions(20000, 1), {{0.0f, 7.99708271f, 0.0f},
                                              150.213028f,
                                              {122.648422f, 130.645508f, 245.296844f},
                                              148.710892f,
                                              452.141205f});
}

TEST(BenchFraming, SoupMillion) {
    expect_framing(soup_positions(1000000, 1),
                   {{-5.85913658e-05f, 8.50558281e-05f, -0.000113010406f},
                    1.74165094f,
                    {1.42199349f, 1.42213714f, 2.84399104f},
                    1.72423446f,
                    5.24236917f});
}

TEST(BenchFraming, Bunny) {
    ZRASTER_REQUIRE_SHARED_DATA();
    std::ifstream in(test::shared_data("meshes/obj/bunny.obj"));
    ASSERT_TRUE(in) << "bunny.obj is missing";
    // Every `v` of this file is used by a face, so the framed points are all the `v` lines.
    std::vector<glm::vec3> points;
    std::string line;
    while (std::getline(in, line)) {
        if (line.size() < 2 || line[0] != 'v' || line[1] != ' ') continue;
        const char* p = line.c_str() + 2;
        char* end = nullptr;
        glm::vec3 v;
        for (int k = 0; k < 3; ++k, p = end) v[k] = std::strtof(p, &end);
        points.push_back(v);
    }
    ASSERT_EQ(points.size(), 34835u);
    expect_framing(points, {{0.0f, 0.0f, 0.0f},
                            1.345927f,
                            {1.09894478f, 1.09894478f, 2.19788957f},
                            1.33246779f,
                            4.05124044f});
}

}  // namespace
}  // namespace zraster
