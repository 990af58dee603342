// See gltf_decode_budget.hpp.
#include "io/gltf_decode_budget.hpp"

#include "io/gltf_document.hpp"

#include <zraster/error.hpp>

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

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
// A primitive's own aiMesh (its name alone a 1 KB aiString) and our mesh, whatever it reads:
// measured 2,156 bytes a one-triangle primitive (60,000 against 20,000), 180 of them counted
// above as its accessors'.
constexpr std::uint64_t kPrimitiveBytes = 1976;
// An aiNode (its name alone is a 1 KB aiString) and our walk over it, measured the same way: a
// graph of 2^19 and of 2^21 empty nodes, 1,150 bytes a node.
constexpr std::uint64_t kNodeBytes = 1152;
// A buffer is read whole into memory, whatever its accessors use: a byte a byte (measured: a
// buffer of 1 GiB of a sparse file, 1.00 byte a byte; a 392-byte file declaring 6 GiB reached
// 6.3 GB).
constexpr std::uint64_t kBufferByteBytes = 1;
// An animation channel's target (a node's translation, rotation, scale or weights; the last
// channel naming it wins): per key of its sampler, the importer's copies of its time and value
// and the key it makes of them, measured 216 bytes (a sampler of 4 million keys against one of 1
// million: 232 bytes a key, 16 of them the dense copies of its two sparse accessors).
constexpr std::uint64_t kKeyBytes = 216;
// A skinned mesh placed by a node: each time (once per path to the node) the importer makes an
// aiBone per joint for each of the mesh's primitives (its name alone a 1 KB aiString, its offset
// matrix, one weight at least): measured 1,178 bytes a bone (2,000 joints placed 256 against 64
// times), with a weight per joint influence of a vertex on top. It reads the inverse bind
// matrices once and copies them for each placement (64 bytes each: 128.6 measured per matrix of
// a sparse accessor, with its dense copy).
constexpr std::uint64_t kBoneBytes = 1178, kWeightBytes = 8, kMatrixBytes = 64;
// A material a primitive uses: 13,346 bytes measured (60,000 primitives each with its own empty
// material against 20,000, less the primitives' own cost measured without materials).
constexpr std::uint64_t kMaterialBytes = 13346;

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

// Bytes an element of the accessor `index` names (4 per component at least: the importer reads
// animation values and matrices as floats); 16 when it does not say.
std::uint64_t element_bytes(const json& accessors, const json& index) {
    const json* accessor = accessor_at(accessors, index);
    if (accessor == nullptr) return 16;
    const auto type = accessor->find("type");
    if (type == accessor->end() || !type->is_string()) return 16;
    const std::string t = type->get<std::string>();
    const std::uint64_t known = gltf_type_components(t);
    const std::uint64_t components = known != 0 ? known : 4;
    return 4 * components;
}

// The dense copy of a sparse accessor at its own element size (animation and skin accessors).
std::uint64_t sparse_copy_bytes(const json& accessors, const json& index) {
    const json* accessor = accessor_at(accessors, index);
    if (accessor == nullptr || !accessor->contains("sparse")) return 0;
    return saturated_mul(accessor_count(accessors, index), element_bytes(accessors, index));
}

const json* object_at(const json& list, const json& index) {
    if (!index.is_number_unsigned() || index.get<std::uint64_t>() >= list.size()) return nullptr;
    const json& item = list[index.get<std::size_t>()];
    return item.is_object() ? &item : nullptr;
}

// What else than the primitives' accessors and the nodes the file expands into: one part each,
// so that the message names the one that dominates.
struct Part {
    std::uint64_t bytes = 0;
    std::string what;  // "... decode to" / "... make" subject, in the file's terms
};

