// render_svg: a well-formed SVG 1.1 document whose polygons, painted back to front, are exactly
// the BSP / painter's frames, and whose merging keeps the painted area while joining coplanar
// neighbours.
#include <zraster/error.hpp>
#include <zraster/scenes.hpp>
#include <zraster/svg.hpp>

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <zraster/load.hpp>

#include "support/test_support.hpp"
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

// A <path> element: its subpaths (closed by Z or open), and whether it is an edge stroke
// (no fill attribute: it takes the group's edge style) or a fill; fill is its fill color.
struct PathElement {
    std::vector<std::vector<glm::dvec2>> subpaths;
    std::vector<bool> closed;
    bool edge = false;
    bool edge_stroked = false;  // no stroke of its own: drawn with the group's edge stroke
    std::string fill;
};

std::vector<PathElement> parse_paths(const std::string& svg) {
    std::vector<PathElement> out;
    for (std::size_t at = svg.find("<path d=\""); at != std::string::npos;
         at = svg.find("<path d=\"", at + 1)) {
        const std::size_t begin = at + 9, end = svg.find('"', begin);
        const std::string d = svg.substr(begin, end - begin);
        PathElement e;
        const std::size_t close = svg.find("/>", end);
        const std::string attributes = svg.substr(end, close - end);
        e.edge = attributes.find("fill=") == std::string::npos;  // the group's style
        e.edge_stroked = attributes.find("stroke=") == std::string::npos;
        const std::size_t fill = attributes.find("fill=\"");
        if (fill != std::string::npos) e.fill = attributes.substr(fill + 6, 7);
        std::vector<double> numbers;
        auto flush = [&](bool closed) {
            std::vector<glm::dvec2> points;
            for (std::size_t k = 0; k + 1 < numbers.size(); k += 2)
                points.emplace_back(numbers[k], numbers[k + 1]);
            if (!points.empty()) {
                e.subpaths.push_back(points);
                e.closed.push_back(closed);
            }
            numbers.clear();
        };
        for (const char* p = d.c_str(); *p;) {
            if (*p == 'M') {
                flush(false);
                ++p;
            } else if (*p == 'Z') {
                flush(true);
                ++p;
            } else if (*p == 'L' || *p == ' ') {
                ++p;
            } else {
                char* next = nullptr;
                numbers.push_back(std::strtod(p, &next));
                EXPECT_NE(next, p) << d;
                if (next == p) break;
                p = next;
            }
        }
        flush(false);
        out.push_back(std::move(e));
    }
    return out;
}

// The subpaths of every fill <path>: lists of points.
std::vector<std::vector<glm::dvec2>> subpaths(const std::string& svg) {
    std::vector<std::vector<glm::dvec2>> out;
    for (const PathElement& e : parse_paths(svg))
        if (!e.edge) out.insert(out.end(), e.subpaths.begin(), e.subpaths.end());
    return out;
}

