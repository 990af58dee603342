// Line rasterization: the digital differential analyzer (DDA) and Bresenham's integer algorithm
// (Bresenham 1965, "Algorithm for computer control of a digital plotter").
//
// Pixel model: lines live in pixel-index coordinates, where pixel (x, y) IS the lattice point
// (x, y) (Bresenham's plotter model). To draw a segment given in window coordinates, where the
// center of pixel (px, py) is (px + 0.5, py + 0.5), subtract 0.5 from both endpoints first.
//
// The endpoint and tie rule, shared by every function here:
//  - The major axis is x when |dx| >= |dy|, otherwise y (a 45-degree line is x-major; both
//    choices give the same pixels there). Exactly one pixel is drawn per major coordinate, from
//    one endpoint's to the other's, both INCLUDED: max(|dx|, |dy|) + 1 pixels, each 8-connected
//    to the next. A zero-length line is its one pixel.
//  - In each column (row, for y-major lines) the pixel is the one nearest to the ideal line in
//    the minor axis, so it is never more than 0.5 away.
//  - A tie (the ideal line passes exactly half-way between two pixels) goes to the LARGER minor
//    coordinate: "round half up", floor(v + 0.5). The rule depends on the geometry only, not on
//    which endpoint comes first, so the line from b to a covers exactly the same pixels as the
//    line from a to b (a direction-dependent rule, such as the textbook "step when the error is
//    > 0", draws different pixels in the two directions and leaves wireframe edges shared by two
//    triangles drawn inconsistently).
//
// Pixels are listed in order from a to b. The functions append to `out` so that a caller drawing
// many lines reuses one buffer and allocates nothing in steady state.
#pragma once
#include <glm/glm.hpp>
#include <zraster/export.hpp>

#include <vector>

namespace zraster {

// Bresenham: integer arithmetic only, exact for any endpoints whose coordinate differences fit
// in an int.
ZRASTER_API void bresenham_line(glm::ivec2 a, glm::ivec2 b, std::vector<glm::ivec2>& out);
ZRASTER_API std::vector<glm::ivec2> bresenham_line(glm::ivec2 a, glm::ivec2 b);

// DDA on real endpoints: one pixel per major coordinate from round(a.major) to round(b.major)
// (rounded half up), minor coordinate = floor(y + 0.5) of the ideal line there, accumulated
// incrementally in double. For integer endpoints it draws max(|dx|, |dy|) + 1 pixels and agrees
// with Bresenham except possibly on exact ties: there the accumulated value is k + 0.5 only up to
// rounding error, and may land on either side.
ZRASTER_API void dda_line(glm::dvec2 a, glm::dvec2 b, std::vector<glm::ivec2>& out);
ZRASTER_API std::vector<glm::ivec2> dda_line(glm::dvec2 a, glm::dvec2 b);

// A wireframe pixel with its interpolated window depth.
struct LinePixel {
    int x, y;
    float depth;
};

// Bresenham's pixels with depth interpolated linearly between depth_a at a and depth_b at b, at
// the pixel's major coordinate. Window depth (z/w after the divide) is affine in screen space, so
// linear interpolation is exact here, not an approximation. The depth is always computed from
// the lexicographically smaller endpoint, so the line from b to a gives bit-identical depths (a
// shared wireframe edge does not z-fight with itself). A zero-length line gets the smaller depth.
ZRASTER_API void bresenham_line_depth(glm::ivec2 a, float depth_a, glm::ivec2 b, float depth_b,
                                      std::vector<LinePixel>& out);
ZRASTER_API std::vector<LinePixel> bresenham_line_depth(glm::ivec2 a, float depth_a, glm::ivec2 b,
                                                        float depth_b);
// The same line's pixels inside [0, width) x [0, height), appended to `out`, in order: what the
// call above gives there, bit for bit, found in O(pixels inside) steps, however far outside the
// endpoints lie (a wireframe edge that crosses a small image from far away).
ZRASTER_API void bresenham_line_depth_in(glm::ivec2 a, float depth_a, glm::ivec2 b, float depth_b,
                                         int width, int height, std::vector<LinePixel>& out);

}  // namespace zraster
