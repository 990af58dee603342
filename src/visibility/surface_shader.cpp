// Shading of visibility polygons as render() shades pixels (see surface_shader.hpp).
#include "visibility/surface_shader.hpp"

#include <algorithm>
#include <cmath>

#include "render/material_alpha.hpp"
#include "render/material_sides.hpp"

namespace zraster::visibility_detail {
namespace {

// The source triangle's weights one pixel over, computed with the point's own.
struct KnownNeighbours {
    detail::NeighbourWeights weights;
    std::optional<detail::NeighbourWeights> operator()() const { return weights; }
};

}  // namespace

SurfaceShader::SurfaceShader(const FrameContext& frame)
    : frame_(frame),
      shading_{&frame.options->lighting, frame.eye, frame.view_axis, frame.options->texture_filter,
               frame.options->two_sided_lighting} {
    const Scene& scene = *frame.scene;
    const RenderOptions& options = *frame.options;
    std::uint32_t total = 0;
    for (const Instance& instance : scene.instances) {
        const Mesh& mesh = scene.meshes.at(instance.mesh);
        InstanceInfo info;
        info.material =
            &scene.materials.at(mesh.material < scene.materials.size() ? mesh.material : 0);
        info.shading = instance.shading.value_or(options.shading);
        info.textured = options.textures && info.material->base_color_texture && !mesh.uvs.empty();
        info.vertex_colored = !mesh.colors.empty();
        // As the renderer's vertex stage decides them (src/render/vertex_stage.cpp).
        const bool uvs = options.textures && !mesh.uvs.empty();
        const float least_vertex_alpha = detail::least_vertex_alpha(mesh.colors);
        info.alpha = detail::effective_alpha_mode(*info.material, uvs, least_vertex_alpha, options);
        info.alpha_varies.textures =
            info.alpha != AlphaMode::Opaque && uvs &&
            (info.material->base_color_texture || info.material->opacity_texture);
        info.alpha_varies.vertices = info.alpha != AlphaMode::Opaque && least_vertex_alpha < 1.0f;
        info.two_sided_lighting = detail::instance_two_sided_lighting(*info.material, options);
        info.first_vertex = total;
        instances_.push_back(info);
        total += static_cast<std::uint32_t>(mesh.positions.size());
    }
    world_.resize(total);
    normal_.resize(total);
    uv_.resize(total);
    gouraud_.resize(total);
    color_.resize(total);
    // As the renderer's vertex stage (src/render/vertex_stage.cpp).
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& instance = scene.instances[i];
        const Mesh& mesh = scene.meshes[instance.mesh];
        const InstanceInfo& info = instances_[i];
        const glm::mat3 to_world_normal = normal_matrix(instance.transform);
        for (std::size_t k = 0; k < mesh.positions.size(); ++k) {
            const std::size_t out = info.first_vertex + k;
            const glm::vec3 n = k < mesh.normals.size() ? mesh.normals[k] : glm::vec3(0, 1, 0);
            detail::world_attributes(instance.transform, to_world_normal, mesh.positions[k], n,
                                     world_[out], normal_[out]);
            uv_[out] = k < mesh.uvs.size() ? mesh.uvs[k] : glm::vec2(0.0f);
            color_[out] = k < mesh.colors.size() ? mesh.colors[k] : glm::vec4(1.0f);
            if (info.shading == ShadingMode::Gouraud)
                gouraud_[out] = evaluate_lighting(options.lighting, *info.material, world_[out],
                                                  normal_[out], frame.eye, frame.view_axis);
        }
    }
}

namespace {

// Whether a polygon may be less than its whole scene triangle: a corner that is not one of the
// triangle's (a split or a clip made it). Clipped by the frustum only, the source projected
// again is the same polygon.
bool is_piece(const ScreenPolygon& polygon) {
    for (const PolygonVertex& v : polygon.vertices) {
        const glm::vec3& w = v.weights;
        const bool corner = (w.x == 1.0f && w.y == 0.0f && w.z == 0.0f) ||
                            (w.x == 0.0f && w.y == 1.0f && w.z == 0.0f) ||
                            (w.x == 0.0f && w.y == 0.0f && w.z == 1.0f);
        if (!corner) return true;
    }
    return false;
}

}  // namespace

