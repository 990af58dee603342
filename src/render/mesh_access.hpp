// Reading a MeshView's arrays (include/zraster/mesh_view.hpp) in the stages: tightly packed
// arrays as typed pointers (the hot paths read those exactly as they read a Mesh's vectors),
// strided attributes element by element or a block at a time, 16-bit indices widened.
//
// Strided elements are copied out with memcpy, never dereferenced in place: a stride need not
// keep the floats aligned.
#pragma once
#include <zraster/mesh_view.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace zraster::detail {

inline constexpr std::size_t kPositionBytes = 3 * sizeof(float);  // also a normal
inline constexpr std::size_t kUvBytes = 2 * sizeof(float);
inline constexpr std::size_t kColorBytes = 4 * sizeof(float);

// The distance between elements of `element` bytes (stride 0: tightly packed).
inline std::size_t stride_of(const AttributeView& a, std::size_t element) {
    return a.stride == 0 ? element : a.stride;
}

// The array as a tightly packed glm::vec3 array, or null when it is strided (or empty).
inline const glm::vec3* packed_vec3(const AttributeView& a) {
    static_assert(sizeof(glm::vec3) == kPositionBytes);
    return a.count > 0 && stride_of(a, kPositionBytes) == kPositionBytes
               ? reinterpret_cast<const glm::vec3*>(a.data)
               : nullptr;
}

inline const std::byte* element_bytes(const AttributeView& a, std::size_t element, std::size_t i) {
    return reinterpret_cast<const std::byte*>(a.data) + i * stride_of(a, element);
}

inline glm::vec3 load_vec3(const AttributeView& a, std::size_t i) {
    glm::vec3 v;
    std::memcpy(&v, element_bytes(a, kPositionBytes, i), kPositionBytes);
    return v;
}

inline glm::vec2 load_vec2(const AttributeView& a, std::size_t i) {
    glm::vec2 v;
    std::memcpy(&v, element_bytes(a, kUvBytes, i), kUvBytes);
    return v;
}

inline glm::vec4 load_vec4(const AttributeView& a, std::size_t i) {
    glm::vec4 v;
    std::memcpy(&v, element_bytes(a, kColorBytes, i), kColorBytes);
    return v;
}

// Elements [first, first + count) of a 3-float attribute, tightly packed into `out`.
inline void gather_vec3(const AttributeView& a, std::size_t first, std::size_t count,
                        glm::vec3* out) {
    const std::size_t stride = stride_of(a, kPositionBytes);
    const std::byte* from = element_bytes(a, kPositionBytes, first);
    for (std::size_t i = 0; i < count; ++i, from += stride)
        std::memcpy(&out[i], from, kPositionBytes);
}

inline std::size_t triangle_count(const MeshView& mesh) {
    return mesh.indices.count / 3;
}

// The indices as 32-bit ones in place, or null when they are 16-bit (or empty).
inline const std::uint32_t* packed_indices32(const IndexView& v) {
    return v.count > 0 && v.type == IndexType::UInt32 ? static_cast<const std::uint32_t*>(v.data)
                                                      : nullptr;
}

inline std::uint32_t load_index(const IndexView& v, std::size_t i) {
    return v.type == IndexType::UInt16 ? static_cast<const std::uint16_t*>(v.data)[i]
                                       : static_cast<const std::uint32_t*>(v.data)[i];
}

// Indices [first, first + count) as 32-bit ones into `out`.
inline void widen_indices(const IndexView& v, std::size_t first, std::size_t count,
                          std::uint32_t* out) {
    if (v.type == IndexType::UInt32) {
        std::copy_n(static_cast<const std::uint32_t*>(v.data) + first, count, out);
        return;
    }
    std::copy_n(static_cast<const std::uint16_t*>(v.data) + first, count, out);
}

// A scene mesh as a frame's stages read it: its view, the packed arrays' typed pointers (null
// where the view is strided, 16-bit or empty) and its object-space bounds (the view's, or
// computed by the renderer).
struct FrameMesh {
    const MeshView* view = nullptr;
    const glm::vec3* positions = nullptr;
    const glm::vec3* normals = nullptr;
    const std::uint32_t* indices = nullptr;
    Bounds3f bounds;
    // The least alpha of its vertex colors (1 without colors; NaN when one is NaN): whether
    // vertex alpha can make its material transparent (material_alpha.hpp).
    float least_vertex_alpha = 1.0f;

    std::size_t vertex_count() const { return view->positions.count; }
    std::size_t triangle_count() const { return detail::triangle_count(*view); }
    bool has_normals() const { return view->normals.count > 0; }
    bool has_uvs() const { return view->uvs.count > 0; }
    bool has_colors() const { return view->colors.count > 0; }
    glm::vec3 position(std::size_t i) const {
        return positions != nullptr ? positions[i] : load_vec3(view->positions, i);
    }
    glm::vec2 uv(std::size_t i) const { return load_vec2(view->uvs, i); }
    glm::vec4 color(std::size_t i) const { return load_vec4(view->colors, i); }
    std::uint32_t index(std::size_t i) const {
        return indices != nullptr ? indices[i] : load_index(view->indices, i);
    }
};

inline FrameMesh frame_mesh(const MeshView& view) {
    FrameMesh mesh;
    mesh.view = &view;
    mesh.positions = packed_vec3(view.positions);
    mesh.normals = packed_vec3(view.normals);
    mesh.indices = packed_indices32(view.indices);
    if (view.bounds) mesh.bounds = *view.bounds;
    return mesh;
}

}  // namespace zraster::detail
