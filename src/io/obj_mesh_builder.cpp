// Mesh building (see obj_mesh_builder.hpp).
#include "io/obj_mesh_builder.hpp"

#include "io/weld_vertices.hpp"

#include <assimp/types.h>
#include <assimp/vector3.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <bit>
#include <cmath>

namespace zraster::io::obj {

namespace {

// For each value (N floats), the index of the first value with the same bits (-0 == +0, as
// weld_identical_vertices compares them). Empty when every value is the first of its kind.
template <int N>
std::vector<std::uint32_t> first_equal_values(const float* values, std::size_t count) {
    const std::size_t capacity = std::bit_ceil(std::max<std::size_t>(16, count * 2));
    std::vector<std::uint32_t> table(capacity, kNone);
    std::vector<std::uint32_t> first(count);
    bool all_first = true;
    auto key = [&](std::size_t i, int k) {
        return std::bit_cast<std::uint32_t>(values[i * N + k] + 0.0f);
    };
    for (std::size_t i = 0; i < count; ++i) {
        std::uint64_t h = 0x9E3779B97F4A7C15ull;
        for (int k = 0; k < N; ++k) {
            h ^= key(i, k);
            h *= 0xBF58476D1CE4E5B9ull;
            h ^= h >> 29;
        }
        std::size_t slot = static_cast<std::size_t>(h) & (capacity - 1);
        while (true) {
            const std::uint32_t t = table[slot];
            if (t == kNone) {
                table[slot] = static_cast<std::uint32_t>(i);
                first[i] = static_cast<std::uint32_t>(i);
                break;
            }
            bool equal = true;
            for (int k = 0; k < N; ++k) equal &= key(t, k) == key(i, k);
            if (equal) {
                first[i] = t;
                all_first = false;
                break;
            }
            slot = (slot + 1) & (capacity - 1);
        }
    }
    if (all_first) first.clear();
    return first;
}

// Assimp's triangulation of a quad: a fan from its concave corner, if it has one (the first
// corner whose two angles against the diagonal add up to more than pi), else from corner 0.
// Computed with Assimp's own vector operations, so that it decides exactly as Assimp does.
unsigned quad_fan_corner(const glm::vec3* corner[4]) {
    for (unsigned i = 0; i < 4; ++i) {
        auto ai = [&](unsigned k) {
            const glm::vec3& p = *corner[k % 4];
            return aiVector3D(p.x, p.y, p.z);
        };
        const aiVector3D v = ai(i);
        aiVector3D left = ai(i + 3) - v;
        aiVector3D diagonal = ai(i + 2) - v;
        aiVector3D right = ai(i + 1) - v;
        left.Normalize();
        diagonal.Normalize();
        right.Normalize();
        const float angle = std::acos(left * diagonal) + std::acos(right * diagonal);
        if (angle > AI_MATH_PI_F) return i;
    }
    return 0;
}

// Welding: for each position, its first vertex in the mesh inline, and the others (seams,
// flat shading: the same position with other uvs or normals) in a list through `Link`s.
struct Slot {
    std::uint32_t stamp = 0;  // which mesh wrote it
    std::uint32_t uv = 0, normal = 0;
    std::uint32_t vertex = 0;
    std::uint32_t next = kNone;  // more vertices at this position
};

struct Link {
    std::uint32_t uv, normal, vertex, next;
};

// The vertices of one mesh by welding key (position, uv, normal: first-equal-value indices).
// The slots, one per position of the file, are shared by the meshes a thread builds: a slot
// whose stamp is not this mesh's is empty.
class VertexTable {
  public:
    VertexTable(std::vector<Slot>& slots, std::uint32_t stamp) : slots_(slots), stamp_(stamp) {}

