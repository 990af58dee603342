// Internal helpers shared by the visibility algorithms: the per-frame projection state, the
// projection of one triangle into a ScreenPolygon, and a canvas that fills polygons with the
// renderer's coverage rule and no depth test.
#pragma once
#include <zraster/clip.hpp>
#include <zraster/error.hpp>
#include <zraster/raster.hpp>
#include <zraster/visibility.hpp>

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "shade/phong_kernel.hpp"

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
    // project_triangle keeps polygons that cover no pixel center (see project_scene).
    bool keep_subpixel = false;
};

// The renderer's color quantization.
using detail::to_unorm8;

// Targets as options asks for them, cleared: color white (RGBA 255), depth to
// depth_clear_value, normal zero, ids -1.
RenderTargets blank_targets(const RenderOptions& options);

// The stats every visibility frame fills in: camera, triangles_in, total_ms since `start`.
void finish_stats(RenderStats& stats, const Camera& camera, const Scene& scene,
                  std::chrono::steady_clock::time_point start);

// f(), with a LimitExceeded that names no file given the scene's (the algorithms see polygons,
// not files).
template <class F>
auto naming_the_scene(const Scene& scene, const F& f) -> decltype(f()) {
    try {
        return f();
    } catch (const LimitExceeded& e) {
        if (!e.file().empty() || scene.name.empty()) throw;
        throw LimitExceeded(scene.name, e.limit(), e.cause());
    }
}

// The algorithms' options from a frame's: budgets (options.limits) and the progress reporter.
inline PainterOptions painter_options(const RenderOptions& options, std::size_t polygons) {
    PainterOptions o;
    o.max_comparisons = painter_comparison_budget(options.limits, polygons);
    o.progress = options.progress;
    return o;
}
inline BspOptions bsp_options(const RenderOptions& options, std::size_t input_polygons) {
    BspOptions o;
    o.max_polygons = bsp_polygon_budget(options.limits, input_polygons);
    o.max_classifications = bsp_classification_budget(options.limits, input_polygons);
    o.progress = options.progress;
    return o;
}

// Throws InputError unless n is 1, 2, 4 or 8 (subsamples per pixel side; `what` names the user).
void check_samples_per_side(int n, const char* what);

// The material of an instance (the default one when its mesh names none that exists).
const Material& instance_material(const Scene& scene, std::size_t instance);

// The cull mode setup_triangle applies over the frame (render/material_sides.hpp): options.cull,
// or none when some instance's material is double-sided (projection then culls per instance).
CullMode scene_cull(const Scene& scene, const RenderOptions& options);

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
    // Each corner's weights in the scene triangle (identity for a whole scene triangle).
    std::array<glm::vec3, 3> weights{glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)};
};

// One instance's transforms, as the renderer's vertex stage computes with them, and the
// sources of its triangles.
struct InstanceProjection {
    glm::mat4 mvp{1.0f}, model{1.0f};
    glm::dmat4 model_d{1.0};
    InstanceProjection() = default;
    InstanceProjection(const FrameContext& frame, const Instance& instance);
    // Triangle t (vertex indices `index`, valid) of `mesh`, instance number `instance`. Its plane
    // is zero for a triangle of no area.
    TriangleSource source(const Mesh& mesh, std::size_t instance, std::size_t t,
                          const std::array<std::uint32_t, 3>& index) const;
};

// Scene triangle (instance, primitive) projected as project_scene projects it (false: nothing
// of it is left, or its indices are bad).
bool project_scene_triangle(const FrameContext& frame, std::int32_t instance,
                            std::int32_t primitive, ScreenPolygon& out);

// The three vertex indices of triangle t of `mesh`; false when one is past its positions.
bool triangle_indices(const Mesh& mesh, std::size_t t, std::array<std::uint32_t, 3>& out);

