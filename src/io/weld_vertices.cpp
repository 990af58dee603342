#include "io/weld_vertices.hpp"

#include <array>
#include <bit>
#include <unordered_map>

namespace zraster::io {

namespace {

using Key = std::array<std::uint32_t, 12>;

struct KeyHash {
    std::size_t operator()(const Key& k) const {
        std::uint64_t h = 0x9E3779B97F4A7C15ull;
        for (std::uint32_t v : k) {
            h ^= v;
            h *= 0xBF58476D1CE4E5B9ull;
            h ^= h >> 31;
        }
        return static_cast<std::size_t>(h);
    }
};

// +0.0f turns -0 into +0, so the two compare equal as bits, as they do as floats.
std::uint32_t bits(float f) {
    return std::bit_cast<std::uint32_t>(f + 0.0f);
}

Key position_key(const glm::vec3& p) {
    return {bits(p.x), bits(p.y), bits(p.z), 0, 0, 0, 0, 0, 0, 0, 0, 0};
}

// For each vertex the index of the first vertex equal to it under key_of, and the count.
template <typename KeyOf>
std::vector<std::uint32_t> first_equal_vertex(std::size_t count, KeyOf key_of,
                                              std::vector<std::uint32_t>& representatives) {
    std::unordered_map<Key, std::uint32_t, KeyHash> ids;
    ids.reserve(count);
    std::vector<std::uint32_t> id_of(count);
    for (std::size_t v = 0; v < count; ++v) {
        const auto [it, inserted] =
            ids.try_emplace(key_of(v), static_cast<std::uint32_t>(representatives.size()));
        if (inserted) representatives.push_back(static_cast<std::uint32_t>(v));
        id_of[v] = it->second;
    }
    return id_of;
}

}  // namespace

void weld_identical_vertices(Mesh& mesh) {
    const bool has_normals = !mesh.normals.empty();
    const bool has_uvs = !mesh.uvs.empty();
    const bool has_colors = !mesh.colors.empty();
    std::vector<std::uint32_t> kept;
    const std::vector<std::uint32_t> id_of = first_equal_vertex(
        mesh.positions.size(),
        [&](std::size_t v) {
            Key k = position_key(mesh.positions[v]);
            if (has_normals) {
                k[3] = bits(mesh.normals[v].x);
                k[4] = bits(mesh.normals[v].y);
                k[5] = bits(mesh.normals[v].z);
            }
            if (has_uvs) {
                k[6] = bits(mesh.uvs[v].x);
                k[7] = bits(mesh.uvs[v].y);
            }
            if (has_colors)
                for (int c = 0; c < 4; ++c) k[8 + std::size_t(c)] = bits(mesh.colors[v][c]);
            return k;
        },
        kept);
    if (kept.size() == mesh.positions.size()) return;

    auto compact = [&](auto& attribute) {
        if (attribute.empty()) return;
        std::remove_reference_t<decltype(attribute)> out;
        out.reserve(kept.size());
        for (std::uint32_t v : kept) out.push_back(attribute[v]);
        attribute.swap(out);
    };
    compact(mesh.positions);
    compact(mesh.normals);
    compact(mesh.uvs);
    compact(mesh.colors);
    for (std::uint32_t& i : mesh.indices) i = id_of[i];
}

std::vector<glm::vec3> normals_over_shared_positions(const Mesh& mesh) {
    std::vector<std::uint32_t> representatives;
    const std::vector<std::uint32_t> id_of = first_equal_vertex(
        mesh.positions.size(), [&](std::size_t v) { return position_key(mesh.positions[v]); },
        representatives);

    Mesh shape;
    shape.positions.reserve(representatives.size());
    for (std::uint32_t v : representatives) shape.positions.push_back(mesh.positions[v]);
    shape.indices.reserve(mesh.indices.size());
    for (std::uint32_t i : mesh.indices) shape.indices.push_back(id_of[i]);
    compute_angle_weighted_normals(shape);

    std::vector<glm::vec3> normals(mesh.positions.size());
    for (std::size_t v = 0; v < normals.size(); ++v) normals[v] = shape.normals[id_of[v]];
    return normals;
}

}  // namespace zraster::io
