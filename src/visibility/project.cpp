// Projection of a scene into ScreenPolygons: the common input of the painter's and Warnock's
// algorithms (and of each BSP frame).
//
// It runs the z-buffer renderer's vertex-stage math through the same public functions
// (Camera::view_projection, clip_outcode, clip_triangle, to_screen), so a triangle that is not
// split later rasterizes bit-identically to render()'s. The difference is the unit of output:
// render() fan-triangulates each clipped polygon at once; here the convex polygon is kept whole,
// with its world-space positions and plane, because the list-priority algorithms reason about whole
// polygons and their planes.
//
// Cost: O(triangles) time and memory (one heap-allocated vertex list per polygon).
#include <zraster/error.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "render/input_checks.hpp"
#include "render/material_sides.hpp"
#include "visibility/frame_context.hpp"

namespace zraster {

Camera effective_camera(const Scene& scene, const RenderOptions& options) {
    if (options.camera) return *options.camera;
    // The fit reads every instanced vertex: within the vertex limit, checked before the copy
    // (a mesh of a million vertices placed a thousand times would ask for 12 GB).
    if (scene.vertex_count() > options.limits.max_vertices)
        throw LimitExceeded(scene.name, "max_vertices",
                            std::to_string(scene.vertex_count()) +
                                " vertices over all instances, more than the limit of " +
                                std::to_string(options.limits.max_vertices));
    return fit_camera(scene.world_positions());
}

namespace visibility_detail {
namespace {

bool finite(const glm::vec4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

constexpr std::int64_t kHalfPixel = kSubpixelScale / 2;

std::int64_t floor_div(std::int64_t a, std::int64_t b) {
    std::int64_t q = a / b;
    if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
    return q;
}

// True when the snapped bounding box of the polygon holds a pixel center of the viewport (the
// same test setup_triangle uses to report NoCoverage), or with `subpixel` any point of it.
bool may_cover_a_pixel(std::span<const PolygonVertex> vertices, const Viewport& viewport,
                       bool subpixel) {
    std::int64_t lo_x = vertices[0].snapped[0], hi_x = lo_x;
    std::int64_t lo_y = vertices[0].snapped[1], hi_y = lo_y;
    for (const PolygonVertex& v : vertices) {
        lo_x = std::min(lo_x, v.snapped[0]);
        hi_x = std::max(hi_x, v.snapped[0]);
        lo_y = std::min(lo_y, v.snapped[1]);
        hi_y = std::max(hi_y, v.snapped[1]);
    }
    if (subpixel)
        return hi_x >= 0 && hi_y >= 0 && lo_x <= std::int64_t(viewport.width) * kSubpixelScale &&
               lo_y <= std::int64_t(viewport.height) * kSubpixelScale;
    const std::int64_t px0 =
        std::max<std::int64_t>(0, -floor_div(kHalfPixel - lo_x, kSubpixelScale));
    const std::int64_t py0 =
        std::max<std::int64_t>(0, -floor_div(kHalfPixel - lo_y, kSubpixelScale));
    const std::int64_t px1 =
        std::min<std::int64_t>(viewport.width - 1, floor_div(hi_x - kHalfPixel, kSubpixelScale));
    const std::int64_t py1 =
        std::min<std::int64_t>(viewport.height - 1, floor_div(hi_y - kHalfPixel, kSubpixelScale));
    return px0 <= px1 && py0 <= py1;
}

}  // namespace

FrameContext make_frame_context(const Scene& scene, const RenderOptions& options) {
    if (options.width < 1 || options.height < 1 || options.width > kMaxViewport ||
        options.height > kMaxViewport)
        throw InputError("", "image size " + std::to_string(options.width) + "x" +
                                 std::to_string(options.height) + " out of range (1.." +
                                 std::to_string(kMaxViewport) + " per side)");
    if (options.clip_planes.size() > std::size_t(kMaxUserClipPlanes))
        throw InputError("", "at most " + std::to_string(kMaxUserClipPlanes) +
                                 " user clip planes are supported");
    if (options.camera) check_camera(*options.camera, options.width, options.height);
    // The same estimate as render()'s: the camera fit's copy and the projection grow with the
    // instanced vertices and triangles (the polygons kept have budgets of their own).
    check_frame_memory(scene.name, scene.vertex_count(), scene.triangle_count(),
                       std::uint64_t(options.width) * std::uint64_t(options.height),
                       options.limits);
    // Vertex colors as the renderer checks them: shading reads them by vertex, and a NaN would
    // spread over whole triangles.
    if (std::any_of(scene.meshes.begin(), scene.meshes.end(),
                    [](const Mesh& m) { return !m.colors.empty(); })) {
        std::vector<MeshView> meshes;
        std::vector<InstanceView> instances;
        const SceneView view = view_of(scene, meshes, instances);
        for (std::size_t m = 0; m < meshes.size(); ++m)
            if (meshes[m].colors.count > 0) (void)detail::checked_vertex_colors(view, "", m);
    }
    FrameContext f;
    f.scene = &scene;
    f.options = &options;
    f.camera = effective_camera(scene, options);
    f.view_projection = f.camera.view_projection(double(options.width) / double(options.height));
    f.eye = glm::vec3(f.camera.position());
    f.view_axis = glm::vec3(-f.camera.view_direction());
    f.viewer = bsp_eye(f.camera);
    f.clip_settings.depth_range = f.camera.clip_depth_range();
    f.clip_settings.guard_x = static_cast<float>(kGuardBand / (0.5 * options.width));
    f.clip_settings.guard_y = static_cast<float>(kGuardBand / (0.5 * options.height));
    f.clip_settings.user_plane_count = static_cast<int>(options.clip_planes.size());
    f.setup_settings.viewport = {options.width, options.height};
    f.setup_settings.depth_range = f.camera.clip_depth_range();
    f.setup_settings.cull = scene_cull(scene, options);
    f.setup_settings.front_face = options.front_face;
    return f;
}

const Material& instance_material(const Scene& scene, std::size_t instance) {
    const Mesh& mesh = scene.meshes.at(scene.instances.at(instance).mesh);
    return scene.materials.at(mesh.material < scene.materials.size() ? mesh.material : 0);
}

CullMode scene_cull(const Scene& scene, const RenderOptions& options) {
    for (std::size_t i = 0; i < scene.instances.size(); ++i)
        if (detail::instance_cull(instance_material(scene, i), options) != options.cull)
            return CullMode::None;
    return options.cull;
}

RenderTargets blank_targets(const RenderOptions& options) {
    const std::size_t pixels = std::size_t(options.width) * std::size_t(options.height);
    RenderTargets t;
    t.width = options.width;
    t.height = options.height;
    if (options.color_target) t.color.assign(pixels * 4, 255);
    t.depth.assign(pixels, depth_clear_value(options));
    if (options.normal_target) t.normal.assign(pixels, glm::vec3(0.0f));
    if (options.id_targets) {
        t.instance_id.assign(pixels, -1);
        t.primitive_id.assign(pixels, -1);
    }
    return t;
}

void finish_stats(RenderStats& stats, const Camera& camera, const Scene& scene,
                  std::chrono::steady_clock::time_point start) {
    stats.camera = camera;
    stats.triangles_in = scene.triangle_count();
    stats.total_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void check_samples_per_side(int n, const char* what) {
    if (n != 1 && n != 2 && n != 4 && n != 8)
        throw InputError("", std::string(what) + " samples per side must be 1, 2, 4 or 8, not " +
                                 std::to_string(n));
}

bool set_window_xy(PolygonVertex& v, const Viewport& viewport) {
    SetupSettings settings;
    settings.viewport = viewport;
    ScreenVertex s;
    if (!to_screen(v.clip, settings, s)) return false;
    v.snapped = {s.x, s.y};
    v.window.x = double(s.x) / double(kSubpixelScale);
    v.window.y = double(s.y) / double(kSubpixelScale);
    return true;
}

bool set_window(PolygonVertex& v, const FrameContext& frame) {
    if (!set_window_xy(v, frame.setup_settings.viewport)) return false;
    // In double (to_screen's float depth is enough for the depth test, not for the depth-range
    // comparisons of the painter's algorithm), and normalized so that larger is farther.
    const double z = double(v.clip.z) / double(v.clip.w);
    v.window.z = frame.setup_settings.depth_range == ClipDepthRange::NegativeOneToOne
                     ? 0.5 * z + 0.5
                     : 1.0 - z;
    return true;
}

std::int64_t snapped_area2(std::span<const PolygonVertex> vertices) {
    std::int64_t area = 0;
    const std::size_t n = vertices.size();
    // Relative to vertex 0 so the products stay within the precision.hpp bounds.
    const std::int64_t ox = vertices[0].snapped[0], oy = vertices[0].snapped[1];
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const std::int64_t ax = vertices[i].snapped[0] - ox, ay = vertices[i].snapped[1] - oy;
        const std::int64_t bx = vertices[i + 1].snapped[0] - ox,
                           by = vertices[i + 1].snapped[1] - oy;
        area += ax * by - bx * ay;
    }
    return area;
}

glm::dvec4 plane_through(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double len = glm::length(n);
    if (!(len > 0.0) || !std::isfinite(len)) return glm::dvec4(0.0);
    const glm::dvec3 u = n / len;
    return {u, -glm::dot(u, a)};
}

glm::dvec4 orient_towards(const glm::dvec4& plane, const glm::dvec4& viewer) {
    const double side = glm::dot(glm::dvec3(plane), glm::dvec3(viewer)) + plane.w * viewer.w;
    return side < 0.0 ? -plane : plane;
}

FlatShade flat_shade(const FrameContext& frame, std::int32_t instance, std::int32_t primitive,
                     bool front_facing) {
    const Scene& scene = *frame.scene;
    const RenderOptions& options = *frame.options;
    const Instance& inst = scene.instances[static_cast<std::size_t>(instance)];
    const Mesh& mesh = scene.meshes[inst.mesh];
    const Material& material =
        scene.materials.at(mesh.material < scene.materials.size() ? mesh.material : 0);
    std::array<glm::vec3, 3> w;
    for (std::size_t k = 0; k < 3; ++k) {
        const std::uint32_t index = mesh.indices[3 * static_cast<std::size_t>(primitive) + k];
        w[k] = glm::vec3(inst.transform * glm::vec4(mesh.positions[index], 1.0f));
    }
    // The renderer's flat_terms, operation for operation, so the colors match bit for bit.
    glm::vec3 n = glm::cross(w[1] - w[0], w[2] - w[0]);
    const float len = glm::length(n);
    n = len > 0.0f ? n / len : glm::vec3(0, 1, 0);
    if (!front_facing && detail::instance_two_sided_lighting(material, options)) n = -n;
    FlatShade out;
    out.normal = n;
    if (inst.shading.value_or(options.shading) == ShadingMode::Unlit) {
        out.color = material.base_color;
        return out;
    }
    const glm::vec3 centroid = (w[0] + w[1] + w[2]) / 3.0f;
    out.terms =
        evaluate_lighting(options.lighting, material, centroid, n, frame.eye, frame.view_axis);
    out.color = combine(out.terms, material.base_color);
    return out;
}

bool project_triangle(const FrameContext& frame, const TriangleSource& source, ScreenPolygon& out) {
    const RenderOptions& options = *frame.options;
    for (const glm::vec4& c : source.clip)
        if (!finite(c)) return false;
    const int user_planes = frame.clip_settings.user_plane_count;
    std::array<std::array<float, 3>, kMaxUserClipPlanes> user_distances{};
    std::uint32_t codes[3];
    for (std::size_t k = 0; k < 3; ++k) {
        float d[kMaxUserClipPlanes] = {};
        for (int p = 0; p < user_planes; ++p) {
            const glm::vec4& plane = options.clip_planes[static_cast<std::size_t>(p)];
            d[p] = glm::dot(glm::vec3(plane), source.world_f[k]) + plane.w;
            user_distances[static_cast<std::size_t>(p)][k] = d[p];
        }
        codes[k] = clip_outcode(source.clip[k], frame.clip_settings,
                                std::span<const float>(d, static_cast<std::size_t>(user_planes)));
    }
    if (codes[0] & codes[1] & codes[2]) return false;
    const std::uint32_t crossing = codes[0] | codes[1] | codes[2];

    out.vertices.clear();
    if (crossing == 0) {
        for (std::size_t k = 0; k < 3; ++k) {
            PolygonVertex v;
            v.clip = source.clip[k];
            v.world = source.world[k];
            v.weights = source.weights[k];
            out.vertices.push_back(v);
        }
    } else {
        ClippedPolygon polygon;
        clip_triangle(source.clip, crossing, frame.clip_settings,
                      std::span(user_distances.data(), static_cast<std::size_t>(user_planes)),
                      polygon);
        if (polygon.count < 3) return false;
        for (int i = 0; i < polygon.count; ++i) {
            const ClipVertex& c = polygon.vertices[static_cast<std::size_t>(i)];
            PolygonVertex v;
            v.clip = c.position;
            v.world = double(c.weights.x) * source.world[0] +
                      double(c.weights.y) * source.world[1] + double(c.weights.z) * source.world[2];
            v.weights = c.weights.x * source.weights[0] + c.weights.y * source.weights[1] +
                        c.weights.z * source.weights[2];
            out.vertices.push_back(v);
        }
    }
    for (PolygonVertex& v : out.vertices)
        if (!set_window(v, frame)) return false;  // as the renderer: drop the polygon

    // Facing and culling as setup_triangle decides them, on the snapped coordinates.
    const std::int64_t area = snapped_area2(out.vertices);
    if (area == 0) return false;
    const bool ccw = area < 0;
    out.front_facing = (options.front_face == FrontFace::CounterClockwise) == ccw;
    const CullMode cull = detail::instance_cull(
        instance_material(*frame.scene, std::size_t(source.instance)), options);
    if ((cull == CullMode::Back && !out.front_facing) ||
        (cull == CullMode::Front && out.front_facing))
        return false;
    if (!may_cover_a_pixel(out.vertices, frame.setup_settings.viewport, frame.keep_subpixel))
        return false;

    out.plane = orient_towards(source.plane, frame.viewer);
    out.instance = source.instance;
    out.primitive = source.primitive;
    const FlatShade shade = flat_shade(frame, source.instance, source.primitive, out.front_facing);
    out.color = shade.color;
    out.normal = shade.normal;
    return true;
}

bool triangle_indices(const Mesh& mesh, std::size_t t, std::array<std::uint32_t, 3>& out) {
    for (std::size_t k = 0; k < 3; ++k) {
        out[k] = mesh.indices[3 * t + k];
        if (out[k] >= mesh.positions.size()) return false;
    }
    return true;
}

DepthPlane depth_plane(const ScreenPolygon& polygon) {
    const auto& v = polygon.vertices;
    const std::size_t n = v.size();
    glm::dvec3 normal(0.0), mean(0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3& p = v[i].window;
        const glm::dvec3& q = v[(i + 1) % n].window;
        normal.x += (p.y - q.y) * (p.z + q.z);
        normal.y += (p.z - q.z) * (p.x + q.x);
        normal.z += (p.x - q.x) * (p.y + q.y);
        mean += p;
    }
    mean /= double(n);
    DepthPlane plane;
    if (std::abs(normal.z) > 1e-300) {
        plane.a = -normal.x / normal.z;
        plane.b = -normal.y / normal.z;
    }
    plane.c = mean.z - plane.a * mean.x - plane.b * mean.y;
    return plane;
}

InstanceProjection::InstanceProjection(const FrameContext& frame, const Instance& instance)
    : mvp(frame.view_projection * instance.transform),
      model(instance.transform),
      model_d(glm::dmat4(instance.transform)) {}

TriangleSource InstanceProjection::source(const Mesh& mesh, std::size_t instance, std::size_t t,
                                          const std::array<std::uint32_t, 3>& index) const {
    // As the renderer's vertex stage computes them (float), plus double world positions.
    TriangleSource source;
    source.instance = static_cast<std::int32_t>(instance);
    source.primitive = static_cast<std::int32_t>(t);
    for (std::size_t k = 0; k < 3; ++k) {
        const glm::vec4 p(mesh.positions[index[k]], 1.0f);
        source.clip[k] = mvp * p;
        source.world_f[k] = glm::vec3(model * p);
        source.world[k] = glm::dvec3(model_d * glm::dvec4(p));
    }
    source.plane = plane_through(source.world[0], source.world[1], source.world[2]);
    return source;
}

bool project_scene_triangle(const FrameContext& frame, std::int32_t instance,
                            std::int32_t primitive, ScreenPolygon& out) {
    const Scene& scene = *frame.scene;
    const Instance& inst = scene.instances.at(static_cast<std::size_t>(instance));
    const Mesh& mesh = scene.meshes.at(inst.mesh);
    std::array<std::uint32_t, 3> index;
    if (!triangle_indices(mesh, static_cast<std::size_t>(primitive), index)) return false;
    const TriangleSource source = InstanceProjection(frame, inst)
                                      .source(mesh, static_cast<std::size_t>(instance),
                                              static_cast<std::size_t>(primitive), index);
    return source.plane != glm::dvec4(0.0) && project_triangle(frame, source, out);
}

}  // namespace visibility_detail

std::vector<ScreenPolygon> project_scene(const Scene& scene, const RenderOptions& options,
                                         bool keep_subpixel) {
    using namespace visibility_detail;
    FrameContext frame = make_frame_context(scene, options);
    frame.keep_subpixel = keep_subpixel;
    // The polygons are counted as they are kept: their memory (0.7 to 2 KB each in the
    // algorithms that take them) is bounded before it is spent, not after.
    const std::uint64_t budget = projected_polygon_budget(options.limits);
    const std::uint64_t triangles = scene.triangle_count();
    std::uint64_t done = 0, next_report = 0;
    std::vector<ScreenPolygon> out;
    ScreenPolygon polygon;
    std::size_t current = scene.instances.size();
    InstanceProjection projection;
    for_each_scene_triangle(scene, [&](std::size_t i, const Instance& instance, const Mesh& mesh,
                                       std::size_t t, const std::array<std::uint32_t, 3>& index) {
        if (options.progress != nullptr && ++done >= next_report) {
            next_report = done + (1 << 16);
            options.progress->report("projecting triangles", double(done) / double(triangles));
        }
        if (i != current) {
            current = i;
            projection = InstanceProjection(frame, instance);
        }
        const TriangleSource source = projection.source(mesh, i, t, index);
        if (source.plane == glm::dvec4(0.0)) return;  // no area: nothing to see
        if (!project_triangle(frame, source, polygon)) return;
        if (out.size() >= budget)
            throw LimitExceeded(scene.name, "max_projected_polygons",
                                "more than " + std::to_string(budget) +
                                    " polygons in view after projecting " + std::to_string(done) +
                                    " of " + std::to_string(triangles) +
                                    " triangles (the budget of the object-space algorithms' "
                                    "input): draw fewer triangles, or use the z-buffer");
        out.push_back(polygon);
    });
    return out;
}

}  // namespace zraster