    // The vertex with this key; `next_vertex` (the mesh's vertex count) when it is new.
    [[gnu::always_inline]] std::uint32_t find_or_add(std::uint32_t kv, std::uint32_t kt,
                                                     std::uint32_t kn, std::uint32_t next_vertex) {
        Slot& slot = slots_[kv];
        if (slot.stamp != stamp_) {
            slot = Slot{stamp_, kt, kn, next_vertex, kNone};
            return next_vertex;
        }
        if (slot.uv == kt && slot.normal == kn) return slot.vertex;
        std::uint32_t l = slot.next;
        while (l != kNone && (links_[l].uv != kt || links_[l].normal != kn)) l = links_[l].next;
        if (l != kNone) return links_[l].vertex;
        links_.push_back(Link{kt, kn, next_vertex, slot.next});
        slot.next = static_cast<std::uint32_t>(links_.size() - 1);
        return next_vertex;
    }

  private:
    std::vector<Slot>& slots_;
    std::vector<Link> links_;
    std::uint32_t stamp_;
};

// As convert_mesh: unusable normals are replaced by normals computed over shared positions (the
// same whether computed on Assimp's per-corner vertices or these). Vertices that become equal
// are then welded, as welding after that replacement does; so are vertices that got zero uvs or
// normals for corners without them (`reweld`). Texture coordinates are always finite here (the
// line parser reads a non-finite one as 0). Returns whether normals were replaced.
bool finish_mesh(Mesh& mesh, bool reweld) {
    bool replaced = false;
    if (std::any_of(mesh.normals.begin(), mesh.normals.end(),
                    [](const glm::vec3& n) { return std::isnan(n.x); })) {
        const std::vector<glm::vec3> computed = normals_over_shared_positions(mesh);
        for (std::size_t i = 0; i < mesh.normals.size(); ++i)
            if (std::isnan(mesh.normals[i].x)) mesh.normals[i] = computed[i];
        reweld = true;
        replaced = true;
    }
    if (reweld) weld_identical_vertices(mesh);
    if (mesh.normals.empty()) mesh.normals = normals_over_shared_positions(mesh);
    update_bounds(mesh);
    return replaced;
}

class MeshBuilder {
  public:
    MeshBuilder(const std::vector<Chunk>& chunks, const std::vector<std::size_t>& face_prefix,
                const Attributes& attributes)
        : chunks_(chunks),
          face_prefix_(face_prefix),
          a_(attributes),
          slots_([&] { return std::vector<Slot>(attributes.positions.size()); }) {}

