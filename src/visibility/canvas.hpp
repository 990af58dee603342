// Render targets filled polygon by polygon without a depth test: the output stage of the
// list-priority algorithms (painter's, BSP) and of Warnock's leaves.
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

    RenderTargets take();
    std::uint64_t fragments() const { return fragments_; }

  private:
    struct Shading;
    void fill(const ScreenPolygon& polygon, std::span<const TriangleSetup> fans,
              const SurfaceShader::Prepared* shading, int x0, int y0, int x1, int y1);

    const RenderOptions& options_;
    SetupSettings setup_;
    RenderTargets targets_;
    std::vector<TriangleSetup> scratch_;
    std::unique_ptr<Shading> shading_;  // null: flat polygon colors
    std::uint64_t fragments_ = 0;
};

}  // namespace zraster::visibility_detail
