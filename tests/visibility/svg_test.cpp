// render_svg: a well-formed SVG 1.1 document whose polygons, painted back to front, are exactly
// the BSP / painter's frames, and whose merging keeps the painted area while joining coplanar
// neighbours.
#include <zraster/error.hpp>
#include <zraster/scenes.hpp>
#include <zraster/svg.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "visibility/visibility_test_util.hpp"

namespace zraster::test {
namespace {

RenderOptions small_options(int width = 160, int height = 120) {
    RenderOptions o;
    o.width = width;
    o.height = height;
    o.threads = 1;
    return o;
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

// Well-formedness basics: every element closed in order, one root <svg>, attributes quoted.
void expect_well_formed(const std::string& svg) {
    std::vector<std::string> open;
    std::size_t roots = 0;
    for (std::size_t at = svg.find('<'); at != std::string::npos; at = svg.find('<', at + 1)) {
        const std::size_t end = svg.find('>', at);
        ASSERT_NE(end, std::string::npos);
        const std::string tag = svg.substr(at + 1, end - at - 1);
        ASSERT_FALSE(tag.empty());
        if (tag[0] == '?' || tag.starts_with("!--")) continue;
        EXPECT_EQ(count(tag, "\"") % 2, 0u) << tag;
        if (tag[0] == '/') {
            ASSERT_FALSE(open.empty()) << tag;
            EXPECT_EQ(open.back(), tag.substr(1));
            open.pop_back();
            continue;
        }
        const std::string name = tag.substr(0, tag.find_first_of(" /"));
        if (open.empty()) ++roots;
        if (tag.back() != '/') open.push_back(name);
    }
    EXPECT_TRUE(open.empty());
    EXPECT_EQ(roots, 1u);
}

// The subpaths of every <path d="...">: lists of points.
std::vector<std::vector<glm::dvec2>> subpaths(const std::string& svg) {
    std::vector<std::vector<glm::dvec2>> out;
    for (std::size_t at = svg.find("<path d=\""); at != std::string::npos;
         at = svg.find("<path d=\"", at + 1)) {
        const std::size_t begin = at + 9, end = svg.find('"', begin);
        const std::string d = svg.substr(begin, end - begin);
        const char* p = d.c_str();
        std::vector<double> numbers;
        while (*p) {
            if (*p == 'M' || *p == 'Z') {
                if (*p == 'Z' || !numbers.empty()) {
                    std::vector<glm::dvec2> loop;
                    for (std::size_t k = 0; k + 1 < numbers.size(); k += 2)
                        loop.emplace_back(numbers[k], numbers[k + 1]);
                    if (!loop.empty()) out.push_back(loop);
                    numbers.clear();
                }
                ++p;
            } else if (*p == 'L' || *p == ' ') {
                ++p;
            } else {
                char* next = nullptr;
                numbers.push_back(std::strtod(p, &next));
                EXPECT_NE(next, p) << d;
                if (next == p) return out;
                p = next;
            }
        }
    }
    return out;
}

double area(const std::vector<glm::dvec2>& loop) {
    double a = 0.0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const glm::dvec2 p = loop[i], q = loop[(i + 1) % loop.size()];
        a += p.x * q.y - q.x * p.y;
    }
    return 0.5 * a;
}

double area(const ScreenPolygon& polygon) {
    std::vector<glm::dvec2> loop;
    for (const PolygonVertex& v : polygon.vertices) loop.emplace_back(v.window.x, v.window.y);
    return std::abs(area(loop));
}

Scene default_scene() {
    return make_procedural_scene("builtin:default");
}

TEST(Svg, DocumentIsWellFormedSvg11) {
    const Scene scene = default_scene();
    SvgStats stats;
    const std::string svg = render_svg(scene, small_options(), {}, &stats);
    ASSERT_TRUE(svg.starts_with("<?xml version=\"1.0\""));
    EXPECT_NE(svg.find("<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"160\" "
                       "height=\"120\" viewBox=\"0 0 160 120\">"),
              std::string::npos);
    EXPECT_NE(svg.find("<rect width=\"160\" height=\"120\" fill=\"#333333\"/>"), std::string::npos);
    expect_well_formed(svg);
    EXPECT_GT(stats.polygons_in, 50u);
    EXPECT_LE(stats.polygons_out, stats.polygons_in);
    EXPECT_LE(stats.paths, stats.polygons_out);
    EXPECT_EQ(count(svg, "<path "), stats.paths);
    EXPECT_EQ(count(svg, "Z"), stats.polygons_out);
    EXPECT_EQ(stats.bytes, svg.size());
    EXPECT_TRUE(svg.ends_with("</svg>\n"));
}

// The polygons the document is made of, filled back to front by paint_polygons, are the BSP /
// painter's frames pixel for pixel.
TEST(Svg, PolygonsPaintTheVisibilityFrames) {
    const Scene soup = scene_from_meshes({make_interpenetrating_soup(300, 0.2, 3)});
    for (const Scene* scene : {&soup}) {
        RenderOptions options = small_options();
        options.cull = CullMode::None;
        const Camera camera = effective_camera(*scene, options);
        for (const auto& [order, algorithm] :
             {std::pair{SvgOptions::Order::Bsp, VisibilityAlgorithm::Bsp},
              std::pair{SvgOptions::Order::Painter, VisibilityAlgorithm::Painter}}) {
            const std::vector<ScreenPolygon> polygons = svg_polygons(*scene, options, order);
            EXPECT_GT(polygons.size(), 200u);
            const RenderTargets painted = paint_polygons(polygons, options, camera);
            const RenderResult frame = render_with_visibility(*scene, options, algorithm);
            EXPECT_EQ(painted.color, frame.targets.color) << int(order);
            SvgOptions svg_options;
            svg_options.order = order;
            SvgStats stats;
            render_svg(*scene, options, svg_options, &stats);
            EXPECT_EQ(stats.polygons_in, polygons.size());
        }
    }
}

// Merged outlines cover exactly the area of the pieces they were made of.
TEST(Svg, MergingKeepsTheArea) {
    const Scene scene = default_scene();
    const RenderOptions options = small_options(320, 240);
    SvgOptions svg_options;
    svg_options.precision = 6;
    SvgStats stats;
    const std::string svg = render_svg(scene, options, svg_options, &stats);
    double expected = 0.0;
    for (const ScreenPolygon& p : svg_polygons(scene, options, SvgOptions::Order::Bsp))
        expected += area(p);
    double total = 0.0;
    const auto loops = subpaths(svg);
    ASSERT_EQ(loops.size(), stats.polygons_out);
    for (const auto& loop : loops) {
        const double a = area(loop);
        EXPECT_GT(a, 0.0);  // one orientation throughout (the nonzero rule unions a run)
        total += a;
    }
    EXPECT_NEAR(total, expected, 1e-6 * expected);
    EXPECT_LT(stats.polygons_out, stats.polygons_in);
}

// A box seen from a corner: in the BSP order the two triangles of a face are neighbours (one
// node), so with edges (plane test on) the three faces become three quads. The painter's order
// need not keep them together.
TEST(Svg, CoplanarTrianglesOfAFaceMerge) {
    const Scene scene = scene_from_meshes({make_box(glm::vec3(1.0f))});
    RenderOptions options = small_options();
    Camera camera = front_camera();
    camera.eye = {4.0, 3.0, 5.0};
    options.camera = camera;
    SvgOptions svg_options;
    svg_options.edges = true;
    SvgStats stats;
    const std::string svg = render_svg(scene, options, svg_options, &stats);
    EXPECT_EQ(stats.polygons_in, 6u);
    EXPECT_EQ(stats.polygons_out, 3u);
    for (const auto& loop : subpaths(svg)) EXPECT_EQ(loop.size(), 4u);
    svg_options.edges = false;  // same-color neighbours join across faces too
    render_svg(scene, options, svg_options, &stats);
    EXPECT_LE(stats.polygons_out, 3u);
    svg_options.merge_coplanar = false;
    for (const SvgOptions::Order order : {SvgOptions::Order::Bsp, SvgOptions::Order::Painter}) {
        svg_options.order = order;
        render_svg(scene, options, svg_options, &stats);
        EXPECT_EQ(stats.polygons_out, 6u);
    }
}

TEST(Svg, EdgesStrokeEveryOutline) {
    const Scene scene = default_scene();
    SvgOptions svg_options;
    svg_options.edges = true;
    svg_options.edge_color = {1.0f, 0.0f, 0.0f};
    svg_options.edge_width = 0.75f;
    SvgStats stats;
    const std::string svg = render_svg(scene, small_options(), svg_options, &stats);
    expect_well_formed(svg);
    EXPECT_NE(svg.find("<g stroke=\"#ff0000\" stroke-width=\"0.75\""), std::string::npos);
    EXPECT_EQ(stats.paths, stats.polygons_out);  // one element each: nearer fills hide edges
    EXPECT_EQ(count(svg, "stroke=\""), 1u);
}

TEST(Svg, SeamStrokesUseTheFillColor) {
    const Scene scene = default_scene();
    const std::string svg = render_svg(scene, small_options());
    const std::size_t at = svg.find("<path ");
    ASSERT_NE(at, std::string::npos);
    const std::size_t fill = svg.find(" fill=\"", at);
    const std::string color = svg.substr(fill + 7, 7);
    EXPECT_NE(svg.find("stroke=\"" + color + "\"", fill), std::string::npos);
    EXPECT_NE(svg.find("stroke-linejoin=\"round\""), std::string::npos);
}

TEST(Svg, PrecisionControlsDecimals) {
    const Scene scene = default_scene();
    const RenderOptions options = small_options();
    SvgOptions svg_options;
    svg_options.precision = 0;
    const std::string svg = render_svg(scene, options, svg_options);
    const std::size_t begin = svg.find("<path d=\"") + 9;
    const std::string d = svg.substr(begin, svg.find('"', begin) - begin);
    EXPECT_EQ(d.find('.'), std::string::npos) << d;
    svg_options.precision = 7;
    EXPECT_THROW(render_svg(scene, options, svg_options), InputError);
    svg_options.precision = 2;
    svg_options.edge_width = -1.0f;
    EXPECT_THROW(render_svg(scene, options, svg_options), InputError);
}

}  // namespace
}  // namespace zraster::test
