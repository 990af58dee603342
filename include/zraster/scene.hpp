// A scene: meshes, their materials, instances placing them in the world, lights.
#pragma once
#include <zraster/export.hpp>
#include <zraster/lighting.hpp>
#include <zraster/mesh.hpp>
#include <zraster/portals.hpp>

#include <memory>

#include <optional>
#include <string>
#include <vector>

namespace zraster {

struct Instance {
    std::uint32_t mesh = 0;
    glm::mat4 transform{1.0f};           // object to world
    std::optional<ShadingMode> shading;  // overrides the render option for this instance
    std::string name;
};

struct ZRASTER_API Scene {
    std::vector<Mesh> meshes;
    std::vector<Material> materials{Material{}};  // index 0 is the default material
    std::vector<Instance> instances;
    // What error messages call this scene: the file it was loaded from, the procedural scene's
    // specification ("city:100"), or the caller's label.
    std::string name;
    // Cells and portals (portals.hpp, validated for these instances), for portal culling; null:
    // none. Shared: copies of a scene share one graph.
    std::shared_ptr<const CellGraph> cells;

    // World-space bounds of all instances (each mesh box transformed).
    Bounds3f bounds() const;
    // World-space positions of every instanced vertex (for exact camera fitting).
    std::vector<glm::vec3> world_positions() const;
    std::size_t triangle_count() const;  // over instances
    std::size_t vertex_count() const;    // over instances
};

// A scene with one instance (identity transform) of each mesh.
ZRASTER_API Scene scene_from_meshes(std::vector<Mesh> meshes);

}  // namespace zraster
