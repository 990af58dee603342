// SVG output of the BSP / painter's order (see svg.hpp).
//
// Cost: that of the order (BSP build and walk, or painter_sort) plus O(polygons * loop size) for
// merging, with merged loops capped at kMaxMergedVertices so that it stays linear, and up to
// merge_lookback overlap tests per polygon (exact separating-axis tests after a box test).
// When to use: figures and diagrams that must stay sharp at any size, or be edited as vectors; a
// few thousand polygons (the document grows with them, about 80 bytes per outline).
#include <zraster/error.hpp>
#include <zraster/precision.hpp>
#include <zraster/svg.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>

#include "visibility/frame_context.hpp"
#include "visibility/surface_shader.hpp"
#include "visibility/svg_alpha.hpp"

namespace zraster {

namespace {

using Point = std::array<std::int64_t, 2>;  // snapped window position, 1/kSubpixelScale pixel

// A merged loop grows by one polygon at a time; past this many vertices a new one is started
// (keeps the shared-edge search cheap on large flat regions).
constexpr std::size_t kMaxMergedVertices = 256;

std::uint32_t rgb8(const glm::vec3& c) {
    using visibility_detail::to_unorm8;
    return std::uint32_t(to_unorm8(c.x)) << 16 | std::uint32_t(to_unorm8(c.y)) << 8 |
           to_unorm8(c.z);
}

struct Box {
    std::int64_t x0, y0, x1, y1;
    bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

Box box_of(const std::vector<Point>& loop) {
    Box b{loop[0][0], loop[0][1], loop[0][0], loop[0][1]};
    for (const Point& p : loop) {
        b.x0 = std::min(b.x0, p[0]);
        b.y0 = std::min(b.y0, p[1]);
        b.x1 = std::max(b.x1, p[0]);
        b.y1 = std::max(b.y1, p[1]);
    }
    return b;
}

struct Outline {
    std::vector<Point> loop;  // positive signed area (clockwise on screen, y down)
    // mesh_edge[i]: the side loop[i] -> loop[i + 1] lies on an edge of the mesh (not on a BSP or
    // painter's split line, a fan diagonal or a clipping line).
    std::vector<std::uint8_t> mesh_edge;
    std::uint32_t color = 0;
    // Materials' alpha (svg_alpha.hpp): fill-opacity, and the clip path of a cut-out (-1: none).
    // Only plain outlines (opaque, not clipped) merge or share an element.
    float opacity = 1.0f;
    int clip = -1;
    bool plain() const { return opacity == 1.0f && clip < 0; }
    glm::dvec4 plane{0.0};
    std::size_t pieces = 1;
    // The convex polygons it was made of, and their boxes: what overlap tests look at.
    std::vector<std::vector<Point>> convex;
    std::vector<Box> boxes;
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
    std::vector<const PolygonVertex*> v;
    for (const PolygonVertex& p : polygon.vertices) v.push_back(&p);
    for (const PolygonVertex* p : v) o.loop.push_back(p->snapped);
    if (area2(o.loop) < 0) {
        std::reverse(o.loop.begin(), o.loop.end());
        std::reverse(v.begin(), v.end());
    }
    // A side is on a mesh edge iff both ends have the same zero barycentric weight (exact: see
    // PolygonVertex::weights).
    for (std::size_t i = 0, n = v.size(); i < n; ++i) {
        const glm::vec3& a = v[i]->weights;
        const glm::vec3& b = v[(i + 1) % n]->weights;
        o.mesh_edge.push_back((a.x == 0.0f && b.x == 0.0f) || (a.y == 0.0f && b.y == 0.0f) ||
                              (a.z == 0.0f && b.z == 0.0f));
    }
    o.color = rgb8(polygon.color);
    o.plane = polygon.plane;
    o.convex.push_back(o.loop);
    o.boxes.push_back(box_of(o.loop));
    return o;
}

// True when some side of convex loop `a` (positive area) has every point of `b` outside or on it.
bool has_separating_side(const std::vector<Point>& a, const std::vector<Point>& b) {
    for (std::size_t i = 0, n = a.size(); i < n; ++i) {
        const Point& p = a[i];
        const Point& q = a[(i + 1) % n];
        const std::int64_t dx = q[0] - p[0], dy = q[1] - p[1];
        bool separates = true;
        for (const Point& v : b)
            if (dx * (v[1] - p[1]) - dy * (v[0] - p[0]) > 0) {
                separates = false;
                break;
            }
        if (separates) return true;
    }
    return false;
}

// Whether the interiors of the outline's pieces and the convex loop overlap (exact, on the
// snapped coordinates; touching along a side is no overlap).
bool overlaps(const Outline& outline, const std::vector<Point>& convex, const Box& box) {
    for (std::size_t k = 0; k < outline.convex.size(); ++k)
        if (outline.boxes[k].overlaps(box) && !has_separating_side(outline.convex[k], convex) &&
            !has_separating_side(convex, outline.convex[k]))
            return true;
    return false;
}

// Every vertex of `polygon` within a small fraction of its size of `plane`.
bool in_plane(const ScreenPolygon& polygon, const glm::dvec4& plane) {
    if (glm::dot(glm::dvec3(plane), glm::dvec3(polygon.plane)) < 1.0 - 1e-6) return false;
    double extent = 0.0;
    for (const PolygonVertex& v : polygon.vertices)
        extent = std::max(extent, glm::length(v.world - polygon.vertices[0].world));
    for (const PolygonVertex& v : polygon.vertices)
        if (std::abs(visibility_detail::plane_distance(plane, v.world)) > 1e-5 * extent)
            return false;
    return true;
}

// Joins `next` (same orientation) into `into` when they share exactly one side and no other
// vertex: the union's loop is then `into` with that side replaced by the rest of `next`.
bool try_merge(Outline& into, const Outline& next) {
    const std::size_t n = into.loop.size(), m = next.loop.size();
    if (n + m > kMaxMergedVertices) return false;
    std::size_t shared_i = n, shared_j = m, common = 0;
    for (std::size_t j = 0; j < m; ++j) {
        const auto it = std::find(into.loop.begin(), into.loop.end(), next.loop[j]);
        if (it == into.loop.end()) continue;
        ++common;
        // The side next[j] -> next[j + 1] runs the other way in `into`: into[i] = next[j + 1],
        // into[i + 1] = next[j].
        const auto i = static_cast<std::size_t>(std::distance(into.loop.begin(), it));
        if (into.loop[(i + n - 1) % n] == next.loop[(j + 1) % m]) {
            if (shared_j != m) return false;  // two shared sides
            shared_i = (i + n - 1) % n;
            shared_j = j;
        }
    }
    if (shared_j == m || common != 2) return false;
    std::vector<Point> loop;
    std::vector<std::uint8_t> edge;
    loop.reserve(n + m - 2);
    edge.reserve(n + m - 2);
    // Each vertex keeps the flag of the side leaving it; into[shared_i] now leaves along next's
    // side from next[shared_j + 1] (the same point).
    for (std::size_t k = 0; k <= shared_i; ++k) {
        loop.push_back(into.loop[k]);
        edge.push_back(k == shared_i ? next.mesh_edge[(shared_j + 1) % m] : into.mesh_edge[k]);
    }
    for (std::size_t k = 2; k < m; ++k) {
        loop.push_back(next.loop[(shared_j + k) % m]);
        edge.push_back(next.mesh_edge[(shared_j + k) % m]);
    }
    for (std::size_t k = shared_i + 1; k < n; ++k) {
        loop.push_back(into.loop[k]);
        edge.push_back(into.mesh_edge[k]);
    }
    into.loop = std::move(loop);
    into.mesh_edge = std::move(edge);
    into.convex.insert(into.convex.end(), next.convex.begin(), next.convex.end());
    into.boxes.insert(into.boxes.end(), next.boxes.begin(), next.boxes.end());
    into.pieces += next.pieces;
    return true;
}

// Drops vertices on the line through their neighbours (left where merged pieces met), unless the
// two sides meeting there differ in being mesh edges.
void drop_collinear(Outline& o) {
    auto& loop = o.loop;
    auto& edge = o.mesh_edge;
    bool changed = true;
    while (changed && loop.size() > 3) {
        changed = false;
        for (std::size_t i = 0; i < loop.size() && loop.size() > 3; ++i) {
            const std::size_t n = loop.size();
            const std::size_t h = (i + n - 1) % n;
            const Point& a = loop[h];
            const Point& b = loop[i];
            const Point& c = loop[(i + 1) % n];
            const std::int64_t cross =
                (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
            if (cross == 0 && edge[h] == edge[i]) {
                loop.erase(loop.begin() + static_cast<std::ptrdiff_t>(i));
                edge.erase(edge.begin() + static_cast<std::ptrdiff_t>(i));
                changed = true;
            }
        }
    }
}

// value with `decimals` digits after the point, correctly rounded (as printf does).
std::string fixed(double value, int decimals) {
    char text[64];
    const int n = std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return n > 0 && n < int(sizeof text) ? std::string(text, std::size_t(n))
                                         : std::to_string(value);
}

// A coordinate with at most `precision` decimals, trailing zeros dropped.
void append_number(std::string& out, std::int64_t snapped, int precision) {
    const double value = double(snapped) / double(kSubpixelScale);
    std::string text = fixed(value, precision);
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

// The outline's mesh-edge sides as polylines ("M a L b c ..."), one closed loop when all are.
std::size_t append_edges(std::string& out, const Outline& o, int precision) {
    const std::size_t n = o.loop.size();
    std::size_t first = n;  // a vertex where an edge run starts (its incoming side is no edge)
    for (std::size_t i = 0; i < n && first == n; ++i)
        if (o.mesh_edge[i] && !o.mesh_edge[(i + n - 1) % n]) first = i;
    if (first == n) {
        if (!o.mesh_edge[0]) return 0;
        append_subpath(out, o.loop, precision);  // every side
        return 1;
    }
    std::size_t runs = 0;
    for (std::size_t step = 0; step < n;) {
        const std::size_t i = (first + step) % n;
        if (!o.mesh_edge[i]) {
            ++step;
            continue;
        }
        out += 'M';
        append_number(out, o.loop[i][0], precision);
        out += ' ';
        append_number(out, o.loop[i][1], precision);
        out += 'L';
        bool space = false;
        while (step < n && o.mesh_edge[(first + step) % n]) {
            const Point& q = o.loop[(first + step + 1) % n];
            if (space) out += ' ';
            append_number(out, q[0], precision);
            out += ' ';
            append_number(out, q[1], precision);
            space = true;
            ++step;
        }
        ++runs;
    }
    return runs;
}

std::string hex(std::uint32_t rgb) {
    char text[8];
    std::snprintf(text, sizeof text, "#%06x", static_cast<unsigned>(rgb & 0xffffffu));
    return text;
}
std::string hex(const glm::vec3& c) {
    return hex(rgb8(c));
}

std::string number(float v) {
    std::string text = fixed(v, 3);
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
    return text;
}

std::vector<ScreenPolygon> bsp_order(const Scene& scene, const RenderOptions& options) {
    using namespace visibility_detail;
    const FrameContext frame = make_frame_context(scene, options);
    check_bsp_budget(scene, options.limits);
    std::vector<BspPolygon> polygons = bsp_polygons_from_scene(scene);
    const BspOptions bsp = bsp_options(options, polygons.size());
    const BspTree tree = BspTree::build(std::move(polygons), bsp);
    // The pieces render_bsp fills, kept as projection keeps polygons: within the same budget.
    const std::uint64_t budget = projected_polygon_budget(options.limits);
    std::vector<ScreenPolygon> out;
    for_each_bsp_piece(tree, frame, [&](const ScreenPolygon& piece) {
        if (out.size() >= budget)
            throw LimitExceeded(scene.name, "max_projected_polygons",
                                "BSP tree: more than " + std::to_string(budget) +
                                    " polygons in view (the budget of the object-space "
                                    "algorithms' output): draw fewer triangles");
        out.push_back(piece);
    });
    return out;
}

// Whether an instance's fill needs the shading core: smooth shading or a texture. Flat and unlit
// faces keep project_scene's color, which is render()'s flat color bit for bit.
bool shaded_fill(const Scene& scene, const RenderOptions& options, std::int32_t instance) {
    const Instance& placed = scene.instances.at(std::size_t(instance));
    const ShadingMode mode = placed.shading.value_or(options.shading);
    if (mode == ShadingMode::Gouraud || mode == ShadingMode::Phong) return true;
    const Mesh& mesh = scene.meshes.at(placed.mesh);
    if (!mesh.colors.empty()) return true;  // vertex colors vary over the face
    if (mode == ShadingMode::Unlit || !options.textures) return false;
    const Material& material =
        scene.materials.at(mesh.material < scene.materials.size() ? mesh.material : 0);
    return material.base_color_texture != nullptr && !mesh.uvs.empty();
}

// A fill holds one color: a smooth, textured or vertex-colored face is shaded by the renderer's
// shading core
// (SurfaceShader, as the painter's and BSP frames shade their pixels) at the piece's centroid.
void shade_fills(const Scene& scene, const RenderOptions& options,
                 std::vector<ScreenPolygon>& polygons) {
    using visibility_detail::SurfaceShader;
    bool any = false;
    for (std::size_t i = 0; i < scene.instances.size() && !any; ++i)
        any = shaded_fill(scene, options, std::int32_t(i));
    if (!any) return;
    const visibility_detail::FrameContext frame =
        visibility_detail::make_frame_context(scene, options);
    const SurfaceShader shader(frame);
    SurfaceShader::Prepared prepared;
    for (ScreenPolygon& polygon : polygons) {
        if (!shaded_fill(scene, options, polygon.instance)) continue;
        glm::dvec2 centroid{0.0};
        for (const PolygonVertex& v : polygon.vertices) centroid += glm::dvec2(v.window);
        centroid /= double(polygon.vertices.size());
        shader.prepare(polygon, prepared);
        polygon.color = shader.shade(prepared, 0, 0, false, centroid.x, centroid.y, false).color;
    }
}

}  // namespace

std::vector<ScreenPolygon> svg_polygons(const Scene& scene, const RenderOptions& options,
                                        SvgOptions::Order order) {
    return visibility_detail::naming_the_scene(scene, [&] {
        std::vector<ScreenPolygon> polygons;
        if (order == SvgOptions::Order::Bsp) {
            polygons = bsp_order(scene, options);
        } else {
            polygons = project_scene(scene, options);
            const PainterOptions painter =
                visibility_detail::painter_options(options, polygons.size());
            polygons =
                painter_sort(std::move(polygons), Viewport{options.width, options.height}, painter)
                    .order;
        }
        shade_fills(scene, options, polygons);
        return polygons;
    });
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
    std::vector<visibility_detail::SvgPolygonAlpha> alphas = visibility_detail::naming_the_scene(
        scene, [&] { return visibility_detail::svg_polygon_alphas(scene, options, polygons); });
    std::vector<std::vector<std::array<int, 3>>> clips;  // cut-outs' kept pixel runs

    // Merge. A polygon may join an outline up to merge_lookback places back in the paint order
    // when no outline painted in between overlaps it: moving it back then changes nothing that is
    // painted. The scan stops at the first outline in between that overlaps it.
    std::vector<Outline> outlines;
    outlines.reserve(polygons.size());
    const std::size_t lookback = std::max<std::size_t>(1, o.merge_lookback);
    for (std::size_t index = 0; index < polygons.size(); ++index) {
        const ScreenPolygon& polygon = polygons[index];
        visibility_detail::SvgPolygonAlpha& alpha = alphas[index];
        if (!alpha.shown) continue;
        Outline next = outline_of(polygon);
        next.opacity = alpha.opacity;
        if (!alpha.kept_runs.empty()) {
            next.clip = int(clips.size());
            clips.push_back(std::move(alpha.kept_runs));
        }
        bool merged = false;
        if (o.merge_coplanar && next.plain()) {
            for (std::size_t back = 0; back < lookback && back < outlines.size(); ++back) {
                Outline& candidate = outlines[outlines.size() - 1 - back];
                // Without edges outlines are invisible: any same-color neighbour can join.
                if (candidate.plain() && candidate.color == next.color &&
                    (!o.edges || in_plane(polygon, candidate.plane)) &&
                    try_merge(candidate, next)) {
                    merged = true;
                    break;
                }
                if (overlaps(candidate, next.loop, next.boxes[0])) break;
            }
        }
        if (!merged) outlines.push_back(std::move(next));
    }

    std::string out;
    out.reserve(outlines.size() * 48 + 512);
    const int w = options.width, h = options.height;
    out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    const std::string ws = std::to_string(w), hs = std::to_string(h);
    out += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + ws +
           "\" height=\"" + hs + "\" viewBox=\"0 0 " + ws + " " + hs + "\">\n";
    out += "<!-- zraster: " + std::to_string(polygons.size()) + " polygons (" +
           std::to_string(outlines.size()) + " after merging), " +
           (o.order == SvgOptions::Order::Bsp ? "BSP" : "painter's") + " order -->\n";
    out += "<rect width=\"" + ws + "\" height=\"" + hs + "\" fill=\"" + hex(options.background) +
           "\"/>\n";
    if (!clips.empty()) {
        // Cut-outs: the pixel squares whose centers pass the alpha test, row by row.
        out += "<defs>\n";
        for (std::size_t k = 0; k < clips.size(); ++k) {
            out += "<clipPath id=\"zraster-cut-" + std::to_string(k) + "\"><path d=\"";
            for (const auto& run : clips[k])
                out += "M" + std::to_string(run[1]) + " " + std::to_string(run[0]) + "h" +
                       std::to_string(run[2] - run[1]) + "v1h-" + std::to_string(run[2] - run[1]) +
                       "z";
            out += "\"/></clipPath>\n";
        }
        out += "</defs>\n";
    }
    // With edges the group's style is the edges' (an edge path is then just its d); fills carry
    // their own fill and seam stroke.
    const bool seams = o.seam_width > 0.0f;
    std::string seam_width;  // on each fill when it differs from the group's stroke width
    if (o.edges) {
        out += "<g fill=\"none\" stroke=\"" + hex(o.edge_color) + "\" stroke-width=\"" +
               number(o.edge_width) + "\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n";
        if (seams && number(o.seam_width) != number(o.edge_width))
            seam_width = " stroke-width=\"" + number(o.seam_width) + "\"";
    } else if (seams) {
        out += "<g stroke-width=\"" + number(o.seam_width) + "\" stroke-linejoin=\"round\">\n";
    } else {
        out += "<g>\n";
    }

    std::size_t paths = 0, edge_paths = 0;
    for (std::size_t i = 0; i < outlines.size();) {
        // Without edges, a run of one color is one element (nonzero rule over same-orientation
        // loops: their union); with edges each outline is its own element followed by its edges,
        // so that nearer fills cover farther edges.
        std::size_t end = i + 1;
        if (!o.edges && outlines[i].plain())
            while (end < outlines.size() && outlines[end].plain() &&
                   outlines[end].color == outlines[i].color)
                ++end;
        out += "<path d=\"";
        for (std::size_t k = i; k < end; ++k) {
            drop_collinear(outlines[k]);
            append_subpath(out, outlines[k].loop, o.precision);
        }
        std::string fill = hex(outlines[i].color);
        // Translucent and cut-out fills: fill-opacity and clip-path after the color, and no seam
        // stroke on a translucent one (it would blend twice where it overlaps the fill).
        std::string extra;
        if (outlines[i].opacity != 1.0f)
            extra += "\" fill-opacity=\"" + number(outlines[i].opacity);
        if (outlines[i].clip >= 0)
            extra += "\" clip-path=\"url(#zraster-cut-" + std::to_string(outlines[i].clip) + ")";
        const bool translucent = outlines[i].opacity != 1.0f;
        const auto& flags = outlines[i].mesh_edge;
        const bool all_edges =
            o.edges && std::all_of(flags.begin(), flags.end(), [](std::uint8_t f) { return f; });
        if (all_edges) {
            // Its whole outline is mesh edges: the group's edge stroke draws them and covers the
            // seams, in one element.
            out += "\" fill=\"" + fill + extra + "\"/>\n";
            ++paths;
            ++edge_paths;
            i = end;
            continue;
        }
        if (seams && !translucent)
            out += "\" fill=\"" + fill + extra + "\" stroke=\"" + fill + "\"" + seam_width + "/>\n";
        else if (o.edges || seams)
            out += "\" fill=\"" + fill + extra + "\" stroke=\"none\"/>\n";
        else
            out += "\" fill=\"" + fill + extra + "\"/>\n";
        ++paths;
        if (o.edges) {
            // Only sides on mesh edges: split lines, fan diagonals and clipping lines are not
            // edges of the model.
            std::string d;
            if (append_edges(d, outlines[i], o.precision) > 0) {
                out += "<path d=\"" + d + "\"";
                if (outlines[i].clip >= 0)
                    out +=
                        " clip-path=\"url(#zraster-cut-" + std::to_string(outlines[i].clip) + ")\"";
                out += "/>\n";
                ++paths;
                ++edge_paths;
            }
        }
        i = end;
    }
    out += "</g>\n</svg>\n";
    if (stats) {
        stats->polygons_in = polygons.size();
        stats->polygons_out = outlines.size();
        stats->paths = paths;
        stats->edge_paths = edge_paths;
        stats->bytes = out.size();
    }
    return out;
}

}  // namespace zraster