    MeshOutcome build(const MeshPlan& plan, std::uint32_t stamp) const {
        MeshOutcome out;
        Mesh& mesh = out.mesh;
        mesh.name = plan.name;
        VertexTable vertices(slots_.local(), stamp);
        mesh.indices.reserve(plan.triangles * 3);
        const std::size_t reserved = std::min(plan.triangles * 3, a_.positions.size());
        mesh.positions.reserve(reserved);
        if (plan.uvs) mesh.uvs.reserve(reserved);
        if (plan.normals) mesh.normals.reserve(reserved);
        // Corners without uv or normal indices in a mesh that has them: Assimp leaves those
        // zero, which FlipUVs makes (0, 1), and a zero normal is replaced by a computed one.
        constexpr std::uint32_t kAbsent = kNone - 1;
        bool absent = false;

        std::size_t chunk = chunk_holding(face_prefix_, plan.face_begin);
        for (std::size_t f = plan.face_begin; f < plan.face_end; ++f) {
            while (f >= face_prefix_[chunk + 1]) ++chunk;
            const Chunk& c = chunks_[chunk];
            const Face& face = c.faces[f - face_prefix_[chunk]];
            if (face.kind != kPolygon) continue;
            const bool has_uv = face.attributes & kHasUv, has_normal = face.attributes & kHasNormal;
            absent |= (plan.uvs && !has_uv) || (plan.normals && !has_normal);
            // Assimp's split of a quad: a fan from this corner.
            unsigned fan = 0;
            if (face.corners == 4) {
                const glm::vec3* corner_positions[4];
                for (unsigned k = 0; k < 4; ++k)
                    corner_positions[k] =
                        &a_.positions[static_cast<std::uint32_t>(c.corner_v[face.first + k])];
                fan = quad_fan_corner(corner_positions);
            }
            const unsigned first_corner = plan.mixed ? fan : 0;  // see MeshPlan::mixed
            std::uint32_t ids[4];
            for (unsigned j = 0; j < face.corners; ++j) {
                const unsigned k = (first_corner + j) % face.corners;
                const std::size_t corner = face.first + k;
                const auto v = static_cast<std::uint32_t>(c.corner_v[corner]);
                const auto t = has_uv ? static_cast<std::uint32_t>(c.corner_t[corner]) : 0u;
                const auto n = has_normal ? static_cast<std::uint32_t>(c.corner_n[corner]) : 0u;
                const std::uint32_t kv = a_.first_position.empty() ? v : a_.first_position[v];
                const std::uint32_t kt = !plan.uvs             ? 0u
                                         : !has_uv             ? kAbsent
                                         : a_.first_uv.empty() ? t
                                                               : a_.first_uv[t];
                const std::uint32_t kn = !plan.normals             ? 0u
                                         : !has_normal             ? kAbsent
                                         : a_.first_normal.empty() ? n
                                                                   : a_.first_normal[n];
                const auto next = static_cast<std::uint32_t>(mesh.positions.size());
                const std::uint32_t id = vertices.find_or_add(kv, kt, kn, next);
                if (id == next) {
                    const glm::vec3& p = a_.positions[v];
                    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
                        out.non_finite = {v, id};
                        return out;
                    }
                    mesh.positions.push_back(p);
                    if (plan.uvs) mesh.uvs.push_back(has_uv ? a_.uvs[t] : glm::vec2(0.0f, 1.0f));
                    if (plan.normals)
                        mesh.normals.push_back(has_normal ? a_.normals[n]
                                                          : glm::vec3(std::nanf("")));
                }
                ids[k] = id;
            }
            if (face.corners == 3) {
                mesh.indices.push_back(ids[0]);
                mesh.indices.push_back(ids[1]);
                mesh.indices.push_back(ids[2]);
            } else {
                for (unsigned k : {fan, fan + 1, fan + 2, fan, fan + 2, fan + 3})
                    mesh.indices.push_back(ids[k % 4]);
            }
        }
        out.normals_recomputed = finish_mesh(mesh, absent);
        return out;
    }

  private:
    const std::vector<Chunk>& chunks_;
    const std::vector<std::size_t>& face_prefix_;
    const Attributes& a_;
    mutable tbb::enumerable_thread_specific<std::vector<Slot>> slots_;
};

}  // namespace

void index_equal_values(const std::vector<Chunk>& chunks, Attributes& attributes) {
    bool uses_uvs = false, uses_normals = false;
    for (const Chunk& c : chunks) {
        for (const Face& face : c.faces) {
            uses_uvs |= (face.attributes & kHasUv) != 0;
            uses_normals |= (face.attributes & kHasNormal) != 0;
        }
    }
    tbb::parallel_invoke(
        [&] {
            attributes.first_position =
                first_equal_values<3>(&attributes.positions.data()->x, attributes.positions.size());
        },
        [&] {
            if (uses_uvs)
                attributes.first_uv =
                    first_equal_values<2>(&attributes.uvs.data()->x, attributes.uvs.size());
        },
        [&] {
            if (uses_normals)
                attributes.first_normal =
                    first_equal_values<3>(&attributes.normals.data()->x, attributes.normals.size());
        });
}

std::vector<MeshOutcome> build_meshes(const std::vector<Chunk>& chunks,
                                      const std::vector<std::size_t>& face_prefix,
                                      const Attributes& attributes,
                                      const std::vector<MeshPlan>& meshes,
                                      const std::vector<std::uint32_t>& output) {
    const MeshBuilder builder(chunks, face_prefix, attributes);
    std::vector<MeshOutcome> built(output.size());
    tbb::parallel_for(std::size_t{0}, output.size(), [&](std::size_t i) {
        built[i] = builder.build(meshes[output[i]], static_cast<std::uint32_t>(i + 1));
    });
    return built;
}

}  // namespace zraster::io::obj