// Calls fn(instance index, instance, mesh, triangle index, its vertex indices) for every triangle
// of every instance (in submission order) whose vertex indices are valid.
template <class Fn>
void for_each_scene_triangle(const Scene& scene, Fn&& fn) {
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& instance = scene.instances[i];
        const Mesh& mesh = scene.meshes.at(instance.mesh);
        std::array<std::uint32_t, 3> index;
        for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
            if (triangle_indices(mesh, t, index)) fn(i, instance, mesh, t, index);
    }
}

// Clips and projects the triangle; false when nothing of it is left (rejected, clipped away,
// non-finite, zero snapped area, culled, or no pixel center in its bounding box).
bool project_triangle(const FrameContext& frame, const TriangleSource& source, ScreenPolygon& out);

// Flat shading of a scene triangle, exactly as the renderer's flat path computes it.
struct FlatShade {
    glm::vec3 color{0.0f};   // combine(terms, material base color); the base color when unlit
    glm::vec3 normal{0.0f};  // the face normal, flipped for back faces with two-sided lighting
    LightTerms terms;        // lighting at the centroid (zero when unlit)
};
FlatShade flat_shade(const FrameContext& frame, std::int32_t instance, std::int32_t primitive,
                     bool front_facing);

// Unit world plane through a, b, c along their winding; (0, 0, 0, 0) when degenerate.
glm::dvec4 plane_through(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

// Signed distance of `p` from a unit world plane (positive on the side the normal points to).
inline double plane_distance(const glm::dvec4& plane, const glm::dvec3& p) {
    return glm::dot(glm::dvec3(plane), p) + plane.w;
}

// A plane flipped (if needed) so that `viewer` is on its positive side.
glm::dvec4 orient_towards(const glm::dvec4& plane, const glm::dvec4& viewer);

// Splits a convex polygon's vertex loop by `plane` (Sutherland-Hodgman against both half
// spaces at once): vertices within eps of the plane go to both sides; a new vertex is made on
// every edge that crosses it by make(from_front, to_back, t, out), t = the fraction from the front
// vertex towards the back one, so polygons sharing an edge get bit-identical new vertices on it.
// make returns false to abandon the split. Vertex needs a dvec3 `world`. False when a side is
// empty (the polygon does not straddle the plane beyond eps) or make refused.
template <class Vertex, class Make>
bool split_by_plane(const std::vector<Vertex>& v, const glm::dvec4& plane, double eps,
                    std::vector<Vertex>& front, std::vector<Vertex>& back, Make&& make) {
    const std::size_t n = v.size();
    std::vector<double> d(n);
    std::vector<int> side(n);
    bool any_front = false, any_back = false;
    for (std::size_t i = 0; i < n; ++i) {
        d[i] = plane_distance(plane, v[i].world);
        side[i] = d[i] > eps ? 1 : (d[i] < -eps ? -1 : 0);
        any_front |= side[i] > 0;
        any_back |= side[i] < 0;
    }
    if (!any_front || !any_back) return false;
    front.clear();
    back.clear();
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j = (i + 1) % n;
        if (side[i] >= 0) front.push_back(v[i]);
        if (side[i] <= 0) back.push_back(v[i]);
        if (side[i] * side[j] < 0) {
            const std::size_t f = side[i] > 0 ? i : j, b = side[i] > 0 ? j : i;
            Vertex c;
            if (!make(v[f], v[b], d[f] / (d[f] - d[b]), c)) return false;
            front.push_back(c);
            back.push_back(c);
        }
    }
    return true;
}

// Window depth z = a x + b y + c over a polygon's plane (x, y in pixels), from Newell's normal of
// its window vertices (robust for nearly collinear consecutive vertices).
struct DepthPlane {
    double a = 0, b = 0, c = 0;
    double at(double x, double y) const { return a * x + b * y + c; }
};
DepthPlane depth_plane(const ScreenPolygon& polygon);

// The BSP tree's walk for the frame's viewer, every stored polygon projected fan triangle by fan
// triangle through project_triangle (the renderer's clipping, culling and snapping): calls
// fn(piece) for each piece that is left, back to front.
void for_each_bsp_piece(const BspTree& tree, const FrameContext& frame,
                        const std::function<void(const ScreenPolygon&)>& fn);

}  // namespace zraster::visibility_detail
