// Scenes as views of memory the caller owns: what Renderer::render(const SceneView&, ...) reads,
// with nothing copied in. An engine hands over its vertex and index buffers as they are
// (interleaved or not, 16- or 32-bit indices); an owning Scene is viewed the same way (view_of).
//
// A view is a pointer, a count and a stride: it does not own, keep or free anything. The memory
// must stay valid and unchanged while a render call reads it; between calls the renderer keeps
// nothing of it except the pointers and counts, as keys of its caches (include/zraster/render.hpp).
// Bad views (a null pointer with elements, a stride shorter than an element, arrays of different
// counts, an index past the vertices) are refused by the renderer with an InputError naming the
// field, before anything is read.
#pragma once
#include <zraster/bounds.hpp>
#include <zraster/export.hpp>
#include <zraster/lighting.hpp>
#include <zraster/material.hpp>
#include <zraster/portals.hpp>
#include <zraster/scene.hpp>

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace zraster {

// `count` elements of N floats (N by the attribute: 3 for positions and normals, 2 for uvs, 4 for
// colors),
// element i at byte offset i * stride from `data`; stride 0 means tightly packed (N * 4 bytes).
// So an interleaved vertex buffer works:
//   positions = {&vertices[0].position.x, n, sizeof(Vertex)}.
// `data` may be null only when count is 0. A stride need not be a multiple of 4 (the floats are
// copied out, not dereferenced in place), but tightly packed arrays are the fast path: the
// vertex stage reads them directly and copies strided ones a block of vertices at a time.
struct AttributeView {
    const float* data = nullptr;
    std::size_t count = 0;
    std::size_t stride = 0;
};

enum class IndexType : std::uint8_t { UInt16, UInt32 };

// `count` indices of `type`, tightly packed, `data` aligned to the index size (null only when
// count is 0).
struct IndexView {
    const void* data = nullptr;
    std::size_t count = 0;
    IndexType type = IndexType::UInt32;
};

struct MeshView {
    AttributeView positions;  // 3 floats each
    AttributeView normals;    // optional (count 0), else one per position, 3 floats, unit length
    AttributeView uvs;        // optional (count 0), else one per position, 2 floats; v = 0 at the
                              // image's top row
    AttributeView colors;     // optional (count 0), else one per position, 4 floats: RGBA
                              // multiplying the material's base color and alpha (Mesh::colors)
    IndexView indices;        // three per triangle, counter-clockwise = front; a partial last
                              // triple is ignored
    std::uint32_t material = 0;  // index into SceneView::materials
    // Object-space bounds of the positions. Unset (or empty while there are positions): the
    // renderer computes them every frame (a pass over the positions: pass them to save it).
    std::optional<Bounds3f> bounds;
    std::string_view name;  // for messages
};

struct InstanceView {
    std::uint32_t mesh = 0;              // index into SceneView::meshes
    glm::mat4 transform{1.0f};           // object to world
    std::optional<ShadingMode> shading;  // overrides RenderOptions::shading for this instance
};

struct SceneView {
    std::span<const MeshView> meshes;
    std::span<const Material> materials;  // must be non-empty; index 0 the default
    std::span<const InstanceView> instances;
    // The scene's cells and portals (portals.hpp), for RenderOptions::portal_cull and a PVS;
    // null: none. Its instance indices are into `instances`. Not owned.
    const CellGraph* cells = nullptr;
};

// A view of an owning mesh: its arrays tightly packed (stride 12 and 8), 32-bit indices, and its
// bounds (left unset when they are empty while the mesh has positions, so the renderer computes
// them). Valid while the mesh's arrays are not reallocated.
ZRASTER_API MeshView view_of(const Mesh& mesh);

// Views of an owning scene's meshes and instances, written into `meshes` and `instances`
// (resized; their capacity is kept, so viewing the same scene every frame allocates nothing),
// and the scene view over them and scene.materials. A mesh's material past scene.materials
// becomes 0 in its view, as render(const Scene&, ...) has always drawn it (a SceneView's own
// material past its materials is refused).
ZRASTER_API SceneView view_of(const Scene& scene, std::vector<MeshView>& meshes,
                              std::vector<InstanceView>& instances);

}  // namespace zraster
