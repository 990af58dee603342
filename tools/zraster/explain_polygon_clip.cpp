// `zraster explain sutherland-hodgman`: a polygon clipped against one boundary at a time, in 2D
// and in homogeneous clip space.
#include <zraster/camera.hpp>
#include <zraster/clip.hpp>
#include <zraster/polygon_clip.hpp>

#include <fmt/format.h>

#include "explain_algorithms.hpp"

namespace zraster::cli {
namespace {

constexpr Rgba kInputColor{150, 150, 150, 255}, kPlaneColor{40, 90, 230, 255},
    kKeptFill{60, 190, 90, 110}, kKeptStroke{20, 120, 50, 255};

std::vector<ClipVertex> as_clip_vertices(const std::vector<glm::dvec2>& polygon) {
    std::vector<ClipVertex> v;
    for (const glm::dvec2& p : polygon)
        v.push_back({glm::vec4(glm::vec2(p), 0.0f, 1.0f), glm::vec3(0.0f)});
    return v;
}

std::vector<ClipVertex> clip_by(const std::vector<ClipVertex>& in, const glm::vec4& plane) {
    std::vector<ClipVertex> out(max_clip_output(in.size()));
    out.resize(std::size_t(clip_polygon_against_plane(in, plane, out)));
    return out;
}

// The 2D example: a concave arrow against a rectangle, one edge at a time.
void two_dimensional(ExplainOutput& out) {
    const std::vector<glm::dvec2> arrow = {{40, 150},  {200, 40},  {200, 100}, {370, 100},
                                           {370, 200}, {200, 200}, {200, 260}};
    const double x0 = 110, y0 = 70, x1 = 300, y1 = 230;
    // Keep dot(plane, (x, y, 0, 1)) >= 0: x >= x0, x <= x1, y >= y0, y <= y1 (y down).
    const std::vector<std::pair<glm::vec4, const char*>> planes = {
        {{1, 0, 0, float(-x0)}, "left: x >= 110"},
        {{-1, 0, 0, float(x1)}, "right: x <= 300"},
        {{0, 1, 0, float(-y0)}, "top: y >= 70"},
        {{0, -1, 0, float(y1)}, "bottom: y <= 230"}};
    std::vector<ClipVertex> current = as_clip_vertices(arrow);
    for (std::size_t k = 0; k < planes.size(); ++k) {
        Figure f(420, 300);
        f.rect(x0, y0, x1, y1, FigureStyle{{0, 0, 0, 0}, {0, 0, 0, 255}, 1, true});
        std::vector<glm::dvec2> before;
        for (const ClipVertex& v : current) before.emplace_back(v.position.x, v.position.y);
        f.polygon(before, FigureStyle{{0, 0, 0, 0}, kInputColor, 1, true});
        const glm::vec4 plane = planes[k].first;
        if (plane.x != 0)
            f.line({-plane.w / plane.x, 0}, {-plane.w / plane.x, 300}, kPlaneColor, 2);
        else
            f.line({0, -plane.w / plane.y}, {420, -plane.w / plane.y}, kPlaneColor, 2);
        current = clip_by(current, plane);
        std::vector<glm::dvec2> after;
        for (const ClipVertex& v : current) after.emplace_back(v.position.x, v.position.y);
        f.polygon(after, FigureStyle{kKeptFill, kKeptStroke, 2});
        for (const glm::dvec2& p : after) f.circle(p, 3, kKeptStroke);
        f.text({8, 8}, fmt::format("step {}: clip against the {} ({} -> {} vertices)", k + 1,
                                   planes[k].second, before.size(), after.size()));
        out.figure(fmt::format("sutherland-hodgman-2d-{}", k + 1), f,
                   fmt::format("2D, step {}: dashed gray the polygon so far, blue the boundary, "
                               "green what is kept",
                               k + 1));
    }
}

// A triangle crossing the near plane, drawn in the (z, w) plane of clip space.
void homogeneous(ExplainOutput& out) {
    const glm::dmat4 projection = perspective(glm::radians(60.0), 1.0, 1.0, 10.0);
    const glm::dvec3 eye_space[3] = {{-1.0, -0.4, -4.0}, {1.2, 0.3, -0.4}, {0.2, 0.9, -2.5}};
    std::vector<ClipVertex> triangle;
    for (const glm::dvec3& p : eye_space)
        triangle.push_back({glm::vec4(projection * glm::dvec4(p, 1.0)), glm::vec3(0.0f)});
    const std::array<glm::vec4, 6> planes = view_volume_planes(ClipDepthRange::NegativeOneToOne);
    const std::vector<ClipVertex> near_clipped = clip_by(triangle, planes[0]);
    std::vector<ClipVertex> all = triangle;
    for (const glm::vec4& plane : planes) all = clip_by(all, plane);
    // Picture axes: z to the right, w up; 40 pixels per unit.
    const auto at = [](const ClipVertex& v) {
        return glm::dvec2(250 + 30.0 * v.position.z, 270 - 30.0 * v.position.w);
    };
    Figure f(500, 300);
    f.line({250 - 30 * 7.0, 270 - 30 * 7.0 * 1.0 + 0}, {250, 270}, kPlaneColor, 2);  // z = -w
    f.line({250, 270}, {250 + 30 * 7.0, 270 - 30 * 7.0}, {200, 120, 30, 255}, 2);    // z = w
    f.line({0, 270}, {500, 270}, {0, 0, 0, 255});
    f.text({20, 40}, "near plane z = -w", kPlaneColor);
    f.text({380, 40}, "far plane z = w", {200, 120, 30, 255});
    std::vector<glm::dvec2> before, after;
    for (const ClipVertex& v : triangle) before.push_back(at(v));
    for (const ClipVertex& v : near_clipped) after.push_back(at(v));
    f.polygon(before, FigureStyle{{0, 0, 0, 0}, kInputColor, 1, true});
    f.polygon(after, FigureStyle{kKeptFill, kKeptStroke, 2});
    for (const glm::dvec2& p : after) f.circle(p, 3, kKeptStroke);
    f.text({8, 8}, fmt::format("clip space, z (right) against w (up): the triangle ({} vertices) "
                               "clipped by the near plane keeps {} vertices",
                               triangle.size(), near_clipped.size()));
    f.text({8, 282}, "w = 0 (the eye's plane); inside the view volume: between the two lines");
    out.figure("sutherland-hodgman-homogeneous", f,
               "homogeneous clipping before the divide: a triangle with a vertex in front of "
               "the near plane, in the (z, w) plane of clip space");
    Figure ndc(300, 300);
    ndc.rect(50, 50, 250, 250, FigureStyle{{0, 0, 0, 0}, {0, 0, 0, 255}, 1, true});
    std::vector<glm::dvec2> divided;
    for (const ClipVertex& v : all)
        divided.emplace_back(150 + 100 * v.position.x / v.position.w,
                             150 - 100 * v.position.y / v.position.w);
    ndc.polygon(divided, FigureStyle{kKeptFill, kKeptStroke, 2});
    ndc.text({8, 8}, fmt::format("after all six planes and the divide: {} vertices in [-1, 1]^2",
                                 all.size()));
    out.figure("sutherland-hodgman-ndc", ndc,
               "the clipped polygon after the perspective divide, inside the normalized square");
}

}  // namespace

void explain_sutherland_hodgman(const ExplainInput&, ExplainOutput& out) {
    two_dimensional(out);
    homogeneous(out);
}

}  // namespace zraster::cli
