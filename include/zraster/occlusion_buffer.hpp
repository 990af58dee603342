// A conservative software occlusion buffer for engines: render a few large occluders, then ask
// whether the bounding boxes of everything else can be seen (after Andersson, Hasselgren and
// Akenine-Möller 2015, "Masked Software Occlusion Culling", Intel; our own implementation).
//
// Conventions (the same as the Renderer's):
//  - OpenGL clip space: visible points have -w <= x, y, z <= w and w > 0.
//  - Window depth in [0, 1]: depth = 0.5 * z / w + 0.5, near -> 0, far -> 1; the depth test is
//    LESS (smaller is nearer). Reversed-Z callers can pass depth' = 1 - depth for rectangles,
//    but occluders and boxes must use a standard (near -> 0) projection.
//  - Pixel rows top to bottom (row 0 at NDC y = +1), as in RenderTargets; NDC x = -1 is the
//    left edge of column 0. A pixel belongs to a triangle when its center is inside.
//
// Representation: the screen is cut into tiles of kTileWidth x kTileHeight pixels (16 x 16);
// each pixel row of a tile (a 16-pixel strip) keeps a coverage bit mask and two depth layers.
// `far_depth` bounds every pixel of the strip; `near_depth` bounds the pixels whose mask bit is
// set. When a strip's mask fills up, its near layer becomes the far layer (MSOC's merge, with
// its rule for dropping the near layer when a much nearer surface arrives). The strips are
// stored by column of tiles, rows in order, so that rasterization takes 16 rows from any row
// (one SIMD lane per strip): a triangle up to 16 rows tall is one vector per column of tiles
// wherever it starts. A row's coverage is the bits between its left and right edge crossings
// (two shifts), its depth bound the triangle's plane at the extreme covered column. Every stored
// depth is an upper bound of the true nearest occluder depth at each pixel
// (src/occlusion/occluder_setup.cpp explains the margins), so "Occluded" is only answered when
// every pixel the object could touch holds an occluder strictly nearer than the object's nearest
// point. Per tile, the largest and smallest bounds are kept too (refreshed at the end of each
// render_occluders call), so most tiles of a test are settled without reading them.
//
// Guarantees:
//  - Conservative: never Occluded for something an exact z-buffer of the same occluders would
//    show. Occluder edges move inwards by their float error (about 2^-21 of the window
//    coordinates, times 1 + |slope|) plus OccluderOptions::subpixel_margin, depths grow by
//    their float error (about 2^-20 relative), tested objects grow by 1/64 pixel and 2^-20 in
//    depth, and "Occluded" needs the object's nearest depth to be strictly behind.
//  - Interior edges are watertight: an edge shared (reversed) with the previous or next
//    triangle of the index list, facing the same way, moves outwards by its float error
//    instead, so the two halves of a quad leave no seam. Other shared edges keep their margin:
//    pixel centers lying exactly on them (screen-aligned geometry) stay uncovered.
//  - NaN or infinite inputs never crash: such occluder triangles are skipped and such objects
//    are Visible.
//  - Occluder triangles crossing the near plane are clipped against it; tested boxes and
//    triangles crossing it are Visible.
//
// Best culling comes from drawing occluders nearest first: each row keeps only two depth
// layers, and a far surface drawn before a near one can cost the near one's detail.
//
// The SIMD path (Google Highway, instruction set chosen at run time) and the scalar reference
// path give bit-identical buffers and answers.
#pragma once
#include <zraster/bounds.hpp>
#include <zraster/export.hpp>

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace zraster {

enum class OcclusionResult {
    Visible,      // may be seen (or could not be decided: NaN, crosses the near plane)
    Occluded,     // certainly hidden behind the occluders rendered since the last clear
    OutsideView,  // entirely outside the view frustum
};

// Which occluder triangles are skipped. The front face is the counter-clockwise one on screen
// (OpenGL's default) unless `front_face_clockwise` is set.
enum class OccluderCull { None, Back, Front };

struct OccluderOptions {
    OccluderCull cull = OccluderCull::Back;
    bool front_face_clockwise = false;
    // Extra inset of occluder edges, in pixels. 0 is conservative against an exact rasterizer
    // of the same unsnapped triangles (up to float error); a rasterizer that snaps vertices to a
    // grid moves edges by up to half a grid step, so pass the step: 1/256 for zraster's
    // Renderer (the Renderer's own occlusion culling does). Larger margins cover less.
    float subpixel_margin = 0.0f;
};

class ZRASTER_API OcclusionBuffer {
  public:
    static constexpr int kTileWidth = 16;
    static constexpr int kTileHeight = 16;

    // Any size from 1x1 to 16384x16384; the storage is rounded up to whole tiles (the extra
    // pixels are never tested). Starts cleared. Throws InputError for a size out of range.
    // Not thread-safe while occluders are drawn; tests are const and may run concurrently.
    OcclusionBuffer(int width, int height);
    OcclusionBuffer();  // 0 x 0: call set_resolution first
    ~OcclusionBuffer();
    // A moved-from buffer may only be destroyed or assigned to.
    OcclusionBuffer(OcclusionBuffer&&) noexcept;
    OcclusionBuffer& operator=(OcclusionBuffer&&) noexcept;

    void set_resolution(int width, int height);  // and clears
    int width() const;
    int height() const;

    // Use the SIMD kernels (default) or the scalar reference path: same results, bit for bit.
    void set_simd(bool on);
    // The instruction set the SIMD path runs on ("AVX2", "AVX3", "SSE4", ...).
    static const char* simd_target();

    // Empties the buffer: every pixel at depth 1 (the far plane), nothing occludes anything.
    void clear();

    // Occluders: triangles given by indices (three per triangle; a partial last triple is
    // ignored; an index past the vertices skips that triangle). Either clip-space positions,
    // or object positions with the object-to-clip matrix (projection * view * model).
    void render_occluders(std::span<const glm::vec4> clip_positions,
                          std::span<const std::uint32_t> indices, const OccluderOptions& = {});
    void render_occluders(std::span<const glm::vec3> positions,
                          std::span<const std::uint32_t> indices, const glm::mat4& to_clip,
                          const OccluderOptions& = {});

    // A screen rectangle in NDC (x right, y up, both in [-1, 1] on screen) whose nearest point
    // has window depth `nearest_depth`. OutsideView when it misses the screen or lies beyond
    // the far plane (nearest_depth > 1); Visible when nearest_depth < 0 (crosses the near
    // plane).
    OcclusionResult test_rect(glm::vec2 ndc_min, glm::vec2 ndc_max, float nearest_depth) const;
    // The same with pixel bounds: columns x0..x1 and rows y0..y1, inclusive (row 0 at the top).
    OcclusionResult test_pixel_rect(int x0, int y0, int x1, int y1, float nearest_depth) const;
    // An axis-aligned box in object space with its object-to-clip matrix (its eight corners are
    // tested). Visible when a corner is behind the near plane or not finite.
    OcclusionResult test_box(const Bounds3f& box, const glm::mat4& to_clip) const;
    // A triangle in clip space (tested by its screen bounding rectangle).
    OcclusionResult test_triangle(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c) const;

    // Per pixel (row-major, width() x height()), the depth bound the buffer holds: an upper
    // bound of the nearest occluder's depth, 1 where nothing was rendered. For debugging and
    // pictures.
    void depth_bounds(std::span<float> out) const;
    // A copy of the raw storage (coverage masks and depth layers), for tests that compare two
    // buffers bit for bit.
    std::vector<std::byte> raw_storage() const;

    // Counters since the last clear.
    std::uint64_t occluder_triangles_rasterized() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace zraster