// The fills point-sampled at pixel centers, nonzero rule, painted in document order: the fill
// color of each pixel as 0xRRGGBB (0xffffffff where none).
std::vector<std::uint32_t> rasterize(const std::string& svg, int width, int height) {
    std::vector<std::uint32_t> image(std::size_t(width) * std::size_t(height), 0xffffffffu);
    for (const PathElement& e : parse_paths(svg)) {
        if (e.edge) continue;
        const std::uint32_t color = std::uint32_t(std::stoul(e.fill.substr(1), nullptr, 16));
        for (const auto& loop : e.subpaths) {
            glm::dvec2 lo(1e300), hi(-1e300);
            for (const glm::dvec2& p : loop) {
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
            for (int y = std::max(0, int(lo.y) - 1); y < std::min(height, int(hi.y) + 1); ++y)
                for (int x = std::max(0, int(lo.x) - 1); x < std::min(width, int(hi.x) + 1); ++x) {
                    const glm::dvec2 c(x + 0.5, y + 0.5);
                    int winding = 0;
                    for (std::size_t i = 0; i < loop.size(); ++i) {
                        const glm::dvec2 a = loop[i], b = loop[(i + 1) % loop.size()];
                        const double side = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
                        if (a.y <= c.y && b.y > c.y && side > 0) ++winding;
                        if (a.y > c.y && b.y <= c.y && side < 0) --winding;
                    }
                    if (winding != 0)
                        image[std::size_t(y) * std::size_t(width) + std::size_t(x)] = color;
                }
        }
    }
    return image;
}

// xmllint's verdict when it is installed (the document must parse as XML).
void expect_valid_xml(const std::string& svg) {
    if (std::system("command -v xmllint > /dev/null 2>&1") != 0) return;
    const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                       ("zraster-svg-test-" + std::to_string(::getpid()) + ".svg");
    {
        std::ofstream out(file);
        out << svg;
    }
    const int status = std::system(("xmllint --noout '" + file.string() + "'").c_str());
    std::filesystem::remove(file);
    EXPECT_EQ(status, 0) << "xmllint rejected the document";
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
    expect_valid_xml(svg);
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
            const RenderTargets painted = paint_polygons(polygons, options, camera, scene);
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

TEST(Svg, EdgesAreStrokedPathsAfterTheirFills) {
    const Scene scene = default_scene();
    SvgOptions svg_options;
    svg_options.edges = true;
    svg_options.edge_color = {1.0f, 0.0f, 0.0f};
    svg_options.edge_width = 0.75f;
    SvgStats stats;
    const std::string svg = render_svg(scene, small_options(), svg_options, &stats);
    expect_well_formed(svg);
    EXPECT_NE(svg.find("<g fill=\"none\" stroke=\"#ff0000\" stroke-width=\"0.75\""),
              std::string::npos);
    std::size_t edge_elements = 0, all_edge_fills = 0, seamed_fills = 0;
    for (const PathElement& e : parse_paths(svg)) {
        edge_elements += e.edge;
        all_edge_fills += !e.edge && e.edge_stroked;
        seamed_fills += !e.edge_stroked;
    }
    EXPECT_EQ(edge_elements + all_edge_fills, stats.edge_paths);
    EXPECT_GT(all_edge_fills, 0u);
    EXPECT_EQ(all_edge_fills + seamed_fills, stats.polygons_out);
    // Seams (0.5) differ from the edge width: each seamed fill says its own.
    EXPECT_EQ(count(svg, "stroke-width=\"0.5\"/>"), seamed_fills);
    EXPECT_GT(stats.edge_paths, stats.polygons_out / 4);
    EXPECT_LE(stats.edge_paths, stats.polygons_out);
    EXPECT_EQ(stats.paths, stats.polygons_out + edge_elements);  // one fill each
    // Each edge path directly follows its outline's fill: nearer fills hide farther edges.
    const auto elements = parse_paths(svg);
    for (std::size_t i = 0; i < elements.size(); ++i)
        if (elements[i].edge) {
            ASSERT_GT(i, 0u);
            EXPECT_FALSE(elements[i - 1].edge_stroked);  // a seamed fill, not all edges
        }
}

// Two triangles crossing each other: the BSP tree and the painter's algorithm split one along
// the intersection line. With edges on, only the triangles' own edges are stroked: every stroked
// segment lies on an edge of one of the two triangles, while the fills do have sides that do not
// (the split line).
TEST(Svg, EdgesAreMeshEdgesNotSplitLines) {
    const Scene scene = scene_from_triangles(interpenetrating_pair());
    RenderOptions options = small_options();
    options.camera = front_camera();
    options.cull = CullMode::None;
    const std::vector<ScreenPolygon> triangles = project_scene(scene, options);
    ASSERT_EQ(triangles.size(), 2u);
    auto on_mesh_edge = [&](glm::dvec2 a, glm::dvec2 b) {
        for (const ScreenPolygon& t : triangles)
            for (std::size_t k = 0; k < 3; ++k) {
                const glm::dvec2 p(t.vertices[k].window), q(t.vertices[(k + 1) % 3].window);
                const glm::dvec2 d = glm::normalize(q - p);
                auto off = [&](glm::dvec2 x) {
                    return std::abs(d.x * (x.y - p.y) - d.y * (x.x - p.x));
                };
                if (off(a) < 0.01 && off(b) < 0.01) return true;
            }
        return false;
    };
    for (const SvgOptions::Order order : {SvgOptions::Order::Bsp, SvgOptions::Order::Painter}) {
        SvgOptions svg_options;
        svg_options.order = order;
        svg_options.edges = true;
        svg_options.precision = 6;
        SvgStats stats;
        const std::string svg = render_svg(scene, options, svg_options, &stats);
        EXPECT_GT(stats.polygons_in, 2u) << int(order);  // split
        std::size_t edge_segments = 0, fill_sides_off_edges = 0;
        for (const PathElement& e : parse_paths(svg))
            for (std::size_t k = 0; k < e.subpaths.size(); ++k) {
                const auto& points = e.subpaths[k];
                const std::size_t sides = e.closed[k] ? points.size() : points.size() - 1;
                for (std::size_t i = 0; i < sides; ++i) {
                    const bool on = on_mesh_edge(points[i], points[(i + 1) % points.size()]);
                    if (e.edge_stroked) {
                        ++edge_segments;
                        EXPECT_TRUE(on) << int(order) << ": " << points[i].x << "," << points[i].y;
                    } else {
                        fill_sides_off_edges += !on;
                    }
                }
            }
        EXPECT_GE(edge_segments, 6u) << int(order);
        EXPECT_GE(fill_sides_off_edges, 1u) << int(order);  // the split line is there, unstroked
    }
}

// Merging across the paint order (merge_lookback) joins more polygons and paints the same image:
// the fills, point-sampled at pixel centers with the nonzero rule and painted in document order,
// match those of the unmerged document.
TEST(Svg, LookbackMergingPaintsTheSameImage) {
    const Scene scene = default_scene();
    const RenderOptions options = small_options();
    for (const bool edges : {false, true}) {
        SvgOptions unmerged;
        unmerged.edges = edges;
        unmerged.precision = 6;
        unmerged.merge_coplanar = false;
        SvgOptions near = unmerged;
        near.merge_coplanar = true;
        near.merge_lookback = 1;
        SvgOptions far = near;
        far.merge_lookback = SvgOptions{}.merge_lookback;
        SvgStats s_unmerged, s_near, s_far;
        const std::string a = render_svg(scene, options, unmerged, &s_unmerged);
        render_svg(scene, options, near, &s_near);
        const std::string b = render_svg(scene, options, far, &s_far);
        std::printf(
            "default scene, edges %d: %zu polygons, %zu merged with neighbours only, %zu "
            "with the default lookback\n",
            int(edges), s_unmerged.polygons_out, s_near.polygons_out, s_far.polygons_out);
        EXPECT_LT(s_near.polygons_out, s_unmerged.polygons_out);
        EXPECT_LT(s_far.polygons_out, s_near.polygons_out);
        const std::vector<std::uint32_t> ia = rasterize(a, options.width, options.height);
        const std::vector<std::uint32_t> ib = rasterize(b, options.width, options.height);
        std::size_t differing = 0;
        for (std::size_t p = 0; p < ia.size(); ++p) differing += ia[p] != ib[p];
        // Only pixel centers exactly on a side that merging removed may go either way.
        EXPECT_LE(double(differing), 0.002 * double(ia.size())) << edges;
    }
}

TEST(Svg, BunnySmallMergeCounts) {
    ZRASTER_REQUIRE_SHARED_DATA();
    const Scene scene = load_scene(shared_data("meshes/obj/bunny-small.obj"));
    const RenderOptions options = small_options(480, 360);
    for (const bool edges : {false, true}) {
        SvgOptions svg_options;
        svg_options.edges = edges;
        std::size_t out[2] = {};
        for (const std::size_t lookback : {std::size_t{1}, SvgOptions{}.merge_lookback}) {
            svg_options.merge_lookback = lookback;
            SvgStats stats;
            const std::string svg = render_svg(scene, options, svg_options, &stats);
            expect_well_formed(svg);
            expect_valid_xml(svg);
            std::printf(
                "bunny-small 480x360, edges %d, lookback %zu: %zu polygons -> %zu "
                "(%zu paths, %zu edge paths, %zu bytes)\n",
                int(edges), lookback, stats.polygons_in, stats.polygons_out, stats.paths,
                stats.edge_paths, stats.bytes);
            out[lookback == 1 ? 0 : 1] = stats.polygons_out;
        }
        EXPECT_LT(out[1], out[0]) << edges;
    }
}

// Fills follow --shading: flat faces keep project_scene's flat color bit for bit; smooth (Phong,
// Gouraud) faces take the renderer's shading at the piece's centroid, so each fill is the
// z-buffer image's color around that point (not the face's flat color).
TEST(Svg, FillsAreShadedAsTheZBufferShades) {
    const Scene scene = scene_from_meshes({make_uv_sphere(1.0f, 48, 64)});
    RenderOptions options = small_options(320, 240);
    options.shading = ShadingMode::Flat;
    const std::vector<ScreenPolygon> flat = svg_polygons(scene, options, SvgOptions::Order::Bsp);
    std::map<std::int32_t, glm::vec3> flat_color;  // of each triangle, as project_scene shades it
    for (const ScreenPolygon& p : project_scene(scene, options)) flat_color[p.primitive] = p.color;
    for (const ScreenPolygon& p : flat) EXPECT_EQ(p.color, flat_color.at(p.primitive));
    for (const ShadingMode mode : {ShadingMode::Phong, ShadingMode::Gouraud}) {
        SCOPED_TRACE(int(mode));
        options.shading = mode;
        const std::vector<ScreenPolygon> smooth =
            svg_polygons(scene, options, SvgOptions::Order::Bsp);
        ASSERT_EQ(smooth.size(), flat.size());
        const RenderResult frame = render(scene, options);
        std::size_t compared = 0, unlike_flat = 0;
        int worst = 0;
        double total = 0.0;
        std::string where;
        for (std::size_t i = 0; i < smooth.size(); ++i) {
            // Pieces of at least 8 square pixels: on a sliver seen edge on, the pixel under the
            // centroid may be far from it on the surface.
            glm::dvec2 c{0.0};
            double area = 0.0;
            const std::vector<PolygonVertex>& corners = smooth[i].vertices;
            for (std::size_t k = 0; k < corners.size(); ++k) {
                const glm::dvec3 &p = corners[k].window,
                                 &q = corners[(k + 1) % corners.size()].window;
                area += 0.5 * (p.x * q.y - q.x * p.y);
                c += glm::dvec2(p);
            }
            c /= double(corners.size());
            if (std::abs(area) < 8.0) continue;
            const int x = int(c.x), y = int(c.y);
            const std::size_t at = (std::size_t(y) * std::size_t(options.width) + std::size_t(x));
            if (frame.targets.depth[at] >= 1.0f) continue;
            ++compared;
            unlike_flat += smooth[i].color != flat[i].color;
            for (int k = 0; k < 3; ++k) {
                const int fill = int(std::lround(std::clamp(smooth[i].color[k], 0.0f, 1.0f) * 255));
                const int d = std::abs(fill - int(frame.targets.color[4 * at + std::size_t(k)]));
                if (d > worst)
                    where = "piece " + std::to_string(i) + " (triangle " +
                            std::to_string(smooth[i].primitive) + ", " +
                            std::to_string(smooth[i].vertices.size()) + " corners) at (" +
                            std::to_string(c.x) + ", " + std::to_string(c.y) + "): fill " +
                            std::to_string(fill) + ", image " +
                            std::to_string(int(frame.targets.color[4 * at + std::size_t(k)]));
                worst = std::max(worst, d);
                total += d;
            }
        }
        ASSERT_GT(compared, 500u);
        EXPECT_GT(unlike_flat, compared * 9 / 10);
        std::printf("%s: %zu pieces, worst %d, mean %.3f, unlike flat %zu\n",
                    mode == ShadingMode::Phong ? "phong" : "gouraud", compared, worst,
                    total / double(3 * compared), unlike_flat);
        EXPECT_LE(worst, 4) << where;
        EXPECT_LE(total / double(3 * compared), 0.5);
    }
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
    // Every fill carries a seam stroke of its own color (no hairline cracks between neighbours);
    // with edges, each fill is stroked either with its seam or, when its outline is all mesh
    // edges, with the edge stroke.
    for (const PathElement& e : parse_paths(svg)) {
        ASSERT_FALSE(e.edge);
        EXPECT_FALSE(e.edge_stroked) << e.fill;
    }
    std::size_t stroked = 0;
    for (const PathElement& e : parse_paths(svg))
        stroked +=
            svg.find("fill=\"" + e.fill + "\" stroke=\"" + e.fill + "\"") != std::string::npos;
    EXPECT_EQ(stroked, parse_paths(svg).size());
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
