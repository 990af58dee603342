// SVG output of the BSP / painter's order (see svg.hpp).
//
// Cost: that of the order (BSP build and walk, or painter_sort) plus O(polygons * loop size) for
// merging, with merged loops capped at kMaxMergedVertices so that it stays linear.
#include <zraster/error.hpp>
#include <zraster/precision.hpp>
#include <zraster/svg.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>

#include "visibility/frame_context.hpp"

namespace zraster {

namespace {

using Point = std::array<std::int64_t, 2>;  // snapped window position, 1/kSubpixelScale pixel

// A merged loop grows by one polygon at a time; past this many vertices a new one is started
// (keeps the shared-edge search cheap on large flat regions).
constexpr std::size_t kMaxMergedVertices = 256;

// The 8-bit quantization of the frames (paint.cpp, the renderer's to_unorm8).
std::uint32_t unorm8(float v) {
    v = v > 0.0f ? v : 0.0f;
    v = v < 1.0f ? v : 1.0f;
    return static_cast<std::uint32_t>(v * 255.0f + 0.5f);
}

std::uint32_t rgb8(const glm::vec3& c) {
    return unorm8(c.x) << 16 | unorm8(c.y) << 8 | unorm8(c.z);
}

struct Outline {
    std::vector<Point> loop;  // positive signed area (clockwise on screen, y down)
    std::uint32_t color = 0;
    glm::dvec4 plane{0.0};
    std::size_t pieces = 1;
};

std::int64_t area2(const std::vector<Point>& loop) {
    std::int64_t a = 0;
    for (std::size_t i = 0, n = loop.size(); i < n; ++i) {
        const Point& p = loop[i];
        const Point& q = loop[(i + 1) % n];
        a += p[0] * q[1] - q[0] * p[1];
    }
    return a;
}

Outline outline_of(const ScreenPolygon& polygon) {
    Outline o;
    for (const PolygonVertex& v : polygon.vertices) o.loop.push_back(v.snapped);
    if (area2(o.loop) < 0) std::reverse(o.loop.begin(), o.loop.end());
    o.color = rgb8(polygon.color);
    o.plane = polygon.plane;
    return o;
}

// Every vertex of `polygon` within a small fraction of its size of `plane`.
bool in_plane(const ScreenPolygon& polygon, const glm::dvec4& plane) {
    if (glm::dot(glm::dvec3(plane), glm::dvec3(polygon.plane)) < 1.0 - 1e-6) return false;
    double extent = 0.0;
    for (const PolygonVertex& v : polygon.vertices)
        extent = std::max(extent, glm::length(v.world - polygon.vertices[0].world));
    for (const PolygonVertex& v : polygon.vertices)
        if (std::abs(glm::dot(glm::dvec3(plane), v.world) + plane.w) > 1e-5 * extent) return false;
    return true;
}

// Joins `next` (same orientation) into `into` when they share exactly one edge and no other
// vertex: the union's loop is then `into` with the edge replaced by the rest of `next`.
bool try_merge(Outline& into, const std::vector<Point>& next) {
    const std::size_t n = into.loop.size(), m = next.size();
    if (n + m > kMaxMergedVertices) return false;
    std::size_t shared_i = n, shared_j = m, common = 0;
    for (std::size_t j = 0; j < m; ++j) {
        const auto it = std::find(into.loop.begin(), into.loop.end(), next[j]);
        if (it == into.loop.end()) continue;
        ++common;
        // The edge next[j] -> next[j + 1] runs the other way in `into`: into[i] = next[j + 1],
        // into[i + 1] = next[j].
        const auto i = static_cast<std::size_t>(std::distance(into.loop.begin(), it));
        if (into.loop[(i + n - 1) % n] == next[(j + 1) % m]) {
            if (shared_j != m) return false;  // two shared edges
            shared_i = (i + n - 1) % n;
            shared_j = j;
        }
    }
    if (shared_j == m || common != 2) return false;
    std::vector<Point> merged;
    merged.reserve(n + m - 2);
    for (std::size_t k = 0; k <= shared_i; ++k) merged.push_back(into.loop[k]);
    for (std::size_t k = 2; k < m; ++k) merged.push_back(next[(shared_j + k) % m]);
    for (std::size_t k = shared_i + 1; k < n; ++k) merged.push_back(into.loop[k]);
    into.loop = std::move(merged);
    ++into.pieces;
    return true;
}

// Drops vertices on the line through their neighbours (left where merged pieces met).
void drop_collinear(std::vector<Point>& loop) {
    bool changed = true;
    while (changed && loop.size() > 3) {
        changed = false;
        for (std::size_t i = 0; i < loop.size() && loop.size() > 3; ++i) {
            const std::size_t n = loop.size();
            const Point& a = loop[(i + n - 1) % n];
            const Point& b = loop[i];
            const Point& c = loop[(i + 1) % n];
            const std::int64_t cross =
                (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
            if (cross == 0) {
                loop.erase(loop.begin() + static_cast<std::ptrdiff_t>(i));
                changed = true;
            }
        }
    }
}

// A coordinate with at most `precision` decimals, trailing zeros dropped.
void append_number(std::string& out, std::int64_t snapped, int precision) {
    const double value = double(snapped) / double(kSubpixelScale);
    std::string text = fmt::format("{:.{}f}", value, precision);
    if (text.find('.') != std::string::npos) {
        while (text.back() == '0') text.pop_back();
        if (text.back() == '.') text.pop_back();
    }
    if (text == "-0") text = "0";
    out += text;
}

void append_subpath(std::string& out, const std::vector<Point>& loop, int precision) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
        out += i == 0 ? "M" : i == 1 ? "L" : " ";
        append_number(out, loop[i][0], precision);
        out += ' ';
        append_number(out, loop[i][1], precision);
    }
    out += 'Z';
}

std::string hex(std::uint32_t rgb) {
    return fmt::format("#{:06x}", rgb);
}
std::string hex(const glm::vec3& c) {
    return hex(rgb8(c));
}

std::string number(float v) {
    std::string text = fmt::format("{:.3f}", v);
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
    return text;
}

std::vector<ScreenPolygon> bsp_order(const Scene& scene, const RenderOptions& options) {
    using namespace visibility_detail;
    const FrameContext frame = make_frame_context(scene, options);
    const BspTree tree = BspTree::build(bsp_polygons_from_scene(scene));
    std::vector<glm::mat4> mvp(scene.instances.size());
    for (std::size_t i = 0; i < mvp.size(); ++i)
        mvp[i] = frame.view_projection * scene.instances[i].transform;
    std::vector<ScreenPolygon> out;
    ScreenPolygon piece;
    const std::vector<BspPolygon>& polygons = tree.polygons();
    // As render_bsp: every fan triangle of a stored polygon through the renderer's clipping and
    // projection (project_triangle), so the pieces are the ones its frames fill.
    for (const std::uint32_t index : tree.back_to_front(frame.viewer)) {
        const BspPolygon& polygon = polygons[index];
        const auto instance = static_cast<std::size_t>(polygon.instance);
        const glm::mat4& model = scene.instances.at(instance).transform;
        for (std::size_t k = 1; k + 1 < polygon.vertices.size(); ++k) {
            TriangleSource source;
            source.instance = polygon.instance;
            source.primitive = polygon.primitive;
            source.plane = polygon.plane;
            const std::size_t corner[3] = {0, k, k + 1};
            for (std::size_t c = 0; c < 3; ++c) {
                const BspVertex& v = polygon.vertices[corner[c]];
                const glm::vec4 p(v.object, 1.0f);
                source.clip[c] = mvp[instance] * p;
                source.world[c] = v.world;
                source.world_f[c] = glm::vec3(model * p);
            }
            if (project_triangle(frame, source, piece)) out.push_back(piece);
        }
    }
    return out;
}

}  // namespace

