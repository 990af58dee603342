// Render targets filled polygon by polygon without a depth test: the output stage of the
// list-priority algorithms (painter's, BSP) and of Warnock's leaves.
//
// Materials' alpha (with shade_from, RenderOptions::alpha_mode Auto), as the z-buffer path treats
// it: a Mask polygon's pixels whose alpha (sampled as render() samples it) is under the cutoff are
// left as they are; a Blend polygon's pixels are composited over what the canvas holds,
// c = color x alpha + c x (1 - alpha) on the 8-bit color as render()'s blend pass does, the
// running value kept in float between layers so that back-to-front drawing gives the z-buffer's
// composite; blended pixels write neither depth nor ids nor normals.
#pragma once
#include <zraster/visibility.hpp>

#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

#include "visibility/frame_context.hpp"
#include "visibility/surface_shader.hpp"

namespace zraster::visibility_detail {

class Canvas {
  public:
    // shade_from: the scene the polygons were projected from; its pixels are then shaded as
    // render() shades them (SurfaceShader). Null: each polygon's flat color and face normal.
    Canvas(const RenderOptions& options, const Camera& camera, const Scene* shade_from = nullptr);
    ~Canvas();

    // The fan triangles (from vertex 0) of a polygon that setup_triangle accepts.
    void prepare(const ScreenPolygon& polygon, std::vector<TriangleSetup>& fans) const;
    // Draws the prepared fans of `polygon` over the pixels of [x0, x1) x [y0, y1). The polygon
    // must stay where it is until the canvas is taken (its shading is kept by its address).
    void draw(const ScreenPolygon& polygon, std::span<const TriangleSetup> fans, int x0, int y0,
              int x1, int y1);
    // Draws a polygon over the whole viewport (it may change or go after the call).
    void draw(const ScreenPolygon& polygon);

    // What the polygon's material alpha does this frame (Opaque without shade_from).
    AlphaMode alpha_mode(const ScreenPolygon& polygon) const;
    // Whether the polygon, drawn with draw(polygon, fans, ...), hides what is behind it at the
    // center of pixel (px, py) that it covers: Opaque, or Mask with alpha passing the test there.
    bool hides_at(const ScreenPolygon& polygon, int px, int py);

    RenderTargets take();
    std::uint64_t fragments() const { return fragments_; }
    std::uint64_t alpha_discarded() const { return alpha_discarded_; }
    std::uint64_t blended() const { return blended_; }
    // Its counts as RenderStats holds them: fragments drawn, cut out (Mask) and composited
    // (Blend; every one drawn, also where a nearer surface covers it later), and the pixels
    // that received at least one of those.
    void count_fragments(RenderStats& stats) const;

  private:
    struct Shading;
    const SurfaceShader::Prepared& kept(const ScreenPolygon& polygon);
    void fill(const ScreenPolygon& polygon, std::span<const TriangleSetup> fans,
              const SurfaceShader::Prepared* shading, int x0, int y0, int x1, int y1);

    const RenderOptions& options_;
    SetupSettings setup_;
    RenderTargets targets_;
    std::vector<TriangleSetup> scratch_;
    std::unique_ptr<Shading> shading_;  // null: flat polygon colors, everything opaque
    // The composite so far of each pixel, in float (as render()'s blend pass keeps it between
    // layers): only when a Blend polygon may be drawn into the color target.
    std::vector<glm::vec3> over_;
    std::vector<std::uint8_t> blended_pixels_;  // 1: a Blend fragment drawn there
    std::uint64_t fragments_ = 0, alpha_discarded_ = 0, blended_ = 0, pixels_blended_ = 0;
};

}  // namespace zraster::visibility_detail