void SurfaceShader::prepare(const ScreenPolygon& piece, Prepared& out) const {
    const Scene& scene = *frame_.scene;
    const bool whole = !is_piece(piece) ||
                       !project_scene_triangle(frame_, piece.instance, piece.primitive, out.source);
    const ScreenPolygon& polygon = whole ? piece : out.source;
    out.polygon = &polygon;
    out.instance = static_cast<std::uint32_t>(polygon.instance);
    const InstanceInfo& info = instances_[out.instance];
    const Mesh& mesh = scene.meshes[scene.instances[out.instance].mesh];
    std::array<std::uint32_t, 3>& vertex = out.corners.vertex;
    for (std::size_t k = 0; k < 3; ++k)
        vertex[k] =
            info.first_vertex + mesh.indices[3 * static_cast<std::size_t>(polygon.primitive) + k];
    out.corners.front_facing = polygon.front_facing;
    out.corners.flat =
        info.shading == ShadingMode::Flat
            ? detail::flat_terms(shading_of(info), *info.material, world_[vertex[0]],
                                 world_[vertex[1]], world_[vertex[2]], polygon.front_facing)
            : LightTerms{};
    const auto& v = polygon.vertices;
    out.screen.resize(v.size());
    for (std::size_t k = 0; k < v.size(); ++k)
        to_screen(v[k].clip, frame_.setup_settings, out.screen[k]);
    out.fans.clear();
    out.fan_k.clear();
    out.fan_valid.clear();
    for (std::size_t k = 1; k + 1 < v.size(); ++k) {
        TriangleSetup setup;
        const bool valid = setup_triangle({out.screen[0], out.screen[k], out.screen[k + 1]},
                                          frame_.setup_settings, setup) == SetupResult::Visible;
        out.fans.push_back(setup);
        out.fan_k.push_back(static_cast<std::uint32_t>(k));
        out.fan_valid.push_back(valid);
    }
}

glm::vec3 SurfaceShader::original_weights(const Prepared& p, std::size_t fan,
                                          const glm::vec3& b) const {
    const auto& v = p.polygon->vertices;
    const std::size_t k = p.fan_k[fan];
    return b.x * v[0].weights + b.y * v[k].weights + b.z * v[k + 1].weights;
}

glm::vec3 SurfaceShader::fan_barycentrics(const Prepared& p, std::size_t fan, double x,
                                          double y) const {
    const std::size_t k = p.fan_k[fan];
    const ScreenVertex* s[3] = {&p.screen[0], &p.screen[k], &p.screen[k + 1]};
    const double x0 = s[0]->window_x, y0 = s[0]->window_y;
    const double ex1 = s[1]->window_x - x0, ey1 = s[1]->window_y - y0;
    const double ex2 = s[2]->window_x - x0, ey2 = s[2]->window_y - y0;
    const double det = ex1 * ey2 - ex2 * ey1;
    if (!(std::abs(det) > 0.0)) return {1.0f, 0.0f, 0.0f};
    const double dx = x - x0, dy = y - y0;
    const double l1 = (dx * ey2 - ex2 * dy) / det, l2 = (ex1 * dy - dx * ey1) / det;
    double b[3] = {1.0 - l1 - l2, l1, l2};
    if (frame_.options->interpolation == Interpolation::PerspectiveCorrect) {
        double sum = 0.0;
        for (int i = 0; i < 3; ++i) sum += b[i] *= s[i]->inv_w;
        if (sum != 0.0)
            for (double& value : b) value /= sum;
    }
    return {float(b[0]), float(b[1]), float(b[2])};
}