Part buffer_part(const json& document, std::optional<std::uint64_t> glb_binary) {
    std::uint64_t declared = 0, count = 0, largest = 0, largest_index = 0;
    bool chunk = false;  // the largest is a GLB's BIN chunk, longer than its byteLength
    const json& buffers = array_member(document, "buffers");
    for (std::size_t i = 0; i < buffers.size(); ++i) {
        const json& b = buffers[i];
        const auto length = b.is_object() ? b.find("byteLength") : b.end();
        if (length == b.end() || !length->is_number_unsigned()) continue;
        std::uint64_t n = length->get<std::uint64_t>();
        const bool longer = i == 0 && glb_binary && !b.contains("uri") && *glb_binary > n;
        if (longer) n = *glb_binary;
        declared = saturated_add(declared, n);
        ++count;
        if (n >= largest) largest = n, largest_index = i, chunk = longer;
    }
    Part part{saturated_mul(declared, kBufferByteBytes), ""};
    part.what = count == 1 ? "buffer " + std::to_string(largest_index) +
                                 (chunk ? " (the GLB's BIN chunk of " : " (byteLength ") +
                                 byte_text(largest) + ", read whole by the importer)"
                           : "the " + std::to_string(count) + " buffers (byteLength " +
                                 byte_text(declared) + " in all, each read whole by the importer)";
    return part;
}

Part animation_part(const json& document, const json& accessors) {
    std::uint64_t bytes = 0, keys = 0, targets = 0;
    std::set<std::uint64_t> copied;  // sparse accessors made dense (once each)
    for (const json& animation : array_member(document, "animations")) {
        const json& samplers = array_member(animation, "samplers");
        // The importer keeps one sampler per target: the last channel naming it.
        std::map<std::pair<std::uint64_t, std::string>, std::size_t> sampler_of;
        for (const json& channel : array_member(animation, "channels")) {
            if (!channel.is_object()) continue;
            const auto sampler = channel.find("sampler"), target = channel.find("target");
            if (sampler == channel.end() || !object_at(samplers, *sampler) ||
                target == channel.end() || !target->is_object())
                continue;
            const auto node = target->find("node"), what = target->find("path");
            if (node == target->end() || !node->is_number_unsigned() || what == target->end() ||
                !what->is_string())
                continue;
            sampler_of[{node->get<std::uint64_t>(), what->get<std::string>()}] =
                sampler->get<std::size_t>();
        }
        for (const auto& [target, s] : sampler_of) {
            ++targets;
            const json& sampler = samplers[s];
            const json none;
            const auto input = sampler.find("input"), output = sampler.find("output");
            const json& in = input != sampler.end() ? *input : none;
            const json& out = output != sampler.end() ? *output : none;
            const std::uint64_t n =
                std::max(accessor_count(accessors, in), accessor_count(accessors, out));
            keys = saturated_add(keys, n);
            bytes = saturated_add(bytes, saturated_mul(n, kKeyBytes));
            for (const json* index : {&in, &out})
                if (index->is_number_unsigned() &&
                    copied.insert(index->get<std::uint64_t>()).second)
                    bytes = saturated_add(bytes, sparse_copy_bytes(accessors, *index));
        }
    }
    return {bytes, "the animations' " + std::to_string(keys) + " keys (over " +
                       std::to_string(targets) + (targets == 1 ? " target" : " targets") +
                       " of their channels)"};
}

