// The vertex stage's inner loop: object position -> clip position (mvp, not stored), outcode
// (frustum and guard band; kNonFinite for NaN/Inf), and for vertices inside, the snapped screen
// vertex (to_screen, in double). Vertices inside whose screen position is not representable get
// kClipLeft so the clipper handles them.
//
// Two implementations with identical output: a scalar reference and a SIMD one (Highway,
// instruction set picked at run time; 8 vertices per AVX-512 step, the snap in double lanes).
// Screen vertices are only defined where the outcode is 0; elsewhere their x is
// kOutsideScreenX (the classifier's sign of "outside"). A test compares both there, and the
// outcodes and that x everywhere.
#pragma once
#include <zraster/clip.hpp>
#include <zraster/raster.hpp>

#include "render/classify_kernel.hpp"

#include <cstddef>
#include <cstdint>

namespace zraster::detail {

struct VertexJob {
    const glm::vec3* positions = nullptr;
    std::size_t count = 0;
    glm::mat4 mvp{1.0f};
    ClipSettings clip;
    SetupSettings setup;
    ScreenVertex* screen_out = nullptr;
    std::uint32_t* outcode_out = nullptr;
    // Optional world attributes, as world_attributes() computes them (frame.hpp): the world
    // position (model) when world_out is set, and the unit world normal (normal_matrix) when
    // normal_out is set too; normals null means (0, 1, 0) for every vertex.
    glm::mat4 model{1.0f};
    glm::mat3 normal_matrix{1.0f};
    const glm::vec3* normals = nullptr;
    glm::vec3* world_out = nullptr;
    glm::vec3* normal_out = nullptr;
};

// m * (p, 1), written out in the order the SIMD version uses (equal to glm's m * vec4(p, 1)).
// Clip positions are not stored: the clipper, which alone needs them, recomputes them with this.
inline glm::vec4 clip_position(const glm::mat4& m, const glm::vec3& p) {
    return glm::vec4((m[0].x * p.x + m[1].x * p.y) + (m[2].x * p.z + m[3].x),
                     (m[0].y * p.x + m[1].y * p.y) + (m[2].y * p.z + m[3].y),
                     (m[0].z * p.x + m[1].z * p.y) + (m[2].z * p.z + m[3].z),
                     (m[0].w * p.x + m[1].w * p.y) + (m[2].w * p.z + m[3].w));
}

void transform_vertices(const VertexJob& job);
void transform_vertices_scalar(const VertexJob& job);

}  // namespace zraster::detail
