// The text `zraster info` prints about a scene.
#include <zraster/load.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace zraster {

namespace {

constexpr std::size_t kMaxListed = 50;

std::string number(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4g", v);
    return buffer;
}

std::string vec(const glm::vec3& v) {
    return "(" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ")";
}

std::string box(const Bounds3f& b) {
    if (b.empty()) return "empty";
    return vec(b.lo) + " - " + vec(b.hi);
}

std::string transform_text(const glm::mat4& m) {
    if (m == glm::mat4(1.0f)) return "identity";
    glm::mat4 translation(1.0f);
    translation[3] = m[3];
    if (m == translation) return "translation " + vec(glm::vec3(m[3]));
    std::string out = "matrix [";
    for (int row = 0; row < 4; ++row) {
        out += row ? "; " : "";
        for (int col = 0; col < 4; ++col) out += (col ? " " : "") + number(m[col][row]);
    }
    return out + "]";
}

std::string quoted(const std::string& s) {
    return "'" + s + "'";
}

// Exact: the box of the transformed vertices (Scene::bounds transforms boxes, which is larger
// under rotation).
Bounds3f exact_world_bounds(const Scene& scene) {
    Bounds3f b;
    for (const Instance& instance : scene.instances) {
        if (instance.mesh >= scene.meshes.size()) continue;
        for (const glm::vec3& p : scene.meshes[instance.mesh].positions) {
            const glm::vec4 q = instance.transform * glm::vec4(p, 1.0f);
            b.extend(glm::vec3(q) / q.w);
        }
    }
    return b;
}

std::string size_text(const Texture& t) {
    return std::to_string(t.width()) + "x" + std::to_string(t.height());
}

// Whether an opacity texture (read in its red channel) has a texel below 1.
bool has_partial_red(const Texture& t) {
    const std::span<const std::uint8_t> rgba = t.level_rgba(0);
    for (std::size_t i = 0; i < rgba.size(); i += 4)
        if (rgba[i] != 255) return true;
    return false;
}

// "alpha opaque", "alpha mask (cutoff 0.5)", "alpha blend (opacity 0.5)", then for mask and
// blend whether alpha can be below 1 and from which factors (material.hpp's product; vertex
// alpha: the least of the meshes that use it).
std::string alpha_text(const Material& m, float least_vertex_alpha) {
    if (m.alpha_mode == AlphaMode::Opaque) return "alpha opaque";
    std::string out = m.alpha_mode == AlphaMode::Mask
                          ? "alpha mask (cutoff " + number(m.alpha_cutoff) +
                                (m.opacity != 1.0f ? ", opacity " + number(m.opacity) : "") + ")"
                          : "alpha blend (opacity " + number(m.opacity) + ")";
    std::string sources;
    const auto add = [&](const char* source) {
        sources += (sources.empty() ? "" : ", ") + std::string(source);
    };
    if (!(m.opacity >= 1.0f)) add("opacity");
    if (m.base_color_texture && m.base_color_texture->has_translucent_texels())
        add("texture alpha");
    if (m.opacity_texture && has_partial_red(*m.opacity_texture)) add("opacity texture");
    if (least_vertex_alpha < 1.0f) add("vertex alpha");
    return out + (sources.empty() ? ", alpha 1 everywhere" : ", alpha below 1 from " + sources);
}

// ", vertex colors (alpha 0.25 to 1)" for a mesh with colors, else nothing.
std::string colors_text(const Mesh& m) {
    if (m.colors.empty()) return "";
    float least = 1.0f, most = 0.0f;
    for (const glm::vec4& c : m.colors) {
        least = std::min(least, c.w);
        most = std::max(most, c.w);
    }
    return ", vertex colors (alpha " +
           (least == most ? number(least) : number(least) + " to " + number(most)) + ")";
}

template <typename Item>
void list(std::string& out, const char* title, const std::vector<Item>& items, auto describe) {
    out += std::string(title) + ": " + std::to_string(items.size()) + "\n";
    for (std::size_t i = 0; i < items.size() && i < kMaxListed; ++i)
        out += "  " + describe(i, items[i]) + "\n";
    if (items.size() > kMaxListed)
        out += "  ... and " + std::to_string(items.size() - kMaxListed) + " more\n";
}

}  // namespace

std::string describe_scene(const Scene& scene, const std::vector<std::string>& warnings) {
    std::string out = "source: " + scene.name + "\n";
    list(out, "meshes", scene.meshes, [&](std::size_t i, const Mesh& m) {
        std::string material = std::to_string(m.material);
        if (m.material < scene.materials.size())
            material += " " + quoted(scene.materials[m.material].name);
        return "mesh " + std::to_string(i) + " " + quoted(m.name) + ": " +
               std::to_string(m.triangle_count()) + " triangles, " +
               std::to_string(m.vertex_count()) + " vertices, material " + material + ", bounds " +
               box(m.bounds) + colors_text(m);
    });
    // Vertex alpha per material: the least over the meshes that use it.
    std::vector<float> least_vertex_alpha(scene.materials.size(), 1.0f);
    for (const Mesh& m : scene.meshes)
        if (m.material < scene.materials.size())
            for (const glm::vec4& c : m.colors)
                least_vertex_alpha[m.material] = std::min(least_vertex_alpha[m.material], c.w);
    list(out, "instances", scene.instances, [&](std::size_t i, const Instance& instance) {
        return "instance " + std::to_string(i) + " " + quoted(instance.name) + ": mesh " +
               std::to_string(instance.mesh) + ", " + transform_text(instance.transform);
    });
    out += "total: " + std::to_string(scene.triangle_count()) + " triangles, " +
           std::to_string(scene.vertex_count()) + " vertices (over instances)\n";
    out += "world bounds: " + box(exact_world_bounds(scene)) + "\n";
    list(out, "materials", scene.materials, [&](std::size_t i, const Material& m) {
        const std::string texture =
            m.base_color_texture ? size_text(*m.base_color_texture) : "none";
        const std::string opacity_texture =
            m.opacity_texture ? ", opacity texture " + size_text(*m.opacity_texture) : "";
        return "material " + std::to_string(i) + " " + quoted(m.name) + ": base color " +
               vec(m.base_color) + ", texture " + texture + opacity_texture + ", " +
               alpha_text(m, least_vertex_alpha[i]) + (m.double_sided ? ", double-sided" : "");
    });
    if (!warnings.empty())
        list(out, "warnings", warnings, [](std::size_t, const std::string& w) { return w; });
    return out;
}

}  // namespace zraster
