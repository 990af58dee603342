// Helpers for the visibility tests: test scenes (a triangle soup with interpenetration, the
// classic cyclic overlap, two interpenetrating triangles) and the comparison of id images.
#pragma once
#include <zraster/scenes.hpp>
#include <zraster/visibility.hpp>

#include <cstdint>
#include <vector>

#include "render/render_test_util.hpp"

namespace zraster::test {

// A triangle in the plane z = depth, counter-clockwise seen from +z.
inline std::vector<glm::vec3> flat_triangle(float x0, float y0, float size, float depth) {
    return {{x0, y0, depth}, {x0 + size, y0, depth}, {x0, y0 + size, depth}};
}

// A point uniform in [lo, hi]^3, its coordinates drawn in the order x, y, z. Not
// glm::dvec3(rng.uniform(..), rng.uniform(..), rng.uniform(..)): the order in which a call's
// arguments are evaluated is unspecified (GCC evaluates them right to left, clang left to right),
// so that gave each compiler's build a different scene under the same seed.
inline glm::dvec3 uniform_point(SplitMix64& rng, double lo, double hi) {
    const double x = rng.uniform(lo, hi);
    const double y = rng.uniform(lo, hi);
    const double z = rng.uniform(lo, hi);
    return {x, y, z};
}

// n triangles with centers uniform in [-1, 1]^3 and corners up to `size` from the center on each
// axis: at size 0.2 (ten times the benchmark soup's) many of them cross each other. The same
// scene in every build (uniform_point).
inline Mesh make_interpenetrating_soup(int n, double size, std::uint64_t seed) {
    SplitMix64 rng(seed);
    Mesh mesh;
    mesh.name = "test-soup";
    for (int i = 0; i < n; ++i) {
        const glm::dvec3 c = uniform_point(rng, -1, 1);
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 o = uniform_point(rng, -size, size);
            mesh.positions.push_back(glm::vec3(c + o));
            mesh.indices.push_back(static_cast<std::uint32_t>(mesh.indices.size()));
        }
    }
    compute_angle_weighted_normals(mesh);
    update_bounds(mesh);
    return mesh;
}

// A camera on +z looking at the origin: the hand-built scenes are laid out in the xy plane.
inline Camera front_camera() {
    Camera c;
    c.eye = {0.0, 0.0, 8.0};
    c.target = {0.0, 0.0, 0.0};
    c.near = 1.0;
    c.far = 50.0;
    return c;
}

// The classic cyclic overlap: three long triangles ("sticks") along the sides of an equilateral
// triangle, each running from far (its wide base) to near (its apex), so that where two meet the
// arriving one lies over the departing one: 0 over 1, 1 over 2, 2 over 0. No triangle crosses
// another in depth where they overlap, yet no order of the three is right. The base's inner
// corner is lowered so that every overlapping pair is ordered by the plane tests (one lies wholly
// on one side of the other's plane): the painter's algorithm meets the cycle as a cycle (a marked
// polygon must move again) rather than as an interpenetration.
inline std::vector<std::vector<glm::vec3>> cyclic_sticks() {
    const double radius = 2.0, extend = 1.2, half_width = 0.7;
    std::vector<std::vector<glm::vec3>> sticks;
    std::vector<glm::dvec2> corner;
    for (int k = 0; k < 3; ++k) {
        const double a = glm::radians(90.0 + 120.0 * k);
        corner.emplace_back(radius * std::cos(a), radius * std::sin(a));
    }
    for (int k = 0; k < 3; ++k) {
        const glm::dvec2 from = corner[std::size_t(k)], to = corner[std::size_t((k + 1) % 3)];
        const glm::dvec2 d = glm::normalize(to - from);
        const glm::dvec2 side(-d.y, d.x);
        const glm::dvec2 base = from - extend * d, apex = to + extend * d;
        // Counter-clockwise as seen from +z (front facing).
        const glm::dvec2 b0 = base - half_width * side, b1 = base + half_width * side;
        const bool ccw = (apex.x - b0.x) * (b1.y - b0.y) - (apex.y - b0.y) * (b1.x - b0.x) < 0;
        std::vector<glm::vec3> t = {glm::vec3(b0.x, b0.y, -1.0), glm::vec3(b1.x, b1.y, -2.0),
                                    glm::vec3(apex.x, apex.y, 1.0)};
        if (!ccw) std::swap(t[1], t[2]);
        sticks.push_back(t);
    }
    return sticks;
}

// Two triangles crossing along the line y = 0, z = 0: the first is nearer above it, the second
// below it.
inline std::vector<std::vector<glm::vec3>> interpenetrating_pair() {
    return {{{-2.0f, -1.5f, -0.75f}, {2.0f, -1.5f, -0.75f}, {0.0f, 1.5f, 0.75f}},
            {{-1.7f, -1.8f, 0.9f}, {2.3f, -1.2f, 0.6f}, {0.3f, 1.8f, -0.9f}}};
}

inline RenderOptions id_options(int width, int height) {
    RenderOptions o;
    o.width = width;
    o.height = height;
    o.threads = 1;
    o.id_targets = true;
    return o;
}

struct IdAgreement {
    std::size_t covered = 0;    // pixels covered in either image
    std::size_t differing = 0;  // pixels whose (instance, primitive) differ
    // Differing pixels whose 3x3 neighborhood in the reference shows one surface only: away from
    // every edge, silhouette and intersection line.
    std::size_t differing_interior = 0;
    // 2x2 blocks of pixels that all differ and are all interior: a surface drawn in the wrong
    // order over an area. Every legitimate cause of a difference is confined to a band narrower
    // than a pixel along a line (an edge, an intersection line, a depth near-tie, and for the
    // BSP tree and the painter's algorithm the split lines: a fragment split again on one side
    // only leaves a T-junction, whose snapped vertex opens a sliver of at most 1/256 pixel where
    // the surface behind shows through). Such a band can hold single pixel centers inside a
    // surface, never the four centers of a 2x2 block (no line passes within 1/2 pixel of all
    // four).
    std::size_t interior_blocks = 0;
    double fraction() const { return covered ? double(differing) / double(covered) : 0.0; }
};

inline IdAgreement compare_ids(const RenderTargets& reference, const RenderTargets& other) {
    IdAgreement a;
    const int w = reference.width, h = reference.height;
    std::vector<bool> interior_mask(std::size_t(w) * std::size_t(h), false);
    auto at = [&](const RenderTargets& t, int x, int y) {
        const std::size_t p = std::size_t(y) * std::size_t(w) + std::size_t(x);
        return std::pair(t.instance_id[p], t.primitive_id[p]);
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const auto r = at(reference, x, y), o = at(other, x, y);
            if (r.first < 0 && o.first < 0) continue;
            ++a.covered;
            if (r == o) continue;
            ++a.differing;
            bool interior = x > 0 && y > 0 && x + 1 < w && y + 1 < h;
            for (int dy = -1; dy <= 1 && interior; ++dy)
                for (int dx = -1; dx <= 1 && interior; ++dx)
                    interior = at(reference, x + dx, y + dy) == r;
            a.differing_interior += interior;
            interior_mask[std::size_t(y) * std::size_t(w) + std::size_t(x)] = interior;
        }
    for (int y = 0; y + 1 < h; ++y)
        for (int x = 0; x + 1 < w; ++x) {
            auto m = [&](int dx, int dy) {
                return interior_mask[std::size_t(y + dy) * std::size_t(w) + std::size_t(x + dx)];
            };
            a.interior_blocks += m(0, 0) && m(1, 0) && m(0, 1) && m(1, 1);
        }
    return a;
}

}  // namespace zraster::test
