// Internal data of one frame, shared by the renderer's stages (src/render/*.cpp).
#pragma once
#include <zraster/clip.hpp>
#include <zraster/render.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace zraster::detail {

// One instance as the later stages see it.
struct FrameInstance {
    std::uint32_t scene_instance = 0;  // index into Scene::instances (the id written out)
    const Mesh* mesh = nullptr;
    const Material* material = nullptr;
    ShadingMode shading = ShadingMode::Phong;
    std::uint32_t first_vertex = 0;  // into FrameVertices
    glm::mat4 mvp{1.0f};
    bool textured = false;
};

// Output of the vertex stage for every vertex of every visible instance.
struct FrameVertices {
    std::vector<glm::vec4> clip;
    std::vector<glm::vec3> world;
    std::vector<glm::vec3> normal;  // world space, unit
    std::vector<glm::vec2> uv;      // (0, 0) when the mesh has none
    std::vector<LightTerms> gouraud;  // per-vertex lighting (Gouraud instances only)
};

// A triangle (or a piece of a clipped one) ready for tile rasterization.
struct RasterTriangle {
    TriangleSetup setup;
    std::uint32_t instance = 0;   // into the frame's FrameInstance list
    std::uint32_t primitive = 0;  // triangle index within its mesh
    std::array<std::uint32_t, 3> vertex{};  // the original triangle's vertices (FrameVertices)
    // For a clipped piece: barycentric weights of its three corners relative to the original
    // triangle; attributes are recovered as sum over corners of beta_k * weights[k].
    bool clipped = false;
    std::array<glm::vec3, 3> weights{};
    LightTerms flat;  // flat shading: lit once per triangle
};

struct Frame {
    const Scene* scene = nullptr;
    const RenderOptions* options = nullptr;
    Camera camera;
    glm::vec3 eye{0.0f}, view_axis{0.0f, 0.0f, 1.0f};
    ClipSettings clip_settings;
    SetupSettings setup_settings;
    std::vector<FrameInstance> instances;
    FrameVertices vertices;
    std::vector<RasterTriangle> triangles;
};

// Stages, in order.
void run_vertex_stage(Frame& frame, RenderStats& stats);
void assemble_and_setup(Frame& frame, RenderStats& stats);
void rasterize_tiles(const Frame& frame, RenderTargets& targets, RenderStats& stats);

// Tiles are kTileSize x kTileSize pixels.
inline constexpr int kTileSize = 64;

}  // namespace zraster::detail
