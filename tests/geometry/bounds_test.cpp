#include <zraster/bounds.hpp>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <random>
#include <vector>

namespace zraster {
namespace {

std::vector<glm::vec3> random_points(std::mt19937& rng, int n) {
    std::uniform_real_distribution<float> d(-3.0f, 3.0f);
    std::vector<glm::vec3> out;
    for (int i = 0; i < n; ++i) out.push_back({d(rng), d(rng), d(rng)});
    return out;
}

TEST(Bounds, OfPoints) {
    const std::vector<glm::vec3> pts = {{1, 2, 3}, {-1, 5, 0}, {0, -2, 7}};
    const Bounds3f b = Bounds3f::of(pts);
    EXPECT_EQ(b.lo, glm::vec3(-1, -2, 0));
    EXPECT_EQ(b.hi, glm::vec3(1, 5, 7));
    EXPECT_FALSE(b.empty());
    EXPECT_TRUE(Bounds3f::of({}).empty());
}

TEST(Bounds, TransformedContainsAllTransformedPoints) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> angle(-3.0f, 3.0f), scale(0.2f, 4.0f), shift(-10, 10);
    for (int trial = 0; trial < 50; ++trial) {
        const auto pts = random_points(rng, 200);
        const Bounds3f b = Bounds3f::of(pts);
        glm::mat4 m = glm::translate(glm::mat4(1.0f), {shift(rng), shift(rng), shift(rng)});
        m = glm::rotate(m, angle(rng), glm::normalize(glm::vec3(angle(rng), angle(rng), 1.0f)));
        m = glm::scale(m, {scale(rng), scale(rng), scale(rng)});
        const Bounds3f t = b.transformed(m);
        for (const glm::vec3& p : pts) {
            const glm::vec3 q = glm::vec3(m * glm::vec4(p, 1.0f));
            for (int k = 0; k < 3; ++k) {
                EXPECT_GE(q[k], t.lo[k] - 1e-4f);
                EXPECT_LE(q[k], t.hi[k] + 1e-4f);
            }
        }
    }
}

TEST(Bounds, TransformedIsExactForTranslationAndScale) {
    Bounds3f b;
    b.extend(glm::vec3(-1, -2, -3));
    b.extend(glm::vec3(1, 2, 3));
    glm::mat4 m = glm::translate(glm::mat4(1.0f), {10, 0, -5});
    m = glm::scale(m, {2, -1, 1});  // a mirror swaps lo and hi along y
    const Bounds3f t = b.transformed(m);
    EXPECT_EQ(t.lo, glm::vec3(8, -2, -8));
    EXPECT_EQ(t.hi, glm::vec3(12, 2, -2));
    EXPECT_TRUE(Bounds3f{}.transformed(m).empty());
}

TEST(BoundingSphere, RadiusIsTheMaxDistanceFromTheBoxCenter) {
    std::mt19937 rng(3);
    const auto pts = random_points(rng, 500);
    const BoundingSphere s = bounding_sphere(pts);
    const Bounds3f b = Bounds3f::of(pts);
    const glm::dvec3 c = (glm::dvec3(b.lo) + glm::dvec3(b.hi)) / 2.0;
    EXPECT_EQ(s.center, c);
    double max_distance = 0.0;
    for (const glm::vec3& p : pts) {
        const double d = glm::length(glm::dvec3(p) - s.center);
        EXPECT_LE(d, s.radius);
        max_distance = std::max(max_distance, d);
    }
    EXPECT_DOUBLE_EQ(s.radius, max_distance);
}

TEST(BoundingSphere, KnownValues) {
    const std::vector<glm::vec3> pts = {{1, 0, 0}, {-1, 0, 0}, {0, 3, 0}, {0, -1, 0}};
    const BoundingSphere s = bounding_sphere(pts);
    EXPECT_EQ(s.center, glm::dvec3(0, 1, 0));
    EXPECT_DOUBLE_EQ(s.radius, 2.0);
    const BoundingSphere empty = bounding_sphere({});
    EXPECT_EQ(empty.radius, 0.0);
}

}  // namespace
}  // namespace zraster
