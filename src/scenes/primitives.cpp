// Simple closed primitives with normals and UVs, counter-clockwise seen from outside.
//
// Vertices are duplicated along UV seams (and at the sphere's poles) so each copy can carry its
// own UV, but the copies have bit-identical positions: the surfaces stay watertight, which is what
// a rasterizer's fill rule needs to leave no cracks.
#include <zraster/scenes.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace zraster {

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

// Triangles (a, b, c), (a, c, d) for each cell of a (rows + 1) x (columns + 1) vertex grid whose
// row index grows along the first surface direction and column index along the second.
void add_grid_triangles(Mesh& mesh, int rows, int columns, bool skip_first_row_apex,
                        bool skip_last_row_apex) {
    auto index = [&](int i, int j) { return std::uint32_t(i * (columns + 1) + j); };
    for (int i = 0; i < rows; ++i) {
        for (int j = 0; j < columns; ++j) {
            const std::uint32_t a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1),
                                d = index(i, j + 1);
            if (!(skip_last_row_apex && i == rows - 1))
                mesh.indices.insert(mesh.indices.end(), {a, b, c});
            if (!(skip_first_row_apex && i == 0))
                mesh.indices.insert(mesh.indices.end(), {a, c, d});
        }
    }
}

}  // namespace

Mesh make_uv_sphere(float radius, int stacks, int slices) {
    stacks = std::max(stacks, 2);
    slices = std::max(slices, 3);
    Mesh mesh;
    mesh.name = "uv_sphere";
    for (int i = 0; i <= stacks; ++i) {
        const double theta = std::numbers::pi * double(i) / double(stacks);
        for (int j = 0; j <= slices; ++j) {
            // Same angle convention as the benchmark sphere; the seam column reuses angle 0 and
            // the poles are exact so that duplicated vertices coincide exactly.
            const double phi = two_pi * double(j % slices) / double(slices);
            glm::dvec3 unit{std::sin(theta) * std::cos(phi), std::cos(theta),
                            -std::sin(theta) * std::sin(phi)};
            if (i == 0) unit = {0, 1, 0};
            if (i == stacks) unit = {0, -1, 0};
            mesh.positions.push_back(glm::vec3(unit * double(radius)));
            mesh.normals.push_back(glm::vec3(unit));
            mesh.uvs.push_back({float(j) / float(slices), float(i) / float(stacks)});
        }
    }
    // One triangle of each quad touching a pole would be degenerate: skip it.
    add_grid_triangles(mesh, stacks, slices, true, true);
    update_bounds(mesh);
    return mesh;
}

Mesh make_box(const glm::vec3& half_extent) {
    struct Face {
        glm::vec3 normal, right, up;  // cross(right, up) = normal: counter-clockwise outside
    };
    static constexpr Face faces[6] = {
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
    };
    // Bottom left, bottom right, top right, top left; v = 0 is the image's top row.
    static constexpr float corner_right[4] = {-1, 1, 1, -1};
    static constexpr float corner_up[4] = {-1, -1, 1, 1};
    static constexpr glm::vec2 corner_uv[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};

    Mesh mesh;
    mesh.name = "box";
    for (const Face& face : faces) {
        const auto base = std::uint32_t(mesh.positions.size());
        for (int k = 0; k < 4; ++k) {
            // Every coordinate is exactly +-half_extent, so shared corners coincide exactly.
            const glm::vec3 unit =
                face.normal + corner_right[k] * face.right + corner_up[k] * face.up;
            mesh.positions.push_back(unit * half_extent);
            mesh.normals.push_back(face.normal);
            mesh.uvs.push_back(corner_uv[k]);
        }
        mesh.indices.insert(mesh.indices.end(),
                            {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    update_bounds(mesh);
    return mesh;
}

Mesh make_torus(float major_radius, float minor_radius, int rings, int sides) {
    rings = std::max(rings, 3);
    sides = std::max(sides, 3);
    Mesh mesh;
    mesh.name = "torus";
    for (int i = 0; i <= rings; ++i) {
        // Around +y, from +x towards -z (as the spheres); the seam reuses angle 0 exactly.
        const double u = two_pi * double(i % rings) / double(rings);
        for (int j = 0; j <= sides; ++j) {
            const double v = two_pi * double(j % sides) / double(sides);
            const glm::dvec3 normal{std::cos(v) * std::cos(u), std::sin(v),
                                    -std::cos(v) * std::sin(u)};
            const glm::dvec3 ring_center{std::cos(u), 0.0, -std::sin(u)};
            const glm::dvec3 p = ring_center * double(major_radius) + normal * double(minor_radius);
            mesh.positions.push_back(glm::vec3(p));
            mesh.normals.push_back(glm::vec3(normal));
            mesh.uvs.push_back({float(i) / float(rings), float(j) / float(sides)});
        }
    }
    // d(position)/du x d(position)/dv points outwards, so (a, b, c) along u then v is
    // counter-clockwise seen from outside.
    add_grid_triangles(mesh, rings, sides, false, false);
    update_bounds(mesh);
    return mesh;
}

Mesh make_ground_plane(float size, float uv_repeat) {
    const float h = size / 2;
    Mesh mesh;
    mesh.name = "ground";
    mesh.positions = {{-h, 0, h}, {h, 0, h}, {h, 0, -h}, {-h, 0, -h}};
    mesh.normals.assign(4, glm::vec3(0, 1, 0));
    mesh.uvs = {{0, uv_repeat}, {uv_repeat, uv_repeat}, {uv_repeat, 0}, {0, 0}};
    mesh.indices = {0, 1, 2, 0, 2, 3};
    update_bounds(mesh);
    return mesh;
}

}  // namespace zraster
