// See batch_limits.hpp.
#include "batch_limits.hpp"

#include <zraster/error.hpp>
#include <zraster/precision.hpp>
#include <zraster/render.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <set>

#include <unistd.h>

#include "command_line.hpp"

namespace zraster::cli {
namespace {

// Encoded outputs wait in memory until the files are written: at most about 48 bytes per pixel
// (color, depth, z, range, normal, ids and a point per pixel). The pipeline's working memory is
// render()'s estimate (estimated_frame_bytes).
constexpr std::uint64_t kOutputBytesPerPixel = 48;
static_assert(kMinBytesPerTriangle == 3 * sizeof(std::uint32_t) + kFrameBytesPerTriangle);

std::string mebibytes(std::uint64_t bytes) {
    if (bytes < (1u << 20)) return fmt::format("{:.0f} KiB", double(bytes) / 1024.0);
    return fmt::format("{:.0f} MiB", double(bytes) / double(1u << 20));
}

std::uint64_t scene_bytes(const Scene& scene) {
    std::uint64_t bytes = 0;
    for (const Mesh& mesh : scene.meshes)
        bytes += mesh.positions.size() * sizeof(glm::vec3) +
                 mesh.normals.size() * sizeof(glm::vec3) + mesh.uvs.size() * sizeof(glm::vec2) +
                 mesh.indices.size() * sizeof(std::uint32_t);
    // Each texture once: materials share them, and an image can be both a base-color and an
    // opacity texture.
    std::set<const Texture*> textures;
    for (const Material& material : scene.materials)
        for (const Texture* t : {material.base_color_texture.get(), material.opacity_texture.get()})
            if (t != nullptr && textures.insert(t).second)
                for (int level = 0; level < t->levels(); ++level)
                    bytes += t->level_rgba(level).size();
    return bytes;
}

}  // namespace

std::uint64_t default_max_memory(int jobs) {
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
    const std::uint64_t physical =
        pages > 0 && page > 0 ? std::uint64_t(pages) * std::uint64_t(page) : std::uint64_t{8} << 30;
    return physical / 4 * 3 / std::uint64_t(std::max(jobs, 1));
}

std::size_t load_triangle_limit(const BatchLimits& limits) {
    return std::size_t(std::min(limits.max_triangles, limits.max_memory / kMinBytesPerTriangle));
}

std::uint64_t estimated_memory(const Scene& scene, const std::vector<RenderArguments>& views) {
    std::uint64_t vertices = 0, triangles = 0;
    for (const Instance& instance : scene.instances) {
        vertices += scene.meshes.at(instance.mesh).positions.size();
        triangles += scene.meshes.at(instance.mesh).triangle_count();
    }
    std::uint64_t largest_samples = 0, outputs = 0;
    for (const RenderArguments& a : views) {
        const glm::ivec2 size = parse_size("--size", a.size, kMaxViewport);
        const std::uint64_t pixels = std::uint64_t(size.x) * std::uint64_t(size.y);
        const int per_side = a.visibility == "abuffer" && a.aa == 1 ? 4 : std::max(a.aa, 1);
        const std::uint64_t samples = std::uint64_t(per_side) * std::uint64_t(per_side);
        largest_samples = std::max(largest_samples, pixels * samples);
        outputs += pixels * kOutputBytesPerPixel;
    }
    return scene_bytes(scene) + estimated_frame_bytes(vertices, triangles, largest_samples) +
           outputs;
}

void check_batch_limits(const Scene& scene, const std::vector<RenderArguments>& views,
                        const BatchLimits& limits) {
    const std::uint64_t triangles = scene.triangle_count();
    if (triangles > limits.max_triangles)
        throw LimitExceeded(scene.name, "max_triangles",
                            fmt::format("{} triangles (over its instances), more than "
                                        "--max-triangles {}",
                                        triangles, limits.max_triangles));
    const std::uint64_t bytes = estimated_memory(scene, views);
    if (bytes > limits.max_memory)
        throw LimitExceeded(scene.name, "max_memory",
                            fmt::format("rendering it needs about {}, more than --max-memory {}",
                                        mebibytes(bytes), mebibytes(limits.max_memory)));
}

}  // namespace zraster::cli