std::vector<ScreenPolygon> svg_polygons(const Scene& scene, const RenderOptions& options,
                                        SvgOptions::Order order) {
    if (order == SvgOptions::Order::Bsp) return bsp_order(scene, options);
    std::vector<ScreenPolygon> polygons = project_scene(scene, options);
    return painter_sort(std::move(polygons), Viewport{options.width, options.height}).order;
}

std::string render_svg(const Scene& scene, const RenderOptions& options,
                       const SvgOptions& svg_options, SvgStats* stats) {
    const SvgOptions& o = svg_options;
    if (o.precision < 0 || o.precision > 6)
        throw InputError(
            "", "SVG precision must be 0..6 decimal places, not " + std::to_string(o.precision));
    if (!(o.edge_width >= 0.0f) || !std::isfinite(o.edge_width) || !(o.seam_width >= 0.0f) ||
        !std::isfinite(o.seam_width))
        throw InputError("", "SVG stroke widths must be finite and >= 0");
    if (!std::isfinite(o.edge_color.x + o.edge_color.y + o.edge_color.z))
        throw InputError("", "SVG edge color must be finite");

    const std::vector<ScreenPolygon> polygons = svg_polygons(scene, options, o.order);

    // Merge neighbours in the paint order.
    std::vector<Outline> outlines;
    outlines.reserve(polygons.size());
    for (const ScreenPolygon& polygon : polygons) {
        Outline next = outline_of(polygon);
        if (o.merge_coplanar && !outlines.empty()) {
            Outline& last = outlines.back();
            // Without edges outlines are invisible: any same-color neighbour can join.
            if (last.color == next.color && (!o.edges || in_plane(polygon, last.plane)) &&
                try_merge(last, next.loop))
                continue;
        }
        outlines.push_back(std::move(next));
    }

    std::string out;
    out.reserve(outlines.size() * 48 + 512);
    const int w = options.width, h = options.height;
    out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out += fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"{0}\" height=\"{1}\" "
        "viewBox=\"0 0 {0} {1}\">\n",
        w, h);
    out +=
        fmt::format("<!-- zraster: {} polygons ({} after merging), {} order -->\n", polygons.size(),
                    outlines.size(), o.order == SvgOptions::Order::Bsp ? "BSP" : "painter's");
    out += fmt::format("<rect width=\"{}\" height=\"{}\" fill=\"{}\"/>\n", w, h,
                       hex(options.background));
    const bool seams = !o.edges && o.seam_width > 0.0f;
    if (o.edges)
        out += fmt::format(
            "<g stroke=\"{}\" stroke-width=\"{}\" stroke-linejoin=\"round\" "
            "stroke-linecap=\"round\">\n",
            hex(o.edge_color), number(o.edge_width));
    else if (seams)
        out += fmt::format("<g stroke-width=\"{}\" stroke-linejoin=\"round\">\n",
                           number(o.seam_width));
    else
        out += "<g>\n";

    std::size_t paths = 0;
    for (std::size_t i = 0; i < outlines.size();) {
        // Without edges, a run of one color is one element (nonzero rule over same-orientation
        // loops: their union); with edges each outline is its own element so that nearer fills
        // cover farther edges.
        std::size_t end = i + 1;
        if (!o.edges)
            while (end < outlines.size() && outlines[end].color == outlines[i].color) ++end;
        out += "<path d=\"";
        for (std::size_t k = i; k < end; ++k) {
            drop_collinear(outlines[k].loop);
            append_subpath(out, outlines[k].loop, o.precision);
        }
        const std::string fill = hex(outlines[i].color);
        if (seams)
            out += fmt::format("\" fill=\"{0}\" stroke=\"{0}\"/>\n", fill);
        else
            out += fmt::format("\" fill=\"{}\"/>\n", fill);
        ++paths;
        i = end;
    }
    out += "</g>\n</svg>\n";
    if (stats) {
        stats->polygons_in = polygons.size();
        stats->polygons_out = outlines.size();
        stats->paths = paths;
        stats->bytes = out.size();
    }
    return out;
}

}  // namespace zraster