bool SurfaceShader::weights_at(const Prepared& p, int px, int py, bool center, double x, double y,
                               glm::vec3& b, detail::NeighbourWeights& over) const {
    const Interpolation interpolation = frame_.options->interpolation;
    // Which fan, and the barycentrics of the source triangle there and one pixel over.
    std::size_t fan = p.fans.size();
    if (center) {
        for (std::size_t f = 0; f < p.fans.size() && fan == p.fans.size(); ++f) {
            if (!p.fan_valid[f]) continue;
            const TriangleSetup& t = p.fans[f];
            bool inside = true;
            for (int e = 0; e < 3; ++e)
                inside = inside && t.edge_a[e] * px + t.edge_b[e] * py + t.edge_c[e] >= 0;
            if (inside) fan = f;
        }
        x = px + 0.5;
        y = py + 0.5;
    }
    if (fan < p.fans.size()) {
        const TriangleSetup& t = p.fans[fan];
        b = original_weights(p, fan, barycentrics(t, px, py, interpolation));
        over.dx = original_weights(p, fan, barycentrics(t, px + 1, py, interpolation));
        over.dy = original_weights(p, fan, barycentrics(t, px, py + 1, interpolation));
        return true;
    }
    // The fan holding (x, y), else the one it is least outside of.
    double best = -1e300;
    for (std::size_t f = 0; f < p.fans.size(); ++f) {
        const glm::vec3 l = fan_barycentrics(p, f, x, y);
        const double worst = std::min({l.x, l.y, l.z});
        if (worst > best) {
            best = worst;
            fan = f;
        }
    }
    if (fan == p.fans.size()) return false;
    b = original_weights(p, fan, fan_barycentrics(p, fan, x, y));
    over.dx = original_weights(p, fan, fan_barycentrics(p, fan, x + 1.0, y));
    over.dy = original_weights(p, fan, fan_barycentrics(p, fan, x, y + 1.0));
    return true;
}

Shaded SurfaceShader::shade(const Prepared& p, int px, int py, bool center, double x, double y,
                            bool want_normal) const {
    const InstanceInfo& info = instances_[p.instance];
    glm::vec3 b;
    detail::NeighbourWeights over;
    if (!weights_at(p, px, py, center, x, y, b, over)) return {p.polygon->color, p.polygon->normal};
    const detail::SurfaceMaterial surface{info.material, info.shading, info.textured,
                                          info.vertex_colored};
    const detail::VertexAttributes attributes{world_, normal_, uv_, gouraud_, color_};
    return detail::shade_surface(shading_of(info), surface, attributes, p.corners, b,
                                 KnownNeighbours{over}, want_normal);
}

float SurfaceShader::constant_alpha(std::int32_t instance) const {
    return detail::material_alpha(*instances_[std::size_t(instance)].material, 1.0f, 1.0f);
}

float SurfaceShader::alpha(const Prepared& p, int px, int py, bool center, double x,
                           double y) const {
    const InstanceInfo& info = instances_[p.instance];
    const Material& material = *info.material;
    glm::vec3 b;
    detail::NeighbourWeights over;
    if (!info.alpha_varies.any() || !weights_at(p, px, py, center, x, y, b, over))
        return detail::material_alpha(material, 1.0f, 1.0f);
    // As the renderer's fragment_alpha (src/render/shade_fragment.cpp).
    const detail::VertexAttributes attributes{world_, normal_, uv_, gouraud_, color_};
    return detail::surface_alpha(shading_of(info), material, attributes, p.corners, b,
                                 KnownNeighbours{over}, info.alpha_varies);
}

bool SurfaceShader::passes_alpha_test(std::int32_t instance, float a) const {
    const InstanceInfo& info = instances_[std::size_t(instance)];
    return info.alpha != AlphaMode::Mask || a >= info.material->alpha_cutoff;
}

bool scene_has_alpha(const Scene& scene, const RenderOptions& options) {
    for (const Instance& instance : scene.instances) {
        const Mesh& mesh = scene.meshes.at(instance.mesh);
        const Material& material =
            scene.materials.at(mesh.material < scene.materials.size() ? mesh.material : 0);
        if (detail::effective_alpha_mode(material, options.textures && !mesh.uvs.empty(),
                                         detail::least_vertex_alpha(mesh.colors),
                                         options) != AlphaMode::Opaque)
            return true;
    }
    return false;
}

}  // namespace zraster::visibility_detail
