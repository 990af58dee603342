// Internal helpers shared by the visibility algorithms: the per-frame projection state, the
// projection of one triangle into a ScreenPolygon, and a canvas that fills polygons with the
// renderer's coverage rule and no depth test.
#pragma once
#include <zraster/clip.hpp>
#include <zraster/raster.hpp>
#include <zraster/visibility.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace zraster::visibility_detail {

// What render() derives from its options before the vertex stage, recomputed here from the same
// public pieces (Camera::view_projection, ClipSettings, SetupSettings).
struct FrameContext {
    const Scene* scene = nullptr;
    const RenderOptions* options = nullptr;
    Camera camera;
    glm::mat4 view_projection{1.0f};
    // Float, as the renderer's lighting sees them.
    glm::vec3 eye{0.0f};
    glm::vec3 view_axis{0.0f, 0.0f, 1.0f};
    glm::dvec4 viewer{0.0};  // bsp_eye(camera)
    ClipSettings clip_settings;
    SetupSettings setup_settings;
};

// Throws InputError for an image size out of range or too many user clip planes.
FrameContext make_frame_context(const Scene& scene, const RenderOptions& options);

// Snaps v.clip with the rasterizer's own per-vertex transform (to_screen) into v.snapped, and
// sets v.window.x, y to that snapped position in pixels. False when to_screen refuses the vertex
// (w <= 0 or beyond the guard band: the clipper never lets such a vertex through).
bool set_window_xy(PolygonVertex& v, const Viewport& viewport);
// The same, plus v.window.z: the window depth, normalized so that larger is farther.
bool set_window(PolygonVertex& v, const FrameContext& frame);

// Twice the signed area of the snapped polygon, y down: negative is counter-clockwise as seen with
// y up, like setup_triangle's area.
std::int64_t snapped_area2(std::span<const PolygonVertex> vertices);

// One scene triangle as the renderer's primitive assembly sees it.
struct TriangleSource {
    std::int32_t instance = -1, primitive = -1;
    std::array<glm::vec4, 3> clip{};     // mvp * object position (float, as render() computes it)
    std::array<glm::dvec3, 3> world{};   // world positions (double)
    std::array<glm::vec3, 3> world_f{};  // float world positions (user clip plane distances)
    glm::dvec4 plane{0.0};               // the source triangle's world plane, unit normal
};

// Clips and projects the triangle; false when nothing of it is left (rejected, clipped away,
// non-finite, zero snapped area, culled, or no pixel center in its bounding box).
bool project_triangle(const FrameContext& frame, const TriangleSource& source, ScreenPolygon& out);

// Flat shading of a scene triangle, exactly as the renderer's flat path computes it.
struct FlatShade {
    glm::vec3 color{0.0f};
    glm::vec3 normal{0.0f};
};
FlatShade flat_shade(const FrameContext& frame, std::int32_t instance, std::int32_t primitive,
                     bool front_facing);

// Unit world plane through a, b, c along their winding; (0, 0, 0, 0) when degenerate.
glm::dvec4 plane_through(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

// A plane flipped (if needed) so that `viewer` is on its positive side.
glm::dvec4 orient_towards(const glm::dvec4& plane, const glm::dvec4& viewer);

// Render targets filled polygon by polygon without a depth test.
class Canvas {
  public:
    Canvas(const RenderOptions& options, const Camera& camera);

    // The fan triangles (from vertex 0) of a polygon that setup_triangle accepts.
    void prepare(const ScreenPolygon& polygon, std::vector<TriangleSetup>& fans) const;
    // Draws the prepared fans of `polygon` over the pixels of [x0, x1) x [y0, y1).
    void draw(const ScreenPolygon& polygon, std::span<const TriangleSetup> fans, int x0, int y0,
              int x1, int y1);
    void draw(const ScreenPolygon& polygon);  // whole viewport

    RenderTargets take();
    std::uint64_t fragments() const { return fragments_; }

  private:
    const RenderOptions& options_;
    SetupSettings setup_;
    RenderTargets targets_;
    std::vector<TriangleSetup> scratch_;
    std::uint64_t fragments_ = 0;
};

}  // namespace zraster::visibility_detail