Part skin_part(const json& document, const json& accessors, const GltfImporterCounts& copies) {
    const json& nodes = array_member(document, "nodes");
    const json& skins = array_member(document, "skins");
    const json& meshes = array_member(document, "meshes");
    std::uint64_t bytes = 0, bones = 0, placements = 0, matrices = 0;
    std::vector<bool> skin_read(skins.size(), false);
    for (std::size_t n = 0; n < nodes.size() && n < copies.paths_to_node.size(); ++n) {
        const json& node = nodes[n];
        if (!node.is_object() || copies.paths_to_node[n] == 0) continue;
        const auto skin_index = node.find("skin"), mesh_index = node.find("mesh");
        if (skin_index == node.end() || mesh_index == node.end()) continue;
        const json* skin = object_at(skins, *skin_index);
        const json* mesh = object_at(meshes, *mesh_index);
        if (skin == nullptr || mesh == nullptr) continue;
        const std::uint64_t joints = array_member(*skin, "joints").size();
        const auto ibm = skin->find("inverseBindMatrices");
        const json none;
        const json& matrices_index = ibm != skin->end() ? *ibm : none;
        // Read once (a sparse one made dense), copied for each primitive placed (freed after).
        if (!skin_read[skin_index->get<std::size_t>()]) {
            skin_read[skin_index->get<std::size_t>()] = true;
            matrices = saturated_add(matrices, accessor_count(accessors, matrices_index));
            bytes = saturated_add(bytes, sparse_copy_bytes(accessors, matrices_index));
            bytes = saturated_add(
                bytes, saturated_mul(accessor_count(accessors, matrices_index), kMatrixBytes));
        }
        // Per primitive placed: a bone per joint, and a weight per joint influence of a vertex.
        std::uint64_t per_placement = 0, primitives = 0;
        for (const json& primitive : array_member(*mesh, "primitives")) {
            if (!primitive.is_object()) continue;
            ++primitives;
            std::uint64_t influences = 0;
            const auto attributes = primitive.find("attributes");
            if (attributes != primitive.end() && attributes->is_object())
                for (const auto& [name, index] : attributes->items())
                    if (name.starts_with("JOINTS_"))
                        influences = saturated_add(
                            influences, saturated_mul(accessor_count(accessors, index), 4));
            per_placement = saturated_add(per_placement,
                                          saturated_add(saturated_mul(joints, kBoneBytes),
                                                        saturated_mul(influences, kWeightBytes)));
        }
        const std::uint64_t times = copies.paths_to_node[n];
        bones = saturated_add(bones, saturated_mul(saturated_mul(joints, primitives), times));
        placements = saturated_add(placements, saturated_mul(primitives, times));
        bytes = saturated_add(bytes, saturated_mul(per_placement, times));
    }
    return {bytes, "the skins' " + std::to_string(bones) + " bones (a bone per joint for each of " +
                       std::to_string(placements) +
                       " placements of a skinned primitive: the importer makes them each "
                       "time) and " +
                       std::to_string(matrices) + " inverse bind matrices"};
}

Part material_part(const json& document) {
    const std::size_t count = array_member(document, "materials").size();
    std::vector<bool> used(count, false);
    std::uint64_t distinct = 0;
    for (const json& mesh : array_member(document, "meshes"))
        for (const json& primitive : array_member(mesh, "primitives")) {
            const auto material =
                primitive.is_object() ? primitive.find("material") : primitive.end();
            if (material == primitive.end() || !material->is_number_unsigned() ||
                material->get<std::uint64_t>() >= count || used[material->get<std::size_t>()])
                continue;
            used[material->get<std::size_t>()] = true;
            ++distinct;
        }
    return {saturated_mul(distinct, kMaterialBytes),
            "the primitives' " + std::to_string(distinct) + " materials"};
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
                              const LoadOptions& options, const GltfImporterCounts& copies) {
    const std::uint64_t importer_nodes = copies.importer_nodes;
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
            bytes = saturated_add(bytes, kPrimitiveBytes);
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
    const Part others[] = {buffer_part(document, copies.glb_binary),
                           animation_part(document, accessors),
                           skin_part(document, accessors, copies), material_part(document)};
    std::uint64_t total = saturated_add(bytes, node_bytes);
    const Part* largest = nullptr;
    for (const Part& part : others) {
        total = saturated_add(total, part.bytes);
        if (largest == nullptr || part.bytes > largest->bytes) largest = &part;
    }
    if (total <= options.max_geometry_bytes) return;
    const std::string limit =
        "more than max_geometry_bytes (" + byte_text(options.max_geometry_bytes) + ")";
    if (largest->bytes > saturated_add(bytes, node_bytes))
        throw LimitExceeded(path.string(), "max_geometry_bytes",
                            "the file decodes to about " + byte_text(total) + " in the importer, " +
                                limit + ", mostly " + largest->what + ": about " +
                                byte_text(largest->bytes));
    throw LimitExceeded(path.string(), "max_geometry_bytes",
                        where + " and the node graph's " + std::to_string(importer_nodes) +
                            (importer_nodes == 1 ? " node" : " nodes") + " decode to about " +
                            byte_text(total) + " of geometry, more than " + "max_geometry_bytes (" +
                            byte_text(options.max_geometry_bytes) + ")" +
                            why.substr(0, why.size() - 1) + ", and a node once per path to it)");
}

}  // namespace zraster::io
