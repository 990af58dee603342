// See gltf_decode_budget.hpp.
#include "io/gltf_decode_budget.hpp"

#include <zraster/error.hpp>

#include <algorithm>
#include <cstdint>
#include <string>

namespace zraster::io {

namespace {

using nlohmann::json;

const json& array_member(const json& object, const char* key) {
    static const json empty = json::array();
    const auto it = object.is_object() ? object.find(key) : object.end();
    return it != object.end() && it->is_array() ? *it : empty;
}

// The accessor `index` names; null when it names none.
const json* accessor_at(const json& accessors, const json& index) {
    if (!index.is_number_unsigned() || index.get<std::uint64_t>() >= accessors.size())
        return nullptr;
    const json& accessor = accessors[index.get<std::size_t>()];
    return accessor.is_object() ? &accessor : nullptr;
}

// The count of the accessor `index` names; 0 when it names none.
std::uint64_t accessor_count(const json& accessors, const json& index) {
    const json* accessor = accessor_at(accessors, index);
    if (accessor == nullptr) return 0;
    const auto count = accessor->find("count");
    return count != accessor->end() && count->is_number_unsigned() ? count->get<std::uint64_t>()
                                                                   : 0;
}

// Bytes per element of what the import and the conversion keep, measured with `zraster info`
// (max RSS per extra primitive reading a 3-million-vertex accessor): an attribute takes 24 bytes
// a vertex (Assimp's 3-float copy, then ours; a color 4 floats twice), a drawn index 36 (Assimp's
// face, its index array and ours, about 107 bytes a triangle). A sparse accessor is first
// expanded to a dense array of its own: 16 bytes an element (up to 4 floats), each time it is
// read.
constexpr std::uint64_t kAttributeBytes = 24, kColorBytes = 32, kIndexBytes = 36, kSparseBytes = 16;
// An aiNode (its name alone is a 1 KB aiString) and our walk over it, measured the same way: a
// graph of 2^19 and of 2^21 empty nodes, 1,150 bytes a node.
constexpr std::uint64_t kNodeBytes = 1152;

std::uint64_t saturated_add(std::uint64_t a, std::uint64_t b) {
    return a > UINT64_MAX - b ? UINT64_MAX : a + b;
}

std::uint64_t saturated_mul(std::uint64_t a, std::uint64_t b) {
    return b != 0 && a > UINT64_MAX / b ? UINT64_MAX : a * b;
}

std::string byte_text(std::uint64_t bytes) {
    return bytes >= (1u << 20) ? std::to_string(bytes >> 20) + " MiB"
                               : std::to_string(bytes) + " bytes";
}

// The dense copy Assimp makes of a sparse accessor before reading it; 0 for the others.
std::uint64_t sparse_bytes(const json& accessors, const json& index) {
    const json* accessor = accessor_at(accessors, index);
    if (accessor == nullptr || !accessor->contains("sparse")) return 0;
    return saturated_mul(accessor_count(accessors, index), kSparseBytes);
}

// Faces Assimp makes of `n` indices (or vertices) drawn in `mode`: points, lines, loops, strips,
// triangles, strips, fans.
std::uint64_t faces(std::uint64_t mode, std::uint64_t n) {
    switch (mode) {
        case 0:
            return n;
        case 1:
            return n / 2;
        case 2:
            return n;
        case 3:
            return n > 0 ? n - 1 : 0;
        case 5:
        case 6:
            return n > 2 ? n - 2 : 0;
        default:
            return n / 3;
    }
}

}  // namespace

void check_gltf_decode_budget(const std::filesystem::path& path, const json& document,
                              const LoadOptions& options, std::uint64_t importer_nodes) {
    const json& accessors = array_member(document, "accessors");
    // Saturated past the limits: a count can be up to 2^64 - 1.
    const std::uint64_t max_faces = options.max_triangles;
    const std::uint64_t max_vertices =
        max_faces > UINT64_MAX / 3 ? UINT64_MAX : 3 * std::uint64_t{max_faces};
    std::uint64_t vertices = 0, face_total = 0, primitives = 0, bytes = 0;
    for (const json& mesh : array_member(document, "meshes")) {
        for (const json& primitive : array_member(mesh, "primitives")) {
            if (!primitive.is_object()) continue;
            ++primitives;
            std::uint64_t n = 0;
            const auto attributes = primitive.find("attributes");
            if (attributes != primitive.end() && attributes->is_object())
                for (const auto& [name, index] : attributes->items()) {
                    const std::uint64_t count = accessor_count(accessors, index);
                    n = std::max(n, count);
                    const std::uint64_t each =
                        name.starts_with("COLOR_") ? kColorBytes : kAttributeBytes;
                    bytes = saturated_add(bytes, saturated_mul(count, each));
                    bytes = saturated_add(bytes, sparse_bytes(accessors, index));
                }
            // Morph targets: Assimp decodes each target's attributes as a mesh of its own.
            for (const json& target : array_member(primitive, "targets"))
                if (target.is_object())
                    for (const auto& [name, index] : target.items()) {
                        const std::uint64_t count = accessor_count(accessors, index);
                        bytes = saturated_add(bytes, saturated_mul(count, kAttributeBytes));
                        bytes = saturated_add(bytes, sparse_bytes(accessors, index));
                    }
            const auto indices = primitive.find("indices");
            const std::uint64_t drawn =
                indices != primitive.end() ? accessor_count(accessors, *indices) : n;
            bytes = saturated_add(bytes, saturated_mul(drawn, kIndexBytes));
            if (indices != primitive.end())
                bytes = saturated_add(bytes, sparse_bytes(accessors, *indices));
            const auto mode = primitive.find("mode");
            const std::uint64_t m = mode != primitive.end() && mode->is_number_unsigned()
                                        ? mode->get<std::uint64_t>()
                                        : 4;
            vertices = std::min(max_vertices + 1, vertices + std::min(n, max_vertices + 1));
            face_total =
                std::min(max_faces + 1, face_total + std::min(faces(m, drawn), max_faces + 1));
        }
    }
    const std::string where = "the meshes' " + std::to_string(primitives) + " primitives";
    const std::string why = " (the importer copies an accessor into every primitive that reads it)";
    if (vertices > max_vertices)
        throw LimitExceeded(path.string(), "max_triangles",
                            where + " decode to more than " + std::to_string(max_vertices) +
                                " vertices, 3 x max_triangles" + why);
    if (face_total > max_faces)
        throw LimitExceeded(path.string(), "max_triangles",
                            where + " decode to more than " + std::to_string(max_faces) +
                                " faces, max_triangles" + why);
    const std::uint64_t node_bytes = saturated_mul(importer_nodes, kNodeBytes);
    if (saturated_add(bytes, node_bytes) <= options.max_geometry_bytes) return;
    throw LimitExceeded(path.string(), "max_geometry_bytes",
                        where + " and the node graph's " + std::to_string(importer_nodes) +
                            (importer_nodes == 1 ? " node" : " nodes") + " decode to about " +
                            byte_text(saturated_add(bytes, node_bytes)) +
                            " of geometry, more than " + "max_geometry_bytes (" +
                            byte_text(options.max_geometry_bytes) + ")" +
                            why.substr(0, why.size() - 1) + ", and a node once per path to it)");
}

}  // namespace zraster::io
